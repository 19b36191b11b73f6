#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterPyramidParameter
{
    float4 ReadLods;
    float4 ReadWeights;
};

kernel void main0(constant PrefilterPyramidParameter& _165 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _257 = uint3(0u);
        uint3 _258 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _257.x = _258.x;
        _257.y = _258.y;
        _257.z = _258.z;
        if (any(gl_GlobalInvocationID >= _257))
        {
            break;
        }
        float2 _306 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_257.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _431;
        if (param.z == 0u)
        {
            _431 = float3(1.0, _306.y, -_306.x);
        }
        else
        {
            float3 _432;
            if (param.z == 1u)
            {
                _432 = float3(-1.0, _306.y, _306.x);
            }
            else
            {
                float3 _433;
                if (param.z == 2u)
                {
                    _433 = float3(_306.x, 1.0, -_306.y);
                }
                else
                {
                    float3 _434;
                    if (param.z == 3u)
                    {
                        _434 = float3(_306.x, -1.0, _306.y);
                    }
                    else
                    {
                        float3 _435;
                        if (param.z == 4u)
                        {
                            _435 = float3(_306.x, _306.y, 1.0);
                        }
                        else
                        {
                            _435 = float3(-_306.x, _306.y, -1.0);
                        }
                        _434 = _435;
                    }
                    _433 = _434;
                }
                _432 = _433;
            }
            _431 = _432;
        }
        float3 _312 = fast::normalize(_431);
        float3 _379 = abs(_312);
        float _395 = fast::max(_379.x, fast::max(_379.y, _379.z));
        float _401 = log2((_395 * _395) * _395);
        Prefiltered.write(float4((EnvMap.sample(EnvMapSampler, _312, level(fast::max(fma(-0.5, _401, _165.ReadLods.x), 0.0))).xyz * _165.ReadWeights.x) + (EnvMap.sample(EnvMapSampler, _312, level(fast::max(fma(-0.5, _401, _165.ReadLods.y), 0.0))).xyz * _165.ReadWeights.y), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

