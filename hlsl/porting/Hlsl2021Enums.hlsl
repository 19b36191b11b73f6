// HLSL 2021 enums: unscoped and scoped, an underlying type, enumerators valued from others,
// casts both ways, an enum as a parameter type.
enum Mode { Off, Half = 5, Full };
enum Level { Low = 1, High = Low + 1, Top = High * Half };
enum class Channel : uint { Red = 1, Green = Red << 1, Blue = Green << 1 };

RWStructuredBuffer<uint> Out : register(u0);

uint maskOf(Channel channel) { return (uint)channel; }

[numthreads(1, 1, 1)]
void main()
{
    Mode mode = Full;
    Out[0] = mode;
    Out[1] = Mode::Half;
    Out[2] = maskOf(Channel::Blue) | maskOf(Channel::Red);
    Channel channel = (Channel)2;
    Out[3] = channel == Channel::Green ? 1 : 0;
    Out[4] = (uint)Channel::Blue + Off;
    Out[5] = Top + Level::High;
}
