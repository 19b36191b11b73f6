// An array member of a vertex shader's output struct at a [[vk::location]] (skinning weights
// handed to the pixel shader): glslang splits it into one output per element and gives each the
// same location; the kit gives element k the location after element k - 1's, as the array
// occupies them.
struct VertexOutput
{
    float4 position : SV_Position;
    [[vk::location(0)]] float3 normal : NORMAL0;
    [[vk::location(1)]] float weights[4] : TEXCOORD1;
};

VertexOutput main([[vk::location(0)]] float3 position : POSITION0, [[vk::location(1)]] float4 weights : BLENDWEIGHT0)
{
    VertexOutput output;
    output.position = float4(position, 1);
    output.normal = normalize(position);
    [unroll] for (uint k = 0; k < 4; ++k) output.weights[k] = weights[k] * 0.5;
    return output;
}
