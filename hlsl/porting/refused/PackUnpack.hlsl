// Shader Model 6.6 pack and unpack intrinsics.
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Out[0] = pack_u8(uint4(1, 2, 3, 4)); }
