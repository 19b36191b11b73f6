// [[vk::binding]] on an array of resources and on the next resource: in Vulkan an array is one
// binding (its descriptor count is the array's size), so binding 1 is free. Mip chains are
// written like this (one storage image per mip).
[[vk::binding(0)]] RWTexture2D<float4> Mips[13];
[[vk::binding(1)]] RWStructuredBuffer<uint> Written;

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    // Each texel of Mips[m] once, by the thread at its corner.
    if (all((id.xy & ((1u << id.z) - 1)) == 0)) Mips[id.z][id.xy >> id.z] = float4(id.xy, id.z, 1);
    if (all(id == 0)) Written[0] = 13;
}
