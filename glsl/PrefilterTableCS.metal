#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterTableParameter
{
    uint SampleCount;
};

struct SampleTable
{
    float4 _data[1];
};

kernel void main0(constant PrefilterTableParameter& _141 [[buffer(0)]], const device SampleTable& SampleTable_1 [[buffer(1)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _296 = uint3(0u);
        uint3 _297 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _296.x = _297.x;
        _296.y = _297.y;
        _296.z = _297.z;
        if (any(gl_GlobalInvocationID >= _296))
        {
            break;
        }
        float2 _300 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_296.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _506;
        if (param.z == 0u)
        {
            _506 = float3(1.0, _300.y, -_300.x);
        }
        else
        {
            float3 _507;
            if (param.z == 1u)
            {
                _507 = float3(-1.0, _300.y, _300.x);
            }
            else
            {
                float3 _508;
                if (param.z == 2u)
                {
                    _508 = float3(_300.x, 1.0, -_300.y);
                }
                else
                {
                    float3 _509;
                    if (param.z == 3u)
                    {
                        _509 = float3(_300.x, -1.0, _300.y);
                    }
                    else
                    {
                        float3 _510;
                        if (param.z == 4u)
                        {
                            _510 = float3(_300.x, _300.y, 1.0);
                        }
                        else
                        {
                            _510 = float3(-_300.x, _300.y, -1.0);
                        }
                        _509 = _510;
                    }
                    _508 = _509;
                }
                _507 = _508;
            }
            _506 = _507;
        }
        float3 _410 = fast::normalize(_506);
        float3 _302 = _410;
        float3 _432 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_302.y) < 0.999000012874603271484375)), _410));
        float3 _436 = fast::normalize(cross(_410, _432));
        float3 _512;
        float _513;
        _513 = 0.0;
        _512 = float3(0.0);
        float3 _493;
        float _497;
        for (uint _511 = 0u; _511 < _141.SampleCount; _513 = _497, _512 = _493, _511++)
        {
            float4 _416 = SampleTable_1._data[_511];
            float3 _460 = ((_432 * _416.x) + (_436 * _416.y)) + (_410 * _416.z);
            float3 _418 = abs(_460);
            float _470 = fast::max(_418.x, fast::max(_418.y, _418.z));
            _493 = _512 + (EnvMap.sample(EnvMapSampler, _460, level(fast::max(fma(-0.5, log2((_470 * _470) * _470), _416.w), 0.0))).xyz * _416.z);
            _497 = _513 + _416.z;
        }
        Prefiltered.write(float4(_512 / float3(_513), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

