// iblkit render's split-sum image: the spheres of Common/SphereGrid.fxh shaded with the baked maps,
// in linear radiance, for the host to hold against RenderReferenceCS's Monte Carlo reference.
// Opaque spheres take the recipe's shading (Common/ImageBasedLighting.fxh's IblShadeOpaque; the
// documents' combine is the recipe of linear lods, R and one lookup at the surface's roughness,
// no lights). Glass takes one of three analogues of the split sum for transmission through a
// solid sphere, each a prefiltered lookup times the share of light that comes out, with the lights
// the bake took out added through the lookup's kernel (IblKernelDiskShare):
//   - GLASS_SCHLICK, engines' solid-sphere refraction (Filament's), here with the sphere's exact
//     chord: the lookup along the direction a smooth sphere sends the view ray out, at the
//     roughness's mip scaled by GlassRoughnessScale, times Schlick's 1 - F at the way in and out;
//   - GLASS_TABULATED: the same lookup, times the transmission table's shares of the rough
//     interface at each crossing;
//   - GLASS_SPHERE: the sphere transmission table's fit of the rough sphere's exiting light (its
//     energy, mean direction and spread as a kernel roughness).
#include "Common/ImageBasedLighting.fxh"
#include "Common/SphereGrid.fxh"

cbuffer SplitSumParameter : register( b0 )
{
    uint Columns;
    uint CellSize;
    uint SpecularMips;
    uint SpecularSize;
    uint LodMapping;
    float LodParameter;
    uint Direction;
    uint Lookup;
    uint LightCount;
    uint LightLevel;
    uint GlassTransmission;
    float GlassRoughnessScale;
};

static const uint GLASS_SCHLICK = 0u;
static const uint GLASS_TABULATED = 1u;
static const uint GLASS_SPHERE = 2u;

TextureCube Specular;
TextureCube IrradianceMap;
Texture2D<float2> BrdfLut;
Texture2D<float4> LobeTable;
Texture2D<float2> TransmissionTable;
Texture2D<float4> SphereTransmissionTable;
// Two float4 per light: (direction towards it, angular radius), (radiance, solid angle).
StructuredBuffer<float4> Lights;
SamplerState LinearClamp;
RWTexture2D<float4> SplitSum;

IblRecipe Recipe()
{
    return IblRecipeOf( LodMapping, LodParameter, SpecularMips, SpecularSize, Direction, Lookup, LightCount, LightLevel );
}

float SchlickTransmission( float cosine, float f0 )
{
    return 1.f - ( f0 + ( 1.f - f0 ) * pow( 1.f - saturate( cosine ), 5.f ) );
}

// The prefiltered radiance about `direction` at a lookup roughness, with the lights the bake
// took out seen through the same kernel where the lookup's mips lack them.
float3 GlassLookup( float3 direction, float lookupRoughness )
{
    float lod = IblLodOfRoughness( lookupRoughness, Recipe() );
    float3 radiance = Specular.SampleLevel( LinearClamp, direction, lod ).rgb;
    float residualShare = IblResidualShare( lod, Recipe() );
    float alpha = max( lookupRoughness * lookupRoughness, 1e-7f );
    for ( uint i = 0u; i < LightCount; ++i )
        radiance += residualShare * Lights[2u * i + 1u].rgb * IblKernelDiskShare( direction, alpha, Lights[2u * i] );
    return radiance;
}

float3 GlassSplitSum( float3 normal, float3 viewDirection, float roughness, float eta )
{
    float ndotv = saturate( dot( normal, viewDirection ) );
    if ( GlassTransmission == GLASS_SPHERE )
    {
        float3 fit = IblSphereTransmission( ndotv, roughness, eta, SphereTransmissionTable, LinearClamp );
        float3 towardsNormal = normal - ndotv * viewDirection;
        float length2 = dot( towardsNormal, towardsNormal );
        towardsNormal = length2 > 1e-12f ? towardsNormal * rsqrt( length2 ) : ( float3 )0.f;
        float3 direction = normalize( -cos( fit.y ) * viewDirection + sin( fit.y ) * towardsNormal );
        return GlassLookup( direction, fit.z ) * fit.x;
    }
    float dielectric = ( 1.f - eta ) / ( 1.f + eta );
    float f0 = dielectric * dielectric;
    float3 inside = refract( -viewDirection, normal, 1.f / eta );
    float3 exitPoint = normalize( normal - 2.f * dot( normal, inside ) * inside );
    float3 outside = refract( inside, -exitPoint, eta );
    if ( dot( outside, outside ) == 0.f )
        return ( float3 )0.f; // a smooth sphere refracts every ray out: only float rounding lands here
    float transmission;
    if ( GlassTransmission == GLASS_TABULATED )
        transmission = IblTransmittedShares( ndotv, roughness, eta, TransmissionTable, LinearClamp ).x *
                       IblTransmittedShares( dot( exitPoint, inside ), roughness, eta, TransmissionTable, LinearClamp ).y;
    else
        transmission = SchlickTransmission( dot( normal, viewDirection ), f0 ) * SchlickTransmission( dot( exitPoint, outside ), f0 );
    return GlassLookup( outside, roughness * GlassRoughnessScale ) * transmission;
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint2 dims = ( uint2 )0;
    SplitSum.GetDimensions( dims.x, dims.y );
    if ( any( DTid.xy >= dims ) )
        return;
    SphereHit hit = SphereAt( DTid.xy, Columns, CellSize );
    float3 color = ( float3 )0.f;
    float3 viewDirection = float3( 0.f, 0.f, 1.f );
    SphereMaterial material = hit.Material;
    if ( hit.Covered && material.Transmittance > 0.f )
        color = GlassSplitSum( hit.Normal, viewDirection, material.Roughness, material.Eta );
    else if ( hit.Covered )
    {
        float residualShare;
        color = IblShadeOpaque( hit.Normal, viewDirection, material.Albedo, material.Roughness, material.Metalness, Recipe(),
                                Specular, IrradianceMap, BrdfLut, LobeTable, LinearClamp, residualShare );
        float3 f0 = lerp( ( float3 )0.04f, material.Albedo, material.Metalness );
        float3 albedo = IblDirectionalAlbedo( hit.Normal, viewDirection, material.Roughness, f0, BrdfLut, LinearClamp );
        for ( uint i = 0u; i < LightCount; ++i )
            color += IblDiskLight( hit.Normal, viewDirection, material.Roughness, f0, albedo,
                                   material.Albedo * ( 1.f - material.Metalness ), residualShare, Lights[2u * i], Lights[2u * i + 1u] );
    }
    SplitSum[DTid.xy] = float4( color, hit.Covered ? 1.f : 0.f );
}
