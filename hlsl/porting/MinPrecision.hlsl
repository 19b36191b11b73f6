// Minimum-precision types: compiled at 32 bits (the kit's policy without -enable-16bit-types),
// with one warning.
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    min16float half = 0.5;
    min16int count = 3;
    Out[0] = half * count;
}
