// 64-bit integers (Shader Model 6.0) on values read at run time: a product past 2^32, split
// into its two halves, and compared with a smaller one.
StructuredBuffer<uint> In : register(t0);
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    uint64_t product = In[0];
    product *= In[1];
    uint64_t smaller = In[2];
    smaller <<= 34;
    Out[0] = (uint)(product >> 32);
    Out[1] = (uint)product; // odd and past 2^24: the run compares integers exactly
    Out[2] = smaller < product ? 1 : 0;
}
