// Interlocked operations on a structured buffer and on a typed UAV (r32ui).
RWStructuredBuffer<uint> Counters : register(u0);
RWTexture2D<uint> Histogram : register(u1);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint previous;
    InterlockedAdd(Counters[0], 1, previous);
    InterlockedMax(Counters[1], id.x * 8 + id.y);
    InterlockedOr(Counters[2], 1u << id.x);
    InterlockedAdd(Histogram[uint2(id.x % 2, 0)], 1);
}
