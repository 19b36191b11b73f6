// A [[vk::...]] attribute the kit does not honour: compiled without it, with a warning.
[[vk::combinedImageSampler]] Texture2D<float4> Colour : register(t0);
RWStructuredBuffer<float4> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Out[0] = Colour.Load(int3(0, 0, 0)); }
