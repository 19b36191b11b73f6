#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct SkyCubeParameter
{
    uint Supersample;
};

kernel void main0(constant SkyCubeParameter& _293 [[buffer(0)]], texture2d_array<float, access::write> Cube [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _381 = uint3(0u);
        uint3 _382 = uint3(Cube.get_width(), Cube.get_height(), Cube.get_array_size());
        _381.x = _382.x;
        _381.y = _382.y;
        _381.z = _382.z;
        if (any(gl_GlobalInvocationID >= _381))
        {
            break;
        }
        float3 _644;
        _644 = float3(0.0);
        float3 _653;
        for (uint _643 = 0u; _643 < _293.Supersample; _644 = _653, _643++)
        {
            _653 = _644;
            float3 _451;
            for (uint _645 = 0u; _645 < _293.Supersample; _653 = _451, _645++)
            {
                float2 _478 = (((float2(gl_GlobalInvocationID.xy) + ((float2(float(_645), float(_643)) + float2(0.5)) / float2(float(_293.Supersample)))) / float2(float(_381.x))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _647;
                if (param.z == 0u)
                {
                    _647 = float3(1.0, _478.y, -_478.x);
                }
                else
                {
                    float3 _648;
                    if (param.z == 1u)
                    {
                        _648 = float3(-1.0, _478.y, _478.x);
                    }
                    else
                    {
                        float3 _649;
                        if (param.z == 2u)
                        {
                            _649 = float3(_478.x, 1.0, -_478.y);
                        }
                        else
                        {
                            float3 _650;
                            if (param.z == 3u)
                            {
                                _650 = float3(_478.x, -1.0, _478.y);
                            }
                            else
                            {
                                float3 _651;
                                if (param.z == 4u)
                                {
                                    _651 = float3(_478.x, _478.y, 1.0);
                                }
                                else
                                {
                                    _651 = float3(-_478.x, _478.y, -1.0);
                                }
                                _650 = _651;
                            }
                            _649 = _650;
                        }
                        _648 = _649;
                    }
                    _647 = _648;
                }
                float3 _484 = fast::normalize(_647);
                float3 _389 = _484;
                float3 _551 = _484;
                float3 _552 = _484;
                float _629 = precise::atan2(length(cross(_484, float3(0.300285398960113525390625, 0.4504280984401702880859375, 0.840799152851104736328125))), dot(_484, float3(0.300285398960113525390625, 0.4504280984401702880859375, 0.840799152851104736328125)));
                _451 = _653 + (select(mix(select(float3(0.1599999964237213134765625, 0.14000000059604644775390625, 0.119999997317790985107421875), float3(0.4199999868869781494140625, 0.36000001430511474609375, 0.2800000011920928955078125), bool3(((int(floor(precise::atan2(_552.x, -_552.z) * 3.8197185993194580078125)) + int(floor(asin(fast::clamp(_552.y, -1.0, 1.0)) * 7.639437198638916015625))) & 1) != 0)), float3(0.89999997615814208984375, 0.920000016689300537109375, 0.949999988079071044921875), float3(exp(_552.y * 40.0))), mix(float3(1.0499999523162841796875, 1.10000002384185791015625, 1.2000000476837158203125), float3(0.180000007152557373046875, 0.36000001430511474609375, 0.949999988079071044921875), float3(pow(fast::clamp(_551.y, 0.0, 1.0), 0.4000000059604644775390625))), bool3(_389.y >= 0.0)) + (float3(1.0, 0.920000016689300537109375, 0.800000011920928955078125) * fma(4000.0, fast::clamp((0.0453785620629787445068359375 - _629) * 286.478912353515625, 0.0, 1.0), 40.0 * exp(_629 * (-25.0)))));
            }
        }
        Cube.write(float4(_644 / float3(float(_293.Supersample * _293.Supersample)), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

