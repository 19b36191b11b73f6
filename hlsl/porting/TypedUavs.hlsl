// Typed UAVs of one to three components: float (r32f), float2 (rg32f), int3 (rgba32i, written
// with four: alpha 1) and uint2 (rg32ui).
RWTexture2D<float> Single : register(u0);
RWTexture2D<float2> Pair : register(u1);
RWTexture2D<int3> Signed : register(u2);
RWTexture2D<uint2> Unsigned : register(u3);

[numthreads(2, 2, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    Single[id.xy] = id.x + 0.5;
    Pair[id.xy] = float2(id.x, id.y);
    Signed[id.xy] = int3(-(int)id.x, id.y, -7);
    Unsigned[id.xy] = uint2(id.x * 10, id.y * 100);
}
