// HLSL 2021 namespaces: nested ones, a member found in an enclosing namespace, ::name for the
// global one, a struct in a namespace, and a using-alias.
static const float Scale = 10.0;

namespace Colour
{
    static const float Scale = 2.0;
    float twice(float x) { return x * Scale; }

    namespace Inner
    {
        static const float Scale = 3.0;
        float thrice(float x) { return x * Scale; }
        float twicePlusGlobal(float x) { return twice(x) + ::Scale; }
    }

    struct Pair { float a; float b; };
    Pair make(float v)
    {
        Pair pair;
        pair.a = v;
        pair.b = Inner::thrice(v);
        return pair;
    }
}

using Real = float;

RWStructuredBuffer<float> Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    Real v = 1.5;
    Colour::Pair pair = Colour::make(v);
    Out[0] = Colour::twice(v);
    Out[1] = Colour::Inner::thrice(v);
    Out[2] = Colour::Inner::twicePlusGlobal(v);
    Out[3] = pair.a + pair.b;
    Out[4] = Scale;
}
