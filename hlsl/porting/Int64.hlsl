// 64-bit integers (Shader Model 6.0): a product past 2^32, split into its two halves, and
// compared with a smaller one.
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    uint64_t product = 100000;
    product *= 300000; // 3e10
    uint64_t smaller = 1;
    smaller <<= 34;
    Out[0] = (uint)(product >> 32);
    Out[1] = (uint)product; // past 2^24: the run compares integers exactly
    Out[2] = smaller < product ? 1 : 0;
}
