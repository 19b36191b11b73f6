#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct IrradianceParameter
{
    uint MomentSize;
};

struct Moments
{
    float4 _data[1];
};

kernel void main0(constant IrradianceParameter& _133 [[buffer(0)]], const device Moments& Moments_1 [[buffer(1)]], texture2d_array<float, access::write> Irradiance [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _228 = uint3(0u);
        uint3 _229 = uint3(Irradiance.get_width(), Irradiance.get_height(), Irradiance.get_array_size());
        _228.x = _229.x;
        _228.y = _229.y;
        _228.z = _229.z;
        if (any(gl_GlobalInvocationID >= _228))
        {
            break;
        }
        uint _263 = (6u * _133.MomentSize) * _133.MomentSize;
        float2 _233 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_228.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _383;
        if (param.z == 0u)
        {
            _383 = float3(1.0, _233.y, -_233.x);
        }
        else
        {
            float3 _384;
            if (param.z == 1u)
            {
                _384 = float3(-1.0, _233.y, _233.x);
            }
            else
            {
                float3 _385;
                if (param.z == 2u)
                {
                    _385 = float3(_233.x, 1.0, -_233.y);
                }
                else
                {
                    float3 _386;
                    if (param.z == 3u)
                    {
                        _386 = float3(_233.x, -1.0, _233.y);
                    }
                    else
                    {
                        float3 _387;
                        if (param.z == 4u)
                        {
                            _387 = float3(_233.x, _233.y, 1.0);
                        }
                        else
                        {
                            _387 = float3(-_233.x, _233.y, -1.0);
                        }
                        _386 = _387;
                    }
                    _385 = _386;
                }
                _384 = _385;
            }
            _383 = _384;
        }
        float3 _382 = fast::normalize(_383);
        float3 _389;
        _389 = float3(0.0);
        float3 _300;
        for (uint _388 = 0u; _388 < _263; _389 = _300, _388++)
        {
            _300 = _389 + (Moments_1._data[2u * _388].xyz * fast::max(dot(_382, Moments_1._data[(2u * _388) + 1u].xyz), 0.0));
        }
        Irradiance.write(float4(_389 * float3(0.3183098733425140380859375), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

