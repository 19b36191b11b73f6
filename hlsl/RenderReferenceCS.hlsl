// iblkit render's Monte Carlo reference: every sphere of Common/SphereGrid.fxh shaded with the
// path tracer document's BSDF and lights (document/Common/), lit by the environment cube and the
// host's lights. Each dispatch adds SampleCount paths to each pixel of ActivePixels (those the host
// has not yet found converged) in the running sums of radiance and of its square, from which the
// host reads the mean and its standard error.
//
// A path starts where the pixel's ray meets the sphere and ends when it leaves: an opaque sphere
// is convex, so every direction above a point escapes to the environment; in glass a refracted
// path crosses the chord to the far side. At each vertex the environment is sampled by its
// texels' luminance (next-event estimation) and so is the BSDF, the two combined by the power
// heuristic; every light is added by the document's own terms, the sphere its only occluder. An
// area light is also found by the BSDF's draws that meet it, the two weighted by the power
// heuristic too, and it hides the environment behind it from both (lights do not hide each other).
//
// With SPLIT_SUM_MATERIAL defined, the material is Common/SplitSumMaterial.fxh's instead: the
// document's BSDF with the split sum's k and diffuse weight, the lights' terms included.
#include "Common/Cube.fxh"
#include "Common/Bsdf.fxh"
#ifdef SPLIT_SUM_MATERIAL
#include "Common/SplitSumMaterial.fxh"
#define BSDF BsdfAsSplitSum
#endif
#include "Common/Lights.fxh"
#include "Common/Sampling.fxh"
#include "Common/SphereGrid.fxh"

cbuffer RenderParameter : register( b0 )
{
    uint Columns;
    uint CellSize;
    uint FirstSample;
    uint SampleCount;
    uint Seed;
    uint LightCount;
    uint DistributionSize; // the face size of EnvironmentCdf's texels
    uint EnvironmentMip;   // the mip of Environment of that size
    uint ActiveCount;      // how many of ActivePixels to render
};

// The cube's faces at the distribution's mip, read as a sampler reads them: bilinearly between
// texel centres, clamped to the edge of each face. The distribution draws a texel, then a point
// about its centre from a tent one texel wide each way, folded back into the face at its edges:
// its density is then the same bilinear blend of the texels' probabilities as the radiance is of
// their values, so a bright texel's radiance and density fall off together and their ratio stays
// flat. (Read texel by texel, the reference saw the environment as blocks where the split sum,
// reading through a sampler, sees it smooth: near-mirror spheres differed texel edge by texel
// edge. Read through a sampler with the density of whole texels, a sun bled half a texel past
// the texels that sample it, a rare and bright ring only the BSDF's draws found: standard errors
// of 10 % at 1024 samples.)
Texture2DArray<float4> Environment;
// Cumulative probabilities of the distribution's texels, face +X..-Z, row, column, each a multiple
// of 2^-24 (so a draw of Random() falls in a texel exactly as often as its difference says); the
// last is 1.
StructuredBuffer<float> EnvironmentCdf;
// Four float4 per light: (type, radiance of an area light), then its vectors (Common/Lights.fxh):
// type 0, directional: direction, radiance; 1, point: position, intensity; 2, area: corner, edges.
StructuredBuffer<float4> Lights;
// Pixels as y * width + x.
StructuredBuffer<uint> ActivePixels;
// Per pixel: the sum of the paths' radiance, and in alpha how many paths ran.
RWTexture2D<float4> RadianceSum;
RWTexture2D<float4> SquareSum;

static const uint MAX_VERTICES = 4;

float PowerHeuristic( float chosen, float other )
{
    return chosen * chosen / ( chosen * chosen + other * other );
}

// The cube face of a direction and where on it, uv in [0, 1]² (Vulkan's face selection, the
// inverse of CubeFaceDirection).
uint CubeFaceOf( float3 d, out float2 uv )
{
    float3 a = abs( d );
    uint face;
    float major;
    float2 st;
    if ( a.x >= a.y && a.x >= a.z ) { major = a.x; face = d.x >= 0.f ? 0u : 1u; st = float2( d.x >= 0.f ? -d.z : d.z, -d.y ); }
    else if ( a.y >= a.z )          { major = a.y; face = d.y >= 0.f ? 2u : 3u; st = float2( d.x, d.y >= 0.f ? d.z : -d.z ); }
    else                            { major = a.z; face = d.z >= 0.f ? 4u : 5u; st = float2( d.z >= 0.f ? d.x : -d.x, -d.y ); }
    uv = saturate( ( st / major + 1.f ) * 0.5f );
    return face;
}

float TexelProbability( uint index )
{
    return EnvironmentCdf[index] - ( index > 0u ? EnvironmentCdf[index - 1u] : 0.f );
}

// The four texels a direction's bilinear reading blends (clamped to its face's edge), their
// weights, and the stretch 1 + x² + y² of the face there.
struct TexelBlend
{
    uint Face;
    uint2 Low, High; // the texels' columns and rows
    float2 Fraction; // the weight of High along each axis
    float Stretch;
};

TexelBlend BlendAt( float3 direction )
{
    TexelBlend blend;
    float2 uv;
    blend.Face = CubeFaceOf( direction, uv );
    float2 at = uv * DistributionSize - 0.5f;
    float2 low = floor( at );
    blend.Fraction = at - low;
    int last = int( DistributionSize ) - 1;
    blend.Low = uint2( clamp( int2( low ), 0, last ) );
    blend.High = uint2( clamp( int2( low ) + 1, 0, last ) );
    float2 xy = uv * 2.f - 1.f;
    blend.Stretch = 1.f + dot( xy, xy );
    return blend;
}

uint TexelIndex( uint face, uint2 texel )
{
    return ( face * DistributionSize + texel.y ) * DistributionSize + texel.x;
}

float4 BlendWeights( TexelBlend blend )
{
    float2 f = blend.Fraction;
    return float4( ( 1.f - f.x ) * ( 1.f - f.y ), f.x * ( 1.f - f.y ), ( 1.f - f.x ) * f.y, f.x * f.y );
}

// The density per solid angle: the texels' probabilities blended per unit of face area, where
// dA = (1 + x² + y²)^1.5 dω.
float EnvironmentPdf( float3 direction )
{
    TexelBlend blend = BlendAt( direction );
    float4 w = BlendWeights( blend );
    float probability = w.x * TexelProbability( TexelIndex( blend.Face, blend.Low ) )
                      + w.y * TexelProbability( TexelIndex( blend.Face, uint2( blend.High.x, blend.Low.y ) ) )
                      + w.z * TexelProbability( TexelIndex( blend.Face, uint2( blend.Low.x, blend.High.y ) ) )
                      + w.w * TexelProbability( TexelIndex( blend.Face, blend.High ) );
    float halfSize = 0.5f * DistributionSize;
    return probability * halfSize * halfSize * blend.Stretch * sqrt( blend.Stretch );
}

float3 TexelRadiance( uint face, uint2 texel )
{
    return Environment.Load( int4( texel, face, EnvironmentMip ) ).rgb;
}

float3 EnvironmentRadiance( float3 direction )
{
    TexelBlend blend = BlendAt( direction );
    float4 w = BlendWeights( blend );
    return w.x * TexelRadiance( blend.Face, blend.Low ) + w.y * TexelRadiance( blend.Face, uint2( blend.High.x, blend.Low.y ) )
         + w.z * TexelRadiance( blend.Face, uint2( blend.Low.x, blend.High.y ) ) + w.w * TexelRadiance( blend.Face, blend.High );
}

// A draw from the tent 1 - |t| on [-1, 1].
float TentDraw( float u )
{
    return u < 0.5f ? sqrt( 2.f * u ) - 1.f : 1.f - sqrt( 2.f - 2.f * u );
}

float3 SampleEnvironment( inout RandomState rng, out float pdf )
{
    float u = Random( rng );
    uint last = 6u * DistributionSize * DistributionSize - 1u;
    uint low = 0u, high = last;
    while ( low < high )
    {
        uint middle = ( low + high ) / 2u;
        if ( EnvironmentCdf[middle] > u ) high = middle;
        else low = middle + 1u;
    }
    uint face = low / ( DistributionSize * DistributionSize );
    uint texel = low % ( DistributionSize * DistributionSize );
    float2 offset = float2( TentDraw( Random( rng ) ), TentDraw( Random( rng ) ) );
    float2 at = float2( texel % DistributionSize, texel / DistributionSize ) + 0.5f + offset;
    float size = float( DistributionSize );
    at = min( abs( at ), 2.f * size - abs( at ) ); // folded back into the face at its edges
    float3 direction = CubeFaceDirection( face, at / size );
    pdf = EnvironmentPdf( direction );
    return direction;
}

// An orthonormal frame about n, for directions the samplers draw about +Z.
struct Frame
{
    float3 T, B, N;
};

Frame FrameAbout( float3 n )
{
    Frame frame;
    float3 helper = abs( n.z ) < 0.999f ? float3( 0.f, 0.f, 1.f ) : float3( 1.f, 0.f, 0.f );
    frame.T = normalize( cross( helper, n ) );
    frame.B = cross( n, frame.T );
    frame.N = n;
    return frame;
}

float3 FromFrame( Frame frame, float3 local ) { return local.x * frame.T + local.y * frame.B + local.z * frame.N; }
float3 ToFrame( Frame frame, float3 world ) { return float3( dot( world, frame.T ), dot( world, frame.B ), dot( world, frame.N ) ); }

// The GGX half vectors the path's direction sees (Heitz 2018, Sampling the GGX Distribution of
// Visible Normals), rather than the document's SampleGGX: drawn in proportion to D (N.H), a rough
// BTDF's weight grows as 1 / (N.H), and rough glass at grazing views kept standard errors of tens
// of percent; drawn by visibility, the weight is about G / G1(V), below 1.
float3 SampleGgxVisible( float3 localV, float roughness, inout RandomState rng )
{
    float alpha = roughness * roughness;
    float3 stretched = normalize( float3( alpha * localV.xy, localV.z ) );
    float lengthSquared = dot( stretched.xy, stretched.xy );
    float3 t1 = lengthSquared > 0.f ? float3( -stretched.y, stretched.x, 0.f ) * rsqrt( lengthSquared ) : float3( 1.f, 0.f, 0.f );
    float3 t2 = cross( stretched, t1 );
    float radius = sqrt( Random( rng ) );
    float phi = 2.f * PI * Random( rng );
    float p1 = radius * cos( phi );
    float p2 = radius * sin( phi );
    float blend = 0.5f * ( 1.f + stretched.z );
    p2 = ( 1.f - blend ) * sqrt( max( 1.f - p1 * p1, 0.f ) ) + blend * p2;
    float3 h = p1 * t1 + p2 * t2 + sqrt( max( 1.f - p1 * p1 - p2 * p2, 0.f ) ) * stretched;
    return normalize( float3( alpha * h.xy, max( h.z, 0.f ) ) );
}

// Smith's masking of GGX, the exact G1 the visible normals are distributed by.
float SmithG1( float NdotV, float roughness )
{
    float alpha2 = roughness * roughness * roughness * roughness;
    return 2.f * NdotV / ( NdotV + sqrt( alpha2 + ( 1.f - alpha2 ) * NdotV * NdotV ) );
}

// The density of a visible half vector H about nV, seen from V: G1(V) max(V.H, 0) D(H) / (N.V).
float VisibleHalfVectorPdf( float3 nV, float3 H, float3 V, float roughness )
{
    float NdotV = dot( nV, V );
    float VdotH = dot( V, H );
    if ( NdotV <= 0.f || VdotH <= 0.f || dot( nV, H ) <= 0.f )
        return 0.f;
    return SmithG1( NdotV, roughness ) * VdotH * D( nV, H, roughness ) / NdotV;
}

// The reflection lobe's density: visible GGX half vectors with probability specularShare, the
// document's cosine hemisphere otherwise; nV is the normal on V's side.
float ReflectionPdf( float3 nV, float3 L, float3 V, float roughness, float specularShare )
{
    float NdotL = dot( nV, L );
    if ( NdotL <= 0.f )
        return 0.f;
    float3 H = normalize( L + V );
    float ggx = VisibleHalfVectorPdf( nV, H, V, roughness ) / ( 4.f * abs( dot( V, H ) ) );
    return specularShare * ggx + ( 1.f - specularShare ) * CosineHemispherePdf( NdotL );
}

// The transmission lobe's density: visible GGX half vectors refracted, with Walter's Jacobian
// eta_L² |L.H| / (eta_V V.H + eta_L L.H)².
float TransmissionPdf( float3 nV, float3 L, float3 V, float roughness, float etaV, float etaL )
{
    if ( dot( nV, L ) >= 0.f )
        return 0.f;
    float3 H = normalize( etaV * V + etaL * L );
    H = dot( H, nV ) < 0.f ? -H : H;
    float VdotH = dot( V, H ), LdotH = dot( L, H );
    if ( VdotH * LdotH >= 0.f )
        return 0.f;
    float sum = etaV * VdotH + etaL * LdotH;
    return VisibleHalfVectorPdf( nV, H, V, roughness ) * etaL * etaL * abs( LdotH ) / ( sum * sum );
}

struct Vertex
{
    SurfacePoint X;
    float3 V;
    float3 NormalOnV; // the normal on V's side
    float EtaV, EtaL;
    float SpecularShare;
};

Vertex MakeVertex( float3 position, float3 V, SphereMaterial material )
{
    Vertex vertex;
    vertex.X.Position = position;
    vertex.X.Normal = position;
    vertex.X.Albedo = material.Albedo;
    vertex.X.Roughness = material.Roughness;
    vertex.X.Metalness = material.Metalness;
    vertex.X.Transmittance = material.Transmittance;
    vertex.X.Eta = material.Eta;
    vertex.V = V;
    bool outside = dot( position, V ) >= 0.f;
    vertex.NormalOnV = outside ? position : -position;
    vertex.EtaV = outside ? 1.f : material.Eta;
    vertex.EtaL = outside ? material.Eta : 1.f;
    vertex.SpecularShare = lerp( 0.5f, 1.f, material.Metalness );
    return vertex;
}

float BsdfPdf( Vertex vertex, float3 L )
{
    float T = vertex.X.Transmittance;
    float r = vertex.X.Roughness;
    return ( 1.f - T ) * ReflectionPdf( vertex.NormalOnV, L, vertex.V, r, vertex.SpecularShare ) +
           T * TransmissionPdf( vertex.NormalOnV, L, vertex.V, r, vertex.EtaV, vertex.EtaL );
}

// A direction from the BSDF's lobes, or false where the draw has none (below the surface, or
// past the critical angle).
bool SampleBsdf( Vertex vertex, inout RandomState rng, out float3 L )
{
    Frame frame = FrameAbout( vertex.NormalOnV );
    float3 nV = vertex.NormalOnV;
    bool transmit = Random( rng ) < vertex.X.Transmittance;
    bool specular = Random( rng ) < vertex.SpecularShare;
    float3 H = FromFrame( frame, SampleGgxVisible( ToFrame( frame, vertex.V ), vertex.X.Roughness, rng ) );
    float3 diffuse = FromFrame( frame, SampleCosineHemisphere( rng ) );
    if ( transmit )
    {
        L = refract( -vertex.V, H, vertex.EtaV / vertex.EtaL );
        return dot( L, L ) > 0.f && dot( L, nV ) < 0.f;
    }
    L = specular ? reflect( -vertex.V, H ) : diffuse;
    return dot( L, nV ) > 0.f;
}

// The sphere is the lights' only occluder: a direction leaves it where it points outwards.
float Visibility( SurfacePoint X, float3 L )
{
    return dot( X.Normal, L ) > 0.f ? 1.f : 0.f;
}

AreaLight AreaLightAt( uint i )
{
    AreaLight light = { Lights[4u * i + 1u].xyz, Lights[4u * i + 2u].xyz, Lights[4u * i + 3u].xyz, Lights[4u * i].yzw };
    return light;
}

// How far along L (unit) a ray from origin meets the area light's parallelogram, or 0 where it
// misses it.
float AreaLightDistance( AreaLight light, float3 origin, float3 L )
{
    float3 across = cross( light.EdgeU, light.EdgeV );
    float facing = dot( across, L );
    if ( facing == 0.f )
        return 0.f;
    float t = dot( across, light.Corner - origin ) / facing;
    float3 p = origin + t * L - light.Corner;
    float uu = dot( light.EdgeU, light.EdgeU ), uv = dot( light.EdgeU, light.EdgeV ), vv = dot( light.EdgeV, light.EdgeV );
    float pu = dot( p, light.EdgeU ), pv = dot( p, light.EdgeV ), determinant = uu * vv - uv * uv;
    float u = ( pu * vv - pv * uv ) / determinant, v = ( pv * uu - pu * uv ) / determinant;
    return t > 0.f && u >= 0.f && u <= 1.f && v >= 0.f && v <= 1.f ? t : 0.f;
}

// The density, per solid angle, of SampleAreaLight's point seen along L from distance t:
// t² / (|n' . L| Area).
float AreaLightPdf( AreaLight light, float3 L, float t )
{
    float3 across = cross( light.EdgeU, light.EdgeV );
    return t * t / abs( dot( across, L ) );
}

// The radiance an area light sends back along L, or 0 from its back.
float3 AreaLightRadiance( AreaLight light, float3 L )
{
    return dot( cross( light.EdgeU, light.EdgeV ), L ) < 0.f ? light.Radiance : ( float3 )0.f;
}

// No return from inside the loop: legalization's merge-return turns one into a flag that
// SPIRV-Cross declares without its initial false (GLSL, HLSL and MSL then read it uninitialized,
// and the round-tripped forms differed from the SPIR-V by 2.8e2 in the consistency suite).
bool HiddenByAreaLight( float3 origin, float3 L )
{
    bool hidden = false;
    for ( uint i = 0u; i < LightCount; ++i )
    {
        if ( Lights[4u * i].x == 2.f && AreaLightDistance( AreaLightAt( i ), origin, L ) > 0.f )
            hidden = true;
    }
    return hidden;
}

float3 LightsTerm( Vertex vertex, inout RandomState rng )
{
    SurfacePoint X = vertex.X;
    float3 V = vertex.V;
    float3 sum = ( float3 )0.f;
    for ( uint i = 0u; i < LightCount; ++i )
    {
        float4 head = Lights[4u * i];
        float3 a = Lights[4u * i + 1u].xyz, b = Lights[4u * i + 2u].xyz;
        if ( head.x == 0.f )
        {
            DirectionalLight light = { a, b };
            sum += DirectionalLightTerm( X, V, light, Visibility( X, -a ) );
        }
        else if ( head.x == 1.f )
        {
            PointLight light = { a, b };
            sum += PointLightTerm( X, V, light, Visibility( X, a - X.Position ) );
        }
        else
        {
            AreaLight light = AreaLightAt( i );
            float3 onLight = SampleAreaLight( light, rng );
            float3 toLight = onLight - X.Position;
            float t = length( toLight );
            float3 L = toLight / t;
            float weight = PowerHeuristic( AreaLightPdf( light, L, t ), BsdfPdf( vertex, L ) );
            sum += AreaLightTerm( X, V, light, onLight, Visibility( X, toLight ) ) * weight;
        }
    }
    return sum;
}

// What a BSDF draw leaving the sphere along L meets: every area light on its way, each weighted
// against its own draws (lights do not hide each other, as next-event estimation has it), or
// where there is none the environment, weighted against the environment's.
float3 EscapingRadiance( float3 origin, float3 L, float bsdfPdf )
{
    float3 sum = ( float3 )0.f;
    bool hidden = false;
    for ( uint i = 0u; i < LightCount; ++i )
    {
        if ( Lights[4u * i].x != 2.f )
            continue;
        AreaLight light = AreaLightAt( i );
        float t = AreaLightDistance( light, origin, L );
        if ( t > 0.f )
        {
            sum += AreaLightRadiance( light, L ) * PowerHeuristic( bsdfPdf, AreaLightPdf( light, L, t ) );
            hidden = true;
        }
    }
    if ( hidden )
        return sum;
    return EnvironmentRadiance( L ) * PowerHeuristic( bsdfPdf, EnvironmentPdf( L ) );
}

// Next-event estimation of the environment, weighted against the BSDF's own draws.
float3 EnvironmentTerm( Vertex vertex, inout RandomState rng )
{
    float pdf;
    float3 L = SampleEnvironment( rng, pdf );
    if ( Visibility( vertex.X, L ) == 0.f || !( pdf > 0.f ) || HiddenByAreaLight( vertex.X.Position, L ) )
        return ( float3 )0.f;
    float3 f = BSDF( vertex.X, L, vertex.V );
    if ( all( f == 0.f ) )
        return ( float3 )0.f;
    float weight = PowerHeuristic( pdf, BsdfPdf( vertex, L ) );
    return f * abs( dot( vertex.X.Normal, L ) ) * EnvironmentRadiance( L ) * weight / pdf;
}

float3 TracePath( SphereHit hit, inout RandomState rng )
{
    float3 radiance = ( float3 )0.f;
    float3 throughput = ( float3 )1.f;
    float3 position = hit.Normal;
    float3 V = float3( 0.f, 0.f, 1.f );
    for ( uint depth = 0u; depth < MAX_VERTICES; ++depth )
    {
        Vertex vertex = MakeVertex( position, V, hit.Material );
        radiance += throughput * ( LightsTerm( vertex, rng ) + EnvironmentTerm( vertex, rng ) );
        float3 L;
        if ( !SampleBsdf( vertex, rng, L ) )
            break;
        float pdf = BsdfPdf( vertex, L );
        if ( !( pdf > 0.f ) )
            break;
        throughput *= BSDF( vertex.X, L, V ) * abs( dot( vertex.X.Normal, L ) ) / pdf;
        if ( Visibility( vertex.X, L ) > 0.f )
        {
            radiance += throughput * EscapingRadiance( vertex.X.Position, L, pdf );
            break;
        }
        // Into the sphere: on to the far end of the chord.
        position = normalize( position - 2.f * dot( position, L ) * L );
        V = -L;
    }
    return radiance;
}

[numthreads(64, 1, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    if ( DTid.x >= ActiveCount )
        return;
    uint2 dims = ( uint2 )0;
    RadianceSum.GetDimensions( dims.x, dims.y );
    uint index = ActivePixels[DTid.x];
    uint2 pixel = uint2( index % dims.x, index / dims.x );
    SphereHit hit = SphereAt( pixel, Columns, CellSize );
    if ( !hit.Covered || pixel.y >= dims.y )
        return;
    float3 sum = ( float3 )0.f, squares = ( float3 )0.f;
    RandomState rng = SeedRandom( Seed + FirstSample, index );
    // The paths that ran, which the host checks: a driver may end loops early (llvmpipe, past
    // 65535 iterations of all of an invocation's loops together).
    float traced = 0.f;
    for ( uint i = 0u; i < SampleCount; ++i )
    {
        float3 radiance = TracePath( hit, rng );
        sum += radiance;
        squares += radiance * radiance;
        traced += 1.f;
    }
    RadianceSum[pixel] = RadianceSum[pixel] + float4( sum, traced );
    SquareSum[pixel] = SquareSum[pixel] + float4( squares, 0.f );
}
