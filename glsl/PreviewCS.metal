#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PreviewParameter
{
    uint Columns;
    uint Rows;
    uint CellSize;
    uint SpecularMips;
    uint StripPanelWidth;
    float Exposure;
};

kernel void main0(constant PreviewParameter& _175 [[buffer(0)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float, access::write> Preview [[texture(3)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint2 _497 = uint2(0u);
        uint2 _498 = uint2(Preview.get_width(), Preview.get_height());
        _497.x = _498.x;
        _497.y = _498.y;
        if (any(gl_GlobalInvocationID.xy >= _497))
        {
            break;
        }
        uint _526 = _175.Rows * _175.CellSize;
        float3 _868;
        if (param.x >= (_175.Columns * _175.CellSize))
        {
            _868 = float3(0.0199999995529651641845703125);
        }
        else
        {
            float3 _869;
            if (param.y < _526)
            {
                float3 _867;
                do
                {
                    uint2 _569 = gl_GlobalInvocationID.xy / uint2(_175.CellSize);
                    float2 _570 = (((float2(gl_GlobalInvocationID.xy % uint2(_175.CellSize)) + float2(0.5)) / float2(float(_175.CellSize))) * 2.0) - float2(1.0);
                    _570.y = -_570.y;
                    float _624 = dot(_570, _570);
                    if ((_624 * 1.2345678806304931640625) >= 1.0)
                    {
                        _867 = float3(0.0199999995529651641845703125);
                        break;
                    }
                    float _680 = (_175.Columns > 1u) ? (float(_569.x) / float(_175.Columns - 1u)) : 0.0;
                    float _691 = (_175.Rows > 1u) ? (float(_569.y) / float(_175.Rows - 1u)) : 0.0;
                    float _645 = sqrt(fma(-_624, 1.2345678806304931640625, 1.0));
                    float3 _648 = float3(_570 * float2(1.111111164093017578125), _645);
                    float2 _695 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_645, 0.0, 1.0), _680), level(0.0)).xy);
                    _867 = fma(Specular.sample(LinearClamp, reflect(float3(-0.0, -0.0, -1.0), _648), level(_680 * float(_175.SpecularMips - 1u))).xyz, (mix(float3(0.039999999105930328369140625), float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), float3(_691)) * _695.x) + float3(_695.y), (IrradianceMap.sample(LinearClamp, _648, level(0.0)).xyz * float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125)) * (1.0 - _691));
                    break;
                } while(false);
                _869 = _867;
            }
            else
            {
                uint2 _502 = uint2(param.x, param.y - _526);
                float3 _866;
                do
                {
                    uint _762 = _502.x / _175.StripPanelWidth;
                    if (_762 >= _175.SpecularMips)
                    {
                        _866 = float3(0.0199999995529651641845703125);
                        break;
                    }
                    float2 _754 = (float2(float(_502.x % _175.StripPanelWidth), float(_502.y)) + float2(0.5)) / float2(float(_175.StripPanelWidth), float(_175.StripPanelWidth / 2u));
                    float _809 = (_754.x - 0.5) * 6.283185482025146484375;
                    float _812 = _754.y * 3.1415927410125732421875;
                    _866 = Specular.sample(LinearClamp, float3(sin(_812) * sin(_809), cos(_812), (-sin(_812)) * cos(_809)), level(float(_762))).xyz;
                    break;
                } while(false);
                _869 = _866;
            }
            _868 = _869;
        }
        float3 _835 = _868 * _175.Exposure;
        float3 _853 = fast::clamp((_835 * ((_835 * 2.5099999904632568359375) + float3(0.02999999932944774627685546875))) / fma(_835, (_835 * 2.4300000667572021484375) + float3(0.589999973773956298828125), float3(0.14000000059604644775390625)), float3(0.0), float3(1.0));
        Preview.write(float4(mix((pow(_853, float3(0.4166666567325592041015625)) * 1.05499994754791259765625) - float3(0.054999999701976776123046875), _853 * 12.9200000762939453125, step(_853, float3(0.003130800090730190277099609375))), 1.0), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

