// Texture reads of Shader Model 5 in a compute shader: Load, SampleLevel with a sampler state,
// GetDimensions, and a texture array.
Texture2D<float4> Colour : register(t0);
Texture2DArray<float> Layers : register(t1);
SamplerState Nearest : register(s0);
RWStructuredBuffer<float4> Out : register(u0);

[numthreads(2, 2, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint width, height;
    Colour.GetDimensions(width, height);
    const uint i = id.y * 2 + id.x;
    Out[i] = Colour.Load(int3(id.xy, 0));
    Out[4 + i] = Colour.SampleLevel(Nearest, (float2(id.xy) + 0.5) / float2(width, height), 0) -
                 Colour.Load(int3(id.xy, 0));
    Out[8 + i] = float4(width, height, Layers.Load(int4(id.xy, 1, 0)), 0);
}
