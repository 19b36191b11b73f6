#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct EquirectToCubeParameter
{
    uint Supersample;
};

kernel void main0(constant EquirectToCubeParameter& _298 [[buffer(0)]], texture2d<float> Equirect [[texture(0)]], texture2d_array<float, access::write> Cube [[texture(1)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _385 = uint3(0u);
        uint3 _386 = uint3(Cube.get_width(), Cube.get_height(), Cube.get_array_size());
        _385.x = _386.x;
        _385.y = _386.y;
        _385.z = _386.z;
        if (any(gl_GlobalInvocationID >= _385))
        {
            break;
        }
        uint2 _387 = uint2(0u);
        uint2 _388 = uint2(Equirect.get_width(), Equirect.get_height());
        _387.x = _388.x;
        _387.y = _388.y;
        float3 _779;
        _779 = float3(0.0);
        float3 _788;
        for (uint _778 = 0u; _778 < _298.Supersample; _779 = _788, _778++)
        {
            _788 = _779;
            float3 _469;
            for (uint _780 = 0u; _780 < _298.Supersample; _788 = _469, _780++)
            {
                float2 _395 = (((float2(gl_GlobalInvocationID.xy) + ((float2(float(_780), float(_778)) + float2(0.5)) / float2(float(_298.Supersample)))) / float2(_385.xy)) - float2(0.5)) * float2(2.0, -2.0);
                float3 _782;
                if (param.z == 0u)
                {
                    _782 = float3(1.0, _395.y, -_395.x);
                }
                else
                {
                    float3 _783;
                    if (param.z == 1u)
                    {
                        _783 = float3(-1.0, _395.y, _395.x);
                    }
                    else
                    {
                        float3 _784;
                        if (param.z == 2u)
                        {
                            _784 = float3(_395.x, 1.0, -_395.y);
                        }
                        else
                        {
                            float3 _785;
                            if (param.z == 3u)
                            {
                                _785 = float3(_395.x, -1.0, _395.y);
                            }
                            else
                            {
                                float3 _786;
                                if (param.z == 4u)
                                {
                                    _786 = float3(_395.x, _395.y, 1.0);
                                }
                                else
                                {
                                    _786 = float3(-_395.x, _395.y, -1.0);
                                }
                                _785 = _786;
                            }
                            _784 = _785;
                        }
                        _783 = _784;
                    }
                    _782 = _783;
                }
                int2 _465 = int2(_387);
                float3 _563 = fast::normalize(_782);
                float2 _585 = fma(float2(fma(precise::atan2(_563.x, -_563.z), 0.15915493667125701904296875, 0.5), acos(fast::clamp(_563.y, -1.0, 1.0)) * 0.3183098733425140380859375), float2(_465), float2(-0.5));
                float2 _587 = floor(_585);
                float2 _565 = _585 - _587;
                int2 _592 = int2(_587);
                int2 _568 = _592;
                int2 _569 = _465;
                _568.x = ((_568.x % _569.x) + _569.x) % _569.x;
                _568.y = clamp(_568.y, 0, _569.y - 1);
                int2 _570 = _592 + int2(1, 0);
                int2 _571 = _465;
                _570.x = ((_570.x % _571.x) + _571.x) % _571.x;
                _570.y = clamp(_570.y, 0, _571.y - 1);
                int2 _573 = _592 + int2(0, 1);
                int2 _574 = _465;
                _573.x = ((_573.x % _574.x) + _574.x) % _574.x;
                _573.y = clamp(_573.y, 0, _574.y - 1);
                int2 _575 = _592 + int2(1);
                int2 _576 = _465;
                _575.x = ((_575.x % _576.x) + _576.x) % _576.x;
                _575.y = clamp(_575.y, 0, _576.y - 1);
                _469 = _788 + mix(mix(Equirect.read(uint2(int3(_568, 0).xy), 0).xyz, Equirect.read(uint2(int3(_570, 0).xy), 0).xyz, float3(_565.x)), mix(Equirect.read(uint2(int3(_573, 0).xy), 0).xyz, Equirect.read(uint2(int3(_575, 0).xy), 0).xyz, float3(_565.x)), float3(_565.y));
            }
        }
        Cube.write(float4(_779 / float3(float(_298.Supersample * _298.Supersample)), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

