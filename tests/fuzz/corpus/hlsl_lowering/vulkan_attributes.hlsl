struct P { float scale; uint mode; };
[[vk::push_constant]] P pc;
[[vk::constant_id(3)]] const float Gain = 2.0;
[[vk::binding(5, 1)]] RWStructuredBuffer<float4> Out;
[[vk::binding(1), vk::image_format("rgba8")]] RWTexture2D<float4> Img : register(u1);
[[vk::binding(2)]] cbuffer Params { float4 k; };
[[vk::location(0)]] [[vk::unknown_thing(1, "x")]] Texture2D t;
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { Out[0] = k * pc.scale * Gain; Img[id.xy] = 1; }
