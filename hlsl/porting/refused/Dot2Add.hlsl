// Shader Model 6.4 dot2add: a half-precision dot product added to a float.
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Out[0] = dot2add(half2(1, 2), half2(3, 4), 1.0); }
