// Shader Model 6.5 WaveMatch: the lanes that hold the same value.
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(8, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { Out[id.x] = WaveMatch(id.x % 2).x; }
