// The document's prefilter estimator (PrefilterSpecular in Common/PBR.fxh) over a range of its
// SAMPLE_COUNT samples, so that counts past a driver's loop limit (llvmpipe stops a loop after
// 65535 iterations) run as several dispatches. Each dispatch adds its samples' sums to
// Accumulated (rgb: radiance · N·L, a: N·L); the last one also writes their ratio. The per-sample
// math is the document's, from PBR.fxh's own functions, in the document's order.
#include "Common/Cube.fxh"
#include "Common/PBR.fxh"

cbuffer PrefilterChunkParameter : register( b0 )
{
    float Roughness;
    uint FirstSample;
    uint ChunkSamples;
    uint Resolve;
};

TextureCube EnvMap;
SamplerState EnvMapSampler;
RWTexture2DArray<float4> Accumulated;
RWTexture2DArray<float4> Prefiltered;

float4 PrefilterChunk( float3 normal )
{
    float3 viewDirection = normal;
    float4 sums = 0.f;
    for ( uint i = FirstSample; i < FirstSample + ChunkSamples; ++i )
    {
        float2 xi = Hammersley( i, SAMPLE_COUNT );
        float3 halfWay = ImportanceSampleGGX( xi, normal, Roughness );
        float3 toLight = normalize( 2.f * dot( viewDirection, halfWay ) * halfWay - viewDirection );
        float ndotl = saturate( dot( normal, toLight ) );
        if ( ndotl > 0.f )
            sums += float4( EnvMap.SampleLevel( EnvMapSampler, toLight, 0 ).rgb * ndotl, ndotl );
    }
    return sums;
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Prefiltered.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    float4 sums = PrefilterChunk( normal );
    if ( FirstSample > 0 )
        sums += Accumulated[DTid];
    Accumulated[DTid] = sums;
    if ( Resolve != 0 )
        Prefiltered[DTid] = float4( sums.rgb / sums.a, 0.f );
}
