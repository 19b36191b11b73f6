#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct IrradianceParameter
{
    uint SourceMip;
};

constant int _843 = {};

kernel void main0(constant IrradianceParameter& _222 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d_array<float, access::write> Irradiance [[texture(1)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _382 = uint3(0u);
        uint3 _383 = uint3(Irradiance.get_width(), Irradiance.get_height(), Irradiance.get_array_size());
        _382.x = _383.x;
        _382.y = _383.y;
        _382.z = _383.z;
        if (any(gl_GlobalInvocationID >= _382))
        {
            break;
        }
        uint3 _388 = uint3(Source.get_width(_222.SourceMip), Source.get_height(_222.SourceMip), Source.get_array_size());
        float2 _391 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_382.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _792;
        if (param.z == 0u)
        {
            _792 = float3(1.0, _391.y, -_391.x);
        }
        else
        {
            float3 _793;
            if (param.z == 1u)
            {
                _793 = float3(-1.0, _391.y, _391.x);
            }
            else
            {
                float3 _794;
                if (param.z == 2u)
                {
                    _794 = float3(_391.x, 1.0, -_391.y);
                }
                else
                {
                    float3 _795;
                    if (param.z == 3u)
                    {
                        _795 = float3(_391.x, -1.0, _391.y);
                    }
                    else
                    {
                        float3 _796;
                        if (param.z == 4u)
                        {
                            _796 = float3(_391.x, _391.y, 1.0);
                        }
                        else
                        {
                            _796 = float3(-_391.x, _391.y, -1.0);
                        }
                        _795 = _796;
                    }
                    _794 = _795;
                }
                _793 = _794;
            }
            _792 = _793;
        }
        float3 _609 = fast::normalize(_792);
        float3 _798;
        _798 = float3(0.0);
        float3 _826;
        for (uint _797 = 0u; _797 < 6u; _798 = _826, _797++)
        {
            _826 = _798;
            float3 _825;
            for (uint _799 = 0u; _799 < _388.y; _799++, _826 = _825)
            {
                _825 = _826;
                float3 _834;
                for (uint _801 = 0u; _801 < _388.x; _825 = _834, _801++)
                {
                    float2 _398 = (((float2(float(_801), float(_799)) + float2(0.5)) / float2(float(_388.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _804;
                    if (_797 == 0u)
                    {
                        _804 = float3(1.0, _398.y, -_398.x);
                    }
                    else
                    {
                        float3 _805;
                        if (_797 == 1u)
                        {
                            _805 = float3(-1.0, _398.y, _398.x);
                        }
                        else
                        {
                            float3 _806;
                            if (_797 == 2u)
                            {
                                _806 = float3(_398.x, 1.0, -_398.y);
                            }
                            else
                            {
                                float3 _807;
                                if (_797 == 3u)
                                {
                                    _807 = float3(_398.x, -1.0, _398.y);
                                }
                                else
                                {
                                    float3 _808;
                                    if (_797 == 4u)
                                    {
                                        _808 = float3(_398.x, _398.y, 1.0);
                                    }
                                    else
                                    {
                                        _808 = float3(-_398.x, _398.y, -1.0);
                                    }
                                    _807 = _808;
                                }
                                _806 = _807;
                            }
                            _805 = _806;
                        }
                        _804 = _805;
                    }
                    float _479 = dot(_609, fast::normalize(_804));
                    if (_479 > 0.0)
                    {
                        int3 _494 = int4(int(_801), int(_799), int(_797), _843).xyz;
                        uint2 _401 = uint2(_801, _799);
                        float _693 = float(_388.x);
                        float _694 = 1.0 / _693;
                        float _701 = fma(2.0 * float(_401.x), _694, -1.0);
                        float _708 = fma(2.0 * float(_401.y), _694, -1.0);
                        float _712 = _701 + (2.0 / _693);
                        float _716 = _708 + (2.0 / _693);
                        _834 = _825 + (Source.read(uint2(_494.xy), uint(_494.z), int(_222.SourceMip)).xyz * (_479 * (((precise::atan2(_701 * _708, sqrt(fma(_701, _701, _708 * _708) + 1.0)) - precise::atan2(_701 * _716, sqrt(fma(_701, _701, _716 * _716) + 1.0))) - precise::atan2(_712 * _708, sqrt(fma(_712, _712, _708 * _708) + 1.0))) + precise::atan2(_712 * _716, sqrt(fma(_712, _712, _716 * _716) + 1.0)))));
                    }
                    else
                    {
                        _834 = _825;
                    }
                }
            }
        }
        Irradiance.write(float4(_798 * float3(0.3183098733425140380859375), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

