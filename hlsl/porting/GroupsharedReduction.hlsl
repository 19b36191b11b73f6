// A tree reduction in groupshared memory with group barriers: each group sums 1..64.
groupshared uint Partial[64];
RWStructuredBuffer<uint> Sums : register(u0);

[numthreads(64, 1, 1)]
void main(uint i : SV_GroupIndex, uint3 group : SV_GroupID)
{
    Partial[i] = i + 1 + group.x;
    GroupMemoryBarrierWithGroupSync();
    for (uint stride = 32; stride > 0; stride >>= 1) {
        if (i < stride) Partial[i] += Partial[i + stride];
        GroupMemoryBarrierWithGroupSync();
    }
    if (i == 0) Sums[group.x] = Partial[0];
}
