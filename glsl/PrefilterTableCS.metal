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

kernel void main0(constant PrefilterTableParameter& _152 [[buffer(0)]], const device SampleTable& SampleTable_1 [[buffer(1)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _307 = uint3(0u);
        uint3 _308 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _307.x = _308.x;
        _307.y = _308.y;
        _307.z = _308.z;
        if (any(gl_GlobalInvocationID >= _307))
        {
            break;
        }
        float2 _356 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_307.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _524;
        if (param.z == 0u)
        {
            _524 = float3(1.0, _356.y, -_356.x);
        }
        else
        {
            float3 _525;
            if (param.z == 1u)
            {
                _525 = float3(-1.0, _356.y, _356.x);
            }
            else
            {
                float3 _526;
                if (param.z == 2u)
                {
                    _526 = float3(_356.x, 1.0, -_356.y);
                }
                else
                {
                    float3 _527;
                    if (param.z == 3u)
                    {
                        _527 = float3(_356.x, -1.0, _356.y);
                    }
                    else
                    {
                        float3 _528;
                        if (param.z == 4u)
                        {
                            _528 = float3(_356.x, _356.y, 1.0);
                        }
                        else
                        {
                            _528 = float3(-_356.x, _356.y, -1.0);
                        }
                        _527 = _528;
                    }
                    _526 = _527;
                }
                _525 = _526;
            }
            _524 = _525;
        }
        float3 _362 = fast::normalize(_524);
        float3 _313 = _362;
        float3 _450 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_313.y) < 0.999000012874603271484375)), _362));
        float3 _454 = fast::normalize(cross(_362, _450));
        float3 _530;
        float _531;
        _531 = 0.0;
        _530 = float3(0.0);
        float3 _511;
        float _515;
        for (uint _529 = 0u; _529 < _152.SampleCount; _531 = _515, _530 = _511, _529++)
        {
            float4 _434 = SampleTable_1._data[_529];
            float3 _478 = ((_450 * _434.x) + (_454 * _434.y)) + (_362 * _434.z);
            float3 _436 = abs(_478);
            float _488 = fast::max(_436.x, fast::max(_436.y, _436.z));
            _511 = _530 + (EnvMap.sample(EnvMapSampler, _478, level(fast::max(fma(-0.5, log2((_488 * _488) * _488), _434.w), 0.0))).xyz * _434.z);
            _515 = _531 + _434.z;
        }
        Prefiltered.write(float4(_530 / float3(_531), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

