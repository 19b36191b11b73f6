// System values glslang's HLSL frontend does not know: SV_ViewID (multiview rendering) in a vertex
// shader beside inputs at [[vk::location]]s. glslang makes it one more input at location 0; the
// kit makes it the ViewIndex built-in.
cbuffer Views : register(b0)
{
    float4x4 viewProjection[2];
};

struct VertexOutput
{
    float4 position : SV_Position;
    [[vk::location(0)]] float3 normal : NORMAL0;
};

VertexOutput main([[vk::location(0)]] float3 position : POSITION0, [[vk::location(1)]] float3 normal : NORMAL0,
                  uint view : SV_ViewID)
{
    VertexOutput output;
    output.position = mul(viewProjection[view], float4(position, 1));
    output.normal = normal;
    return output;
}
