#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct DownsampleParameter
{
    uint SourceMip;
};

constant int _340 = {};

kernel void main0(constant DownsampleParameter& _68 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d_array<float, access::write> Destination [[texture(1)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _199 = uint3(0u);
        uint3 _200 = uint3(Destination.get_width(), Destination.get_height(), Destination.get_array_size());
        _199.x = _200.x;
        _199.y = _200.y;
        _199.z = _200.z;
        if (any(gl_GlobalInvocationID >= _199))
        {
            break;
        }
        int2 _227 = int2(gl_GlobalInvocationID.xy) * int2(2);
        int3 _239 = int4(_227, int(param.z), _340).xyz;
        int3 _264 = int4(_227 + int2(1, 0), int(param.z), _340).xyz;
        int3 _291 = int4(_227 + int2(0, 1), int(param.z), _340).xyz;
        int3 _318 = int4(_227 + int2(1), int(param.z), _340).xyz;
        Destination.write((((Source.read(uint2(_239.xy), uint(_239.z), int(_68.SourceMip)) + Source.read(uint2(_264.xy), uint(_264.z), int(_68.SourceMip))) + Source.read(uint2(_291.xy), uint(_291.z), int(_68.SourceMip))) + Source.read(uint2(_318.xy), uint(_318.z), int(_68.SourceMip))) * 0.25, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

