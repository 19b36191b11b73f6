// HLSL 2021 templates and sizeof, as current engine code writes them: a function template called
// with its arguments written and deduced (from a variable, a literal, a constructor), a constant
// parameter, a struct template, a template that calls another, sizeof of types and a variable.
struct Sample
{
    float3 colour;
    float weight;
    uint2 texel;
};

template <typename T> T Twice(T value) { return value * 2; }
template <typename T, uint N> T Repeat(T value) { T sum = value; for (uint i = 1; i < N; ++i) sum += value; return sum; }
template <typename T> struct Pair { T first; T second; T Sum() { return first + second; } };
template <typename T> T SumOfTwice(Pair<T> pair) { return Twice(pair.first) + Twice<T>(pair.second); }

RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    const float half = 0.5;
    Pair<float> pair;
    pair.first = 1.5;
    pair.second = 4;
    Sample sample;
    Out[0] = Twice(half);
    Out[1] = Twice(int2(3, 4)).y;
    Out[2] = Twice<uint>(7);
    Out[3] = Repeat<float, 3>(1.25);
    Out[4] = pair.Sum();
    Out[5] = SumOfTwice(pair);
    Out[6] = sizeof(Sample) + 100 * sizeof(float3x4);
    Out[7] = sizeof(sample) + sizeof(uint2);
}
