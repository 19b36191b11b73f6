// GGX's D at its peak (N·H = 1) for roughness 0.25, 0.5, 0.75 and 1: 1 / (pi roughness^4).
#include "Common/PBR.fxh"

RWStructuredBuffer<float> Peak;

[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    Peak[id.x] = DistributionGGX(1.f, 0.25f * (id.x + 1));
}
