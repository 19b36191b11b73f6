// Quad operations in a compute shader (Shader Model 6.6): a quad is four consecutive lanes;
// 0 wherever each read gives the lane it names.
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint lane = WaveGetLaneIndex();
    Out[id.x] = (QuadReadAcrossX(lane) - (lane ^ 1)) + (QuadReadAcrossY(lane) - (lane ^ 2)) +
                (QuadReadAcrossDiagonal(lane) - (lane ^ 3)) + (QuadReadLaneAt(lane, 2) - ((lane & ~3u) + 2));
}
