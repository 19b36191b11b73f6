// float16_t without -enable-16bit-types, which DXC refuses too.
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { float16_t half = 0.5; Out[0] = half; }
