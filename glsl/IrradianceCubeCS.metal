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

kernel void main0(constant IrradianceParameter& _144 [[buffer(0)]], const device Moments& Moments_1 [[buffer(1)]], texture2d_array<float, access::write> Irradiance [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _239 = uint3(0u);
        uint3 _240 = uint3(Irradiance.get_width(), Irradiance.get_height(), Irradiance.get_array_size());
        _239.x = _240.x;
        _239.y = _240.y;
        _239.z = _240.z;
        if (any(gl_GlobalInvocationID >= _239))
        {
            break;
        }
        uint _274 = (6u * _144.MomentSize) * _144.MomentSize;
        float2 _328 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_239.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _401;
        if (param.z == 0u)
        {
            _401 = float3(1.0, _328.y, -_328.x);
        }
        else
        {
            float3 _402;
            if (param.z == 1u)
            {
                _402 = float3(-1.0, _328.y, _328.x);
            }
            else
            {
                float3 _403;
                if (param.z == 2u)
                {
                    _403 = float3(_328.x, 1.0, -_328.y);
                }
                else
                {
                    float3 _404;
                    if (param.z == 3u)
                    {
                        _404 = float3(_328.x, -1.0, _328.y);
                    }
                    else
                    {
                        float3 _405;
                        if (param.z == 4u)
                        {
                            _405 = float3(_328.x, _328.y, 1.0);
                        }
                        else
                        {
                            _405 = float3(-_328.x, _328.y, -1.0);
                        }
                        _404 = _405;
                    }
                    _403 = _404;
                }
                _402 = _403;
            }
            _401 = _402;
        }
        float3 _334 = fast::normalize(_401);
        float3 _407;
        _407 = float3(0.0);
        float3 _311;
        for (uint _406 = 0u; _406 < _274; _407 = _311, _406++)
        {
            _311 = _407 + (Moments_1._data[2u * _406].xyz * fast::max(dot(_334, Moments_1._data[(2u * _406) + 1u].xyz), 0.0));
        }
        Irradiance.write(float4(_407 * float3(0.3183098733425140380859375), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

