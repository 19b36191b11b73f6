// A byte-address buffer's GetDimensions answers its size in bytes, as Direct3D and DXC define it.
// glslang's HLSL frontend answers 32-bit words; the kit scales them (byte-address-dimensions), so
// that the HLSL form's StructuredBuffer lengths, written as bytes over the stride, come back right.
ByteAddressBuffer Data : register(t0);
RWByteAddressBuffer Out : register(u0);

[numthreads(1, 1, 1)]
void main()
{
    uint bytes, written, again = 0;
    Data.GetDimensions(bytes);
    Out.GetDimensions(written);
    if (bytes == 64u)
        Data.GetDimensions(again);
    Out.Store(0, bytes);
    Out.Store(4, written);
    Out.Store(8, again);
}
