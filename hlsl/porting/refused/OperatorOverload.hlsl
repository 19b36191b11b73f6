// HLSL 2021 operator overloading on a struct.
struct Complex
{
    float re, im;
    Complex operator+(Complex other) { Complex sum; sum.re = re + other.re; sum.im = im + other.im; return sum; }
};
RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main() { Complex a = {1, 2}; Complex b = {3, 4}; Out[0] = (a + b).re; }
