// Minimum-precision types on values read at run time: compiled at 32 bits (the kit's policy
// without -enable-16bit-types), with one warning; 2049 survives, as it would not in a half.
StructuredBuffer<float> In : register(t0);
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    min16float big = In[0];
    min16int count = (min16int)In[1];
    Out[0] = big + count;
}
