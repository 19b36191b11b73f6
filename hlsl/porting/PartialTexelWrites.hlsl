// Writes to some components of a storage texel, as engines write them (Data[xy].w = state;),
// directly, through a parameter, in an array of textures, and compound (+=): each reads the texel,
// writes its components and stores it back, so the components not written keep their values.
RWTexture2D<float4> Colour : register(u0);
RWTexture2D<float2> Pairs[2] : register(u1);

void SetAlpha(RWTexture2D<float4> target, uint2 texel, float alpha)
{
    target[texel].a = alpha;
}

[numthreads(2, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    if (id.x == 0) Colour[id.xy].rg = float2(10, 20);
    else SetAlpha(Colour, id.xy, 40);
    Colour[id.xy].b += 0.5;
    Pairs[1][id.xy].y = id.x + 7;
}
