// Common/ImageBasedLighting.fxh — shading with the baked maps: the documents' split-sum combine,
// and the kit's, whose every choice was measured against a Monte Carlo reference of the same BSDF
// (docs/shading.md).
#ifndef COMMON_IMAGE_BASED_LIGHTING_FXH
#define COMMON_IMAGE_BASED_LIGHTING_FXH

#include "Common/PBR.fxh"

// The specular IBL document's final combine, as printed: the prefiltered radiance of the
// reflected direction at mip roughness * (mips - 1), times F0 * scale + bias from the LUT.
float3 SplitSumSpecular( float3 normal, float3 viewDirection, float roughness, float3 f0,
                         TextureCube prefilterMap, uint reflectionMipLevels,
                         Texture2D<float2> brdfLut, SamplerState linearSampler )
{
    float ndotv = saturate( dot( normal, viewDirection ) );
    float3 r = reflect( -viewDirection, normal );
    float3 prefilteredColor = prefilterMap.SampleLevel( linearSampler, r, roughness * ( reflectionMipLevels - 1 ) ).rgb;
    float2 brdf = brdfLut.SampleLevel( linearSampler, float2( ndotv, roughness ), 0 ).rg;
    return prefilteredColor * ( f0 * brdf.x + brdf.y );
}

// The diffuse term from an irradiance cube holding E(n) / pi: albedo times the texel, for the
// non-metallic part of the material.
float3 IrradianceDiffuse( float3 normal, float3 albedo, float metalness, TextureCube irradianceMap,
                          SamplerState linearSampler )
{
    return irradianceMap.SampleLevel( linearSampler, normal, 0 ).rgb * albedo * ( 1.f - metalness );
}

// ---------------------------------------------------------------------------------------------
// The kit's split sum. A recipe says how the maps were made and how they are read; the bake
// writes it into manifest.json and the files' key/value data (docs/shading.md).

// How a lookup's roughness becomes a mip level, n = mips - 1 (runtime/shading/mip_schedule.hpp):
static const uint IBL_LOD_LINEAR = 0;    // r n: the documents, the glTF Sample Viewer
static const uint IBL_LOD_QUADRATIC = 1; // r (2 - r) n: three.js, Filament
static const uint IBL_LOD_POWER = 2;     // r^p n
static const uint IBL_LOD_BABYLON = 3;   // 0.8 log2(r² size), clamped to [0, n]
static const uint IBL_LOD_LOGARITHMIC = 4; // k log2(r² size) + b, clamped to [0, n]: mip 1 at r² = c / size, mip n at 1
                                           // (linear for fewer than 3 mips, or faces no larger than c)

// Where the lookup looks:
static const uint IBL_DIRECTION_REFLECTED = 0; // R
static const uint IBL_DIRECTION_FROSTBITE = 1; // lerp(N, R, s (sqrt(s) + α)), s = 1 - α (Lagarde and de Rousiers 2014)
static const uint IBL_DIRECTION_FILAMENT = 2;  // lerp(R, N, α²)
static const uint IBL_DIRECTION_FITTED = 3;    // the lobe's mean direction, from the lobe table

// What the lookups read:
static const uint IBL_LOOKUP_ROUGHNESS = 0; // one lookup at the surface's roughness
static const uint IBL_LOOKUP_FITTED = 1;    // one lookup at the lobe table's roughness
static const uint IBL_LOOKUP_PAIR = 2;      // two lookups about the mean direction, the lobe table's pair

struct IblRecipe
{
    uint LodMapping;
    float LodParameter; // IBL_LOD_POWER's p, IBL_LOD_LOGARITHMIC's c
    uint SpecularMips;
    uint SpecularSize; // mip 0's face size
    uint Direction;
    uint Lookup;
    uint LightCount;
    uint LightLevel;   // the first mip prefiltered without the lights (mips below it hold them)
};

// A recipe from the fields a kernel's cbuffer holds.
IblRecipe IblRecipeOf( uint lodMapping, float lodParameter, uint specularMips, uint specularSize, uint direction, uint lookup,
                       uint lightCount, uint lightLevel )
{
    IblRecipe recipe;
    recipe.LodMapping = lodMapping;
    recipe.LodParameter = lodParameter;
    recipe.SpecularMips = specularMips;
    recipe.SpecularSize = specularSize;
    recipe.Direction = direction;
    recipe.Lookup = lookup;
    recipe.LightCount = lightCount;
    recipe.LightLevel = lightLevel;
    return recipe;
}

float IblLodOfRoughness( float roughness, IblRecipe recipe )
{
    float last = float( recipe.SpecularMips - 1u );
    float r = saturate( roughness );
    if ( recipe.LodMapping == IBL_LOD_QUADRATIC )
        return r * ( 2.f - r ) * last;
    if ( recipe.LodMapping == IBL_LOD_POWER )
        return pow( r, recipe.LodParameter ) * last;
    if ( recipe.LodMapping == IBL_LOD_BABYLON )
        return r > 0.f ? clamp( 0.8f * log2( r * r * float( recipe.SpecularSize ) ), 0.f, last ) : 0.f;
    if ( recipe.LodMapping == IBL_LOD_LOGARITHMIC && recipe.SpecularMips >= 3u && float( recipe.SpecularSize ) > recipe.LodParameter )
    {
        float size = float( recipe.SpecularSize );
        float slope = ( last - 1.f ) / log2( size / recipe.LodParameter );
        return r > 0.f ? clamp( slope * ( log2( r * r * size ) - log2( size ) ) + last, 0.f, last ) : 0.f;
    }
    return r * last;
}

// The lobe table at (N·V, roughness): (blend, roughness, pair roughness, pair spread), as
// runtime/shading/lobe_table.hpp fits them to the split sum's reflection lobe.
float4 IblLobeFit( float ndotv, float roughness, Texture2D<float4> lobeTable, SamplerState linearSampler )
{
    return lobeTable.SampleLevel( linearSampler, float2( ndotv, roughness ), 0 );
}

// The direction `share` of the way from N to R, along the great circle.
float3 IblTowardsReflection( float3 normal, float3 reflected, float share )
{
    float cosine = clamp( dot( normal, reflected ), -1.f, 1.f );
    float angle = acos( cosine );
    if ( angle < 1e-4f )
        return reflected;
    float sine = sin( angle );
    return ( sin( ( 1.f - share ) * angle ) * normal + sin( share * angle ) * reflected ) / sine;
}

float3 IblLookupDirection( float3 normal, float3 reflected, float roughness, float blend, uint mode )
{
    float alpha = roughness * roughness;
    if ( mode == IBL_DIRECTION_FROSTBITE )
    {
        float smoothness = saturate( 1.f - alpha );
        return normalize( lerp( normal, reflected, smoothness * ( sqrt( smoothness ) + alpha ) ) );
    }
    if ( mode == IBL_DIRECTION_FILAMENT )
        return normalize( lerp( reflected, normal, alpha * alpha ) );
    if ( mode == IBL_DIRECTION_FITTED )
        return IblTowardsReflection( normal, reflected, blend );
    return reflected;
}

// A lookup's share of levels prefiltered without the lights: the weight its trilinear blend
// gives to mips at or past LightLevel.
float IblResidualShare( float lod, IblRecipe recipe )
{
    return recipe.LightCount > 0u ? saturate( lod - float( recipe.LightLevel ) + 1.f ) : 0.f;
}

float3 IblLookup( TextureCube prefiltered, SamplerState linearSampler, float3 direction, float roughness,
                  IblRecipe recipe, inout float residualShare, float weight )
{
    float lod = IblLodOfRoughness( roughness, recipe );
    residualShare += weight * IblResidualShare( lod, recipe );
    return weight * prefiltered.SampleLevel( linearSampler, direction, lod ).rgb;
}

// The prefiltered radiance the recipe reads for (N, V, roughness); residualShare is how much of it
// came from levels without the lights, whose specular the caller adds analytically.
float3 IblSpecularRadiance( float3 normal, float3 viewDirection, float roughness, IblRecipe recipe,
                            TextureCube prefiltered, Texture2D<float4> lobeTable, SamplerState linearSampler,
                            out float residualShare )
{
    residualShare = 0.f;
    float ndotv = saturate( dot( normal, viewDirection ) );
    float3 reflected = reflect( -viewDirection, normal );
    float4 fit = IblLobeFit( ndotv, roughness, lobeTable, linearSampler );
    float3 direction = IblLookupDirection( normal, reflected, roughness, fit.x, recipe.Direction );
    if ( recipe.Lookup == IBL_LOOKUP_ROUGHNESS )
        return IblLookup( prefiltered, linearSampler, direction, roughness, recipe, residualShare, 1.f );
    if ( recipe.Lookup == IBL_LOOKUP_FITTED )
        return IblLookup( prefiltered, linearSampler, direction, fit.y, recipe, residualShare, 1.f );
    // The pair: ± the spread about the mean direction, in the plane of N and V, where a grazing
    // lobe is long.
    float3 across = cross( normal, viewDirection );
    float acrossLength = length( across );
    float3 along = acrossLength > 1e-6f ? cross( across / acrossLength, direction ) : ( float3 )0.f;
    float3 first = normalize( cos( fit.w ) * direction + sin( fit.w ) * along );
    float3 second = normalize( cos( fit.w ) * direction - sin( fit.w ) * along );
    return IblLookup( prefiltered, linearSampler, first, fit.z, recipe, residualShare, 0.5f )
         + IblLookup( prefiltered, linearSampler, second, fit.z, recipe, residualShare, 0.5f );
}

// ---------------------------------------------------------------------------------------------
// The lights a bake takes out of the environment: disks of constant radiance, two float4 each,
// (direction towards the light, angular radius), (radiance, solid angle).

// Nineteen points of equal area on the unit disk: the centre, then rings of 6 and 12 at the
// middles (by area) of their annuli.
static const uint IBL_DISK_POINTS = 19;

float2 IblDiskPoint( uint i )
{
    if ( i == 0u )
        return ( float2 )0.f;
    bool inner = i <= 6u;
    float radius = inner ? 0.45883147f : 0.82717019f; // sqrt(4 / 19), sqrt(13 / 19)
    float angle = inner ? ( float( i - 1u ) / 6.f ) * 2.f * PI : ( ( float( i - 7u ) + 0.5f ) / 12.f ) * 2.f * PI;
    return radius * float2( cos( angle ), sin( angle ) );
}

// The split sum's BRDF (Smith-Schlick k = r² / 2, Schlick's F), specular part, times N·L.
float3 IblSpecularBrdfCosine( float3 normal, float3 viewDirection, float3 toLight, float roughness, float3 f0 )
{
    float ndotl = dot( normal, toLight );
    float ndotv = saturate( dot( normal, viewDirection ) );
    if ( ndotl <= 0.f || ndotv <= 0.f )
        return ( float3 )0.f;
    float3 halfway = normalize( toLight + viewDirection );
    float vdoth = saturate( dot( viewDirection, halfway ) );
    float3 fresnel = FresnelSchlick( vdoth, f0 );
    float g = GeometrySmithForIBL( ndotl, ndotv, roughness );
    return fresnel * ( g * DistributionGGX( saturate( dot( normal, halfway ) ), roughness ) / ( 4.f * ndotv ) );
}

// The specular of a disk narrow enough for small angles: the BRDF's directional albedo (the LUT's
// F0 scale and bias, `albedo`) times the share of GGX's half vectors whose reflection of V falls
// in the disk. A reflection doubles the half vector's angles, so in slope space the disk has
// radius a = θ / 2 at b = ∠(R, centre) / 2 from the lobe's peak; GGX's slopes have the density
// 1 / (π α² (1 + ρ² / α²)²) (Walter et al. 2007), whose mass over that disk is, with V = a² / α²
// and β = b / α (the angle integral ∫ dφ / (A + B cos φ)² = 2π A / (A² - B²)^1.5, then ρ²):
//   ½ + (V - 1 - β²) / (2 sqrt((V + 1 - β²)² + 4 β²)),
// V / (1 + V) about the peak, and about V / β⁴, the lobe's tail, far from it.
float IblGgxDiskShare( float radius, float offset, float alpha )
{
    float V = radius * radius / ( alpha * alpha );
    float beta2 = offset * offset / ( alpha * alpha );
    float w = V + 1.f - beta2;
    return saturate( 0.5f + ( V - 1.f - beta2 ) / ( 2.f * sqrt( w * w + 4.f * beta2 ) ) );
}

// The share of a prefiltered kernel of GGX's α about `direction` that falls in a light's disk
// (head: direction towards it, angular radius): IblGgxDiskShare in slope space, where the
// kernel's half angles x become slopes tan x and a small disk's area grows by sec³ x.
float IblKernelDiskShare( float3 direction, float alpha, float4 head )
{
    float away = 0.5f * acos( clamp( dot( direction, head.xyz ), -1.f, 1.f ) );
    float slope = tan( min( away, 1.5f ) );
    float stretch = pow( 1.f + slope * slope, 0.75f ); // sec^1.5: the disk of equal area
    return IblGgxDiskShare( 0.5f * head.w * stretch, slope, alpha );
}

float3 IblNarrowLobeDisk( float3 normal, float3 viewDirection, float roughness, float3 albedo, float4 head )
{
    float3 reflected = reflect( -viewDirection, normal );
    float away = acos( clamp( dot( reflected, head.xyz ), -1.f, 1.f ) );
    return albedo * IblGgxDiskShare( 0.5f * head.w, 0.5f * away, max( roughness * roughness, 1e-7f ) );
}

// ∫ max(0, N·L) dω over a uniform spherical cap of angular radius σ whose centre lies at cos θ
// from N, the horizon's clipping included (Snyder 1996; Lagarde and de Rousiers 2014, Frostbite's
// illuminanceSphereOrDisk): π sin²σ cos θ while the cap is above the horizon, 0 once below.
float IblCapCosine( float cosTheta, float sinSigma2 )
{
    if ( cosTheta * cosTheta > sinSigma2 || sinSigma2 <= 0.f )
        return PI * sinSigma2 * saturate( cosTheta );
    float sinTheta = sqrt( saturate( 1.f - cosTheta * cosTheta ) );
    float x = sqrt( 1.f / sinSigma2 - 1.f );
    float y = -x * ( cosTheta / sinTheta );
    float sinThetaSqrtY = sinTheta * sqrt( saturate( 1.f - y * y ) );
    return max( ( cosTheta * acos( clamp( y, -1.f, 1.f ) ) - x * sinThetaSqrtY ) * sinSigma2 + atan( sinThetaSqrtY / x ), 0.f );
}

// A light's specular (weighted by `specularWeight`) and diffuse radiance towards V. The diffuse
// by the cap's exact cosine integral; the specular of a lobe twice as wide as the disk,
// 2α >= 2 radius, by the disk's points; of a lobe no wider than it by IblNarrowLobeDisk; between,
// a blend.
// `diffuseColor` is albedo (1 - metalness), `albedo` the LUT's F0 scale and bias applied to f0.
float3 IblDiskLight( float3 normal, float3 viewDirection, float roughness, float3 f0, float3 albedo, float3 diffuseColor,
                     float specularWeight, float4 head, float4 body )
{
    float3 centre = head.xyz;
    float3 helper = abs( centre.z ) < 0.999f ? float3( 0.f, 0.f, 1.f ) : float3( 1.f, 0.f, 0.f );
    float3 tangent = normalize( cross( helper, centre ) );
    float3 bitangent = cross( centre, tangent );
    float spread = tan( head.w );
    float3 specular = ( float3 )0.f;
    for ( uint i = 0u; i < IBL_DISK_POINTS; ++i )
    {
        float2 p = IblDiskPoint( i ) * spread;
        float3 toLight = normalize( centre + p.x * tangent + p.y * bitangent );
        if ( dot( normal, toLight ) > 0.f )
            specular += IblSpecularBrdfCosine( normal, viewDirection, toLight, roughness, f0 );
    }
    float share = 1.f / float( IBL_DISK_POINTS );
    float wide = saturate( 2.f * roughness * roughness / max( head.w, 1e-6f ) - 1.f );
    float3 narrow = wide < 1.f ? IblNarrowLobeDisk( normal, viewDirection, roughness, albedo, head ) / body.w
                               : ( float3 )0.f;
    specular = lerp( narrow, specular * share, wide );
    float sinRadius = sin( head.w );
    float3 diffuse = diffuseColor * ( IblCapCosine( dot( normal, centre ), sinRadius * sinRadius ) / PI );
    return ( specularWeight * specular * body.w + diffuse ) * body.rgb;
}

// The kit's opaque shading from the maps: the recipe's specular lookups times the LUT's F0 scale
// and bias, and the irradiance cube's diffuse. The caller adds each light the bake took out of
// the environment, IblDiskLight with specularWeight = residualShare and albedo = IblDirectionalAlbedo.
float3 IblShadeOpaque( float3 normal, float3 viewDirection, float3 albedo, float roughness, float metalness,
                       IblRecipe recipe, TextureCube prefiltered, TextureCube irradianceMap, Texture2D<float2> brdfLut,
                       Texture2D<float4> lobeTable, SamplerState linearSampler, out float residualShare )
{
    float3 f0 = lerp( ( float3 )0.04f, albedo, metalness );
    float ndotv = saturate( dot( normal, viewDirection ) );
    float3 radiance = IblSpecularRadiance( normal, viewDirection, roughness, recipe, prefiltered, lobeTable, linearSampler,
                                           residualShare );
    float2 brdf = brdfLut.SampleLevel( linearSampler, float2( ndotv, roughness ), 0 ).rg;
    return radiance * ( f0 * brdf.x + brdf.y ) + irradianceMap.SampleLevel( linearSampler, normal, 0 ).rgb * albedo * ( 1.f - metalness );
}

// The LUT's F0 scale and bias at (N, V, roughness), applied to f0: the BRDF's directional albedo.
float3 IblDirectionalAlbedo( float3 normal, float3 viewDirection, float roughness, float3 f0, Texture2D<float2> brdfLut,
                             SamplerState linearSampler )
{
    float2 brdf = brdfLut.SampleLevel( linearSampler, float2( saturate( dot( normal, viewDirection ) ), roughness ), 0 ).rg;
    return f0 * brdf.x + brdf.y;
}

// The share of the light a dielectric's rough interface passes on along a view ray crossing it,
// (entering from outside, leaving from inside), from the transmission table
// (runtime/shading/transmission_table.hpp): one square layer per index of refraction, 1.1, 1.3,
// .. 2.5, stacked down one texture, N·V (on V's side) across and roughness down each. Indices
// between two layers blend them; reads stay a half texel inside their layer.
static const float IBL_TRANSMISSION_FIRST_ETA = 1.1f;
static const float IBL_TRANSMISSION_ETA_STEP = 0.2f;

// Where a layered table is read for (N·V, roughness, eta): the two layers' coordinates and the
// weight of the upper.
struct IblLayeredRead
{
    float2 Below, Above;
    float Blend;
};

IblLayeredRead IblLayeredReadOf( float ndotv, float roughness, float eta, uint width, uint height )
{
    float layers = float( height / width );
    float at = clamp( ( eta - IBL_TRANSMISSION_FIRST_ETA ) / IBL_TRANSMISSION_ETA_STEP, 0.f, layers - 1.f );
    float below = floor( at );
    float halfTexel = 0.5f / float( width );
    float v = clamp( roughness, halfTexel, 1.f - halfTexel );
    IblLayeredRead read;
    read.Below = float2( ndotv, ( below + v ) / layers );
    read.Above = float2( ndotv, ( min( below + 1.f, layers - 1.f ) + v ) / layers );
    read.Blend = at - below;
    return read;
}

float2 IblTransmittedShares( float ndotv, float roughness, float eta, Texture2D<float2> transmissionTable,
                             SamplerState linearSampler )
{
    uint width = 0u, height = 0u;
    transmissionTable.GetDimensions( width, height );
    IblLayeredRead read = IblLayeredReadOf( ndotv, roughness, eta, width, height );
    return lerp( transmissionTable.SampleLevel( linearSampler, read.Below, 0 ).rg,
                 transmissionTable.SampleLevel( linearSampler, read.Above, 0 ).rg, read.Blend );
}

// The sphere transmission table (runtime/shading/sphere_transmission.hpp), laid out as the
// transmission table: (energy, angle from -V towards N of the mean exiting direction, the
// kernel roughness of its spread) for a solid sphere of rough glass.
float3 IblSphereTransmission( float ndotv, float roughness, float eta, Texture2D<float4> table, SamplerState linearSampler )
{
    uint width = 0u, height = 0u;
    table.GetDimensions( width, height );
    IblLayeredRead read = IblLayeredReadOf( ndotv, roughness, eta, width, height );
    return lerp( table.SampleLevel( linearSampler, read.Below, 0 ).rgb, table.SampleLevel( linearSampler, read.Above, 0 ).rgb,
                 read.Blend );
}

// ---------------------------------------------------------------------------------------------
// Glass: a solid sphere of rough glass shaded as one prefiltered lookup times the share of the
// light that comes out, the lights the bake took out seen through the lookup's kernel. Three
// analogues, measured against the Monte Carlo reference in docs/shading.md:
static const uint IBL_GLASS_SCHLICK = 0;   // engines' solid-sphere refraction (Filament's) with the sphere's exact
                                           // chord, at the roughness's mip scaled by a factor, times Schlick's 1 - F
                                           // at the way in and out
static const uint IBL_GLASS_TABULATED = 1; // the same lookup, times the transmission table's shares of the rough
                                           // interface at each crossing
static const uint IBL_GLASS_SPHERE = 2;    // the sphere transmission table's fit of the rough sphere's exiting light:
                                           // its energy, mean direction and spread as a kernel roughness (the kit's)

// Where glass reads the prefiltered map, at which kernel roughness, and the share of light that
// comes out along V.
struct IblGlassRead
{
    float3 Direction;
    float Roughness;
    float Weight;
};

float IblSchlickTransmission( float cosine, float f0 )
{
    return 1.f - ( f0 + ( 1.f - f0 ) * pow( 1.f - saturate( cosine ), 5.f ) );
}

IblGlassRead IblSphereGlassRead( float3 normal, float3 viewDirection, float roughness, float eta,
                                 Texture2D<float4> sphereTable, SamplerState linearSampler )
{
    float ndotv = saturate( dot( normal, viewDirection ) );
    float3 fit = IblSphereTransmission( ndotv, roughness, eta, sphereTable, linearSampler );
    float3 towardsNormal = normal - ndotv * viewDirection;
    float length2 = dot( towardsNormal, towardsNormal );
    towardsNormal = length2 > 1e-12f ? towardsNormal * rsqrt( length2 ) : ( float3 )0.f;
    IblGlassRead read;
    read.Direction = normalize( -cos( fit.y ) * viewDirection + sin( fit.y ) * towardsNormal );
    read.Roughness = fit.z;
    read.Weight = fit.x;
    return read;
}

// The refracted read of IBL_GLASS_SCHLICK and IBL_GLASS_TABULATED: along the direction a smooth
// sphere sends the view ray out.
IblGlassRead IblRefractedGlassRead( uint mode, float3 normal, float3 viewDirection, float roughness, float eta,
                                    float roughnessScale, Texture2D<float2> transmissionTable, SamplerState linearSampler )
{
    float dielectric = ( 1.f - eta ) / ( 1.f + eta );
    float f0 = dielectric * dielectric;
    float3 inside = refract( -viewDirection, normal, 1.f / eta );
    float3 exitPoint = normalize( normal - 2.f * dot( normal, inside ) * inside );
    float3 outside = refract( inside, -exitPoint, eta );
    IblGlassRead read;
    read.Roughness = roughness * roughnessScale;
    read.Direction = -viewDirection;
    read.Weight = 0.f;
    if ( dot( outside, outside ) == 0.f )
        return read; // a smooth sphere refracts every ray out: only float rounding lands here
    read.Direction = outside;
    if ( mode == IBL_GLASS_TABULATED )
        read.Weight = IblTransmittedShares( saturate( dot( normal, viewDirection ) ), roughness, eta, transmissionTable,
                                            linearSampler ).x *
                      IblTransmittedShares( dot( exitPoint, inside ), roughness, eta, transmissionTable, linearSampler ).y;
    else
        read.Weight = IblSchlickTransmission( dot( normal, viewDirection ), f0 ) *
                      IblSchlickTransmission( dot( exitPoint, outside ), f0 );
    return read;
}

IblGlassRead IblGlassReadOf( uint mode, float3 normal, float3 viewDirection, float roughness, float eta,
                             float roughnessScale, Texture2D<float2> transmissionTable, Texture2D<float4> sphereTable,
                             SamplerState linearSampler )
{
    if ( mode == IBL_GLASS_SPHERE )
        return IblSphereGlassRead( normal, viewDirection, roughness, eta, sphereTable, linearSampler );
    return IblRefractedGlassRead( mode, normal, viewDirection, roughness, eta, roughnessScale, transmissionTable,
                                  linearSampler );
}

// The prefiltered radiance of a glass read, before its weight; residualShare as IblShadeOpaque's.
// The caller adds IblGlassLight for each light, then multiplies the sum by read.Weight.
float3 IblGlassRadiance( IblGlassRead read, IblRecipe recipe, TextureCube prefiltered, SamplerState linearSampler,
                         out float residualShare )
{
    float lod = IblLodOfRoughness( read.Roughness, recipe );
    residualShare = IblResidualShare( lod, recipe );
    return prefiltered.SampleLevel( linearSampler, read.Direction, lod ).rgb;
}

// A light the bake took out, seen through a glass read's kernel (head, body: as IblDiskLight's).
float3 IblGlassLight( IblGlassRead read, float residualShare, float4 head, float4 body )
{
    float alpha = max( read.Roughness * read.Roughness, 1e-7f );
    return residualShare * body.rgb * IblKernelDiskShare( read.Direction, alpha, head );
}

#endif // COMMON_IMAGE_BASED_LIGHTING_FXH
