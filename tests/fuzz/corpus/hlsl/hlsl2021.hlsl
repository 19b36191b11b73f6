namespace Colour {
enum class Space : uint { Linear, Srgb = 3 };
static const float Gamma = 2.4;
float3 toLinear(float3 c) { return select(c <= 0.04045, c / 12.92, pow((c + 0.055) / 1.055, Gamma)); }
namespace Inner { float twice(float x) { return x * 2; } }
}
enum Mode { A, B = 4, C };
using Colour3 = float3;
RWStructuredBuffer<float3> Out : register(u0);
[numthreads(1, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    Colour3 c = Colour::toLinear(float3(0.5, 0.01, 1));
    uint s = (uint)Colour::Space::Srgb + Mode::C + ::Colour::Inner::twice(1);
    bool2 q = and(bool2(true, false), or(bool2(true, true), bool2(false, false)));
    Out[id.x] = c * s * float(q.x);
}
