// Double precision arithmetic: 1/3 * 3 is 1 in double, and 2^-30 survives 1 + 2^-30 - 1.
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    double third = 1.0 / 3.0;
    double tiny = 1.0 / 1073741824.0;
    Out[0] = (float)(third * 3.0);
    Out[1] = (float)(((1.0 + tiny) - 1.0) * 1073741824.0);
}
