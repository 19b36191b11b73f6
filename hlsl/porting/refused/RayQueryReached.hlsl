// Ray tracing the entry point reaches stays refused by name, at its place.
RaytracingAccelerationStructure SceneBvh : register(t0);
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    RayQuery<RAY_FLAG_NONE> query;
    Out[0] = 0.0;
}
