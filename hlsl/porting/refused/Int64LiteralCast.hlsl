// A literal cast to a 64-bit integer type, as (uint64_t)100000.
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    uint64_t product = (uint64_t)100000 * 300000;
    Out[0] = (uint)(product >> 32);
}
