// Float matrices in a structured buffer, column- and row-major: SPIRV-Cross writes the buffer in
// the HLSL form as a byte-address buffer and loads each matrix from it element by element.
struct Instance
{
    float4x4 world;         // column-major, HLSL's default
    row_major float4x4 view;
};
StructuredBuffer<Instance> Instances : register(t0);
RWStructuredBuffer<float4> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    const float4 position = float4(1, 2, 3, 1);
    Out[0] = mul(Instances[0].world, position);
    Out[1] = mul(Instances[0].view, position);
}
