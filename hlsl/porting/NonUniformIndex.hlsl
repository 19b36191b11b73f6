// NonUniformResourceIndex on an array of textures, as bindless engines index them: each thread
// reads the texture its own id picks.
Texture2D<float4> Tiles[2] : register(t0);
RWStructuredBuffer<float> Out : register(u0);

[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    const uint tile = id.x & 1;
    Out[id.x] = Tiles[NonUniformResourceIndex(tile)].Load(int3(id.x >> 1, 0, 0)).x;
}
