// A storage texture's Load written as for a sampled one, with a mip level (HDR.Load(int3(xy, 0))
// on a RWTexture2D): DXC truncates the coordinates with a warning; the kit converts them.
RWTexture2D<float4> Colour : register(u0);

[numthreads(2, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    const int2 texel = id.xy;
    const float4 value = Colour.Load(int3(texel, 0));
    Colour[texel] = value * 2;
}
