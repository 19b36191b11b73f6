#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterRingParameter
{
    float4 Ring;
};

kernel void main0(constant PrefilterRingParameter& _144 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _298 = uint3(0u);
        uint3 _299 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _298.x = _299.x;
        _298.y = _299.y;
        _298.z = _299.z;
        if (any(gl_GlobalInvocationID >= _298))
        {
            break;
        }
        float2 _347 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_298.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _508;
        if (param.z == 0u)
        {
            _508 = float3(1.0, _347.y, -_347.x);
        }
        else
        {
            float3 _509;
            if (param.z == 1u)
            {
                _509 = float3(-1.0, _347.y, _347.x);
            }
            else
            {
                float3 _510;
                if (param.z == 2u)
                {
                    _510 = float3(_347.x, 1.0, -_347.y);
                }
                else
                {
                    float3 _511;
                    if (param.z == 3u)
                    {
                        _511 = float3(_347.x, -1.0, _347.y);
                    }
                    else
                    {
                        float3 _512;
                        if (param.z == 4u)
                        {
                            _512 = float3(_347.x, _347.y, 1.0);
                        }
                        else
                        {
                            _512 = float3(-_347.x, _347.y, -1.0);
                        }
                        _511 = _512;
                    }
                    _510 = _511;
                }
                _509 = _510;
            }
            _508 = _509;
        }
        float3 _353 = fast::normalize(_508);
        float3 _304 = _353;
        float3 _438 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_304.y) < 0.999000012874603271484375)), _353));
        float3 _442 = fast::normalize(cross(_353, _438));
        float _450 = sqrt(fast::clamp(fma(-_144.Ring.z, _144.Ring.z, 1.0), 0.0, 1.0));
        float3 _660 = ((((EnvMap.sample(EnvMapSampler, ((_353 * _144.Ring.z) + ((_438 * 1.0) * _450)), level(_144.Ring.y)).xyz + EnvMap.sample(EnvMapSampler, ((_353 * _144.Ring.z) + (((_438 * 0.707106769084930419921875) + (_442 * 0.707106769084930419921875)) * _450)), level(_144.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_353 * _144.Ring.z) + (((_438 * (-4.3711388286737928865477442741394e-08)) + (_442 * 1.0)) * _450)), level(_144.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_353 * _144.Ring.z) + (((_438 * (-0.707106769084930419921875)) + (_442 * 0.707106769084930419921875)) * _450)), level(_144.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_353 * _144.Ring.z) + (((_438 * (-1.0)) + (_442 * (-8.7422776573475857730954885482788e-08))) * _450)), level(_144.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_353 * _144.Ring.z) + (((_438 * (-0.707106649875640869140625)) + (_442 * (-0.707106888294219970703125))) * _450)), level(_144.Ring.y)).xyz;
        float3 _507 = (EnvMap.sample(EnvMapSampler, _353, level(_144.Ring.x)).xyz * _144.Ring.w) + (((_660 + EnvMap.sample(EnvMapSampler, ((_353 * _144.Ring.z) + (((_438 * 1.1924880638503054797183722257614e-08) + (_442 * (-1.0))) * _450)), level(_144.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_353 * _144.Ring.z) + (((_438 * 0.707107007503509521484375) + (_442 * (-0.707106530666351318359375))) * _450)), level(_144.Ring.y)).xyz) * ((1.0 - _144.Ring.w) * 0.125));
        Prefiltered.write(float4(_507, 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

