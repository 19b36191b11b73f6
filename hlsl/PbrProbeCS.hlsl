// Common/PBR.fxh's functions one by one, at arguments the host chooses: the stress sweep
// (iblkit stress) and the consistency suite compare each path with the C++ reference at the
// documents' singular points and around them. Argument i is (c, roughness, c2, c3) of cosines
// in [0, 1]; its four results are, in order:
//   0: DistributionGGX( c, r ), GeometrySmithForIBL( c2, c, r ), GeometrySchlickGGXForIBL( c, r ), 0
//   1: FresnelSchlick( c3, float3( 0.04, 0.5, 1 ) ), 0
//   2: ImportanceSampleGGX( float2( c2, c3 ), ProbeNormals[i % 5], r ), 0
//   3: Hammersley( SampleIndices[i].x, SampleIndices[i].y ), IntegrateBRDF( c, r )
#include "Common/PBR.fxh"

cbuffer ProbeParameter : register( b0 )
{
    uint ArgumentCount;
};

StructuredBuffer<float4> Arguments;
StructuredBuffer<uint2> SampleIndices;
RWStructuredBuffer<float4> Results;

// The normals ImportanceSampleGGX meets: the axes, both sides of its 0.999 switch of the up
// vector, and a diagonal.
static const float3 ProbeNormals[5] = {
    float3( 0.f, 0.f, 1.f ),
    float3( 0.f, 1.f, 0.f ),
    float3( 0.f, 0.9989995f, 0.04472135f ),
    float3( 0.f, -0.99900013f, 0.04470727f ),
    float3( 0.57735026f, 0.57735026f, 0.57735026f ),
};

[numthreads(64, 1, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint i = DTid.x;
    if ( i >= ArgumentCount )
        return;
    float4 argument = Arguments[i];
    float c = argument.x, roughness = argument.y;
    Results[4 * i] = float4( DistributionGGX( c, roughness ), GeometrySmithForIBL( argument.z, c, roughness ),
                             GeometrySchlickGGXForIBL( c, roughness ), 0.f );
    Results[4 * i + 1] = float4( FresnelSchlick( argument.w, float3( 0.04f, 0.5f, 1.f ) ), 0.f );
    Results[4 * i + 2] = float4( ImportanceSampleGGX( argument.zw, ProbeNormals[i % 5], roughness ), 0.f );
    Results[4 * i + 3] = float4( Hammersley( SampleIndices[i].x, SampleIndices[i].y ), IntegrateBRDF( c, roughness ) );
}
