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

kernel void main0(constant SplitSumParameter& _1243 [[buffer(0)]], const device Spheres& Spheres_1 [[buffer(1)]], const device Spheres& Lights [[buffer(2)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float> LobeTable [[texture(3)]], texture2d<float, access::write> SplitSum [[texture(4)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    do
    {
        uint2 _1592 = uint2(0u);
        uint2 _1593 = uint2(SplitSum.get_width(), SplitSum.get_height());
        _1592.x = _1593.x;
        _1592.y = _1593.y;
        if (any(gl_GlobalInvocationID.xy >= _1592))
        {
            break;
        }
        float2 _1767 = (((float2(gl_GlobalInvocationID.xy % uint2(_1243.CellSize)) + float2(0.5)) / float2(float(_1243.CellSize))) * 2.0) - float2(1.0);
        _1767.y = -_1767.y;
        float _1798 = dot(_1767, _1767);
        bool _1801 = (_1798 * 1.2345678806304931640625) < 1.0;
        float _1809 = sqrt(fast::max(fma(-_1798, 1.2345678806304931640625, 1.0), 0.0));
        float3 _1812 = float3(_1767 * float2(1.111111164093017578125), _1809);
        uint2 _1770 = gl_GlobalInvocationID.xy / uint2(_1243.CellSize);
        uint _1832 = 2u * ((_1770.y * _1243.Columns) + _1770.x);
        float4 _1820 = Spheres_1._data[_1832];
        float4 _1821 = Spheres_1._data[_1832 + 1u];
        float3 _3692;
        if (_1801 && (_1821.y > 0.0))
        {
            float3 _3691;
            do
            {
                float _1877 = (1.0 - _1821.z) / (1.0 + _1821.z);
                float3 _1886 = refract(float3(-0.0, -0.0, -1.0), _1812, 1.0 / _1821.z);
                float3 _1895 = fast::normalize(_1812 - (_1886 * (2.0 * dot(_1812, _1886))));
                float3 _1900 = refract(_1886, -_1895, _1821.z);
                if (dot(_1900, _1900) == 0.0)
                {
                    _3691 = float3(0.0);
                    break;
                }
                float _3690;
                do
                {
                    float _2015 = float(_1243.SpecularMips - 1u);
                    float _2017 = fast::clamp(_1820.w, 0.0, 1.0);
                    if (_1243.LodMapping == 1u)
                    {
                        _3690 = (_2017 * (2.0 - _2017)) * _2015;
                        break;
                    }
                    if (_1243.LodMapping == 2u)
                    {
                        _3690 = pow(_2017, _1243.LodParameter) * _2015;
                        break;
                    }
                    if (_1243.LodMapping == 3u)
                    {
                        _3690 = (_2017 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2017 * _2017) * float(_1243.SpecularSize)), 0.0, _2015) : 0.0;
                        break;
                    }
                    if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                    {
                        float _2076 = float(_1243.SpecularSize);
                        _3690 = (_2017 > 0.0) ? fast::clamp(fma((_2015 - 1.0) / log2(_2076 / _1243.LodParameter), log2((_2017 * _2017) * _2076) - log2(_2076), _2015), 0.0, _2015) : 0.0;
                        break;
                    }
                    _3690 = _2017 * _2015;
                    break;
                } while(false);
                _3691 = Specular.sample(LinearClamp, _1900, level(_3690)).xyz * ((1.0 - fma(_1877, _1877, fma(-_1877, _1877, 1.0) * pow(1.0 - fast::clamp(_1809, 0.0, 1.0), 5.0))) * (1.0 - fma(_1877, _1877, fma(-_1877, _1877, 1.0) * pow(1.0 - fast::clamp(dot(_1895, _1900), 0.0, 1.0), 5.0))));
                break;
            } while(false);
            _3692 = _3691;
        }
        else
        {
            float3 _3693;
            if (_1801)
            {
                float3 _3672;
                float _3673;
                do
                {
                    float3 _2277 = reflect(float3(-0.0, -0.0, -1.0), _1812);
                    float4 _2223 = LobeTable.sample(LinearClamp, float2(fast::clamp(_1809, 0.0, 1.0), _1820.w), level(0.0));
                    float3 _3661;
                    do
                    {
                        float _2399 = _1820.w * _1820.w;
                        if (_1243.Direction == 1u)
                        {
                            float _2405 = fast::clamp(fma(-_1820.w, _1820.w, 1.0), 0.0, 1.0);
                            _3661 = fast::normalize(mix(_1812, _2277, float3(_2405 * fma(_1820.w, _1820.w, sqrt(_2405)))));
                            break;
                        }
                        if (_1243.Direction == 2u)
                        {
                            _3661 = fast::normalize(mix(_2277, _1812, float3(_2399 * _2399)));
                            break;
                        }
                        if (_1243.Direction == 3u)
                        {
                            float3 _3660;
                            do
                            {
                                float _2454 = acos(fast::clamp(dot(_1812, _2277), -1.0, 1.0));
                                if (_2454 < 9.9999997473787516355514526367188e-05)
                                {
                                    _3660 = _2277;
                                    break;
                                }
                                _3660 = ((_1812 * sin((1.0 - _2223.x) * _2454)) + (_2277 * sin(_2223.x * _2454))) / float3(sin(_2454));
                                break;
                            } while(false);
                            _3661 = _3660;
                            break;
                        }
                        _3661 = _2277;
                        break;
                    } while(false);
                    if (_1243.Lookup == 0u)
                    {
                        float _3670;
                        do
                        {
                            float _2519 = float(_1243.SpecularMips - 1u);
                            float _2521 = fast::clamp(_1820.w, 0.0, 1.0);
                            if (_1243.LodMapping == 1u)
                            {
                                _3670 = (_2521 * (2.0 - _2521)) * _2519;
                                break;
                            }
                            if (_1243.LodMapping == 2u)
                            {
                                _3670 = pow(_2521, _1243.LodParameter) * _2519;
                                break;
                            }
                            if (_1243.LodMapping == 3u)
                            {
                                _3670 = (_2521 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2521 * _2521) * float(_1243.SpecularSize)), 0.0, _2519) : 0.0;
                                break;
                            }
                            if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                            {
                                float _2580 = float(_1243.SpecularSize);
                                _3670 = (_2521 > 0.0) ? fast::clamp(fma((_2519 - 1.0) / log2(_2580 / _1243.LodParameter), log2((_2521 * _2521) * _2580) - log2(_2580), _2519), 0.0, _2519) : 0.0;
                                break;
                            }
                            _3670 = _2521 * _2519;
                            break;
                        } while(false);
                        _3673 = (_1243.LightCount > 0u) ? fast::clamp((_3670 - float(_1243.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3672 = Specular.sample(LinearClamp, _3661, level(_3670)).xyz * 1.0;
                        break;
                    }
                    if (_1243.Lookup == 1u)
                    {
                        float _3668;
                        do
                        {
                            float _2664 = float(_1243.SpecularMips - 1u);
                            float _2666 = fast::clamp(_2223.y, 0.0, 1.0);
                            if (_1243.LodMapping == 1u)
                            {
                                _3668 = (_2666 * (2.0 - _2666)) * _2664;
                                break;
                            }
                            if (_1243.LodMapping == 2u)
                            {
                                _3668 = pow(_2666, _1243.LodParameter) * _2664;
                                break;
                            }
                            if (_1243.LodMapping == 3u)
                            {
                                _3668 = (_2666 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2666 * _2666) * float(_1243.SpecularSize)), 0.0, _2664) : 0.0;
                                break;
                            }
                            if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                            {
                                float _2725 = float(_1243.SpecularSize);
                                _3668 = (_2666 > 0.0) ? fast::clamp(fma((_2664 - 1.0) / log2(_2725 / _1243.LodParameter), log2((_2666 * _2666) * _2725) - log2(_2725), _2664), 0.0, _2664) : 0.0;
                                break;
                            }
                            _3668 = _2666 * _2664;
                            break;
                        } while(false);
                        _3673 = (_1243.LightCount > 0u) ? fast::clamp((_3668 - float(_1243.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3672 = Specular.sample(LinearClamp, _3661, level(_3668)).xyz * 1.0;
                        break;
                    }
                    float3 _2320 = cross(_1812, float3(0.0, 0.0, 1.0));
                    float _2322 = length(_2320);
                    float3 _2332 = select(float3(0.0), cross(_2320 / float3(_2322), _3661), bool3(_2322 > 9.9999999747524270787835121154785e-07));
                    float _3664;
                    do
                    {
                        float _2809 = float(_1243.SpecularMips - 1u);
                        float _2811 = fast::clamp(_2223.z, 0.0, 1.0);
                        if (_1243.LodMapping == 1u)
                        {
                            _3664 = (_2811 * (2.0 - _2811)) * _2809;
                            break;
                        }
                        if (_1243.LodMapping == 2u)
                        {
                            _3664 = pow(_2811, _1243.LodParameter) * _2809;
                            break;
                        }
                        if (_1243.LodMapping == 3u)
                        {
                            _3664 = (_2811 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2811 * _2811) * float(_1243.SpecularSize)), 0.0, _2809) : 0.0;
                            break;
                        }
                        if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                        {
                            float _2870 = float(_1243.SpecularSize);
                            _3664 = (_2811 > 0.0) ? fast::clamp(fma((_2809 - 1.0) / log2(_2870 / _1243.LodParameter), log2((_2811 * _2811) * _2870) - log2(_2870), _2809), 0.0, _2809) : 0.0;
                            break;
                        }
                        _3664 = _2811 * _2809;
                        break;
                    } while(false);
                    float _3666;
                    do
                    {
                        float _2954 = float(_1243.SpecularMips - 1u);
                        float _2956 = fast::clamp(_2223.z, 0.0, 1.0);
                        if (_1243.LodMapping == 1u)
                        {
                            _3666 = (_2956 * (2.0 - _2956)) * _2954;
                            break;
                        }
                        if (_1243.LodMapping == 2u)
                        {
                            _3666 = pow(_2956, _1243.LodParameter) * _2954;
                            break;
                        }
                        if (_1243.LodMapping == 3u)
                        {
                            _3666 = (_2956 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2956 * _2956) * float(_1243.SpecularSize)), 0.0, _2954) : 0.0;
                            break;
                        }
                        if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                        {
                            float _3015 = float(_1243.SpecularSize);
                            _3666 = (_2956 > 0.0) ? fast::clamp(fma((_2954 - 1.0) / log2(_3015 / _1243.LodParameter), log2((_2956 * _2956) * _3015) - log2(_3015), _2954), 0.0, _2954) : 0.0;
                            break;
                        }
                        _3666 = _2956 * _2954;
                        break;
                    } while(false);
                    _3673 = fma(0.5, (_1243.LightCount > 0u) ? fast::clamp((_3664 - float(_1243.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1243.LightCount > 0u) ? fast::clamp((_3666 - float(_1243.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                    _3672 = (Specular.sample(LinearClamp, fast::normalize((_3661 * cos(_2223.w)) + (_2332 * sin(_2223.w))), level(_3664)).xyz * 0.5) + (Specular.sample(LinearClamp, fast::normalize((_3661 * cos(_2223.w)) - (_2332 * sin(_2223.w))), level(_3666)).xyz * 0.5);
                    break;
                } while(false);
                float2 _2167 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1809, 0.0, 1.0), _1820.w), level(0.0)).xy);
                float3 _1704 = mix(float3(0.039999999105930328369140625), Spheres_1._data[_1832].xyz, float3(_1821.x));
                float2 _3061 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_1809, 0.0, 1.0), _1820.w), level(0.0)).xy);
                float3 _3084 = (_1704 * _3061.x) + float3(_3061.y);
                float3 _3679;
                _3679 = fma(_3672, (mix(float3(0.039999999105930328369140625), Spheres_1._data[_1832].xyz, float3(_1821.x)) * _2167.x) + float3(_2167.y), (IrradianceMap.sample(LinearClamp, _1812, level(0.0)).xyz * Spheres_1._data[_1832].xyz) * (1.0 - _1821.x));
                float3 _1746;
                for (uint _3674 = 0u; _3674 < _1243.LightCount; _3679 = _1746, _3674++)
                {
                    float3 _1726 = Spheres_1._data[_1832].xyz * (1.0 - _1821.x);
                    uint _1728 = 2u * _3674;
                    uint _1731 = (2u * _3674) + 1u;
                    float4 _1634 = Lights._data[_1728];
                    float4 _1635 = Lights._data[_1731];
                    float3 _3085 = Lights._data[_1728].xyz;
                    float3 _3123 = fast::normalize(cross(select(float3(1.0, 0.0, 0.0), float3(0.0, 0.0, 1.0), bool3(abs(_3085.z) < 0.999000012874603271484375)), Lights._data[_1728].xyz));
                    float3 _3126 = cross(Lights._data[_1728].xyz, _3123);
                    float _3129 = tan(_1634.w);
                    float3 _3676;
                    float3 _3677;
                    _3677 = float3(0.0);
                    _3676 = float3(0.0);
                    float3 _3694;
                    float3 _3695;
                    for (uint _3675 = 0u; _3675 < 19u; _3677 = _3695, _3676 = _3694, _3675++)
                    {
                        float2 _3681;
                        do
                        {
                            if (_3675 == 0u)
                            {
                                _3681 = float2(0.0);
                                break;
                            }
                            bool _3233 = _3675 <= 6u;
                            float _3250 = _3233 ? (float(_3675 - 1u) * 1.0471975803375244140625) : ((float(_3675 - 7u) + 0.5) * 0.52359879016876220703125);
                            _3681 = float2(cos(_3250), sin(_3250)) * (_3233 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                            break;
                        } while(false);
                        float2 _3093 = _3681 * _3129;
                        float3 _3150 = fast::normalize((Lights._data[_1728].xyz + (_3123 * _3093.x)) + (_3126 * _3093.y));
                        float _3153 = dot(_1812, _3150);
                        if (_3153 <= 0.0)
                        {
                            _3695 = _3677;
                            _3694 = _3676;
                            continue;
                        }
                        float3 _3682;
                        do
                        {
                            float _3280 = dot(_1812, _3150);
                            float _3284 = fast::clamp(_1809, 0.0, 1.0);
                            if ((_3280 <= 0.0) || (_3284 <= 0.0))
                            {
                                _3682 = float3(0.0);
                                break;
                            }
                            float3 _3295 = fast::normalize(_3150 + float3(0.0, 0.0, 1.0));
                            float _3369 = _1820.w * _1820.w;
                            float _3390 = _1820.w * _1820.w;
                            float _3312 = fast::clamp(dot(_1812, _3295), 0.0, 1.0);
                            float _3411 = _1820.w * _1820.w;
                            float _3423 = fma(_3312 * _3312, fma(_3411, _3411, -1.0), 1.0);
                            _3682 = (_1704 + ((float3(1.0) - _1704) * pow(fast::clamp(1.0 - fast::clamp(_3295.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_3280 / fma(_3280, fma(-_3369, 0.5, 1.0), _3369 * 0.5)) * (_3284 / fma(_3284, fma(-_3390, 0.5, 1.0), _3390 * 0.5))) * ((_3411 * _3411) / ((3.1415927410125732421875 * _3423) * _3423))) / (4.0 * _3284));
                            break;
                        } while(false);
                        _3695 = _3677 + (_1726 * (_3153 * 0.3183098733425140380859375));
                        _3694 = _3676 + _3682;
                    }
                    float _3185 = fast::clamp((((2.0 * _1820.w) * _1820.w) / fast::max(_1634.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                    float4 _3109 = Lights._data[_1728];
                    float _3451 = 0.5 * _3109.w;
                    float _3453 = 0.5 * acos(fast::clamp(dot(reflect(float3(-0.0, -0.0, -1.0), _1812), Lights._data[_1728].xyz), -1.0, 1.0));
                    float _3457 = fast::max(_1820.w * _1820.w, 1.0000000116860974230803549289703e-07);
                    float _3471 = (_3451 * _3451) / (_3457 * _3457);
                    float _3478 = (_3453 * _3453) / (_3457 * _3457);
                    float _3482 = (_3471 + 1.0) - _3478;
                    _1746 = _3679 + ((((mix(select(float3(0.0), (_3084 * fast::clamp(0.5 + (((_3471 - 1.0) - _3478) / (2.0 * sqrt(fma(_3482, _3482, 4.0 * _3478)))), 0.0, 1.0)) / float3(_1635.w), bool3(_3185 < 1.0)), _3676 * 0.052631579339504241943359375, float3(_3185)) * _3673) + (_3677 * 0.052631579339504241943359375)) * Lights._data[_1731].xyz) * _1635.w);
                }
                _3693 = _3679;
            }
            else
            {
                _3693 = float3(0.0);
            }
            _3692 = _3693;
        }
        SplitSum.write(float4(_3692, float(_1801)), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

