#pragma clang diagnostic ignored "-Wmissing-prototypes"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

// Implementation of the unsigned GLSL findMSB() function
template<typename T>
inline T spvFindUMSB(T x)
{
    return select(clz(T(0)) - (clz(x) + T(1)), T(-1), x == T(0));
}

template<typename T>
[[clang::optnone]] T spvFMul(T l, T r)
{
    return fma(l, r, T(0));
}

template<typename T, int Cols, int Rows>
[[clang::optnone]] vec<T, Cols> spvFMulVectorMatrix(vec<T, Rows> v, matrix<T, Cols, Rows> m)
{
    vec<T, Cols> res = vec<T, Cols>(0);
    for (uint i = Rows; i > 0; --i)
    {
        vec<T, Cols> tmp(0);
        for (uint j = 0; j < Cols; ++j)
        {
            tmp[j] = m[j][i - 1];
        }
        res = fma(tmp, vec<T, Cols>(v[i - 1]), res);
    }
    return res;
}

template<typename T, int Cols, int Rows>
[[clang::optnone]] vec<T, Rows> spvFMulMatrixVector(matrix<T, Cols, Rows> m, vec<T, Cols> v)
{
    vec<T, Rows> res = vec<T, Rows>(0);
    for (uint i = Cols; i > 0; --i)
    {
        res = fma(m[i - 1], vec<T, Rows>(v[i - 1]), res);
    }
    return res;
}

template<typename T, int LCols, int LRows, int RCols, int RRows>
[[clang::optnone]] matrix<T, RCols, LRows> spvFMulMatrixMatrix(matrix<T, LCols, LRows> l, matrix<T, RCols, RRows> r)
{
    matrix<T, RCols, LRows> res;
    for (uint i = 0; i < RCols; i++)
    {
        vec<T, RCols> tmp(0);
        for (uint j = 0; j < LCols; j++)
        {
            tmp = fma(vec<T, RCols>(r[i][j]), l[j], tmp);
        }
        res[i] = tmp;
    }
    return res;
}

template<typename T>
[[clang::optnone]] T spvFAdd(T l, T r)
{
    return fma(T(1), l, r);
}

struct PrefilterConvolutionParameter
{
    float Roughness;
    uint TopLevel;
    uint FineLevel;
    float Refine;
    uint HorizonLevel;
    uint Weighting;
};

kernel void main0(constant PrefilterConvolutionParameter& _511 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d<float> TexelSolidAngle [[texture(1)]], texture2d_array<float> Energy [[texture(2)]], texture2d_array<float> Centroid [[texture(3)]], texture2d_array<float> Geometry [[texture(4)]], texture2d_array<float, access::write> Prefiltered [[texture(5)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _1083 = uint3(0u);
        uint3 _1084 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _1083.x = _1084.x;
        _1083.y = _1084.y;
        _1083.z = _1084.z;
        if (any(gl_GlobalInvocationID >= _1083))
        {
            break;
        }
        float2 _1087 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_1083.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _2615;
        if (param.z == 0u)
        {
            _2615 = float3(1.0, _1087.y, -_1087.x);
        }
        else
        {
            float3 _2616;
            if (param.z == 1u)
            {
                _2616 = float3(-1.0, _1087.y, _1087.x);
            }
            else
            {
                float3 _2617;
                if (param.z == 2u)
                {
                    _2617 = float3(_1087.x, 1.0, -_1087.y);
                }
                else
                {
                    float3 _2618;
                    if (param.z == 3u)
                    {
                        _2618 = float3(_1087.x, -1.0, _1087.y);
                    }
                    else
                    {
                        float3 _2619;
                        if (param.z == 4u)
                        {
                            _2619 = float3(_1087.x, _1087.y, 1.0);
                        }
                        else
                        {
                            _2619 = float3(-_1087.x, _1087.y, -1.0);
                        }
                        _2618 = _2619;
                    }
                    _2617 = _2618;
                }
                _2616 = _2617;
            }
            _2615 = _2616;
        }
        float3 _1377 = fast::normalize(_2615);
        uint3 _1091 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
        uint _1179 = max((_1091.x >> _511.TopLevel), 1u);
        uint _1181 = spvFindUMSB(_1091.x);
        float _2621;
        float _2622;
        _2622 = 0.0;
        _2621 = 0.0;
        float _1408;
        float _1412;
        for (uint _2620 = 0u; _2620 < 6u; _2622 = _1412, _2621 = _1408, _2620++)
        {
            float4 _2760;
            float4 _2761;
            do
            {
                if (_1181 == 0u)
                {
                    int3 _1443 = int4(0, 0, int(_2620), 0).xyz;
                    float4 _1466 = TexelSolidAngle.read(uint2(int2(0)), 0);
                    float _1467 = _1466.x;
                    float2 _1508 = ((spvFAdd(float2(0.0), float2(0.5)) / float2(float(_1091.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2755;
                    if (_2620 == 0u)
                    {
                        _2755 = float3(1.0, _1508.y, -_1508.x);
                    }
                    else
                    {
                        float3 _2756;
                        if (_2620 == 1u)
                        {
                            _2756 = float3(-1.0, _1508.y, _1508.x);
                        }
                        else
                        {
                            float3 _2757;
                            if (_2620 == 2u)
                            {
                                _2757 = float3(_1508.x, 1.0, -_1508.y);
                            }
                            else
                            {
                                float3 _2758;
                                if (_2620 == 3u)
                                {
                                    _2758 = float3(_1508.x, -1.0, _1508.y);
                                }
                                else
                                {
                                    float3 _2759;
                                    if (_2620 == 4u)
                                    {
                                        _2759 = float3(_1508.x, _1508.y, 1.0);
                                    }
                                    else
                                    {
                                        _2759 = float3(-_1508.x, _1508.y, -1.0);
                                    }
                                    _2758 = _2759;
                                }
                                _2757 = _2758;
                            }
                            _2756 = _2757;
                        }
                        _2755 = _2756;
                    }
                    float3 _1622 = fast::normalize(_2755);
                    float _1528 = spvFMul(fast::max(dot(Source.read(uint2(_1443.xy), uint(_1443.z), 0).xyz, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1467);
                    _2761 = float4(_1622 * _1467, _1467);
                    _2760 = float4(_1622 * _1528, _1528);
                    break;
                }
                int4 _1486 = int4(0, 0, int(_2620), int(_1181 - 1u));
                int4 _1429 = _1486;
                int3 _1495 = _1486.xyz;
                int3 _1501 = _1486.xyz;
                _2761 = Geometry.read(uint2(_1501.xy), uint(_1501.z), _1429.w);
                _2760 = Centroid.read(uint2(_1495.xy), uint(_1495.z), _1429.w);
                break;
            } while(false);
            float4 _1382 = _2760;
            float4 _1383 = _2761;
            _1408 = _2621 + _1382.w;
            _1412 = _2622 + _1383.w;
        }
        float _1419 = _2621 / _2622;
        uint _1190 = 3u + (2u * (_511.TopLevel - _511.FineLevel));
        uint _1205 = (65535u / _1190) - min(((((6u * _1179) * _1179) + (3u * _511.TopLevel)) + 1u), (65535u / _1190));
        float3 _2624;
        float _2626;
        uint2 _2628;
        _2628 = uint2(0u);
        _2626 = 0.0;
        _2624 = float3(0.0);
        uint _2780;
        float3 _2787;
        float _2800;
        uint2 _2804;
        uint _2805;
        uint _2806;
        for (uint _2623 = 0u, _2629 = _511.TopLevel, _2646 = 0u; _2623 < 6u; _2646 = _2806, _2629 = _2805, _2628 = _2804, _2626 = _2800, _2624 = _2787, _2623 = _2780)
        {
            float4 _2635;
            float4 _2636;
            float4 _2637;
            do
            {
                if (_2629 == 0u)
                {
                    int3 _1646 = int4(int2(_2628), int(_2623), 0).xyz;
                    float4 _1669 = TexelSolidAngle.read(uint2(int3(int2(_2628), 0).xy), 0);
                    float _1670 = _1669.x;
                    float3 _1671 = Source.read(uint2(_1646.xy), uint(_1646.z), 0).xyz;
                    float2 _1711 = ((spvFAdd(float2(_2628), float2(0.5)) / float2(float(_1091.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2630;
                    if (_2623 == 0u)
                    {
                        _2630 = float3(1.0, _1711.y, -_1711.x);
                    }
                    else
                    {
                        float3 _2631;
                        if (_2623 == 1u)
                        {
                            _2631 = float3(-1.0, _1711.y, _1711.x);
                        }
                        else
                        {
                            float3 _2632;
                            if (_2623 == 2u)
                            {
                                _2632 = float3(_1711.x, 1.0, -_1711.y);
                            }
                            else
                            {
                                float3 _2633;
                                if (_2623 == 3u)
                                {
                                    _2633 = float3(_1711.x, -1.0, _1711.y);
                                }
                                else
                                {
                                    float3 _2634;
                                    if (_2623 == 4u)
                                    {
                                        _2634 = float3(_1711.x, _1711.y, 1.0);
                                    }
                                    else
                                    {
                                        _2634 = float3(-_1711.x, _1711.y, -1.0);
                                    }
                                    _2633 = _2634;
                                }
                                _2632 = _2633;
                            }
                            _2631 = _2632;
                        }
                        _2630 = _2631;
                    }
                    float3 _1825 = fast::normalize(_2630);
                    float _1731 = spvFMul(fast::max(dot(_1671, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1670);
                    _2637 = float4(_1825 * _1670, _1670);
                    _2636 = float4(_1825 * _1731, _1731);
                    _2635 = float4(_1671 * _1670, _1670);
                    break;
                }
                int4 _1689 = int4(int2(_2628), int(_2623), int(_2629 - 1u));
                int4 _1632 = _1689;
                int3 _1692 = _1689.xyz;
                int3 _1698 = _1689.xyz;
                int3 _1704 = _1689.xyz;
                _2637 = Geometry.read(uint2(_1704.xy), uint(_1704.z), _1632.w);
                _2636 = Centroid.read(uint2(_1698.xy), uint(_1698.z), _1632.w);
                _2635 = Energy.read(uint2(_1692.xy), uint(_1692.z), _1632.w);
                break;
            } while(false);
            float4 _1104 = _2635;
            float4 _1105 = _2636;
            float4 _1106 = _2637;
            uint _1232 = max((_1091.x >> _2629), 1u);
            float4 _1120 = _2636;
            float4 _1121 = _2637;
            float2 _1828 = (((float2(_2628) + float2(0.5)) / float2(float(_1232))) - float2(0.5)) * float2(2.0, -2.0);
            float3 _2663;
            if (_2623 == 0u)
            {
                _2663 = float3(1.0, _1828.y, -_1828.x);
            }
            else
            {
                float3 _2664;
                if (_2623 == 1u)
                {
                    _2664 = float3(-1.0, _1828.y, _1828.x);
                }
                else
                {
                    float3 _2665;
                    if (_2623 == 2u)
                    {
                        _2665 = float3(_1828.x, 1.0, -_1828.y);
                    }
                    else
                    {
                        float3 _2666;
                        if (_2623 == 3u)
                        {
                            _2666 = float3(_1828.x, -1.0, _1828.y);
                        }
                        else
                        {
                            float3 _2667;
                            if (_2623 == 4u)
                            {
                                _2667 = float3(_1828.x, _1828.y, 1.0);
                            }
                            else
                            {
                                _2667 = float3(-_1828.x, _1828.y, -1.0);
                            }
                            _2666 = _2667;
                        }
                        _2665 = _2666;
                    }
                    _2664 = _2665;
                }
                _2663 = _2664;
            }
            float _1848 = dot(_1377, fast::normalize(_2663));
            float _1866 = ((_511.Refine * 2.0) / float(_1232)) * pow(fast::max(_1120.w / fast::max(_1121.w * _1419, 1.0000000031710768509710513471353e-30), 1.0), 0.3333333432674407958984375);
            if (((_2629 > _511.FineLevel) && (_2646 < _1205)) && ((fma(-2.0, _1848, 2.0) < (_1866 * _1866)) || ((_2629 > _511.HorizonLevel) && (abs(_1848) < (2.0 / float(_1232))))))
            {
                _2806 = _2646;
                _2805 = _2629 - 1u;
                _2804 = _2628 * uint2(2u);
                _2800 = _2626;
                _2787 = _2624;
                _2780 = _2623;
                continue;
            }
            float3 _1254 = _2637.xyz / float3(_1106.w);
            float3 _1266 = select(_1254, _2636.xyz / float3(_1105.w), bool3(_1105.w > 0.0));
            float _1965 = dot(_1266, _1266);
            float _1968 = dot(_1377, _1266);
            float _1980 = (0.5 * fast::max(1.0 - _1965, 0.0)) * fast::max(1.0 - ((_1968 * _1968) / _1965), 0.0);
            float _2008 = sqrt(fast::max(_1980, 0.0));
            float _2013 = sqrt(fma(0.5, fast::max(_1968, 0.0), 0.5));
            float _2143 = _511.Roughness * _511.Roughness;
            float _2155 = fma(_2013 * _2013, fma(_2143, _2143, -1.0), 1.0);
            float _2019 = (0.5 * _511.Roughness) * _511.Roughness;
            float _2669;
            if (_1968 > (3.0 * _2008))
            {
                float _2031 = ((_511.Roughness * _511.Roughness) * _511.Roughness) * _511.Roughness;
                float _2034 = fma(0.5, _2031, 0.5);
                float _2037 = fma(0.5, _2031, -0.5);
                float _2042 = fma(_2037, _1968, _2034);
                float _2670;
                if (_511.Weighting == 0u)
                {
                    _2670 = _1968 + ((((0.5 * _1980) * (-_2037)) * fma(4.0, _2034, -((2.0 * _2037) * _1968))) / (_2042 * _2042));
                }
                else
                {
                    float _2072 = fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _1968, _2019);
                    float _2075 = _1968 / _2072;
                    _2670 = fma(0.5 * _1980, (((((_2075 * 6.0) * _2037) * _2037) / (_2042 * _2042)) - (((4.0 * _2037) * (_2019 / (_2072 * _2072))) / _2042)) + ((((-2.0) * fma(_511.Roughness * (-0.5), _511.Roughness, 1.0)) * _2019) / ((_2072 * _2072) * _2072)), _2075);
                }
                _2669 = _2670;
            }
            else
            {
                float _2668;
                if ((_2008 > 0.0) && (abs(_1968) <= (5.0 * _2008)))
                {
                    float _2182 = _1968 / _2008;
                    float _2206 = abs(_2182);
                    float _2210 = fma(_2206, 0.23164187371730804443359375, 1.0);
                    float _2211 = 1.0 / _2210;
                    float _2227 = (0.5 / _2210) * fma(_2211, fma(_2211, fma(_2211, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2210), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2232 = exp((_2206 * (-0.707106769084930419921875)) * (_2206 * 0.707106769084930419921875));
                    _2668 = fma(_2008, exp(((-0.5) * _2182) * _2182) * 0.398942291736602783203125, _1968 * ((_2182 >= 0.0) ? fma(-_2227, _2232, 1.0) : (_2227 * _2232)));
                }
                else
                {
                    _2668 = fast::max(_1968, 0.0);
                }
                float _2121 = fast::max(_2668, 0.0);
                _2669 = (_511.Weighting == 0u) ? _2121 : (_2121 / fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2121, _2019));
            }
            float _2260 = dot(_1254, _1254);
            float _2263 = dot(_1377, _1254);
            float _2275 = (0.5 * fast::max(1.0 - _2260, 0.0)) * fast::max(1.0 - ((_2263 * _2263) / _2260), 0.0);
            float _2303 = sqrt(fast::max(_2275, 0.0));
            float _2308 = sqrt(fma(0.5, fast::max(_2263, 0.0), 0.5));
            float _2438 = _511.Roughness * _511.Roughness;
            float _2450 = fma(_2308 * _2308, fma(_2438, _2438, -1.0), 1.0);
            float _2314 = (0.5 * _511.Roughness) * _511.Roughness;
            float _2686;
            if (_2263 > (3.0 * _2303))
            {
                float _2326 = ((_511.Roughness * _511.Roughness) * _511.Roughness) * _511.Roughness;
                float _2329 = fma(0.5, _2326, 0.5);
                float _2332 = fma(0.5, _2326, -0.5);
                float _2337 = fma(_2332, _2263, _2329);
                float _2687;
                if (_511.Weighting == 0u)
                {
                    _2687 = _2263 + ((((0.5 * _2275) * (-_2332)) * fma(4.0, _2329, -((2.0 * _2332) * _2263))) / (_2337 * _2337));
                }
                else
                {
                    float _2367 = fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2263, _2314);
                    float _2370 = _2263 / _2367;
                    _2687 = fma(0.5 * _2275, (((((_2370 * 6.0) * _2332) * _2332) / (_2337 * _2337)) - (((4.0 * _2332) * (_2314 / (_2367 * _2367))) / _2337)) + ((((-2.0) * fma(_511.Roughness * (-0.5), _511.Roughness, 1.0)) * _2314) / ((_2367 * _2367) * _2367)), _2370);
                }
                _2686 = _2687;
            }
            else
            {
                float _2685;
                if ((_2303 > 0.0) && (abs(_2263) <= (5.0 * _2303)))
                {
                    float _2477 = _2263 / _2303;
                    float _2501 = abs(_2477);
                    float _2505 = fma(_2501, 0.23164187371730804443359375, 1.0);
                    float _2506 = 1.0 / _2505;
                    float _2522 = (0.5 / _2505) * fma(_2506, fma(_2506, fma(_2506, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2505), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2527 = exp((_2501 * (-0.707106769084930419921875)) * (_2501 * 0.707106769084930419921875));
                    _2685 = fma(_2303, exp(((-0.5) * _2477) * _2477) * 0.398942291736602783203125, _2263 * ((_2477 >= 0.0) ? fma(-_2522, _2527, 1.0) : (_2522 * _2527)));
                }
                else
                {
                    _2685 = fast::max(_2263, 0.0);
                }
                float _2416 = fast::max(_2685, 0.0);
                _2686 = (_511.Weighting == 0u) ? _2416 : (_2416 / fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2416, _2314));
            }
            uint2 _1131 = _2628;
            uint _2749;
            _2749 = _2629;
            uint _2566;
            for (; (_2749 < _511.TopLevel) && (((_1131.x & _1131.y) & 1u) != 0u); _2749 = _2566)
            {
                _1131 = _1131 >> uint2(int2(1));
                _2566 = _2749 + 1u;
            }
            uint _2751;
            if (_2749 == _511.TopLevel)
            {
                uint _2578 = _1131.y;
                uint _2583 = _1131.x;
                uint _2585 = ((((_2623 * _1179) + _2578) * _1179) + _2583) + 1u;
                _1131 = uint2(_2585 % _1179, (_2585 / _1179) % _1179);
                _2751 = _2585 / (_1179 * _1179);
            }
            else
            {
                if ((_1131.x & 1u) == 0u)
                {
                    _1131.x++;
                }
                else
                {
                    _1131 += uint2(4294967295u, 1u);
                }
                _2751 = _2623;
            }
            _2806 = _2646 + 1u;
            _2805 = _2749;
            _2804 = _1131;
            _2800 = fma(_1104.w, ((_2438 * _2438) / ((3.1415927410125732421875 * _2450) * _2450)) * _2686, _2626);
            _2787 = _2624 + (_2635.xyz * (((_2143 * _2143) / ((3.1415927410125732421875 * _2155) * _2155)) * _2669));
            _2780 = _2751;
        }
        Prefiltered.write(float4(_2624 / float3(_2626), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

