TextureCube EnvMap; SamplerState Linear;
RWTexture2DArray<float4> Prefiltered;
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { Prefiltered[id] = EnvMap.SampleLevel(Linear, float3(1, 0, 0), 0); }
