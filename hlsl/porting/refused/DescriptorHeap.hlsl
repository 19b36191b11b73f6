// Shader Model 6.6 dynamic resources: a buffer taken from the descriptor heap by index.
[numthreads(1, 1, 1)]
void main()
{
    RWStructuredBuffer<float> out = ResourceDescriptorHeap[0];
    out[0] = 1;
}
