// Wave operations: the exclusive prefix operations leave their own lane out, the reductions
// cover every lane; 0 wherever they agree with the lane's index and the wave's size.
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint lane = WaveGetLaneIndex();
    uint size = WaveGetLaneCount();
    Out[id.x] = (WavePrefixSum(1u) - lane) + (WavePrefixCountBits(true) - lane) +
                (uint(WavePrefixProduct(2.0)) - (1u << lane)) + (WaveActiveSum(1u) - size) +
                (WaveActiveCountBits(true) - size) + (WaveIsFirstLane() == (lane == 0) ? 0 : 1);
}
