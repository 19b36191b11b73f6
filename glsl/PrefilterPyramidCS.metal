#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterPyramidParameter
{
    float4 ReadLods;
    float4 ReadWeights;
};

kernel void main0(constant PrefilterPyramidParameter& _154 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _246 = uint3(0u);
        uint3 _247 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _246.x = _247.x;
        _246.y = _247.y;
        _246.z = _247.z;
        if (any(gl_GlobalInvocationID >= _246))
        {
            break;
        }
        float2 _250 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_246.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _413;
        if (param.z == 0u)
        {
            _413 = float3(1.0, _250.y, -_250.x);
        }
        else
        {
            float3 _414;
            if (param.z == 1u)
            {
                _414 = float3(-1.0, _250.y, _250.x);
            }
            else
            {
                float3 _415;
                if (param.z == 2u)
                {
                    _415 = float3(_250.x, 1.0, -_250.y);
                }
                else
                {
                    float3 _416;
                    if (param.z == 3u)
                    {
                        _416 = float3(_250.x, -1.0, _250.y);
                    }
                    else
                    {
                        float3 _417;
                        if (param.z == 4u)
                        {
                            _417 = float3(_250.x, _250.y, 1.0);
                        }
                        else
                        {
                            _417 = float3(-_250.x, _250.y, -1.0);
                        }
                        _416 = _417;
                    }
                    _415 = _416;
                }
                _414 = _415;
            }
            _413 = _414;
        }
        float3 _360 = fast::normalize(_413);
        float3 _361 = abs(_360);
        float _377 = fast::max(_361.x, fast::max(_361.y, _361.z));
        float _383 = log2((_377 * _377) * _377);
        Prefiltered.write(float4((EnvMap.sample(EnvMapSampler, _360, level(fast::max(fma(-0.5, _383, _154.ReadLods.x), 0.0))).xyz * _154.ReadWeights.x) + (EnvMap.sample(EnvMapSampler, _360, level(fast::max(fma(-0.5, _383, _154.ReadLods.y), 0.0))).xyz * _154.ReadWeights.y), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

