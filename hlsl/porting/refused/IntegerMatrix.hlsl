// An integer matrix, as asfloat(uint4x4(...)) makes one: SPIR-V has no integer matrix type.
RWStructuredBuffer<float4x4> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    Out[0] = asfloat(uint4x4(0x3F800000u, 0, 0, 0, 0, 0x3F800000u, 0, 0, 0, 0, 0x3F800000u, 0, 0, 0, 0, 0x3F800000u));
}
