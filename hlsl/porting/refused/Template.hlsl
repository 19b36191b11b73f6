// An HLSL 2021 template function.
template <typename T> T twice(T value) { return value * 2; }
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Out[0] = twice(1.5); }
