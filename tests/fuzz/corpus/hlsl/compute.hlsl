#define SCALE 2.f
cbuffer Params : register(b0) { float Factor; uint Count; };
StructuredBuffer<float> In;
RWStructuredBuffer<float> Out;
float Twice(float x) { return x * SCALE; }
[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) { if (id.x < Count) Out[id.x] = Twice(In[id.x]) * Factor; }
