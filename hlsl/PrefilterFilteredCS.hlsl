// Filtered importance sampling (Křivánek & Colbert, "Real-time Shading with Filtered Importance
// Sampling", 2008): the document's estimator (PrefilterSpecular: GGX samples of H at N = V, N·L
// weights), but each sample reads the source mip whose texels cover the solid angle that sample
// stands for, 1 / (SAMPLE_COUNT pdf(L)), instead of mip 0. A sample then carries the mean light
// of its share of the lobe rather than one point of it, so a small bright source is spread over
// the samples near it instead of being hit or missed: no bright dots, at the price of a blur
// that shrinks as SAMPLE_COUNT grows and the mips read get finer.
#include "Common/PBR.fxh"
#include "Common/Cube.fxh"

cbuffer PrefilterSpecularParameter : register( b0 )
{
    float Roughness;
};

TextureCube EnvMap;
SamplerState EnvMapSampler;
RWTexture2DArray<float4> Prefiltered;

// The paper's one mip of bias: a sample's footprint is a box filter of its solid angle, the
// mip's trilinear filter a tent twice as wide.
static const float LodBias = 0.f;

// The mip whose texels' solid angle matches the sample's. At N = V, pdf(L) = D N·H / (4 V·H)
// = D / 4, and mip 0's texels cover 4 pi / (6 w²) on average; each mip up covers 4 times as much.
// A D that is 0 or not a number (a lobe too narrow for float: roughness near 0) is a mirror: mip 0.
float SourceLod( float ndoth, float sourceTexelSolidAngle )
{
    float d = DistributionGGX( ndoth, Roughness );
    float texelsPerSample = 4.f / ( SAMPLE_COUNT * d * sourceTexelSolidAngle );
    float lod = 0.5f * log2( texelsPerSample ) + LodBias;
    return ( d > 0.f && lod > 0.f ) ? lod : 0.f;
}

float3 PrefilterFiltered( float3 normal, float sourceTexelSolidAngle )
{
    float3 viewDirection = normal;
    float totalWeight = 0.f;
    float3 prefilteredColor = (float3)0.f;
    for ( uint i = 0; i < SAMPLE_COUNT; ++i )
    {
        float2 xi = Hammersley( i, SAMPLE_COUNT );
        float3 halfWay = ImportanceSampleGGX( xi, normal, Roughness );
        float3 toLight = normalize( 2.f * dot( viewDirection, halfWay ) * halfWay - viewDirection );
        float ndotl = saturate( dot( normal, toLight ) );
        if ( ndotl > 0.f )
        {
            float3 m = abs( toLight );
            float major = max( m.x, max( m.y, m.z ) );
            float lod = SourceLod( saturate( dot( normal, halfWay ) ), sourceTexelSolidAngle * major * major * major );
            prefilteredColor += EnvMap.SampleLevel( EnvMapSampler, toLight, lod ).rgb * ndotl;
            totalWeight += ndotl;
        }
    }
    return prefilteredColor / totalWeight;
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Prefiltered.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    uint sourceWidth, sourceHeight;
    EnvMap.GetDimensions( sourceWidth, sourceHeight );
    float sourceTexelSolidAngle = 4.f / ( float( sourceWidth ) * float( sourceWidth ) );
    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    Prefiltered[DTid] = float4( PrefilterFiltered( normal, sourceTexelSolidAngle ), 0.f );
}
