// Explicit 16-bit types (Shader Model 6.2, DXC's -enable-16bit-types) on values read at run
// time: half-precision arithmetic rounds to 11 significant bits, 16-bit integers wrap at 2^16.
// glslang converts a 32-bit value to a 16-bit type only when asked (a cast), where DXC converts
// it implicitly, and a 16-bit integer to a float only through a 32-bit one.
StructuredBuffer<float> Floats : register(t0);
StructuredBuffer<uint> Integers : register(t1);
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    float16_t big = (float16_t)Floats[0];
    float16_t one = (float16_t)Floats[1];
    float16_t2 pair = float16_t2((float16_t)Floats[2], (float16_t)Floats[3]);
    uint16_t top = (uint16_t)Integers[0];
    int16_t negative = (int16_t)(int)Integers[1];
    Out[0] = (float)(big + one); // 2049 is not a half: rounds to 2048
    Out[1] = (float)(uint)(uint16_t)(top + (uint16_t)2); // wraps to 1
    Out[2] = (float)(int)(int16_t)(negative * (int16_t)3);
    Out[3] = (float)dot(pair, pair);
}
