// HLSL 2021's select, and and or, component-wise on vectors.
RWStructuredBuffer<float4> Out : register(u0);

[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    float4 x = float4(id.x, 1, 2, 3);
    bool4 big = x >= 2;
    Out[id.x * 3 + 0] = select(big, x, -x);
    Out[id.x * 3 + 1] = float4(and(big, x < 3));
    Out[id.x * 3 + 2] = float4(or(x == 0, x == 3));
}
