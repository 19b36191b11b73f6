// A constant buffer Direct3D packs tighter than a Vulkan uniform block can: HLSL puts 'scale' in
// the unused end of the array's last register (byte 36), where a uniform block cannot place it.
cbuffer Filter : register(b0)
{
    float weights[3];
    float scale;
};
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    Out[0] = weights[2] * scale;
}
