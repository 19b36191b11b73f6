// [[vk::binding(b, s)]] as written, beside a resource bound by the register rule.
[[vk::binding(3, 1)]] RWStructuredBuffer<uint> Doubled;
[[vk::binding(0, 1)]] StructuredBuffer<uint> Values;
RWStructuredBuffer<uint> Lanes : register(u0);

[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    Doubled[id.x] = Values[id.x] * 2;
    Lanes[id.x] = id.x;
}
