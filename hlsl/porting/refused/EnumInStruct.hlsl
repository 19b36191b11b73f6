// An enum declared inside a struct.
struct Light
{
    enum Kind { Point, Spot };
    Kind kind;
};
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Light light; light.kind = Light::Spot; Out[0] = (uint)light.kind; }
