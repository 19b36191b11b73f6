#pragma clang diagnostic ignored "-Wmissing-prototypes"
#pragma clang diagnostic ignored "-Wmissing-braces"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

template<typename T, size_t Num>
struct spvUnsafeArray
{
    T elements[Num ? Num : 1];
    
    thread T& operator [] (size_t pos) thread
    {
        return elements[pos];
    }
    constexpr const thread T& operator [] (size_t pos) const thread
    {
        return elements[pos];
    }
    
    device T& operator [] (size_t pos) device
    {
        return elements[pos];
    }
    constexpr const device T& operator [] (size_t pos) const device
    {
        return elements[pos];
    }
    
    constexpr const constant T& operator [] (size_t pos) const constant
    {
        return elements[pos];
    }
    
    threadgroup T& operator [] (size_t pos) threadgroup
    {
        return elements[pos];
    }
    constexpr const threadgroup T& operator [] (size_t pos) const threadgroup
    {
        return elements[pos];
    }
};

struct ShProjectParameter
{
    uint SourceMip;
};

struct Partials
{
    float4 _data[1];
};

constant int _1083 = {};

kernel void main0(constant ShProjectParameter& _290 [[buffer(0)]], device Partials& Partials_1 [[buffer(1)]], texture2d_array<float> Source [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]], uint3 gl_WorkGroupID [[threadgroup_position_in_grid]], uint gl_LocalInvocationIndex [[thread_index_in_threadgroup]])
{
    threadgroup float4 Shared[64][9];
    uint3 param = gl_GlobalInvocationID;
    uint3 param_1 = gl_WorkGroupID;
    uint3 _526 = uint3(Source.get_width(_290.SourceMip), Source.get_height(_290.SourceMip), Source.get_array_size());
    uint _552 = _526.x;
    uint _554 = _526.y;
    float3 _528 = float3(0.0, 0.0, 1.0);
    spvUnsafeArray<float, 9> _1039 = spvUnsafeArray<float, 9>({ 0.2820948064327239990234375, 0.48860251903533935546875 * _528.y, 0.48860251903533935546875 * _528.z, 0.48860251903533935546875 * _528.x, (1.09254848957061767578125 * _528.x) * _528.y, (1.09254848957061767578125 * _528.y) * _528.z, 0.3153915703296661376953125 * fma(3.0 * _528.z, _528.z, -1.0), (1.09254848957061767578125 * _528.x) * _528.z, 0.546274244785308837890625 * fma(_528.x, _528.x, -(_528.y * _528.y)) });
    spvUnsafeArray<float, 9> _527;
    _527 = _1039;
    float3 _1071;
    float _1073;
    if ((param.x < _552) && (param.y < _554))
    {
        float2 _776 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_552))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _1059;
        if (param.z == 0u)
        {
            _1059 = float3(1.0, _776.y, -_776.x);
        }
        else
        {
            float3 _1060;
            if (param.z == 1u)
            {
                _1060 = float3(-1.0, _776.y, _776.x);
            }
            else
            {
                float3 _1061;
                if (param.z == 2u)
                {
                    _1061 = float3(_776.x, 1.0, -_776.y);
                }
                else
                {
                    float3 _1062;
                    if (param.z == 3u)
                    {
                        _1062 = float3(_776.x, -1.0, _776.y);
                    }
                    else
                    {
                        float3 _1063;
                        if (param.z == 4u)
                        {
                            _1063 = float3(_776.x, _776.y, 1.0);
                        }
                        else
                        {
                            _1063 = float3(-_776.x, _776.y, -1.0);
                        }
                        _1062 = _1063;
                    }
                    _1061 = _1062;
                }
                _1060 = _1061;
            }
            _1059 = _1060;
        }
        float3 _535 = fast::normalize(_1059);
        spvUnsafeArray<float, 9> _1058 = spvUnsafeArray<float, 9>({ 0.2820948064327239990234375, 0.48860251903533935546875 * _535.y, 0.48860251903533935546875 * _535.z, 0.48860251903533935546875 * _535.x, (1.09254848957061767578125 * _535.x) * _535.y, (1.09254848957061767578125 * _535.y) * _535.z, 0.3153915703296661376953125 * fma(3.0 * _535.z, _535.z, -1.0), (1.09254848957061767578125 * _535.x) * _535.z, 0.546274244785308837890625 * fma(_535.x, _535.x, -(_535.y * _535.y)) });
        _527 = _1058;
        uint2 _537 = gl_GlobalInvocationID.xy;
        float _922 = float(_552);
        float _923 = 1.0 / _922;
        float _930 = fma(2.0 * float(_537.x), _923, -1.0);
        float _937 = fma(2.0 * float(_537.y), _923, -1.0);
        float _941 = _930 + (2.0 / _922);
        float _945 = _937 + (2.0 / _922);
        int3 _603 = int4(int2(gl_GlobalInvocationID.xy), int(param.z), _1083).xyz;
        _1073 = ((precise::atan2(_930 * _937, sqrt(fma(_930, _930, _937 * _937) + 1.0)) - precise::atan2(_930 * _945, sqrt(fma(_930, _930, _945 * _945) + 1.0))) - precise::atan2(_941 * _937, sqrt(fma(_941, _941, _937 * _937) + 1.0))) + precise::atan2(_941 * _945, sqrt(fma(_941, _941, _945 * _945) + 1.0));
        _1071 = Source.read(uint2(_603.xy), uint(_603.z), int(_290.SourceMip)).xyz;
    }
    else
    {
        _1073 = 0.0;
        _1071 = float3(0.0);
    }
    for (uint _1064 = 0u; _1064 < 9u; _1064++)
    {
        Shared[gl_LocalInvocationIndex][_1064] = float4((_1071 * _527[_1064]) * _1073, _1073);
    }
    threadgroup_barrier(mem_flags::mem_threadgroup);
    for (uint _1065 = 32u; _1065 > 0u; _1065 /= 2u)
    {
        if (gl_LocalInvocationIndex < _1065)
        {
            for (uint _1067 = 0u; _1067 < 9u; _1067++)
            {
                Shared[gl_LocalInvocationIndex][_1067] += Shared[gl_LocalInvocationIndex + _1065][_1067];
            }
        }
        threadgroup_barrier(mem_flags::mem_threadgroup);
    }
    if (gl_LocalInvocationIndex == 0u)
    {
        uint _699 = (((param_1.z * ((_554 + 7u) / 8u)) + param_1.y) * ((_552 + 7u) / 8u)) + param_1.x;
        for (uint _1066 = 0u; _1066 < 9u; _1066++)
        {
            Partials_1._data[(_699 * 9u) + _1066] = Shared[0][_1066];
        }
    }
}

