// The pyramid method's reads for a lobe too wide for reads along the normal alone
// (reference::pyramidRing): one read along the normal for the half of the lobe's mass nearest
// it, and RING_COUNT reads evenly around a ring for the other half, at the angle from the normal
// that halves the outer half's mass. The lods, the ring's angle and the centre's weight are
// computed per mip on the host; the reads take no per-texel lod (llvmpipe reads a lod shared by
// the dispatch about 1.5 times as fast) and the ring's count is a compile-time constant, so that
// its sines and cosines are constants.
#include "Common/Cube.fxh"

#ifndef RING_COUNT
#define RING_COUNT 8
#endif

cbuffer PrefilterRingParameter : register( b0 )
{
    float4 Ring; // the centre read's lod, the ring reads' lod, cos of the ring's angle from N, the centre's weight
};

TextureCube EnvMap;
SamplerState EnvMapSampler;
RWTexture2DArray<float4> Prefiltered;

float3 PrefilterFromRing( float3 normal )
{
    // ImportanceSampleGGX's frame (Common/PBR.fxh).
    float3 up = ( abs( normal.y ) < 0.999f ) ? float3( 0.f, 1.f, 0.f ) : float3( 0.f, 0.f, 1.f );
    float3 right = normalize( cross( up, normal ) );
    up = normalize( cross( normal, right ) );

    float sinAngle = sqrt( saturate( 1.f - Ring.z * Ring.z ) );
    float3 ring = (float3)0.f;
    [unroll]
    for ( uint k = 0; k < RING_COUNT; ++k )
    {
        float phi = 6.28318530718f * (float)k / (float)RING_COUNT;
        float3 toLight = Ring.z * normal + sinAngle * ( cos( phi ) * right + sin( phi ) * up );
        ring += EnvMap.SampleLevel( EnvMapSampler, toLight, Ring.y ).rgb;
    }
    return EnvMap.SampleLevel( EnvMapSampler, normal, Ring.x ).rgb * Ring.w + ring * ( ( 1.f - Ring.w ) / RING_COUNT );
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Prefiltered.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    Prefiltered[DTid] = float4( PrefilterFromRing( normal ), 0.f );
}
