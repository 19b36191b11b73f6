// Wave lane operations: reads from another lane, the first lane, a ballot, all/any and a
// maximum; 0 wherever they agree with the lane's index and the wave's size, on any wave size.
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint lane = WaveGetLaneIndex();
    uint size = WaveGetLaneCount();
    uint4 even = WaveActiveBallot(lane % 2 == 0);
    uint evenCount = countbits(even.x) + countbits(even.y) + countbits(even.z) + countbits(even.w);
    Out[id.x] = (WaveReadLaneAt(lane * 10, (lane + 1) % size) - ((lane + 1) % size) * 10) +
                WaveReadLaneFirst(lane) + (evenCount - (size + 1) / 2) +
                (WaveActiveAllTrue(lane < size) ? 0 : 1) + (WaveActiveAnyTrue(lane == 0) ? 0 : 1) +
                (WaveActiveMax(lane) - (size - 1));
}
