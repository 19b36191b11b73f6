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
    uint SpecularSize;
    uint LodMapping;
    float LodParameter;
    uint Direction;
    uint Lookup;
    uint LightCount;
    uint LightLevel;
};

struct Lights
{
    float4 _data[1];
};

kernel void main0(constant PreviewParameter& _1238 [[buffer(0)]], const device Lights& Lights_1 [[buffer(1)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float> LobeTable [[texture(3)]], texture2d<float, access::write> Preview [[texture(4)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint2 _1687 = uint2(0u);
        uint2 _1688 = uint2(Preview.get_width(), Preview.get_height());
        _1687.x = _1688.x;
        _1687.y = _1688.y;
        if (any(gl_GlobalInvocationID.xy >= _1687))
        {
            break;
        }
        uint _1716 = _1238.Rows * _1238.CellSize;
        float3 _3618;
        if (param.x >= (_1238.Columns * _1238.CellSize))
        {
            _3618 = float3(0.0199999995529651641845703125);
        }
        else
        {
            float3 _3619;
            if (param.y < _1716)
            {
                float3 _3617;
                do
                {
                    uint2 _1759 = gl_GlobalInvocationID.xy / uint2(_1238.CellSize);
                    float2 _1760 = (((float2(gl_GlobalInvocationID.xy % uint2(_1238.CellSize)) + float2(0.5)) / float2(float(_1238.CellSize))) * 2.0) - float2(1.0);
                    _1760.y = -_1760.y;
                    float _1832 = dot(_1760, _1760);
                    if ((_1832 * 1.2345678806304931640625) >= 1.0)
                    {
                        _3617 = float3(0.0199999995529651641845703125);
                        break;
                    }
                    float _1924 = (_1238.Columns > 1u) ? (float(_1759.x) / float(_1238.Columns - 1u)) : 0.0;
                    float _1935 = (_1238.Rows > 1u) ? (float(_1759.y) / float(_1238.Rows - 1u)) : 0.0;
                    float _1853 = sqrt(fma(-_1832, 1.2345678806304931640625, 1.0));
                    float3 _1856 = float3(_1760 * float2(1.111111164093017578125), _1853);
                    float3 _3598;
                    float _3599;
                    do
                    {
                        float3 _2104 = reflect(float3(-0.0, -0.0, -1.0), _1856);
                        float4 _2050 = LobeTable.sample(LinearClamp, float2(fast::clamp(_1853, 0.0, 1.0), _1924), level(0.0));
                        float3 _3587;
                        do
                        {
                            float _2226 = _1924 * _1924;
                            if (_1238.Direction == 1u)
                            {
                                float _2232 = fast::clamp(fma(-_1924, _1924, 1.0), 0.0, 1.0);
                                _3587 = fast::normalize(mix(_1856, _2104, float3(_2232 * fma(_1924, _1924, sqrt(_2232)))));
                                break;
                            }
                            if (_1238.Direction == 2u)
                            {
                                _3587 = fast::normalize(mix(_2104, _1856, float3(_2226 * _2226)));
                                break;
                            }
                            if (_1238.Direction == 3u)
                            {
                                float3 _3586;
                                do
                                {
                                    float _2281 = acos(fast::clamp(dot(_1856, _2104), -1.0, 1.0));
                                    if (_2281 < 9.9999997473787516355514526367188e-05)
                                    {
                                        _3586 = _2104;
                                        break;
                                    }
                                    _3586 = ((_1856 * sin((1.0 - _2050.x) * _2281)) + (_2104 * sin(_2050.x * _2281))) / float3(sin(_2281));
                                    break;
                                } while(false);
                                _3587 = _3586;
                                break;
                            }
                            _3587 = _2104;
                            break;
                        } while(false);
                        if (_1238.Lookup == 0u)
                        {
                            float _3596;
                            do
                            {
                                float _2346 = float(_1238.SpecularMips - 1u);
                                float _2348 = fast::clamp(_1924, 0.0, 1.0);
                                if (_1238.LodMapping == 1u)
                                {
                                    _3596 = (_2348 * (2.0 - _2348)) * _2346;
                                    break;
                                }
                                if (_1238.LodMapping == 2u)
                                {
                                    _3596 = pow(_2348, _1238.LodParameter) * _2346;
                                    break;
                                }
                                if (_1238.LodMapping == 3u)
                                {
                                    _3596 = (_2348 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2348 * _2348) * float(_1238.SpecularSize)), 0.0, _2346) : 0.0;
                                    break;
                                }
                                if (((_1238.LodMapping == 4u) && (_1238.SpecularMips >= 3u)) && (float(_1238.SpecularSize) > _1238.LodParameter))
                                {
                                    float _2407 = float(_1238.SpecularSize);
                                    _3596 = (_2348 > 0.0) ? fast::clamp(fma((_2346 - 1.0) / log2(_2407 / _1238.LodParameter), log2((_2348 * _2348) * _2407) - log2(_2407), _2346), 0.0, _2346) : 0.0;
                                    break;
                                }
                                _3596 = _2348 * _2346;
                                break;
                            } while(false);
                            _3599 = (_1238.LightCount > 0u) ? fast::clamp((_3596 - float(_1238.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                            _3598 = Specular.sample(LinearClamp, _3587, level(_3596)).xyz * 1.0;
                            break;
                        }
                        if (_1238.Lookup == 1u)
                        {
                            float _3594;
                            do
                            {
                                float _2491 = float(_1238.SpecularMips - 1u);
                                float _2493 = fast::clamp(_2050.y, 0.0, 1.0);
                                if (_1238.LodMapping == 1u)
                                {
                                    _3594 = (_2493 * (2.0 - _2493)) * _2491;
                                    break;
                                }
                                if (_1238.LodMapping == 2u)
                                {
                                    _3594 = pow(_2493, _1238.LodParameter) * _2491;
                                    break;
                                }
                                if (_1238.LodMapping == 3u)
                                {
                                    _3594 = (_2493 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2493 * _2493) * float(_1238.SpecularSize)), 0.0, _2491) : 0.0;
                                    break;
                                }
                                if (((_1238.LodMapping == 4u) && (_1238.SpecularMips >= 3u)) && (float(_1238.SpecularSize) > _1238.LodParameter))
                                {
                                    float _2552 = float(_1238.SpecularSize);
                                    _3594 = (_2493 > 0.0) ? fast::clamp(fma((_2491 - 1.0) / log2(_2552 / _1238.LodParameter), log2((_2493 * _2493) * _2552) - log2(_2552), _2491), 0.0, _2491) : 0.0;
                                    break;
                                }
                                _3594 = _2493 * _2491;
                                break;
                            } while(false);
                            _3599 = (_1238.LightCount > 0u) ? fast::clamp((_3594 - float(_1238.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                            _3598 = Specular.sample(LinearClamp, _3587, level(_3594)).xyz * 1.0;
                            break;
                        }
                        float3 _2147 = cross(_1856, float3(0.0, 0.0, 1.0));
                        float _2149 = length(_2147);
                        float3 _2159 = select(float3(0.0), cross(_2147 / float3(_2149), _3587), bool3(_2149 > 9.9999999747524270787835121154785e-07));
                        float _3590;
                        do
                        {
                            float _2636 = float(_1238.SpecularMips - 1u);
                            float _2638 = fast::clamp(_2050.z, 0.0, 1.0);
                            if (_1238.LodMapping == 1u)
                            {
                                _3590 = (_2638 * (2.0 - _2638)) * _2636;
                                break;
                            }
                            if (_1238.LodMapping == 2u)
                            {
                                _3590 = pow(_2638, _1238.LodParameter) * _2636;
                                break;
                            }
                            if (_1238.LodMapping == 3u)
                            {
                                _3590 = (_2638 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2638 * _2638) * float(_1238.SpecularSize)), 0.0, _2636) : 0.0;
                                break;
                            }
                            if (((_1238.LodMapping == 4u) && (_1238.SpecularMips >= 3u)) && (float(_1238.SpecularSize) > _1238.LodParameter))
                            {
                                float _2697 = float(_1238.SpecularSize);
                                _3590 = (_2638 > 0.0) ? fast::clamp(fma((_2636 - 1.0) / log2(_2697 / _1238.LodParameter), log2((_2638 * _2638) * _2697) - log2(_2697), _2636), 0.0, _2636) : 0.0;
                                break;
                            }
                            _3590 = _2638 * _2636;
                            break;
                        } while(false);
                        float _3592;
                        do
                        {
                            float _2781 = float(_1238.SpecularMips - 1u);
                            float _2783 = fast::clamp(_2050.z, 0.0, 1.0);
                            if (_1238.LodMapping == 1u)
                            {
                                _3592 = (_2783 * (2.0 - _2783)) * _2781;
                                break;
                            }
                            if (_1238.LodMapping == 2u)
                            {
                                _3592 = pow(_2783, _1238.LodParameter) * _2781;
                                break;
                            }
                            if (_1238.LodMapping == 3u)
                            {
                                _3592 = (_2783 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2783 * _2783) * float(_1238.SpecularSize)), 0.0, _2781) : 0.0;
                                break;
                            }
                            if (((_1238.LodMapping == 4u) && (_1238.SpecularMips >= 3u)) && (float(_1238.SpecularSize) > _1238.LodParameter))
                            {
                                float _2842 = float(_1238.SpecularSize);
                                _3592 = (_2783 > 0.0) ? fast::clamp(fma((_2781 - 1.0) / log2(_2842 / _1238.LodParameter), log2((_2783 * _2783) * _2842) - log2(_2842), _2781), 0.0, _2781) : 0.0;
                                break;
                            }
                            _3592 = _2783 * _2781;
                            break;
                        } while(false);
                        _3599 = fma(0.5, (_1238.LightCount > 0u) ? fast::clamp((_3590 - float(_1238.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1238.LightCount > 0u) ? fast::clamp((_3592 - float(_1238.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                        _3598 = (Specular.sample(LinearClamp, fast::normalize((_3587 * cos(_2050.w)) + (_2159 * sin(_2050.w))), level(_3590)).xyz * 0.5) + (Specular.sample(LinearClamp, fast::normalize((_3587 * cos(_2050.w)) - (_2159 * sin(_2050.w))), level(_3592)).xyz * 0.5);
                        break;
                    } while(false);
                    float2 _1994 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1853, 0.0, 1.0), _1924), level(0.0)).xy);
                    float3 _1871 = mix(float3(0.039999999105930328369140625), float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), float3(_1935));
                    float2 _2888 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1853, 0.0, 1.0), _1924), level(0.0)).xy);
                    float3 _2911 = (_1871 * _2888.x) + float3(_2888.y);
                    float3 _3601;
                    _3601 = fma(_3598, (mix(float3(0.039999999105930328369140625), float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), float3(_1935)) * _1994.x) + float3(_1994.y), (IrradianceMap.sample(LinearClamp, _1856, level(0.0)).xyz * float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125)) * (1.0 - _1935));
                    float3 _1906;
                    for (uint _3600 = 0u; _3600 < _1238.LightCount; _3601 = _1906, _3600++)
                    {
                        uint _1890 = 2u * _3600;
                        uint _1893 = (2u * _3600) + 1u;
                        float4 _1800 = Lights_1._data[_1890];
                        float4 _1801 = Lights_1._data[_1893];
                        float3 _2912 = Lights_1._data[_1890].xyz;
                        float3 _2952 = fast::normalize(cross(select(float3(1.0, 0.0, 0.0), float3(0.0, 0.0, 1.0), bool3(abs(_2912.z) < 0.999000012874603271484375)), Lights_1._data[_1890].xyz));
                        float3 _2955 = cross(Lights_1._data[_1890].xyz, _2952);
                        float _2958 = tan(_1800.w);
                        float3 _3603;
                        _3603 = float3(0.0);
                        float3 _3620;
                        for (uint _3602 = 0u; _3602 < 19u; _3603 = _3620, _3602++)
                        {
                            float2 _3610;
                            do
                            {
                                if (_3602 == 0u)
                                {
                                    _3610 = float2(0.0);
                                    break;
                                }
                                bool _3066 = _3602 <= 6u;
                                float _3083 = _3066 ? (float(_3602 - 1u) * 1.0471975803375244140625) : ((float(_3602 - 7u) + 0.5) * 0.52359879016876220703125);
                                _3610 = float2(cos(_3083), sin(_3083)) * (_3066 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                                break;
                            } while(false);
                            float2 _2919 = _3610 * _2958;
                            float3 _2979 = fast::normalize((Lights_1._data[_1890].xyz + (_2952 * _2919.x)) + (_2955 * _2919.y));
                            if (dot(_1856, _2979) > 0.0)
                            {
                                float3 _3611;
                                do
                                {
                                    float _3113 = dot(_1856, _2979);
                                    float _3117 = fast::clamp(_1853, 0.0, 1.0);
                                    if ((_3113 <= 0.0) || (_3117 <= 0.0))
                                    {
                                        _3611 = float3(0.0);
                                        break;
                                    }
                                    float3 _3128 = fast::normalize(_2979 + float3(0.0, 0.0, 1.0));
                                    float _3202 = _1924 * _1924;
                                    float _3223 = _1924 * _1924;
                                    float _3145 = fast::clamp(dot(_1856, _3128), 0.0, 1.0);
                                    float _3244 = _1924 * _1924;
                                    float _3256 = fma(_3145 * _3145, fma(_3244, _3244, -1.0), 1.0);
                                    _3611 = (_1871 + ((float3(1.0) - _1871) * pow(fast::clamp(1.0 - fast::clamp(_3128.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_3113 / fma(_3113, fma(-_3202, 0.5, 1.0), _3202 * 0.5)) * (_3117 / fma(_3117, fma(-_3223, 0.5, 1.0), _3223 * 0.5))) * ((_3244 * _3244) / ((3.1415927410125732421875 * _3256) * _3256))) / (4.0 * _3117));
                                    break;
                                } while(false);
                                _3620 = _3603 + _3611;
                            }
                            else
                            {
                                _3620 = _3603;
                            }
                        }
                        float _3007 = fast::clamp((((2.0 * _1924) * _1924) / fast::max(_1800.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                        float4 _2934 = Lights_1._data[_1890];
                        float _3284 = 0.5 * _2934.w;
                        float _3286 = 0.5 * acos(fast::clamp(dot(reflect(float3(-0.0, -0.0, -1.0), _1856), Lights_1._data[_1890].xyz), -1.0, 1.0));
                        float _3290 = fast::max(_1924 * _1924, 1.0000000116860974230803549289703e-07);
                        float _3304 = (_3284 * _3284) / (_3290 * _3290);
                        float _3311 = (_3286 * _3286) / (_3290 * _3290);
                        float _3315 = (_3304 + 1.0) - _3311;
                        float _3031 = sin(_1800.w);
                        float _3035 = dot(_1856, Lights_1._data[_1890].xyz);
                        float _3038 = _3031 * _3031;
                        float _3604;
                        do
                        {
                            if (((_3035 * _3035) > _3038) || (_3038 <= 0.0))
                            {
                                _3604 = (3.1415927410125732421875 * _3038) * fast::clamp(_3035, 0.0, 1.0);
                                break;
                            }
                            float _3360 = sqrt(fast::clamp(fma(-_3035, _3035, 1.0), 0.0, 1.0));
                            float _3364 = sqrt((1.0 / _3038) - 1.0);
                            float _3370 = (-_3364) * (_3035 / _3360);
                            float _3378 = _3360 * sqrt(fast::clamp(fma(-_3370, _3370, 1.0), 0.0, 1.0));
                            _3604 = fast::max(fma(fma(_3035, acos(fast::clamp(_3370, -1.0, 1.0)), -(_3364 * _3378)), _3038, atan(_3378 / _3364)), 0.0);
                            break;
                        } while(false);
                        _1906 = fma(((mix(select(float3(0.0), (_2911 * fast::clamp(0.5 + (((_3304 - 1.0) - _3311) / (2.0 * sqrt(fma(_3315, _3315, 4.0 * _3311)))), 0.0, 1.0)) / float3(_1801.w), bool3(_3007 < 1.0)), _3603 * 0.052631579339504241943359375, float3(_3007)) * _3599) * _1801.w) + ((float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125) * (1.0 - _1935)) * (_3604 * 0.3183098733425140380859375)), Lights_1._data[_1893].xyz, _3601);
                    }
                    _3617 = _3601;
                    break;
                } while(false);
                _3619 = _3617;
            }
            else
            {
                uint2 _1692 = uint2(param.x, param.y - _1716);
                float3 _3585;
                do
                {
                    uint _3410 = _1692.x / _1238.StripPanelWidth;
                    if (_3410 >= _1238.SpecularMips)
                    {
                        _3585 = float3(0.0199999995529651641845703125);
                        break;
                    }
                    float2 _3402 = (float2(float(_1692.x % _1238.StripPanelWidth), float(_1692.y)) + float2(0.5)) / float2(float(_1238.StripPanelWidth), float(_1238.StripPanelWidth / 2u));
                    float _3457 = (_3402.x - 0.5) * 6.283185482025146484375;
                    float _3460 = _3402.y * 3.1415927410125732421875;
                    _3585 = Specular.sample(LinearClamp, float3(sin(_3460) * sin(_3457), cos(_3460), (-sin(_3460)) * cos(_3457)), level(float(_3410))).xyz;
                    break;
                } while(false);
                _3619 = _3585;
            }
            _3618 = _3619;
        }
        float3 _3483 = _3618 * _1238.Exposure;
        float3 _3501 = fast::clamp((_3483 * ((_3483 * 2.5099999904632568359375) + float3(0.02999999932944774627685546875))) / fma(_3483, (_3483 * 2.4300000667572021484375) + float3(0.589999973773956298828125), float3(0.14000000059604644775390625)), float3(0.0), float3(1.0));
        Preview.write(float4(mix((pow(_3501, float3(0.4166666567325592041015625)) * 1.05499994754791259765625) - float3(0.054999999701976776123046875), _3501 * 12.9200000762939453125, step(_3501, float3(0.003130800090730190277099609375))), 1.0), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

