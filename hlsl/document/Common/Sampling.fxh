// Common/Sampling.fxh — the path tracer document's indirect path sampling, transcribed from WGSL:
// cosine-weighted hemisphere sampling for diffuse bounces, GGX sampling of the half vector for the
// rest. Both return directions about +Z (tangent space). Every change from the printed WGSL is in
// docs/hlsl-transcription.md.
#ifndef COMMON_SAMPLING_FXH
#define COMMON_SAMPLING_FXH

#include "Common/PBR.fxh" // PI
#include "Common/Random.fxh"

float3 SampleCosineHemisphere( inout RandomState rng )
{
    float Random_1 = Random( rng );
    float Random_2 = Random( rng );

    float R   = sqrt( Random_1 );
    float Phi = 2.f * PI * Random_2;

    float X = R * cos( Phi );
    float Y = R * sin( Phi );
    float Z = sqrt( 1.f - Random_1 );

    return float3( X, Y, Z );
}

float3 SampleGGX( float Roughness, inout RandomState rng )
{
    float Random_1 = Random( rng );
    float Random_2 = Random( rng );

    float Alpha = Roughness * Roughness;
    float Phi   = 2.f * PI * Random_1;

    float CosTheta = sqrt( ( 1.f - Random_2 ) / ( 1.f + ( Alpha * Alpha - 1.f ) * Random_2 ) );
    float SinTheta = sqrt( 1.f - CosTheta * CosTheta );

    float H_X = SinTheta * cos( Phi );
    float H_Y = SinTheta * sin( Phi );
    float H_Z = CosTheta;

    return normalize( float3( H_X, H_Y, H_Z ) );
}

// The densities the estimators divide by, which the document leaves to the reader: per solid
// angle about +Z, of a direction with cosine CosTheta to the axis.
float CosineHemispherePdf( float CosTheta )
{
    return CosTheta / PI;
}

float GgxHalfVectorPdf( float CosTheta, float Roughness )
{
    float Alpha2 = Roughness * Roughness * Roughness * Roughness;
    float Denominator = CosTheta * CosTheta * ( Alpha2 - 1.f ) + 1.f;
    return Alpha2 / ( PI * Denominator * Denominator ) * CosTheta;
}

#endif // COMMON_SAMPLING_FXH
