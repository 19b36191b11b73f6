// Local variables that hold resources, as bindless code writes them (ByteAddressBuffer vertices =
// Buffers[index];): each names the resource it was given, at every use in its block.
StructuredBuffer<float> Weights : register(t0);
ByteAddressBuffer Words : register(t1);
RWStructuredBuffer<float> Out : register(u0);

float WeightedWord(uint index)
{
    const StructuredBuffer<float> weights = Weights;
    ByteAddressBuffer words = Words;
    return weights[index] * asfloat(words.Load(index * 4));
}

[numthreads(2, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    RWStructuredBuffer<float> result = Out;
    result[id.x] = WeightedWord(id.x);
}
