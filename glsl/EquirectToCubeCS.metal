#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct EquirectToCubeParameter
{
    uint Supersample;
};

kernel void main0(constant EquirectToCubeParameter& _323 [[buffer(0)]], texture2d<float> Equirect [[texture(0)]], texture2d_array<float, access::write> Cube [[texture(1)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _410 = uint3(0u);
        uint3 _411 = uint3(Cube.get_width(), Cube.get_height(), Cube.get_array_size());
        _410.x = _411.x;
        _410.y = _411.y;
        _410.z = _411.z;
        if (any(gl_GlobalInvocationID >= _410))
        {
            break;
        }
        uint2 _412 = uint2(0u);
        uint2 _413 = uint2(Equirect.get_width(), Equirect.get_height());
        _412.x = _413.x;
        _412.y = _413.y;
        float3 _867;
        _867 = float3(0.0);
        float3 _876;
        for (uint _866 = 0u; _866 < _323.Supersample; _867 = _876, _866++)
        {
            _876 = _867;
            float3 _494;
            for (uint _868 = 0u; _868 < _323.Supersample; _876 = _494, _868++)
            {
                float2 _521 = (((float2(gl_GlobalInvocationID.xy) + ((float2(float(_868), float(_866)) + float2(0.5)) / float2(float(_323.Supersample)))) / float2(_410.xy)) - float2(0.5)) * float2(2.0, -2.0);
                float3 _870;
                if (param.z == 0u)
                {
                    _870 = float3(1.0, _521.y, -_521.x);
                }
                else
                {
                    float3 _871;
                    if (param.z == 1u)
                    {
                        _871 = float3(-1.0, _521.y, _521.x);
                    }
                    else
                    {
                        float3 _872;
                        if (param.z == 2u)
                        {
                            _872 = float3(_521.x, 1.0, -_521.y);
                        }
                        else
                        {
                            float3 _873;
                            if (param.z == 3u)
                            {
                                _873 = float3(_521.x, -1.0, _521.y);
                            }
                            else
                            {
                                float3 _874;
                                if (param.z == 4u)
                                {
                                    _874 = float3(_521.x, _521.y, 1.0);
                                }
                                else
                                {
                                    _874 = float3(-_521.x, _521.y, -1.0);
                                }
                                _873 = _874;
                            }
                            _872 = _873;
                        }
                        _871 = _872;
                    }
                    _870 = _871;
                }
                int2 _490 = int2(_412);
                float3 _595 = fast::normalize(_870);
                float2 _617 = fma(float2(fma(precise::atan2(_595.x, -_595.z), 0.15915493667125701904296875, 0.5), acos(fast::clamp(_595.y, -1.0, 1.0)) * 0.3183098733425140380859375), float2(_490), float2(-0.5));
                float2 _619 = floor(_617);
                float2 _597 = _617 - _619;
                int2 _624 = int2(_619);
                int2 _600 = _624;
                int2 _601 = _490;
                _600.x += ((_600.x < 0) ? _601.x : ((_600.x >= _601.x) ? (-_601.x) : 0));
                _600.x = clamp(_600.x, 0, _601.x - 1);
                _600.y = clamp(_600.y, 0, _601.y - 1);
                int2 _602 = _624 + int2(1, 0);
                int2 _603 = _490;
                _602.x += ((_602.x < 0) ? _603.x : ((_602.x >= _603.x) ? (-_603.x) : 0));
                _602.x = clamp(_602.x, 0, _603.x - 1);
                _602.y = clamp(_602.y, 0, _603.y - 1);
                int2 _605 = _624 + int2(0, 1);
                int2 _606 = _490;
                _605.x += ((_605.x < 0) ? _606.x : ((_605.x >= _606.x) ? (-_606.x) : 0));
                _605.x = clamp(_605.x, 0, _606.x - 1);
                _605.y = clamp(_605.y, 0, _606.y - 1);
                int2 _607 = _624 + int2(1);
                int2 _608 = _490;
                _607.x += ((_607.x < 0) ? _608.x : ((_607.x >= _608.x) ? (-_608.x) : 0));
                _607.x = clamp(_607.x, 0, _608.x - 1);
                _607.y = clamp(_607.y, 0, _608.y - 1);
                _494 = _876 + mix(mix(Equirect.read(uint2(int3(_600, 0).xy), 0).xyz, Equirect.read(uint2(int3(_602, 0).xy), 0).xyz, float3(_597.x)), mix(Equirect.read(uint2(int3(_605, 0).xy), 0).xyz, Equirect.read(uint2(int3(_607, 0).xy), 0).xyz, float3(_597.x)), float3(_597.y));
            }
        }
        Cube.write(float4(_867 / float3(float(_323.Supersample * _323.Supersample)), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

