#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct IrradianceParameter
{
    uint SourceMip;
};

constant int _899 = {};

kernel void main0(constant IrradianceParameter& _222 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d_array<float, access::write> Irradiance [[texture(1)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]], uint gl_LocalInvocationIndex [[thread_index_in_threadgroup]])
{
    threadgroup float3 ChunkDirection[64];
    threadgroup float3 ChunkEnergy[64];
    uint3 param = gl_GlobalInvocationID;
    uint3 _420 = uint3(0u);
    uint3 _421 = uint3(Irradiance.get_width(), Irradiance.get_height(), Irradiance.get_array_size());
    _420.x = _421.x;
    _420.y = _421.y;
    _420.z = _421.z;
    uint3 _461 = _420;
    uint3 _427 = uint3(Source.get_width(_222.SourceMip), Source.get_height(_222.SourceMip), Source.get_array_size());
    uint _478 = _427.x * _427.x;
    uint _480 = 6u * _478;
    float2 _432 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_461.xy)) - float2(0.5)) * float2(2.0, -2.0);
    float3 _859;
    if (param.z == 0u)
    {
        _859 = float3(1.0, _432.y, -_432.x);
    }
    else
    {
        float3 _860;
        if (param.z == 1u)
        {
            _860 = float3(-1.0, _432.y, _432.x);
        }
        else
        {
            float3 _861;
            if (param.z == 2u)
            {
                _861 = float3(_432.x, 1.0, -_432.y);
            }
            else
            {
                float3 _862;
                if (param.z == 3u)
                {
                    _862 = float3(_432.x, -1.0, _432.y);
                }
                else
                {
                    float3 _863;
                    if (param.z == 4u)
                    {
                        _863 = float3(_432.x, _432.y, 1.0);
                    }
                    else
                    {
                        _863 = float3(-_432.x, _432.y, -1.0);
                    }
                    _862 = _863;
                }
                _861 = _862;
            }
            _860 = _861;
        }
        _859 = _860;
    }
    float3 _676 = fast::normalize(_859);
    float3 _865;
    _865 = float3(0.0);
    float3 _881;
    for (uint _864 = 0u; _864 < _480; _865 = _881, _864 += 64u)
    {
        uint _501 = _864 + gl_LocalInvocationIndex;
        float3 _871;
        float3 _872;
        if (_501 < _480)
        {
            uint _508 = _501 / _478;
            uint _511 = _501 % _427.x;
            uint _516 = (_501 % _478) / _427.x;
            float2 _442 = (((float2(float(_511), float(_516)) + float2(0.5)) / float2(float(_427.x))) - float2(0.5)) * float2(2.0, -2.0);
            float3 _866;
            if (_508 == 0u)
            {
                _866 = float3(1.0, _442.y, -_442.x);
            }
            else
            {
                float3 _867;
                if (_508 == 1u)
                {
                    _867 = float3(-1.0, _442.y, _442.x);
                }
                else
                {
                    float3 _868;
                    if (_508 == 2u)
                    {
                        _868 = float3(_442.x, 1.0, -_442.y);
                    }
                    else
                    {
                        float3 _869;
                        if (_508 == 3u)
                        {
                            _869 = float3(_442.x, -1.0, _442.y);
                        }
                        else
                        {
                            float3 _870;
                            if (_508 == 4u)
                            {
                                _870 = float3(_442.x, _442.y, 1.0);
                            }
                            else
                            {
                                _870 = float3(-_442.x, _442.y, -1.0);
                            }
                            _869 = _870;
                        }
                        _868 = _869;
                    }
                    _867 = _868;
                }
                _866 = _867;
            }
            int3 _541 = int4(int(_511), int(_516), int(_508), _899).xyz;
            uint2 _443 = uint2(_511, _516);
            float _760 = float(_427.x);
            float _761 = 1.0 / _760;
            float _768 = fma(2.0 * float(_443.x), _761, -1.0);
            float _775 = fma(2.0 * float(_443.y), _761, -1.0);
            float _779 = _768 + (2.0 / _760);
            float _783 = _775 + (2.0 / _760);
            _872 = Source.read(uint2(_541.xy), uint(_541.z), int(_222.SourceMip)).xyz * (((precise::atan2(_768 * _775, sqrt(fma(_768, _768, _775 * _775) + 1.0)) - precise::atan2(_768 * _783, sqrt(fma(_768, _768, _783 * _783) + 1.0))) - precise::atan2(_779 * _775, sqrt(fma(_779, _779, _775 * _775) + 1.0))) + precise::atan2(_779 * _783, sqrt(fma(_779, _779, _783 * _783) + 1.0)));
            _871 = fast::normalize(_866);
        }
        else
        {
            _872 = float3(0.0);
            _871 = float3(0.0);
        }
        ChunkDirection[gl_LocalInvocationIndex] = _871;
        ChunkEnergy[gl_LocalInvocationIndex] = _872;
        threadgroup_barrier(mem_flags::mem_threadgroup);
        _881 = _865;
        float3 _890;
        for (uint _873 = 0u; _873 < 64u; _881 = _890, _873++)
        {
            float _577 = dot(_676, ChunkDirection[_873]);
            if (_577 > 0.0)
            {
                _890 = _881 + (ChunkEnergy[_873] * _577);
            }
            else
            {
                _890 = _881;
            }
        }
        threadgroup_barrier(mem_flags::mem_threadgroup);
    }
    if (all(gl_GlobalInvocationID < _461))
    {
        Irradiance.write(float4(_865 * float3(0.3183098733425140380859375), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
    }
}

