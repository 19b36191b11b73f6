#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct SkyCubeParameter
{
    uint Supersample;
};

kernel void main0(constant SkyCubeParameter& _282 [[buffer(0)]], texture2d_array<float, access::write> Cube [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _370 = uint3(0u);
        uint3 _371 = uint3(Cube.get_width(), Cube.get_height(), Cube.get_array_size());
        _370.x = _371.x;
        _370.y = _371.y;
        _370.z = _371.z;
        if (any(gl_GlobalInvocationID >= _370))
        {
            break;
        }
        float3 _626;
        _626 = float3(0.0);
        float3 _635;
        for (uint _625 = 0u; _625 < _282.Supersample; _626 = _635, _625++)
        {
            _635 = _626;
            float3 _440;
            for (uint _627 = 0u; _627 < _282.Supersample; _635 = _440, _627++)
            {
                float2 _377 = (((float2(gl_GlobalInvocationID.xy) + ((float2(float(_627), float(_625)) + float2(0.5)) / float2(float(_282.Supersample)))) / float2(float(_370.x))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _629;
                if (param.z == 0u)
                {
                    _629 = float3(1.0, _377.y, -_377.x);
                }
                else
                {
                    float3 _630;
                    if (param.z == 1u)
                    {
                        _630 = float3(-1.0, _377.y, _377.x);
                    }
                    else
                    {
                        float3 _631;
                        if (param.z == 2u)
                        {
                            _631 = float3(_377.x, 1.0, -_377.y);
                        }
                        else
                        {
                            float3 _632;
                            if (param.z == 3u)
                            {
                                _632 = float3(_377.x, -1.0, _377.y);
                            }
                            else
                            {
                                float3 _633;
                                if (param.z == 4u)
                                {
                                    _633 = float3(_377.x, _377.y, 1.0);
                                }
                                else
                                {
                                    _633 = float3(-_377.x, _377.y, -1.0);
                                }
                                _632 = _633;
                            }
                            _631 = _632;
                        }
                        _630 = _631;
                    }
                    _629 = _630;
                }
                float3 _532 = fast::normalize(_629);
                float3 _378 = _532;
                float3 _533 = _532;
                float3 _534 = _532;
                float _611 = precise::atan2(length(cross(_532, float3(0.300285398960113525390625, 0.4504280984401702880859375, 0.840799152851104736328125))), dot(_532, float3(0.300285398960113525390625, 0.4504280984401702880859375, 0.840799152851104736328125)));
                _440 = _635 + (select(mix(select(float3(0.1599999964237213134765625, 0.14000000059604644775390625, 0.119999997317790985107421875), float3(0.4199999868869781494140625, 0.36000001430511474609375, 0.2800000011920928955078125), bool3(((int(floor(precise::atan2(_534.x, -_534.z) * 3.8197185993194580078125)) + int(floor(asin(fast::clamp(_534.y, -1.0, 1.0)) * 7.639437198638916015625))) & 1) != 0)), float3(0.89999997615814208984375, 0.920000016689300537109375, 0.949999988079071044921875), float3(exp(_534.y * 40.0))), mix(float3(1.0499999523162841796875, 1.10000002384185791015625, 1.2000000476837158203125), float3(0.180000007152557373046875, 0.36000001430511474609375, 0.949999988079071044921875), float3(pow(fast::clamp(_533.y, 0.0, 1.0), 0.4000000059604644775390625))), bool3(_378.y >= 0.0)) + (float3(1.0, 0.920000016689300537109375, 0.800000011920928955078125) * fma(4000.0, fast::clamp((0.0453785620629787445068359375 - _611) * 286.478912353515625, 0.0, 1.0), 40.0 * exp(_611 * (-25.0)))));
            }
        }
        Cube.write(float4(_626 / float3(float(_282.Supersample * _282.Supersample)), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

