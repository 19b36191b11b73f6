// A using-directive that brings a namespace's names into scope.
namespace Units { static const float Metre = 1.0; }
using namespace Units;
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Out[0] = Metre; }
