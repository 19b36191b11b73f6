// A signed 64-bit integer.
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    int64_t value = 0;
    value -= 5;
    Out[0] = value < 0 ? 1 : 0;
}
