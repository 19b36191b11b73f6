// A texture offset passed through a function parameter, as shared sampling helpers take it:
// glslang writes it as a run-time Offset, which Vulkan allows only on gathers; once the helper is
// inlined the offset is a constant, and the kit makes it one (ConstOffset).
Texture2D<float> Heights : register(t0);
SamplerState Nearest : register(s0);
RWStructuredBuffer<float> Out : register(u0);

float SampleBeside(float2 uv, int2 offset)
{
    return Heights.SampleLevel(Nearest, uv, 0, offset);
}

[numthreads(2, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    const float2 uv = (float2(id.x, 0) + 0.5) / float2(4, 1);
    Out[id.x] = SampleBeside(uv, int2(1, 0)) + 10 * SampleBeside(uv, int2(2, 0));
}
