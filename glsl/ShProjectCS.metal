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

constant int _1065 = {};

kernel void main0(constant ShProjectParameter& _279 [[buffer(0)]], device Partials& Partials_1 [[buffer(1)]], texture2d_array<float> Source [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]], uint3 gl_WorkGroupID [[threadgroup_position_in_grid]], uint gl_LocalInvocationIndex [[thread_index_in_threadgroup]])
{
    threadgroup float4 Shared[64][9];
    uint3 param = gl_GlobalInvocationID;
    uint3 param_1 = gl_WorkGroupID;
    uint3 _515 = uint3(Source.get_width(_279.SourceMip), Source.get_height(_279.SourceMip), Source.get_array_size());
    uint _541 = _515.x;
    uint _543 = _515.y;
    float3 _517 = float3(0.0, 0.0, 1.0);
    spvUnsafeArray<float, 9> _1021 = spvUnsafeArray<float, 9>({ 0.2820948064327239990234375, 0.48860251903533935546875 * _517.y, 0.48860251903533935546875 * _517.z, 0.48860251903533935546875 * _517.x, (1.09254848957061767578125 * _517.x) * _517.y, (1.09254848957061767578125 * _517.y) * _517.z, 0.3153915703296661376953125 * fma(3.0 * _517.z, _517.z, -1.0), (1.09254848957061767578125 * _517.x) * _517.z, 0.546274244785308837890625 * fma(_517.x, _517.x, -(_517.y * _517.y)) });
    spvUnsafeArray<float, 9> _516;
    _516 = _1021;
    float3 _1053;
    float _1055;
    if ((param.x < _541) && (param.y < _543))
    {
        float2 _523 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_541))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _1041;
        if (param.z == 0u)
        {
            _1041 = float3(1.0, _523.y, -_523.x);
        }
        else
        {
            float3 _1042;
            if (param.z == 1u)
            {
                _1042 = float3(-1.0, _523.y, _523.x);
            }
            else
            {
                float3 _1043;
                if (param.z == 2u)
                {
                    _1043 = float3(_523.x, 1.0, -_523.y);
                }
                else
                {
                    float3 _1044;
                    if (param.z == 3u)
                    {
                        _1044 = float3(_523.x, -1.0, _523.y);
                    }
                    else
                    {
                        float3 _1045;
                        if (param.z == 4u)
                        {
                            _1045 = float3(_523.x, _523.y, 1.0);
                        }
                        else
                        {
                            _1045 = float3(-_523.x, _523.y, -1.0);
                        }
                        _1044 = _1045;
                    }
                    _1043 = _1044;
                }
                _1042 = _1043;
            }
            _1041 = _1042;
        }
        float3 _524 = fast::normalize(_1041);
        spvUnsafeArray<float, 9> _1040 = spvUnsafeArray<float, 9>({ 0.2820948064327239990234375, 0.48860251903533935546875 * _524.y, 0.48860251903533935546875 * _524.z, 0.48860251903533935546875 * _524.x, (1.09254848957061767578125 * _524.x) * _524.y, (1.09254848957061767578125 * _524.y) * _524.z, 0.3153915703296661376953125 * fma(3.0 * _524.z, _524.z, -1.0), (1.09254848957061767578125 * _524.x) * _524.z, 0.546274244785308837890625 * fma(_524.x, _524.x, -(_524.y * _524.y)) });
        _516 = _1040;
        uint2 _526 = gl_GlobalInvocationID.xy;
        float _904 = float(_541);
        float _905 = 1.0 / _904;
        float _912 = fma(2.0 * float(_526.x), _905, -1.0);
        float _919 = fma(2.0 * float(_526.y), _905, -1.0);
        float _923 = _912 + (2.0 / _904);
        float _927 = _919 + (2.0 / _904);
        int3 _592 = int4(int2(gl_GlobalInvocationID.xy), int(param.z), _1065).xyz;
        _1055 = ((precise::atan2(_912 * _919, sqrt(fma(_912, _912, _919 * _919) + 1.0)) - precise::atan2(_912 * _927, sqrt(fma(_912, _912, _927 * _927) + 1.0))) - precise::atan2(_923 * _919, sqrt(fma(_923, _923, _919 * _919) + 1.0))) + precise::atan2(_923 * _927, sqrt(fma(_923, _923, _927 * _927) + 1.0));
        _1053 = Source.read(uint2(_592.xy), uint(_592.z), int(_279.SourceMip)).xyz;
    }
    else
    {
        _1055 = 0.0;
        _1053 = float3(0.0);
    }
    for (uint _1046 = 0u; _1046 < 9u; _1046++)
    {
        Shared[gl_LocalInvocationIndex][_1046] = float4((_1053 * _516[_1046]) * _1055, _1055);
    }
    threadgroup_barrier(mem_flags::mem_threadgroup);
    for (uint _1047 = 32u; _1047 > 0u; _1047 /= 2u)
    {
        if (gl_LocalInvocationIndex < _1047)
        {
            for (uint _1049 = 0u; _1049 < 9u; _1049++)
            {
                Shared[gl_LocalInvocationIndex][_1049] += Shared[gl_LocalInvocationIndex + _1047][_1049];
            }
        }
        threadgroup_barrier(mem_flags::mem_threadgroup);
    }
    if (gl_LocalInvocationIndex == 0u)
    {
        uint _688 = (((param_1.z * ((_543 + 7u) / 8u)) + param_1.y) * ((_541 + 7u) / 8u)) + param_1.x;
        for (uint _1048 = 0u; _1048 < 9u; _1048++)
        {
            Partials_1._data[(_688 * 9u) + _1048] = Shared[0][_1048];
        }
    }
}

