// HLSL 2021 bitfields in a struct.
struct Packed { uint low : 16; uint high : 16; };
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Packed packed; packed.low = 1; packed.high = 2; Out[0] = packed.low + packed.high; }
