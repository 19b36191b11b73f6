// The cheapest prefilter: each texel reads the source's mip chain along its own normal
// READ_COUNT times, at lods and weights fitted on the host (reference::fitPyramidReads) so that
// the reads' filter kernels together match the GGX lobe at N = V in least squares. No samples,
// no frame: one log2 per texel and READ_COUNT filtered reads. The count is a compile-time
// constant: on llvmpipe a read inside a loop of varying length costs about twice a read
// unrolled, and a read under a branch not taken still costs about as much as one taken.
#include "Common/Cube.fxh"

#ifndef READ_COUNT
#define READ_COUNT 2
#endif

cbuffer PrefilterPyramidParameter : register( b0 )
{
    float4 ReadLods;    // each read's lod at a face centre
    float4 ReadWeights; // summing to 1 over the first READ_COUNT
};

TextureCube EnvMap;
SamplerState EnvMapSampler;
RWTexture2DArray<float4> Prefiltered;

float3 PrefilterFromPyramid( float3 normal )
{
    // A texel's solid angle shrinks as |N_major|³ away from a face centre.
    float3 m = abs( normal );
    float major = max( m.x, max( m.y, m.z ) );
    float lodShift = -0.5f * log2( major * major * major );
    float3 prefilteredColor = (float3)0.f;
    [unroll]
    for ( uint i = 0; i < READ_COUNT; ++i )
        prefilteredColor += EnvMap.SampleLevel( EnvMapSampler, normal, max( ReadLods[i] + lodShift, 0.f ) ).rgb * ReadWeights[i];
    return prefilteredColor;
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Prefiltered.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    Prefiltered[DTid] = float4( PrefilterFromPyramid( normal ), 0.f );
}
