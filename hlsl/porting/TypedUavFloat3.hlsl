// A typed UAV of three components: rgba32f, written with four (alpha 1).
RWTexture2D<float3> Colour : register(u0);

[numthreads(2, 2, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    Colour[id.xy] = float3(id.x, id.y, 7);
}
