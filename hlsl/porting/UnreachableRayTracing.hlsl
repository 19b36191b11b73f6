// An engine's shared header declares every pass's resources and helpers, ray tracing among them;
// this pass reaches none of the ray tracing, and DXC emits only what the entry point reaches.
RaytracingAccelerationStructure SceneBvh[] : register(t7, space1);
RaytracingAccelerationStructure GetBvh(uint index) { return SceneBvh[index]; }
ByteAddressBuffer Geometry[] : register(t8, space1);
uint GeometryWord(uint mesh, uint offset) { return Geometry[mesh].Load(offset); }

StructuredBuffer<float> In : register(t0);
RWStructuredBuffer<float> Out : register(u0);

float Square(float x) { return x * x; }

[numthreads(1, 1, 1)]
void main()
{
    Out[0] = Square(In[0]) + 1.0;
}
