#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterRingParameter
{
    float4 Ring;
};

kernel void main0(constant PrefilterRingParameter& _133 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _287 = uint3(0u);
        uint3 _288 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _287.x = _288.x;
        _287.y = _288.y;
        _287.z = _288.z;
        if (any(gl_GlobalInvocationID >= _287))
        {
            break;
        }
        float2 _291 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_287.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _490;
        if (param.z == 0u)
        {
            _490 = float3(1.0, _291.y, -_291.x);
        }
        else
        {
            float3 _491;
            if (param.z == 1u)
            {
                _491 = float3(-1.0, _291.y, _291.x);
            }
            else
            {
                float3 _492;
                if (param.z == 2u)
                {
                    _492 = float3(_291.x, 1.0, -_291.y);
                }
                else
                {
                    float3 _493;
                    if (param.z == 3u)
                    {
                        _493 = float3(_291.x, -1.0, _291.y);
                    }
                    else
                    {
                        float3 _494;
                        if (param.z == 4u)
                        {
                            _494 = float3(_291.x, _291.y, 1.0);
                        }
                        else
                        {
                            _494 = float3(-_291.x, _291.y, -1.0);
                        }
                        _493 = _494;
                    }
                    _492 = _493;
                }
                _491 = _492;
            }
            _490 = _491;
        }
        float3 _401 = fast::normalize(_490);
        float3 _293 = _401;
        float3 _420 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_293.y) < 0.999000012874603271484375)), _401));
        float3 _424 = fast::normalize(cross(_401, _420));
        float _432 = sqrt(fast::clamp(fma(-_133.Ring.z, _133.Ring.z, 1.0), 0.0, 1.0));
        float3 _642 = ((((EnvMap.sample(EnvMapSampler, ((_401 * _133.Ring.z) + ((_420 * 1.0) * _432)), level(_133.Ring.y)).xyz + EnvMap.sample(EnvMapSampler, ((_401 * _133.Ring.z) + (((_420 * 0.707106769084930419921875) + (_424 * 0.707106769084930419921875)) * _432)), level(_133.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_401 * _133.Ring.z) + (((_420 * (-4.3711388286737928865477442741394e-08)) + (_424 * 1.0)) * _432)), level(_133.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_401 * _133.Ring.z) + (((_420 * (-0.707106769084930419921875)) + (_424 * 0.707106769084930419921875)) * _432)), level(_133.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_401 * _133.Ring.z) + (((_420 * (-1.0)) + (_424 * (-8.7422776573475857730954885482788e-08))) * _432)), level(_133.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_401 * _133.Ring.z) + (((_420 * (-0.707106649875640869140625)) + (_424 * (-0.707106888294219970703125))) * _432)), level(_133.Ring.y)).xyz;
        float3 _489 = (EnvMap.sample(EnvMapSampler, _401, level(_133.Ring.x)).xyz * _133.Ring.w) + (((_642 + EnvMap.sample(EnvMapSampler, ((_401 * _133.Ring.z) + (((_420 * 1.1924880638503054797183722257614e-08) + (_424 * (-1.0))) * _432)), level(_133.Ring.y)).xyz) + EnvMap.sample(EnvMapSampler, ((_401 * _133.Ring.z) + (((_420 * 0.707107007503509521484375) + (_424 * (-0.707106530666351318359375))) * _432)), level(_133.Ring.y)).xyz) * ((1.0 - _133.Ring.w) * 0.125));
        Prefiltered.write(float4(_489, 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

