// [[vk::push_constant]] on a plain struct variable, and a [[vk::constant_id]] specialization
// constant.
struct Parameters { float scale; uint offset; };
[[vk::push_constant]] Parameters Push;
[[vk::constant_id(3)]] const uint Count = 2;
RWStructuredBuffer<float> Out : register(u0);

[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    if (id.x < Count) Out[id.x] = id.x * Push.scale + Push.offset;
}
