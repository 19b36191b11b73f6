// The kit's LUT function (Common/BrdfQuadrature.fxh) at arguments the host chooses, as
// PbrProbeCS does for PBR.fxh: argument i is (N.V, roughness, 1 - N.V, 0), the complement
// passed apart as the LUT kernels pass it; result i is (scale, bias, 0, 0).
#include "Common/BrdfQuadrature.fxh"

cbuffer ProbeParameter : register( b0 )
{
    uint ArgumentCount;
};

StructuredBuffer<float4> Arguments;
RWStructuredBuffer<float4> Results;

[numthreads(64, 1, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint i = DTid.x;
    if ( i >= ArgumentCount )
        return;
    BuildGaussLegendre();
    float4 argument = Arguments[i];
    Results[i] = float4( IntegrateBrdfQuadrature( argument.x, argument.z, argument.y ), 0.f, 0.f );
}
