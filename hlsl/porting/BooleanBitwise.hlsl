// Bitwise |, & and ^ of bools, which HLSL allows and engines write for flags: glslang writes them
// as integer operations on booleans, which SPIR-V forbids; the kit writes the logical ones.
StructuredBuffer<uint> Flags : register(t0);
RWStructuredBuffer<uint> Out : register(u0);

[numthreads(4, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    const bool a = (Flags[id.x] & 1) != 0;
    const bool b = (Flags[id.x] & 2) != 0;
    bool either = a | b;
    bool both = a & b;
    bool one = a ^ b;
    either |= both;
    Out[id.x] = uint(either) | uint(both) << 1 | uint(one) << 2;
}
