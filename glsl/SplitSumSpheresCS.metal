#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct SplitSumParameter
{
    uint Columns;
    uint MetalRows;
    uint CellSize;
    uint SpecularMips;
};

kernel void main0(constant SplitSumParameter& _337 [[buffer(0)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float, access::write> SplitSum [[texture(3)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    do
    {
        uint2 _495 = uint2(0u);
        uint2 _496 = uint2(SplitSum.get_width(), SplitSum.get_height());
        _495.x = _496.x;
        _495.y = _496.y;
        if (any(gl_GlobalInvocationID.xy >= _495))
        {
            break;
        }
        float2 _612 = (((float2(gl_GlobalInvocationID.xy % uint2(_337.CellSize)) + float2(0.5)) / float2(float(_337.CellSize))) * 2.0) - float2(1.0);
        _612.y = -_612.y;
        float _644 = dot(_612, _612);
        bool _647 = (_644 * 1.2345678806304931640625) < 1.0;
        float _655 = sqrt(fast::max(fma(-_644, 1.2345678806304931640625, 1.0), 0.0));
        float3 _658 = float3(_612 * float2(1.111111164093017578125), _655);
        uint2 _615 = gl_GlobalInvocationID.xy / uint2(_337.CellSize);
        float _678 = fast::max((_337.Columns > 1u) ? (float(_615.x) / float(_337.Columns - 1u)) : 0.0, 0.0500000007450580596923828125);
        bool _683 = _615.y >= _337.MetalRows;
        float3 _686 = select(float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), float3(1.0), bool3(_683));
        float _693 = _683 ? 0.0 : ((_337.MetalRows > 1u) ? (float(_615.y) / float(_337.MetalRows - 1u)) : 0.0);
        float3 _928;
        if (_647 && (float(_683) > 0.0))
        {
            float3 _927;
            do
            {
                float3 _742 = refract(float3(-0.0, -0.0, -1.0), _658, 0.666666686534881591796875);
                float3 _751 = fast::normalize(_658 - (_742 * (2.0 * dot(_658, _742))));
                float3 _755 = refract(_742, -_751, 1.5);
                if (dot(_755, _755) == 0.0)
                {
                    _927 = float3(0.0);
                    break;
                }
                _927 = Specular.sample(LinearClamp, _755, level(_678 * float(_337.SpecularMips - 1u))).xyz * ((1.0 - fma(0.959999978542327880859375, pow(1.0 - fast::clamp(_655, 0.0, 1.0), 5.0), 0.0400000028312206268310546875)) * (1.0 - fma(0.959999978542327880859375, pow(1.0 - fast::clamp(dot(_751, _755), 0.0, 1.0), 5.0), 0.0400000028312206268310546875)));
                break;
            } while(false);
            _928 = _927;
        }
        else
        {
            float3 _929;
            if (_647)
            {
                float2 _816 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_655, 0.0, 1.0), _678), level(0.0)).xy);
                _929 = fma(Specular.sample(LinearClamp, reflect(float3(-0.0, -0.0, -1.0), _658), level(_678 * float(_337.SpecularMips - 1u))).xyz, (mix(float3(0.039999999105930328369140625), _686, float3(_693)) * _816.x) + float3(_816.y), (IrradianceMap.sample(LinearClamp, _658, level(0.0)).xyz * _686) * (1.0 - _693));
            }
            else
            {
                _929 = float3(0.0);
            }
            _928 = _929;
        }
        SplitSum.write(float4(_928, float(_647)), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

