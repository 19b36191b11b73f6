// DXR's RayDesc used outside ray tracing, as a compute pass sets up a primary ray: the kit declares
// the struct as the HLSL specification defines it (Origin, TMin, Direction, TMax).
RWStructuredBuffer<float4> Out : register(u0);

RayDesc PrimaryRay(uint pixel)
{
    RayDesc ray;
    ray.Origin = float3(pixel, 0, -1);
    ray.TMin = 0.25;
    ray.Direction = float3(0, 0, 1);
    ray.TMax = 100;
    return ray;
}

[numthreads(2, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    const RayDesc ray = PrimaryRay(id.x);
    Out[id.x * 2] = float4(ray.Origin, ray.TMin);
    Out[id.x * 2 + 1] = float4(ray.Direction, ray.TMax);
}
