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

kernel void main0(constant PreviewParameter& _1166 [[buffer(0)]], const device Lights& Lights_1 [[buffer(1)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float> LobeTable [[texture(3)]], texture2d<float, access::write> Preview [[texture(4)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint2 _1608 = uint2(0u);
        uint2 _1609 = uint2(Preview.get_width(), Preview.get_height());
        _1608.x = _1609.x;
        _1608.y = _1609.y;
        if (any(gl_GlobalInvocationID.xy >= _1608))
        {
            break;
        }
        uint _1637 = _1166.Rows * _1166.CellSize;
        float3 _3465;
        if (param.x >= (_1166.Columns * _1166.CellSize))
        {
            _3465 = float3(0.0199999995529651641845703125);
        }
        else
        {
            float3 _3466;
            if (param.y < _1637)
            {
                float3 _3464;
                do
                {
                    uint2 _1680 = gl_GlobalInvocationID.xy / uint2(_1166.CellSize);
                    float2 _1681 = (((float2(gl_GlobalInvocationID.xy % uint2(_1166.CellSize)) + float2(0.5)) / float2(float(_1166.CellSize))) * 2.0) - float2(1.0);
                    _1681.y = -_1681.y;
                    float _1753 = dot(_1681, _1681);
                    if ((_1753 * 1.2345678806304931640625) >= 1.0)
                    {
                        _3464 = float3(0.0199999995529651641845703125);
                        break;
                    }
                    float _1845 = (_1166.Columns > 1u) ? (float(_1680.x) / float(_1166.Columns - 1u)) : 0.0;
                    float _1856 = (_1166.Rows > 1u) ? (float(_1680.y) / float(_1166.Rows - 1u)) : 0.0;
                    float _1774 = sqrt(fma(-_1753, 1.2345678806304931640625, 1.0));
                    float3 _1777 = float3(_1681 * float2(1.111111164093017578125), _1774);
                    float3 _3446;
                    float _3447;
                    do
                    {
                        float3 _2025 = reflect(float3(-0.0, -0.0, -1.0), _1777);
                        float4 _1971 = LobeTable.sample(LinearClamp, float2(fast::clamp(_1774, 0.0, 1.0), _1845), level(0.0));
                        float3 _3435;
                        do
                        {
                            float _2147 = _1845 * _1845;
                            if (_1166.Direction == 1u)
                            {
                                float _2153 = fast::clamp(fma(-_1845, _1845, 1.0), 0.0, 1.0);
                                _3435 = fast::normalize(mix(_1777, _2025, float3(_2153 * fma(_1845, _1845, sqrt(_2153)))));
                                break;
                            }
                            if (_1166.Direction == 2u)
                            {
                                _3435 = fast::normalize(mix(_2025, _1777, float3(_2147 * _2147)));
                                break;
                            }
                            if (_1166.Direction == 3u)
                            {
                                float3 _3434;
                                do
                                {
                                    float _2202 = acos(fast::clamp(dot(_1777, _2025), -1.0, 1.0));
                                    if (_2202 < 9.9999997473787516355514526367188e-05)
                                    {
                                        _3434 = _2025;
                                        break;
                                    }
                                    _3434 = ((_1777 * sin((1.0 - _1971.x) * _2202)) + (_2025 * sin(_1971.x * _2202))) / float3(sin(_2202));
                                    break;
                                } while(false);
                                _3435 = _3434;
                                break;
                            }
                            _3435 = _2025;
                            break;
                        } while(false);
                        if (_1166.Lookup == 0u)
                        {
                            float _3444;
                            do
                            {
                                float _2267 = float(_1166.SpecularMips - 1u);
                                float _2269 = fast::clamp(_1845, 0.0, 1.0);
                                if (_1166.LodMapping == 1u)
                                {
                                    _3444 = (_2269 * (2.0 - _2269)) * _2267;
                                    break;
                                }
                                if (_1166.LodMapping == 2u)
                                {
                                    _3444 = pow(_2269, _1166.LodParameter) * _2267;
                                    break;
                                }
                                if (_1166.LodMapping == 3u)
                                {
                                    _3444 = (_2269 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2269 * _2269) * float(_1166.SpecularSize)), 0.0, _2267) : 0.0;
                                    break;
                                }
                                if (((_1166.LodMapping == 4u) && (_1166.SpecularMips >= 3u)) && (float(_1166.SpecularSize) > _1166.LodParameter))
                                {
                                    float _2328 = float(_1166.SpecularSize);
                                    _3444 = (_2269 > 0.0) ? fast::clamp(fma((_2267 - 1.0) / log2(_2328 / _1166.LodParameter), log2((_2269 * _2269) * _2328) - log2(_2328), _2267), 0.0, _2267) : 0.0;
                                    break;
                                }
                                _3444 = _2269 * _2267;
                                break;
                            } while(false);
                            _3447 = (_1166.LightCount > 0u) ? fast::clamp((_3444 - float(_1166.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                            _3446 = Specular.sample(LinearClamp, _3435, level(_3444)).xyz * 1.0;
                            break;
                        }
                        if (_1166.Lookup == 1u)
                        {
                            float _3442;
                            do
                            {
                                float _2412 = float(_1166.SpecularMips - 1u);
                                float _2414 = fast::clamp(_1971.y, 0.0, 1.0);
                                if (_1166.LodMapping == 1u)
                                {
                                    _3442 = (_2414 * (2.0 - _2414)) * _2412;
                                    break;
                                }
                                if (_1166.LodMapping == 2u)
                                {
                                    _3442 = pow(_2414, _1166.LodParameter) * _2412;
                                    break;
                                }
                                if (_1166.LodMapping == 3u)
                                {
                                    _3442 = (_2414 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2414 * _2414) * float(_1166.SpecularSize)), 0.0, _2412) : 0.0;
                                    break;
                                }
                                if (((_1166.LodMapping == 4u) && (_1166.SpecularMips >= 3u)) && (float(_1166.SpecularSize) > _1166.LodParameter))
                                {
                                    float _2473 = float(_1166.SpecularSize);
                                    _3442 = (_2414 > 0.0) ? fast::clamp(fma((_2412 - 1.0) / log2(_2473 / _1166.LodParameter), log2((_2414 * _2414) * _2473) - log2(_2473), _2412), 0.0, _2412) : 0.0;
                                    break;
                                }
                                _3442 = _2414 * _2412;
                                break;
                            } while(false);
                            _3447 = (_1166.LightCount > 0u) ? fast::clamp((_3442 - float(_1166.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                            _3446 = Specular.sample(LinearClamp, _3435, level(_3442)).xyz * 1.0;
                            break;
                        }
                        float3 _2068 = cross(_1777, float3(0.0, 0.0, 1.0));
                        float _2070 = length(_2068);
                        float3 _2080 = select(float3(0.0), cross(_2068 / float3(_2070), _3435), bool3(_2070 > 9.9999999747524270787835121154785e-07));
                        float _3438;
                        do
                        {
                            float _2557 = float(_1166.SpecularMips - 1u);
                            float _2559 = fast::clamp(_1971.z, 0.0, 1.0);
                            if (_1166.LodMapping == 1u)
                            {
                                _3438 = (_2559 * (2.0 - _2559)) * _2557;
                                break;
                            }
                            if (_1166.LodMapping == 2u)
                            {
                                _3438 = pow(_2559, _1166.LodParameter) * _2557;
                                break;
                            }
                            if (_1166.LodMapping == 3u)
                            {
                                _3438 = (_2559 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2559 * _2559) * float(_1166.SpecularSize)), 0.0, _2557) : 0.0;
                                break;
                            }
                            if (((_1166.LodMapping == 4u) && (_1166.SpecularMips >= 3u)) && (float(_1166.SpecularSize) > _1166.LodParameter))
                            {
                                float _2618 = float(_1166.SpecularSize);
                                _3438 = (_2559 > 0.0) ? fast::clamp(fma((_2557 - 1.0) / log2(_2618 / _1166.LodParameter), log2((_2559 * _2559) * _2618) - log2(_2618), _2557), 0.0, _2557) : 0.0;
                                break;
                            }
                            _3438 = _2559 * _2557;
                            break;
                        } while(false);
                        float _3440;
                        do
                        {
                            float _2702 = float(_1166.SpecularMips - 1u);
                            float _2704 = fast::clamp(_1971.z, 0.0, 1.0);
                            if (_1166.LodMapping == 1u)
                            {
                                _3440 = (_2704 * (2.0 - _2704)) * _2702;
                                break;
                            }
                            if (_1166.LodMapping == 2u)
                            {
                                _3440 = pow(_2704, _1166.LodParameter) * _2702;
                                break;
                            }
                            if (_1166.LodMapping == 3u)
                            {
                                _3440 = (_2704 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2704 * _2704) * float(_1166.SpecularSize)), 0.0, _2702) : 0.0;
                                break;
                            }
                            if (((_1166.LodMapping == 4u) && (_1166.SpecularMips >= 3u)) && (float(_1166.SpecularSize) > _1166.LodParameter))
                            {
                                float _2763 = float(_1166.SpecularSize);
                                _3440 = (_2704 > 0.0) ? fast::clamp(fma((_2702 - 1.0) / log2(_2763 / _1166.LodParameter), log2((_2704 * _2704) * _2763) - log2(_2763), _2702), 0.0, _2702) : 0.0;
                                break;
                            }
                            _3440 = _2704 * _2702;
                            break;
                        } while(false);
                        _3447 = fma(0.5, (_1166.LightCount > 0u) ? fast::clamp((_3438 - float(_1166.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1166.LightCount > 0u) ? fast::clamp((_3440 - float(_1166.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                        _3446 = (Specular.sample(LinearClamp, fast::normalize((_3435 * cos(_1971.w)) + (_2080 * sin(_1971.w))), level(_3438)).xyz * 0.5) + (Specular.sample(LinearClamp, fast::normalize((_3435 * cos(_1971.w)) - (_2080 * sin(_1971.w))), level(_3440)).xyz * 0.5);
                        break;
                    } while(false);
                    float2 _1915 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1774, 0.0, 1.0), _1845), level(0.0)).xy);
                    float3 _1792 = mix(float3(0.039999999105930328369140625), float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), float3(_1856));
                    float2 _2809 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1774, 0.0, 1.0), _1845), level(0.0)).xy);
                    float3 _2832 = (_1792 * _2809.x) + float3(_2809.y);
                    float3 _3449;
                    _3449 = fma(_3446, (mix(float3(0.039999999105930328369140625), float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), float3(_1856)) * _1915.x) + float3(_1915.y), (IrradianceMap.sample(LinearClamp, _1777, level(0.0)).xyz * float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125)) * (1.0 - _1856));
                    float3 _1827;
                    for (uint _3448 = 0u; _3448 < _1166.LightCount; _3449 = _1827, _3448++)
                    {
                        float3 _1809 = float3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125) * (1.0 - _1856);
                        uint _1811 = 2u * _3448;
                        uint _1814 = (2u * _3448) + 1u;
                        float4 _1721 = Lights_1._data[_1811];
                        float4 _1722 = Lights_1._data[_1814];
                        float3 _2833 = Lights_1._data[_1811].xyz;
                        float3 _2871 = fast::normalize(cross(select(float3(1.0, 0.0, 0.0), float3(0.0, 0.0, 1.0), bool3(abs(_2833.z) < 0.999000012874603271484375)), Lights_1._data[_1811].xyz));
                        float3 _2874 = cross(Lights_1._data[_1811].xyz, _2871);
                        float _2877 = tan(_1721.w);
                        float3 _3451;
                        float3 _3452;
                        _3452 = float3(0.0);
                        _3451 = float3(0.0);
                        float3 _3467;
                        float3 _3468;
                        for (uint _3450 = 0u; _3450 < 19u; _3452 = _3468, _3451 = _3467, _3450++)
                        {
                            float2 _3455;
                            do
                            {
                                if (_3450 == 0u)
                                {
                                    _3455 = float2(0.0);
                                    break;
                                }
                                bool _2981 = _3450 <= 6u;
                                float _2998 = _2981 ? (float(_3450 - 1u) * 1.0471975803375244140625) : ((float(_3450 - 7u) + 0.5) * 0.52359879016876220703125);
                                _3455 = float2(cos(_2998), sin(_2998)) * (_2981 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                                break;
                            } while(false);
                            float2 _2841 = _3455 * _2877;
                            float3 _2898 = fast::normalize((Lights_1._data[_1811].xyz + (_2871 * _2841.x)) + (_2874 * _2841.y));
                            float _2901 = dot(_1777, _2898);
                            if (_2901 <= 0.0)
                            {
                                _3468 = _3452;
                                _3467 = _3451;
                                continue;
                            }
                            float3 _3456;
                            do
                            {
                                float _3028 = dot(_1777, _2898);
                                float _3032 = fast::clamp(_1774, 0.0, 1.0);
                                if ((_3028 <= 0.0) || (_3032 <= 0.0))
                                {
                                    _3456 = float3(0.0);
                                    break;
                                }
                                float3 _3043 = fast::normalize(_2898 + float3(0.0, 0.0, 1.0));
                                float _3117 = _1845 * _1845;
                                float _3138 = _1845 * _1845;
                                float _3060 = fast::clamp(dot(_1777, _3043), 0.0, 1.0);
                                float _3159 = _1845 * _1845;
                                float _3171 = fma(_3060 * _3060, fma(_3159, _3159, -1.0), 1.0);
                                _3456 = (_1792 + ((float3(1.0) - _1792) * pow(fast::clamp(1.0 - fast::clamp(_3043.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_3028 / fma(_3028, fma(-_3117, 0.5, 1.0), _3117 * 0.5)) * (_3032 / fma(_3032, fma(-_3138, 0.5, 1.0), _3138 * 0.5))) * ((_3159 * _3159) / ((3.1415927410125732421875 * _3171) * _3171))) / (4.0 * _3032));
                                break;
                            } while(false);
                            _3468 = _3452 + (_1809 * (_2901 * 0.3183098733425140380859375));
                            _3467 = _3451 + _3456;
                        }
                        float _2933 = fast::clamp((((2.0 * _1845) * _1845) / fast::max(_1721.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                        float4 _2857 = Lights_1._data[_1811];
                        float _3199 = 0.5 * _2857.w;
                        float _3201 = 0.5 * acos(fast::clamp(dot(reflect(float3(-0.0, -0.0, -1.0), _1777), Lights_1._data[_1811].xyz), -1.0, 1.0));
                        float _3205 = fast::max(_1845 * _1845, 1.0000000116860974230803549289703e-07);
                        float _3219 = (_3199 * _3199) / (_3205 * _3205);
                        float _3226 = (_3201 * _3201) / (_3205 * _3205);
                        float _3230 = (_3219 + 1.0) - _3226;
                        _1827 = _3449 + ((((mix(select(float3(0.0), (_2832 * fast::clamp(0.5 + (((_3219 - 1.0) - _3226) / (2.0 * sqrt(fma(_3230, _3230, 4.0 * _3226)))), 0.0, 1.0)) / float3(_1722.w), bool3(_2933 < 1.0)), _3451 * 0.052631579339504241943359375, float3(_2933)) * _3447) + (_3452 * 0.052631579339504241943359375)) * Lights_1._data[_1814].xyz) * _1722.w);
                    }
                    _3464 = _3449;
                    break;
                } while(false);
                _3466 = _3464;
            }
            else
            {
                uint2 _1613 = uint2(param.x, param.y - _1637);
                float3 _3433;
                do
                {
                    uint _3258 = _1613.x / _1166.StripPanelWidth;
                    if (_3258 >= _1166.SpecularMips)
                    {
                        _3433 = float3(0.0199999995529651641845703125);
                        break;
                    }
                    float2 _3250 = (float2(float(_1613.x % _1166.StripPanelWidth), float(_1613.y)) + float2(0.5)) / float2(float(_1166.StripPanelWidth), float(_1166.StripPanelWidth / 2u));
                    float _3305 = (_3250.x - 0.5) * 6.283185482025146484375;
                    float _3308 = _3250.y * 3.1415927410125732421875;
                    _3433 = Specular.sample(LinearClamp, float3(sin(_3308) * sin(_3305), cos(_3308), (-sin(_3308)) * cos(_3305)), level(float(_3258))).xyz;
                    break;
                } while(false);
                _3466 = _3433;
            }
            _3465 = _3466;
        }
        float3 _3331 = _3465 * _1166.Exposure;
        float3 _3349 = fast::clamp((_3331 * ((_3331 * 2.5099999904632568359375) + float3(0.02999999932944774627685546875))) / fma(_3331, (_3331 * 2.4300000667572021484375) + float3(0.589999973773956298828125), float3(0.14000000059604644775390625)), float3(0.0), float3(1.0));
        Preview.write(float4(mix((pow(_3349, float3(0.4166666567325592041015625)) * 1.05499994754791259765625) - float3(0.054999999701976776123046875), _3349 * 12.9200000762939453125, step(_3349, float3(0.003130800090730190277099609375))), 1.0), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

