#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct Spheres
{
    float4 _data[1];
};

struct SplitSumParameter
{
    uint Columns;
    uint CellSize;
    uint SpecularMips;
    uint SpecularSize;
    uint LodMapping;
    float LodParameter;
    uint Direction;
    uint Lookup;
    uint LightCount;
    uint LightLevel;
};

kernel void main0(constant SplitSumParameter& _1213 [[buffer(0)]], const device Spheres& Spheres_1 [[buffer(1)]], const device Spheres& Lights [[buffer(2)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float> LobeTable [[texture(3)]], texture2d<float, access::write> SplitSum [[texture(4)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    do
    {
        uint2 _1562 = uint2(0u);
        uint2 _1563 = uint2(SplitSum.get_width(), SplitSum.get_height());
        _1562.x = _1563.x;
        _1562.y = _1563.y;
        if (any(gl_GlobalInvocationID.xy >= _1562))
        {
            break;
        }
        float2 _1737 = (((float2(gl_GlobalInvocationID.xy % uint2(_1213.CellSize)) + float2(0.5)) / float2(float(_1213.CellSize))) * 2.0) - float2(1.0);
        _1737.y = -_1737.y;
        float _1768 = dot(_1737, _1737);
        bool _1771 = (_1768 * 1.2345678806304931640625) < 1.0;
        float _1779 = sqrt(fast::max(fma(-_1768, 1.2345678806304931640625, 1.0), 0.0));
        float3 _1782 = float3(_1737 * float2(1.111111164093017578125), _1779);
        uint2 _1740 = gl_GlobalInvocationID.xy / uint2(_1213.CellSize);
        uint _1802 = 2u * ((_1740.y * _1213.Columns) + _1740.x);
        float4 _1790 = Spheres_1._data[_1802];
        float4 _1791 = Spheres_1._data[_1802 + 1u];
        float3 _3624;
        if (_1771 && (_1791.y > 0.0))
        {
            float3 _3623;
            do
            {
                float _1847 = (1.0 - _1791.z) / (1.0 + _1791.z);
                float3 _1856 = refract(float3(-0.0, -0.0, -1.0), _1782, 1.0 / _1791.z);
                float3 _1865 = fast::normalize(_1782 - (_1856 * (2.0 * dot(_1782, _1856))));
                float3 _1870 = refract(_1856, -_1865, _1791.z);
                if (dot(_1870, _1870) == 0.0)
                {
                    _3623 = float3(0.0);
                    break;
                }
                float _3622;
                do
                {
                    float _1966 = float(_1213.SpecularMips - 1u);
                    float _1968 = fast::clamp(_1790.w, 0.0, 1.0);
                    if (_1213.LodMapping == 1u)
                    {
                        _3622 = (_1968 * (2.0 - _1968)) * _1966;
                        break;
                    }
                    if (_1213.LodMapping == 2u)
                    {
                        _3622 = pow(_1968, _1213.LodParameter) * _1966;
                        break;
                    }
                    if (_1213.LodMapping == 3u)
                    {
                        _3622 = (_1968 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_1968 * _1968) * float(_1213.SpecularSize)), 0.0, _1966) : 0.0;
                        break;
                    }
                    if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                    {
                        float _2027 = float(_1213.SpecularSize);
                        _3622 = (_1968 > 0.0) ? fast::clamp(fma((_1966 - 1.0) / log2(_2027 / _1213.LodParameter), log2((_1968 * _1968) * _2027) - log2(_2027), _1966), 0.0, _1966) : 0.0;
                        break;
                    }
                    _3622 = _1968 * _1966;
                    break;
                } while(false);
                _3623 = Specular.sample(LinearClamp, _1870, level(_3622)).xyz * ((1.0 - fma(_1847, _1847, fma(-_1847, _1847, 1.0) * pow(1.0 - fast::clamp(_1779, 0.0, 1.0), 5.0))) * (1.0 - fma(_1847, _1847, fma(-_1847, _1847, 1.0) * pow(1.0 - fast::clamp(dot(_1865, _1870), 0.0, 1.0), 5.0))));
                break;
            } while(false);
            _3624 = _3623;
        }
        else
        {
            float3 _3625;
            if (_1771)
            {
                float3 _3604;
                float _3605;
                do
                {
                    float3 _2209 = reflect(float3(-0.0, -0.0, -1.0), _1782);
                    float4 _2155 = LobeTable.sample(LinearClamp, float2(fast::clamp(_1779, 0.0, 1.0), _1790.w), level(0.0));
                    float3 _3593;
                    do
                    {
                        float _2331 = _1790.w * _1790.w;
                        if (_1213.Direction == 1u)
                        {
                            float _2337 = fast::clamp(fma(-_1790.w, _1790.w, 1.0), 0.0, 1.0);
                            _3593 = fast::normalize(mix(_1782, _2209, float3(_2337 * fma(_1790.w, _1790.w, sqrt(_2337)))));
                            break;
                        }
                        if (_1213.Direction == 2u)
                        {
                            _3593 = fast::normalize(mix(_2209, _1782, float3(_2331 * _2331)));
                            break;
                        }
                        if (_1213.Direction == 3u)
                        {
                            float3 _3592;
                            do
                            {
                                float _2386 = acos(fast::clamp(dot(_1782, _2209), -1.0, 1.0));
                                if (_2386 < 9.9999997473787516355514526367188e-05)
                                {
                                    _3592 = _2209;
                                    break;
                                }
                                _3592 = ((_1782 * sin((1.0 - _2155.x) * _2386)) + (_2209 * sin(_2155.x * _2386))) / float3(sin(_2386));
                                break;
                            } while(false);
                            _3593 = _3592;
                            break;
                        }
                        _3593 = _2209;
                        break;
                    } while(false);
                    if (_1213.Lookup == 0u)
                    {
                        float _3602;
                        do
                        {
                            float _2451 = float(_1213.SpecularMips - 1u);
                            float _2453 = fast::clamp(_1790.w, 0.0, 1.0);
                            if (_1213.LodMapping == 1u)
                            {
                                _3602 = (_2453 * (2.0 - _2453)) * _2451;
                                break;
                            }
                            if (_1213.LodMapping == 2u)
                            {
                                _3602 = pow(_2453, _1213.LodParameter) * _2451;
                                break;
                            }
                            if (_1213.LodMapping == 3u)
                            {
                                _3602 = (_2453 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2453 * _2453) * float(_1213.SpecularSize)), 0.0, _2451) : 0.0;
                                break;
                            }
                            if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                            {
                                float _2512 = float(_1213.SpecularSize);
                                _3602 = (_2453 > 0.0) ? fast::clamp(fma((_2451 - 1.0) / log2(_2512 / _1213.LodParameter), log2((_2453 * _2453) * _2512) - log2(_2512), _2451), 0.0, _2451) : 0.0;
                                break;
                            }
                            _3602 = _2453 * _2451;
                            break;
                        } while(false);
                        _3605 = (_1213.LightCount > 0u) ? fast::clamp((_3602 - float(_1213.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3604 = Specular.sample(LinearClamp, _3593, level(_3602)).xyz * 1.0;
                        break;
                    }
                    if (_1213.Lookup == 1u)
                    {
                        float _3600;
                        do
                        {
                            float _2596 = float(_1213.SpecularMips - 1u);
                            float _2598 = fast::clamp(_2155.y, 0.0, 1.0);
                            if (_1213.LodMapping == 1u)
                            {
                                _3600 = (_2598 * (2.0 - _2598)) * _2596;
                                break;
                            }
                            if (_1213.LodMapping == 2u)
                            {
                                _3600 = pow(_2598, _1213.LodParameter) * _2596;
                                break;
                            }
                            if (_1213.LodMapping == 3u)
                            {
                                _3600 = (_2598 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2598 * _2598) * float(_1213.SpecularSize)), 0.0, _2596) : 0.0;
                                break;
                            }
                            if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                            {
                                float _2657 = float(_1213.SpecularSize);
                                _3600 = (_2598 > 0.0) ? fast::clamp(fma((_2596 - 1.0) / log2(_2657 / _1213.LodParameter), log2((_2598 * _2598) * _2657) - log2(_2657), _2596), 0.0, _2596) : 0.0;
                                break;
                            }
                            _3600 = _2598 * _2596;
                            break;
                        } while(false);
                        _3605 = (_1213.LightCount > 0u) ? fast::clamp((_3600 - float(_1213.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3604 = Specular.sample(LinearClamp, _3593, level(_3600)).xyz * 1.0;
                        break;
                    }
                    float3 _2252 = cross(_1782, float3(0.0, 0.0, 1.0));
                    float _2254 = length(_2252);
                    float3 _2264 = select(float3(0.0), cross(_2252 / float3(_2254), _3593), bool3(_2254 > 9.9999999747524270787835121154785e-07));
                    float _3596;
                    do
                    {
                        float _2741 = float(_1213.SpecularMips - 1u);
                        float _2743 = fast::clamp(_2155.z, 0.0, 1.0);
                        if (_1213.LodMapping == 1u)
                        {
                            _3596 = (_2743 * (2.0 - _2743)) * _2741;
                            break;
                        }
                        if (_1213.LodMapping == 2u)
                        {
                            _3596 = pow(_2743, _1213.LodParameter) * _2741;
                            break;
                        }
                        if (_1213.LodMapping == 3u)
                        {
                            _3596 = (_2743 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2743 * _2743) * float(_1213.SpecularSize)), 0.0, _2741) : 0.0;
                            break;
                        }
                        if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                        {
                            float _2802 = float(_1213.SpecularSize);
                            _3596 = (_2743 > 0.0) ? fast::clamp(fma((_2741 - 1.0) / log2(_2802 / _1213.LodParameter), log2((_2743 * _2743) * _2802) - log2(_2802), _2741), 0.0, _2741) : 0.0;
                            break;
                        }
                        _3596 = _2743 * _2741;
                        break;
                    } while(false);
                    float _3598;
                    do
                    {
                        float _2886 = float(_1213.SpecularMips - 1u);
                        float _2888 = fast::clamp(_2155.z, 0.0, 1.0);
                        if (_1213.LodMapping == 1u)
                        {
                            _3598 = (_2888 * (2.0 - _2888)) * _2886;
                            break;
                        }
                        if (_1213.LodMapping == 2u)
                        {
                            _3598 = pow(_2888, _1213.LodParameter) * _2886;
                            break;
                        }
                        if (_1213.LodMapping == 3u)
                        {
                            _3598 = (_2888 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2888 * _2888) * float(_1213.SpecularSize)), 0.0, _2886) : 0.0;
                            break;
                        }
                        if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                        {
                            float _2947 = float(_1213.SpecularSize);
                            _3598 = (_2888 > 0.0) ? fast::clamp(fma((_2886 - 1.0) / log2(_2947 / _1213.LodParameter), log2((_2888 * _2888) * _2947) - log2(_2947), _2886), 0.0, _2886) : 0.0;
                            break;
                        }
                        _3598 = _2888 * _2886;
                        break;
                    } while(false);
                    _3605 = fma(0.5, (_1213.LightCount > 0u) ? fast::clamp((_3596 - float(_1213.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1213.LightCount > 0u) ? fast::clamp((_3598 - float(_1213.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                    _3604 = (Specular.sample(LinearClamp, fast::normalize((_3593 * cos(_2155.w)) + (_2264 * sin(_2155.w))), level(_3596)).xyz * 0.5) + (Specular.sample(LinearClamp, fast::normalize((_3593 * cos(_2155.w)) - (_2264 * sin(_2155.w))), level(_3598)).xyz * 0.5);
                    break;
                } while(false);
                float2 _2099 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1779, 0.0, 1.0), _1790.w), level(0.0)).xy);
                float3 _1674 = mix(float3(0.039999999105930328369140625), Spheres_1._data[_1802].xyz, float3(_1791.x));
                float2 _2993 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1779, 0.0, 1.0), _1790.w), level(0.0)).xy);
                float3 _3016 = (_1674 * _2993.x) + float3(_2993.y);
                float3 _3611;
                _3611 = fma(_3604, (mix(float3(0.039999999105930328369140625), Spheres_1._data[_1802].xyz, float3(_1791.x)) * _2099.x) + float3(_2099.y), (IrradianceMap.sample(LinearClamp, _1782, level(0.0)).xyz * Spheres_1._data[_1802].xyz) * (1.0 - _1791.x));
                float3 _1716;
                for (uint _3606 = 0u; _3606 < _1213.LightCount; _3611 = _1716, _3606++)
                {
                    float3 _1696 = Spheres_1._data[_1802].xyz * (1.0 - _1791.x);
                    uint _1698 = 2u * _3606;
                    uint _1701 = (2u * _3606) + 1u;
                    float4 _1604 = Lights._data[_1698];
                    float4 _1605 = Lights._data[_1701];
                    float3 _3017 = Lights._data[_1698].xyz;
                    float3 _3055 = fast::normalize(cross(select(float3(1.0, 0.0, 0.0), float3(0.0, 0.0, 1.0), bool3(abs(_3017.z) < 0.999000012874603271484375)), Lights._data[_1698].xyz));
                    float3 _3058 = cross(Lights._data[_1698].xyz, _3055);
                    float _3061 = tan(_1604.w);
                    float3 _3608;
                    float3 _3609;
                    _3609 = float3(0.0);
                    _3608 = float3(0.0);
                    float3 _3626;
                    float3 _3627;
                    for (uint _3607 = 0u; _3607 < 19u; _3609 = _3627, _3608 = _3626, _3607++)
                    {
                        float2 _3613;
                        do
                        {
                            if (_3607 == 0u)
                            {
                                _3613 = float2(0.0);
                                break;
                            }
                            bool _3165 = _3607 <= 6u;
                            float _3182 = _3165 ? (float(_3607 - 1u) * 1.0471975803375244140625) : ((float(_3607 - 7u) + 0.5) * 0.52359879016876220703125);
                            _3613 = float2(cos(_3182), sin(_3182)) * (_3165 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                            break;
                        } while(false);
                        float2 _3025 = _3613 * _3061;
                        float3 _3082 = fast::normalize((Lights._data[_1698].xyz + (_3055 * _3025.x)) + (_3058 * _3025.y));
                        float _3085 = dot(_1782, _3082);
                        if (_3085 <= 0.0)
                        {
                            _3627 = _3609;
                            _3626 = _3608;
                            continue;
                        }
                        float3 _3614;
                        do
                        {
                            float _3212 = dot(_1782, _3082);
                            float _3216 = fast::clamp(_1779, 0.0, 1.0);
                            if ((_3212 <= 0.0) || (_3216 <= 0.0))
                            {
                                _3614 = float3(0.0);
                                break;
                            }
                            float3 _3227 = fast::normalize(_3082 + float3(0.0, 0.0, 1.0));
                            float _3301 = _1790.w * _1790.w;
                            float _3322 = _1790.w * _1790.w;
                            float _3244 = fast::clamp(dot(_1782, _3227), 0.0, 1.0);
                            float _3343 = _1790.w * _1790.w;
                            float _3355 = fma(_3244 * _3244, fma(_3343, _3343, -1.0), 1.0);
                            _3614 = (_1674 + ((float3(1.0) - _1674) * pow(fast::clamp(1.0 - fast::clamp(_3227.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_3212 / fma(_3212, fma(-_3301, 0.5, 1.0), _3301 * 0.5)) * (_3216 / fma(_3216, fma(-_3322, 0.5, 1.0), _3322 * 0.5))) * ((_3343 * _3343) / ((3.1415927410125732421875 * _3355) * _3355))) / (4.0 * _3216));
                            break;
                        } while(false);
                        _3627 = _3609 + (_1696 * (_3085 * 0.3183098733425140380859375));
                        _3626 = _3608 + _3614;
                    }
                    float _3117 = fast::clamp((((2.0 * _1790.w) * _1790.w) / fast::max(_1604.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                    float4 _3041 = Lights._data[_1698];
                    float _3383 = 0.5 * _3041.w;
                    float _3385 = 0.5 * acos(fast::clamp(dot(reflect(float3(-0.0, -0.0, -1.0), _1782), Lights._data[_1698].xyz), -1.0, 1.0));
                    float _3389 = fast::max(_1790.w * _1790.w, 1.0000000116860974230803549289703e-07);
                    float _3403 = (_3383 * _3383) / (_3389 * _3389);
                    float _3410 = (_3385 * _3385) / (_3389 * _3389);
                    float _3414 = (_3403 + 1.0) - _3410;
                    _1716 = _3611 + ((((mix(select(float3(0.0), (_3016 * fast::clamp(0.5 + (((_3403 - 1.0) - _3410) / (2.0 * sqrt(fma(_3414, _3414, 4.0 * _3410)))), 0.0, 1.0)) / float3(_1605.w), bool3(_3117 < 1.0)), _3608 * 0.052631579339504241943359375, float3(_3117)) * _3605) + (_3609 * 0.052631579339504241943359375)) * Lights._data[_1701].xyz) * _1605.w);
                }
                _3625 = _3611;
            }
            else
            {
                _3625 = float3(0.0);
            }
            _3624 = _3625;
        }
        SplitSum.write(float4(_3624, float(_1771)), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

