// The prefilter of PrefilterFilteredCS with its per-sample work done once on the host (as
// Filament's cmgen does): every texel of a mip shares the same GGX samples about its normal, so
// their directions in the normal's frame, their N·L weights and their source lods are computed
// per mip in double (reference::prefilterSampleTable) and read from SampleTable. A texel only
// turns each sample into its own frame, corrects the lod for where it falls on the cube, and
// reads the source there: no Hammersley, no sin, cos or sqrt, no D per sample.
#include "Common/Cube.fxh"

cbuffer PrefilterTableParameter : register( b0 )
{
    uint SampleCount; // entries of SampleTable
};

TextureCube EnvMap;
SamplerState EnvMapSampler;
StructuredBuffer<float4> SampleTable; // (L in the normal's frame, lod at a face centre); L.z = N·L > 0
RWTexture2DArray<float4> Prefiltered;

float3 PrefilterFromTable( float3 normal )
{
    // ImportanceSampleGGX's frame (Common/PBR.fxh), so the samples fall where the document's do.
    float3 up = ( abs( normal.y ) < 0.999f ) ? float3( 0.f, 1.f, 0.f ) : float3( 0.f, 0.f, 1.f );
    float3 right = normalize( cross( up, normal ) );
    up = normalize( cross( normal, right ) );

    float totalWeight = 0.f;
    float3 prefilteredColor = (float3)0.f;
    for ( uint i = 0; i < SampleCount; ++i )
    {
        float4 entry = SampleTable[i];
        float3 toLight = entry.x * right + entry.y * up + entry.z * normal;
        // A texel's solid angle shrinks as |L_major|³ away from a face centre.
        float3 m = abs( toLight );
        float major = max( m.x, max( m.y, m.z ) );
        float lod = max( entry.w - 0.5f * log2( major * major * major ), 0.f );
        prefilteredColor += EnvMap.SampleLevel( EnvMapSampler, toLight, lod ).rgb * entry.z;
        totalWeight += entry.z;
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

    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    Prefiltered[DTid] = float4( PrefilterFromTable( normal ), 0.f );
}
