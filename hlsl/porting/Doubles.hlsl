// Double precision arithmetic on values read at run time (so that no compiler folds it away):
// 2^-30 survives 1 + 2^-30 - 1 in double, where float loses it, and x/3*3 is x again.
StructuredBuffer<float> In : register(t0);
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    double one = In[0], tiny = In[1], x = In[2];
    Out[0] = (float)(((one + tiny) - one) / tiny);
    Out[1] = (float)(x / 3.0 * 3.0);
}
