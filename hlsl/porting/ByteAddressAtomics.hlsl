// Interlocked operations on a RWByteAddressBuffer with int literals for uint results, as engine
// code writes them (glslang keeps the int operand, which SPIR-V does not allow).
RWByteAddressBuffer Counters : register(u0);

[numthreads(16, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint previous;
    Counters.InterlockedAdd(0, 1, previous);
    Counters.InterlockedMax(4, previous);
    uint original;
    Counters.InterlockedCompareExchange(8, 0, 7, original);
    Counters.InterlockedAdd(12, original == 0 ? 1 : 0);
}
