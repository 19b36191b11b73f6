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

kernel void main0(constant SplitSumParameter& _1315 [[buffer(0)]], const device Spheres& Spheres_1 [[buffer(1)]], const device Spheres& Lights [[buffer(2)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float> LobeTable [[texture(3)]], texture2d<float, access::write> SplitSum [[texture(4)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    do
    {
        uint2 _1669 = uint2(0u);
        uint2 _1670 = uint2(SplitSum.get_width(), SplitSum.get_height());
        _1669.x = _1670.x;
        _1669.y = _1670.y;
        if (any(gl_GlobalInvocationID.xy >= _1669))
        {
            break;
        }
        float2 _1844 = (((float2(gl_GlobalInvocationID.xy % uint2(_1315.CellSize)) + float2(0.5)) / float2(float(_1315.CellSize))) * 2.0) - float2(1.0);
        _1844.y = -_1844.y;
        float _1875 = dot(_1844, _1844);
        bool _1878 = (_1875 * 1.2345678806304931640625) < 1.0;
        float _1886 = sqrt(fast::max(fma(-_1875, 1.2345678806304931640625, 1.0), 0.0));
        float3 _1889 = float3(_1844 * float2(1.111111164093017578125), _1886);
        uint2 _1847 = gl_GlobalInvocationID.xy / uint2(_1315.CellSize);
        uint _1909 = 2u * ((_1847.y * _1315.Columns) + _1847.x);
        float4 _1897 = Spheres_1._data[_1909];
        float4 _1898 = Spheres_1._data[_1909 + 1u];
        float3 _3843;
        if (_1878 && (_1898.y > 0.0))
        {
            float3 _3842;
            do
            {
                float _1954 = (1.0 - _1898.z) / (1.0 + _1898.z);
                float3 _1963 = refract(float3(-0.0, -0.0, -1.0), _1889, 1.0 / _1898.z);
                float3 _1972 = fast::normalize(_1889 - (_1963 * (2.0 * dot(_1889, _1963))));
                float3 _1977 = refract(_1963, -_1972, _1898.z);
                if (dot(_1977, _1977) == 0.0)
                {
                    _3842 = float3(0.0);
                    break;
                }
                float _3841;
                do
                {
                    float _2092 = float(_1315.SpecularMips - 1u);
                    float _2094 = fast::clamp(_1897.w, 0.0, 1.0);
                    if (_1315.LodMapping == 1u)
                    {
                        _3841 = (_2094 * (2.0 - _2094)) * _2092;
                        break;
                    }
                    if (_1315.LodMapping == 2u)
                    {
                        _3841 = pow(_2094, _1315.LodParameter) * _2092;
                        break;
                    }
                    if (_1315.LodMapping == 3u)
                    {
                        _3841 = (_2094 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2094 * _2094) * float(_1315.SpecularSize)), 0.0, _2092) : 0.0;
                        break;
                    }
                    if (((_1315.LodMapping == 4u) && (_1315.SpecularMips >= 3u)) && (float(_1315.SpecularSize) > _1315.LodParameter))
                    {
                        float _2153 = float(_1315.SpecularSize);
                        _3841 = (_2094 > 0.0) ? fast::clamp(fma((_2092 - 1.0) / log2(_2153 / _1315.LodParameter), log2((_2094 * _2094) * _2153) - log2(_2153), _2092), 0.0, _2092) : 0.0;
                        break;
                    }
                    _3841 = _2094 * _2092;
                    break;
                } while(false);
                _3842 = Specular.sample(LinearClamp, _1977, level(_3841)).xyz * ((1.0 - fma(_1954, _1954, fma(-_1954, _1954, 1.0) * pow(1.0 - fast::clamp(_1886, 0.0, 1.0), 5.0))) * (1.0 - fma(_1954, _1954, fma(-_1954, _1954, 1.0) * pow(1.0 - fast::clamp(dot(_1972, _1977), 0.0, 1.0), 5.0))));
                break;
            } while(false);
            _3843 = _3842;
        }
        else
        {
            float3 _3844;
            if (_1878)
            {
                float3 _3822;
                float _3823;
                do
                {
                    float3 _2354 = reflect(float3(-0.0, -0.0, -1.0), _1889);
                    float4 _2300 = LobeTable.sample(LinearClamp, float2(fast::clamp(_1886, 0.0, 1.0), _1897.w), level(0.0));
                    float3 _3811;
                    do
                    {
                        float _2476 = _1897.w * _1897.w;
                        if (_1315.Direction == 1u)
                        {
                            float _2482 = fast::clamp(fma(-_1897.w, _1897.w, 1.0), 0.0, 1.0);
                            _3811 = fast::normalize(mix(_1889, _2354, float3(_2482 * fma(_1897.w, _1897.w, sqrt(_2482)))));
                            break;
                        }
                        if (_1315.Direction == 2u)
                        {
                            _3811 = fast::normalize(mix(_2354, _1889, float3(_2476 * _2476)));
                            break;
                        }
                        if (_1315.Direction == 3u)
                        {
                            float3 _3810;
                            do
                            {
                                float _2531 = acos(fast::clamp(dot(_1889, _2354), -1.0, 1.0));
                                if (_2531 < 9.9999997473787516355514526367188e-05)
                                {
                                    _3810 = _2354;
                                    break;
                                }
                                _3810 = ((_1889 * sin((1.0 - _2300.x) * _2531)) + (_2354 * sin(_2300.x * _2531))) / float3(sin(_2531));
                                break;
                            } while(false);
                            _3811 = _3810;
                            break;
                        }
                        _3811 = _2354;
                        break;
                    } while(false);
                    if (_1315.Lookup == 0u)
                    {
                        float _3820;
                        do
                        {
                            float _2596 = float(_1315.SpecularMips - 1u);
                            float _2598 = fast::clamp(_1897.w, 0.0, 1.0);
                            if (_1315.LodMapping == 1u)
                            {
                                _3820 = (_2598 * (2.0 - _2598)) * _2596;
                                break;
                            }
                            if (_1315.LodMapping == 2u)
                            {
                                _3820 = pow(_2598, _1315.LodParameter) * _2596;
                                break;
                            }
                            if (_1315.LodMapping == 3u)
                            {
                                _3820 = (_2598 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2598 * _2598) * float(_1315.SpecularSize)), 0.0, _2596) : 0.0;
                                break;
                            }
                            if (((_1315.LodMapping == 4u) && (_1315.SpecularMips >= 3u)) && (float(_1315.SpecularSize) > _1315.LodParameter))
                            {
                                float _2657 = float(_1315.SpecularSize);
                                _3820 = (_2598 > 0.0) ? fast::clamp(fma((_2596 - 1.0) / log2(_2657 / _1315.LodParameter), log2((_2598 * _2598) * _2657) - log2(_2657), _2596), 0.0, _2596) : 0.0;
                                break;
                            }
                            _3820 = _2598 * _2596;
                            break;
                        } while(false);
                        _3823 = (_1315.LightCount > 0u) ? fast::clamp((_3820 - float(_1315.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3822 = Specular.sample(LinearClamp, _3811, level(_3820)).xyz * 1.0;
                        break;
                    }
                    if (_1315.Lookup == 1u)
                    {
                        float _3818;
                        do
                        {
                            float _2741 = float(_1315.SpecularMips - 1u);
                            float _2743 = fast::clamp(_2300.y, 0.0, 1.0);
                            if (_1315.LodMapping == 1u)
                            {
                                _3818 = (_2743 * (2.0 - _2743)) * _2741;
                                break;
                            }
                            if (_1315.LodMapping == 2u)
                            {
                                _3818 = pow(_2743, _1315.LodParameter) * _2741;
                                break;
                            }
                            if (_1315.LodMapping == 3u)
                            {
                                _3818 = (_2743 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2743 * _2743) * float(_1315.SpecularSize)), 0.0, _2741) : 0.0;
                                break;
                            }
                            if (((_1315.LodMapping == 4u) && (_1315.SpecularMips >= 3u)) && (float(_1315.SpecularSize) > _1315.LodParameter))
                            {
                                float _2802 = float(_1315.SpecularSize);
                                _3818 = (_2743 > 0.0) ? fast::clamp(fma((_2741 - 1.0) / log2(_2802 / _1315.LodParameter), log2((_2743 * _2743) * _2802) - log2(_2802), _2741), 0.0, _2741) : 0.0;
                                break;
                            }
                            _3818 = _2743 * _2741;
                            break;
                        } while(false);
                        _3823 = (_1315.LightCount > 0u) ? fast::clamp((_3818 - float(_1315.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3822 = Specular.sample(LinearClamp, _3811, level(_3818)).xyz * 1.0;
                        break;
                    }
                    float3 _2397 = cross(_1889, float3(0.0, 0.0, 1.0));
                    float _2399 = length(_2397);
                    float3 _2409 = select(float3(0.0), cross(_2397 / float3(_2399), _3811), bool3(_2399 > 9.9999999747524270787835121154785e-07));
                    float _3814;
                    do
                    {
                        float _2886 = float(_1315.SpecularMips - 1u);
                        float _2888 = fast::clamp(_2300.z, 0.0, 1.0);
                        if (_1315.LodMapping == 1u)
                        {
                            _3814 = (_2888 * (2.0 - _2888)) * _2886;
                            break;
                        }
                        if (_1315.LodMapping == 2u)
                        {
                            _3814 = pow(_2888, _1315.LodParameter) * _2886;
                            break;
                        }
                        if (_1315.LodMapping == 3u)
                        {
                            _3814 = (_2888 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2888 * _2888) * float(_1315.SpecularSize)), 0.0, _2886) : 0.0;
                            break;
                        }
                        if (((_1315.LodMapping == 4u) && (_1315.SpecularMips >= 3u)) && (float(_1315.SpecularSize) > _1315.LodParameter))
                        {
                            float _2947 = float(_1315.SpecularSize);
                            _3814 = (_2888 > 0.0) ? fast::clamp(fma((_2886 - 1.0) / log2(_2947 / _1315.LodParameter), log2((_2888 * _2888) * _2947) - log2(_2947), _2886), 0.0, _2886) : 0.0;
                            break;
                        }
                        _3814 = _2888 * _2886;
                        break;
                    } while(false);
                    float _3816;
                    do
                    {
                        float _3031 = float(_1315.SpecularMips - 1u);
                        float _3033 = fast::clamp(_2300.z, 0.0, 1.0);
                        if (_1315.LodMapping == 1u)
                        {
                            _3816 = (_3033 * (2.0 - _3033)) * _3031;
                            break;
                        }
                        if (_1315.LodMapping == 2u)
                        {
                            _3816 = pow(_3033, _1315.LodParameter) * _3031;
                            break;
                        }
                        if (_1315.LodMapping == 3u)
                        {
                            _3816 = (_3033 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_3033 * _3033) * float(_1315.SpecularSize)), 0.0, _3031) : 0.0;
                            break;
                        }
                        if (((_1315.LodMapping == 4u) && (_1315.SpecularMips >= 3u)) && (float(_1315.SpecularSize) > _1315.LodParameter))
                        {
                            float _3092 = float(_1315.SpecularSize);
                            _3816 = (_3033 > 0.0) ? fast::clamp(fma((_3031 - 1.0) / log2(_3092 / _1315.LodParameter), log2((_3033 * _3033) * _3092) - log2(_3092), _3031), 0.0, _3031) : 0.0;
                            break;
                        }
                        _3816 = _3033 * _3031;
                        break;
                    } while(false);
                    _3823 = fma(0.5, (_1315.LightCount > 0u) ? fast::clamp((_3814 - float(_1315.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1315.LightCount > 0u) ? fast::clamp((_3816 - float(_1315.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                    _3822 = (Specular.sample(LinearClamp, fast::normalize((_3811 * cos(_2300.w)) + (_2409 * sin(_2300.w))), level(_3814)).xyz * 0.5) + (Specular.sample(LinearClamp, fast::normalize((_3811 * cos(_2300.w)) - (_2409 * sin(_2300.w))), level(_3816)).xyz * 0.5);
                    break;
                } while(false);
                float2 _2244 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1886, 0.0, 1.0), _1897.w), level(0.0)).xy);
                float3 _1781 = mix(float3(0.039999999105930328369140625), Spheres_1._data[_1909].xyz, float3(_1898.x));
                float2 _3138 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1886, 0.0, 1.0), _1897.w), level(0.0)).xy);
                float3 _3161 = (_1781 * _3138.x) + float3(_3138.y);
                float3 _3831;
                _3831 = fma(_3822, (mix(float3(0.039999999105930328369140625), Spheres_1._data[_1909].xyz, float3(_1898.x)) * _2244.x) + float3(_2244.y), (IrradianceMap.sample(LinearClamp, _1889, level(0.0)).xyz * Spheres_1._data[_1909].xyz) * (1.0 - _1898.x));
                float3 _1823;
                for (uint _3824 = 0u; _3824 < _1315.LightCount; _3831 = _1823, _3824++)
                {
                    uint _1805 = 2u * _3824;
                    uint _1808 = (2u * _3824) + 1u;
                    float4 _1711 = Lights._data[_1805];
                    float4 _1712 = Lights._data[_1808];
                    float3 _3162 = Lights._data[_1805].xyz;
                    float3 _3202 = fast::normalize(cross(select(float3(1.0, 0.0, 0.0), float3(0.0, 0.0, 1.0), bool3(abs(_3162.z) < 0.999000012874603271484375)), Lights._data[_1805].xyz));
                    float3 _3205 = cross(Lights._data[_1805].xyz, _3202);
                    float _3208 = tan(_1711.w);
                    float3 _3826;
                    _3826 = float3(0.0);
                    float3 _3845;
                    for (uint _3825 = 0u; _3825 < 19u; _3826 = _3845, _3825++)
                    {
                        float2 _3834;
                        do
                        {
                            if (_3825 == 0u)
                            {
                                _3834 = float2(0.0);
                                break;
                            }
                            bool _3316 = _3825 <= 6u;
                            float _3333 = _3316 ? (float(_3825 - 1u) * 1.0471975803375244140625) : ((float(_3825 - 7u) + 0.5) * 0.52359879016876220703125);
                            _3834 = float2(cos(_3333), sin(_3333)) * (_3316 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                            break;
                        } while(false);
                        float2 _3169 = _3834 * _3208;
                        float3 _3229 = fast::normalize((Lights._data[_1805].xyz + (_3202 * _3169.x)) + (_3205 * _3169.y));
                        if (dot(_1889, _3229) > 0.0)
                        {
                            float3 _3835;
                            do
                            {
                                float _3363 = dot(_1889, _3229);
                                float _3367 = fast::clamp(_1886, 0.0, 1.0);
                                if ((_3363 <= 0.0) || (_3367 <= 0.0))
                                {
                                    _3835 = float3(0.0);
                                    break;
                                }
                                float3 _3378 = fast::normalize(_3229 + float3(0.0, 0.0, 1.0));
                                float _3452 = _1897.w * _1897.w;
                                float _3473 = _1897.w * _1897.w;
                                float _3395 = fast::clamp(dot(_1889, _3378), 0.0, 1.0);
                                float _3494 = _1897.w * _1897.w;
                                float _3506 = fma(_3395 * _3395, fma(_3494, _3494, -1.0), 1.0);
                                _3835 = (_1781 + ((float3(1.0) - _1781) * pow(fast::clamp(1.0 - fast::clamp(_3378.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_3363 / fma(_3363, fma(-_3452, 0.5, 1.0), _3452 * 0.5)) * (_3367 / fma(_3367, fma(-_3473, 0.5, 1.0), _3473 * 0.5))) * ((_3494 * _3494) / ((3.1415927410125732421875 * _3506) * _3506))) / (4.0 * _3367));
                                break;
                            } while(false);
                            _3845 = _3826 + _3835;
                        }
                        else
                        {
                            _3845 = _3826;
                        }
                    }
                    float _3257 = fast::clamp((((2.0 * _1897.w) * _1897.w) / fast::max(_1711.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                    float4 _3184 = Lights._data[_1805];
                    float _3534 = 0.5 * _3184.w;
                    float _3536 = 0.5 * acos(fast::clamp(dot(reflect(float3(-0.0, -0.0, -1.0), _1889), Lights._data[_1805].xyz), -1.0, 1.0));
                    float _3540 = fast::max(_1897.w * _1897.w, 1.0000000116860974230803549289703e-07);
                    float _3554 = (_3534 * _3534) / (_3540 * _3540);
                    float _3561 = (_3536 * _3536) / (_3540 * _3540);
                    float _3565 = (_3554 + 1.0) - _3561;
                    float _3281 = sin(_1711.w);
                    float _3285 = dot(_1889, Lights._data[_1805].xyz);
                    float _3288 = _3281 * _3281;
                    float _3827;
                    do
                    {
                        if (((_3285 * _3285) > _3288) || (_3288 <= 0.0))
                        {
                            _3827 = (3.1415927410125732421875 * _3288) * fast::clamp(_3285, 0.0, 1.0);
                            break;
                        }
                        float _3610 = sqrt(fast::clamp(fma(-_3285, _3285, 1.0), 0.0, 1.0));
                        float _3614 = sqrt((1.0 / _3288) - 1.0);
                        float _3620 = (-_3614) * (_3285 / _3610);
                        float _3628 = _3610 * sqrt(fast::clamp(fma(-_3620, _3620, 1.0), 0.0, 1.0));
                        _3827 = fast::max(fma(fma(_3285, acos(fast::clamp(_3620, -1.0, 1.0)), -(_3614 * _3628)), _3288, atan(_3628 / _3614)), 0.0);
                        break;
                    } while(false);
                    _1823 = fma(((mix(select(float3(0.0), (_3161 * fast::clamp(0.5 + (((_3554 - 1.0) - _3561) / (2.0 * sqrt(fma(_3565, _3565, 4.0 * _3561)))), 0.0, 1.0)) / float3(_1712.w), bool3(_3257 < 1.0)), _3826 * 0.052631579339504241943359375, float3(_3257)) * _3823) * _1712.w) + ((Spheres_1._data[_1909].xyz * (1.0 - _1898.x)) * (_3827 * 0.3183098733425140380859375)), Lights._data[_1808].xyz, _3831);
                }
                _3844 = _3831;
            }
            else
            {
                _3844 = float3(0.0);
            }
            _3843 = _3844;
        }
        SplitSum.write(float4(_3843, float(_1878)), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

