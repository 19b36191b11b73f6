// [[vk::image_format]] as DXC spells it: a float4 UAV stored as rgba16f instead of rgba32f.
[[vk::image_format("rgba16f")]] RWTexture2D<float4> Colour : register(u0);

[numthreads(2, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { Colour[id.xy] = float4(id.x, 0.5, 1.0 / 3.0, 1); }
