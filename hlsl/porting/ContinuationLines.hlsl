// Lines joined by a backslash, as engines write root signatures and long macros: a macro whose
// name the backslash follows (#define RS\), a string continued across lines, a function-like
// macro whose parameters begin on the next line. Every later line keeps its number.
#define RS\
[\
    RootSignature\
    (\
       "CBV(b0),\
        DescriptorTable(UAV(u0, numDescriptors=1))"\
    )\
]
#define SCALED\
(value, scale) ((value) *\
                (scale))

RWStructuredBuffer<float> Out : register(u0);

[numthreads(2, 1, 1)]
RS
void main(uint3 id : SV_DispatchThreadID)
{
    Out[id.x] = SCALED(id.x + 1, 3);
}
