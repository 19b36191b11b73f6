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
        uint2 _500 = uint2(0u);
        uint2 _501 = uint2(Preview.get_width(), Preview.get_height());
        _500.x = _501.x;
        _500.y = _501.y;
        if (any(gl_GlobalInvocationID.xy >= _500))
        {
            break;
        }
        uint _529 = _175.Rows * _175.CellSize;
        float3 _871;
        if (param.x >= (_175.Columns * _175.CellSize))
        {
            _871 = float3(0.0199999995529651641845703125);
        }
        else
        {
            float3 _872;
            if (param.y < _529)
            {
                float3 _870;
                do
                {
                    uint2 _572 = gl_GlobalInvocationID.xy / uint2(_175.CellSize);
                    float2 _573 = (((float2(gl_GlobalInvocationID.xy % uint2(_175.CellSize)) + float2(0.5)) / float2(float(_175.CellSize))) * 2.0) - float2(1.0);
                    _573.y = -_573.y;
                    float _627 = dot(_573, _573);
                    if ((_627 * 1.2345678806304931640625) >= 1.0)
                    {
                        _870 = float3(0.0199999995529651641845703125);
                        break;
                    }
                    float _683 = (_175.Columns > 1u) ? (float(_572.x) / float(_175.Columns - 1u)) : 0.0;
                    float _694 = (_175.Rows > 1u) ? (float(_572.y) / float(_175.Rows - 1u)) : 0.0;
                    float _648 = sqrt(fma(-_627, 1.2345678806304931640625, 1.0));
                    float3 _651 = float3(_573 * float2(1.111111164093017578125), _648);
                    float2 _698 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_648, 0.0, 1.0), _683), level(0.0)).xy);
                    _870 = fma(Specular.sample(LinearClamp, reflect(float3(-0.0, -0.0, -1.0), _651), level(_683 * float(_175.SpecularMips - 1u))).xyz, (mix(float3(0.039999999105930328369140625), float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), float3(_694)) * _698.x) + float3(_698.y), (IrradianceMap.sample(LinearClamp, _651, level(0.0)).xyz * float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125)) * (1.0 - _694));
                    break;
                } while(false);
                _872 = _870;
            }
            else
            {
                uint2 _505 = uint2(param.x, param.y - _529);
                float3 _869;
                do
                {
                    uint _765 = _505.x / _175.StripPanelWidth;
                    if (_765 >= _175.SpecularMips)
                    {
                        _869 = float3(0.0199999995529651641845703125);
                        break;
                    }
                    float2 _757 = (float2(float(_505.x % _175.StripPanelWidth), float(_505.y)) + float2(0.5)) / float2(float(_175.StripPanelWidth), float(_175.StripPanelWidth / 2u));
                    float _812 = (_757.x - 0.5) * 6.283185482025146484375;
                    float _815 = _757.y * 3.1415927410125732421875;
                    _869 = Specular.sample(LinearClamp, float3(sin(_815) * sin(_812), cos(_815), (-sin(_815)) * cos(_812)), level(float(_765))).xyz;
                    break;
                } while(false);
                _872 = _869;
            }
            _871 = _872;
        }
        float3 _838 = _871 * _175.Exposure;
        float3 _856 = fast::clamp((_838 * ((_838 * 2.5099999904632568359375) + float3(0.02999999932944774627685546875))) / fma(_838, (_838 * 2.4300000667572021484375) + float3(0.589999973773956298828125), float3(0.14000000059604644775390625)), float3(0.0), float3(1.0));
        Preview.write(float4(mix((pow(_856, float3(0.4166666567325592041015625)) * 1.05499994754791259765625) - float3(0.054999999701976776123046875), _856 * 12.9200000762939453125, step(_856, float3(0.003130800090730190277099609375))), 1.0), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

