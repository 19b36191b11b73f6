// The path tracer document's functions (document/Common/Bsdf.fxh, Sampling.fxh, Lights.fxh,
// Random.fxh) one by one, at arguments the host chooses, for the consistency suite to compare each
// path with the C++ reference (runtime/reference/path_tracer_*.hpp), and for iblkit stress to
// sweep them at their singular points. Argument i is (cos theta_L, cos theta_V, roughness, phi_V)
// about N = +Z, L at azimuth 0; its metalness (0, 0.5, 1) and its generator's stream come from i.
// Its seven results are, in order:
//   0: BRDF( X, L, V ), D( N, normalize( L + V ), roughness )
//   1: BTDF( X, L, V' ), G( N, V, L, roughness )            V' = V mirrored below the surface
//   2: BSDF( X, L, V' ), BSDF( X, L, V ).g
//   3: SampleCosineHemisphere( rng ), CosineHemispherePdf( cos theta_V )
//   4: SampleGGX( roughness, rng ), GgxHalfVectorPdf( cos theta_L, roughness )
// (the densities at the host's cosines: at a sampled half vector near the peak the GGX density is
// ill-conditioned in float, 1e-4 relative, whoever computes it)
//   5: PointLightTerm( X, V, ProbePoint ), Random( rng )
//   6: AreaLightTerm( X, V, ProbeArea, SampleAreaLight( ProbeArea, rng ) ), DirectionalLightTerm( X, V, ProbeSun ).g
#include "Common/Lights.fxh"
#include "Common/Sampling.fxh"

cbuffer ProbeParameter : register( b0 )
{
    uint ArgumentCount;
};

StructuredBuffer<float4> Arguments;
RWStructuredBuffer<float4> Results;

float3 ProbeDirection( float CosTheta, float Phi )
{
    float SinTheta = sqrt( 1.f - CosTheta * CosTheta );
    return float3( SinTheta * cos( Phi ), SinTheta * sin( Phi ), CosTheta );
}

// Metalness 0, 0.5 and 1 by i; half transmissive glass of eta 1.5.
SurfacePoint ProbeSurface( uint i, float Roughness )
{
    SurfacePoint X;
    X.Position = float3( 0.f, 0.f, 0.f );
    X.Normal = float3( 0.f, 0.f, 1.f );
    X.Albedo = float3( 0.9f, 0.6f, 0.3f );
    X.Roughness = Roughness;
    X.Metalness = 0.5f * float( i % 3u );
    X.Transmittance = 0.5f;
    X.Eta = 1.5f;
    return X;
}

[numthreads(64, 1, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint i = DTid.x;
    if ( i >= ArgumentCount )
        return;
    float4 argument = Arguments[i];
    float3 L = ProbeDirection( argument.x, 0.f );
    float3 V = ProbeDirection( argument.y, argument.w );
    float3 Below = float3( V.xy, -V.z );
    SurfacePoint X = ProbeSurface( i, argument.z );
    float3 N = X.Normal;
    RandomState rng = SeedRandom( 17u, i );

    PointLight ProbePoint;
    ProbePoint.Position = float3( 0.3f, -0.2f, 2.f );
    ProbePoint.Radiance = float3( 4.f, 3.f, 2.f );
    AreaLight ProbeArea;
    ProbeArea.Corner = float3( -0.5f, -0.5f, 1.5f );
    ProbeArea.EdgeU = float3( 0.f, 1.f, 0.f );
    ProbeArea.EdgeV = float3( 1.f, 0.f, 0.f );
    ProbeArea.Radiance = float3( 1.f, 2.f, 3.f );
    DirectionalLight ProbeSun;
    ProbeSun.Direction = normalize( float3( -0.3f, 0.2f, -1.f ) );
    ProbeSun.Radiance = float3( 5.f, 5.f, 5.f );

    Results[7 * i] = float4( BRDF( X, L, V ), D( N, normalize( L + V ), X.Roughness ) );
    Results[7 * i + 1] = float4( BTDF( X, L, Below ), G( N, V, L, X.Roughness ) );
    Results[7 * i + 2] = float4( BSDF( X, L, Below ), BSDF( X, L, V ).g );
    float3 Cosine = SampleCosineHemisphere( rng );
    Results[7 * i + 3] = float4( Cosine, CosineHemispherePdf( argument.y ) );
    float3 Half = SampleGGX( X.Roughness, rng );
    Results[7 * i + 4] = float4( Half, GgxHalfVectorPdf( argument.x, X.Roughness ) );
    Results[7 * i + 5] = float4( PointLightTerm( X, V, ProbePoint, 1.f ), Random( rng ) );
    float3 LightPoint = SampleAreaLight( ProbeArea, rng );
    Results[7 * i + 6] = float4( AreaLightTerm( X, V, ProbeArea, LightPoint, 1.f ),
                                 DirectionalLightTerm( X, V, ProbeSun, 1.f ).g );
}
