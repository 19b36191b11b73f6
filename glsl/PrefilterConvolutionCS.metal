#pragma clang diagnostic ignored "-Wmissing-prototypes"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

// Implementation of the GLSL findLSB() function
template<typename T>
inline T spvFindLSB(T x)
{
    return select(ctz(x), T(-1), x == T(0));
}

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
        uint3 _1085 = uint3(0u);
        uint3 _1086 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _1085.x = _1086.x;
        _1085.y = _1086.y;
        _1085.z = _1086.z;
        if (any(gl_GlobalInvocationID >= _1085))
        {
            break;
        }
        float2 _1089 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_1085.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _2619;
        if (param.z == 0u)
        {
            _2619 = float3(1.0, _1089.y, -_1089.x);
        }
        else
        {
            float3 _2620;
            if (param.z == 1u)
            {
                _2620 = float3(-1.0, _1089.y, _1089.x);
            }
            else
            {
                float3 _2621;
                if (param.z == 2u)
                {
                    _2621 = float3(_1089.x, 1.0, -_1089.y);
                }
                else
                {
                    float3 _2622;
                    if (param.z == 3u)
                    {
                        _2622 = float3(_1089.x, -1.0, _1089.y);
                    }
                    else
                    {
                        float3 _2623;
                        if (param.z == 4u)
                        {
                            _2623 = float3(_1089.x, _1089.y, 1.0);
                        }
                        else
                        {
                            _2623 = float3(-_1089.x, _1089.y, -1.0);
                        }
                        _2622 = _2623;
                    }
                    _2621 = _2622;
                }
                _2620 = _2621;
            }
            _2619 = _2620;
        }
        float3 _1379 = fast::normalize(_2619);
        uint3 _1093 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
        uint _1181 = max((_1093.x >> _511.TopLevel), 1u);
        uint _1183 = spvFindUMSB(_1093.x);
        float _2625;
        float _2626;
        _2626 = 0.0;
        _2625 = 0.0;
        float _1410;
        float _1414;
        for (uint _2624 = 0u; _2624 < 6u; _2626 = _1414, _2625 = _1410, _2624++)
        {
            float4 _2760;
            float4 _2761;
            do
            {
                if (_1183 == 0u)
                {
                    int3 _1445 = int4(0, 0, int(_2624), 0).xyz;
                    float4 _1468 = TexelSolidAngle.read(uint2(int2(0)), 0);
                    float _1469 = _1468.x;
                    float2 _1510 = ((spvFAdd(float2(0.0), float2(0.5)) / float2(float(_1093.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2755;
                    if (_2624 == 0u)
                    {
                        _2755 = float3(1.0, _1510.y, -_1510.x);
                    }
                    else
                    {
                        float3 _2756;
                        if (_2624 == 1u)
                        {
                            _2756 = float3(-1.0, _1510.y, _1510.x);
                        }
                        else
                        {
                            float3 _2757;
                            if (_2624 == 2u)
                            {
                                _2757 = float3(_1510.x, 1.0, -_1510.y);
                            }
                            else
                            {
                                float3 _2758;
                                if (_2624 == 3u)
                                {
                                    _2758 = float3(_1510.x, -1.0, _1510.y);
                                }
                                else
                                {
                                    float3 _2759;
                                    if (_2624 == 4u)
                                    {
                                        _2759 = float3(_1510.x, _1510.y, 1.0);
                                    }
                                    else
                                    {
                                        _2759 = float3(-_1510.x, _1510.y, -1.0);
                                    }
                                    _2758 = _2759;
                                }
                                _2757 = _2758;
                            }
                            _2756 = _2757;
                        }
                        _2755 = _2756;
                    }
                    float3 _1624 = fast::normalize(_2755);
                    float _1530 = spvFMul(fast::max(dot(Source.read(uint2(_1445.xy), uint(_1445.z), 0).xyz, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1469);
                    _2761 = float4(_1624 * _1469, _1469);
                    _2760 = float4(_1624 * _1530, _1530);
                    break;
                }
                int4 _1488 = int4(0, 0, int(_2624), int(_1183 - 1u));
                int4 _1431 = _1488;
                int3 _1497 = _1488.xyz;
                int3 _1503 = _1488.xyz;
                _2761 = Geometry.read(uint2(_1503.xy), uint(_1503.z), _1431.w);
                _2760 = Centroid.read(uint2(_1497.xy), uint(_1497.z), _1431.w);
                break;
            } while(false);
            float4 _1384 = _2760;
            float4 _1385 = _2761;
            _1410 = _2625 + _1384.w;
            _1414 = _2626 + _1385.w;
        }
        float _1421 = _2625 / _2626;
        uint _1192 = 3u + (2u * (_511.TopLevel - _511.FineLevel));
        uint _1207 = (65535u / _1192) - min(((((6u * _1181) * _1181) + (3u * _511.TopLevel)) + 1u), (65535u / _1192));
        float3 _2628;
        float _2630;
        uint2 _2632;
        _2632 = uint2(0u);
        _2630 = 0.0;
        _2628 = float3(0.0);
        uint _2780;
        float3 _2787;
        float _2799;
        uint2 _2802;
        uint _2803;
        uint _2804;
        for (uint _2627 = 0u, _2633 = _511.TopLevel, _2650 = 0u; _2627 < 6u; _2650 = _2804, _2633 = _2803, _2632 = _2802, _2630 = _2799, _2628 = _2787, _2627 = _2780)
        {
            float4 _2639;
            float4 _2640;
            float4 _2641;
            do
            {
                if (_2633 == 0u)
                {
                    int3 _1648 = int4(int2(_2632), int(_2627), 0).xyz;
                    float4 _1671 = TexelSolidAngle.read(uint2(int3(int2(_2632), 0).xy), 0);
                    float _1672 = _1671.x;
                    float3 _1673 = Source.read(uint2(_1648.xy), uint(_1648.z), 0).xyz;
                    float2 _1713 = ((spvFAdd(float2(_2632), float2(0.5)) / float2(float(_1093.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2634;
                    if (_2627 == 0u)
                    {
                        _2634 = float3(1.0, _1713.y, -_1713.x);
                    }
                    else
                    {
                        float3 _2635;
                        if (_2627 == 1u)
                        {
                            _2635 = float3(-1.0, _1713.y, _1713.x);
                        }
                        else
                        {
                            float3 _2636;
                            if (_2627 == 2u)
                            {
                                _2636 = float3(_1713.x, 1.0, -_1713.y);
                            }
                            else
                            {
                                float3 _2637;
                                if (_2627 == 3u)
                                {
                                    _2637 = float3(_1713.x, -1.0, _1713.y);
                                }
                                else
                                {
                                    float3 _2638;
                                    if (_2627 == 4u)
                                    {
                                        _2638 = float3(_1713.x, _1713.y, 1.0);
                                    }
                                    else
                                    {
                                        _2638 = float3(-_1713.x, _1713.y, -1.0);
                                    }
                                    _2637 = _2638;
                                }
                                _2636 = _2637;
                            }
                            _2635 = _2636;
                        }
                        _2634 = _2635;
                    }
                    float3 _1827 = fast::normalize(_2634);
                    float _1733 = spvFMul(fast::max(dot(_1673, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1672);
                    _2641 = float4(_1827 * _1672, _1672);
                    _2640 = float4(_1827 * _1733, _1733);
                    _2639 = float4(_1673 * _1672, _1672);
                    break;
                }
                int4 _1691 = int4(int2(_2632), int(_2627), int(_2633 - 1u));
                int4 _1634 = _1691;
                int3 _1694 = _1691.xyz;
                int3 _1700 = _1691.xyz;
                int3 _1706 = _1691.xyz;
                _2641 = Geometry.read(uint2(_1706.xy), uint(_1706.z), _1634.w);
                _2640 = Centroid.read(uint2(_1700.xy), uint(_1700.z), _1634.w);
                _2639 = Energy.read(uint2(_1694.xy), uint(_1694.z), _1634.w);
                break;
            } while(false);
            float4 _1106 = _2639;
            float4 _1107 = _2640;
            float4 _1108 = _2641;
            uint _1234 = max((_1093.x >> _2633), 1u);
            float4 _1122 = _2640;
            float4 _1123 = _2641;
            float2 _1830 = (((float2(_2632) + float2(0.5)) / float2(float(_1234))) - float2(0.5)) * float2(2.0, -2.0);
            float3 _2667;
            if (_2627 == 0u)
            {
                _2667 = float3(1.0, _1830.y, -_1830.x);
            }
            else
            {
                float3 _2668;
                if (_2627 == 1u)
                {
                    _2668 = float3(-1.0, _1830.y, _1830.x);
                }
                else
                {
                    float3 _2669;
                    if (_2627 == 2u)
                    {
                        _2669 = float3(_1830.x, 1.0, -_1830.y);
                    }
                    else
                    {
                        float3 _2670;
                        if (_2627 == 3u)
                        {
                            _2670 = float3(_1830.x, -1.0, _1830.y);
                        }
                        else
                        {
                            float3 _2671;
                            if (_2627 == 4u)
                            {
                                _2671 = float3(_1830.x, _1830.y, 1.0);
                            }
                            else
                            {
                                _2671 = float3(-_1830.x, _1830.y, -1.0);
                            }
                            _2670 = _2671;
                        }
                        _2669 = _2670;
                    }
                    _2668 = _2669;
                }
                _2667 = _2668;
            }
            float _1850 = dot(_1379, fast::normalize(_2667));
            float _1868 = ((_511.Refine * 2.0) / float(_1234)) * pow(fast::max(_1122.w / fast::max(_1123.w * _1421, 1.0000000031710768509710513471353e-30), 1.0), 0.3333333432674407958984375);
            if (((_2633 > _511.FineLevel) && (_2650 < _1207)) && ((fma(-2.0, _1850, 2.0) < (_1868 * _1868)) || ((_2633 > _511.HorizonLevel) && (abs(_1850) < (2.0 / float(_1234))))))
            {
                _2804 = _2650;
                _2803 = _2633 - 1u;
                _2802 = _2632 * uint2(2u);
                _2799 = _2630;
                _2787 = _2628;
                _2780 = _2627;
                continue;
            }
            float3 _1256 = _2641.xyz / float3(_1108.w);
            float3 _1268 = select(_1256, _2640.xyz / float3(_1107.w), bool3(_1107.w > 0.0));
            float _1967 = dot(_1268, _1268);
            float _1970 = dot(_1379, _1268);
            float _1982 = (0.5 * fast::max(1.0 - _1967, 0.0)) * fast::max(1.0 - ((_1970 * _1970) / _1967), 0.0);
            float _2010 = sqrt(fast::max(_1982, 0.0));
            float _2015 = sqrt(fma(0.5, fast::max(_1970, 0.0), 0.5));
            float _2145 = _511.Roughness * _511.Roughness;
            float _2157 = fma(_2015 * _2015, fma(_2145, _2145, -1.0), 1.0);
            float _2021 = (0.5 * _511.Roughness) * _511.Roughness;
            float _2673;
            if (_1970 > (3.0 * _2010))
            {
                float _2033 = ((_511.Roughness * _511.Roughness) * _511.Roughness) * _511.Roughness;
                float _2036 = fma(0.5, _2033, 0.5);
                float _2039 = fma(0.5, _2033, -0.5);
                float _2044 = fma(_2039, _1970, _2036);
                float _2674;
                if (_511.Weighting == 0u)
                {
                    _2674 = _1970 + ((((0.5 * _1982) * (-_2039)) * fma(4.0, _2036, -((2.0 * _2039) * _1970))) / (_2044 * _2044));
                }
                else
                {
                    float _2074 = fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _1970, _2021);
                    float _2077 = _1970 / _2074;
                    _2674 = fma(0.5 * _1982, (((((_2077 * 6.0) * _2039) * _2039) / (_2044 * _2044)) - (((4.0 * _2039) * (_2021 / (_2074 * _2074))) / _2044)) + ((((-2.0) * fma(_511.Roughness * (-0.5), _511.Roughness, 1.0)) * _2021) / ((_2074 * _2074) * _2074)), _2077);
                }
                _2673 = _2674;
            }
            else
            {
                float _2672;
                if ((_2010 > 0.0) && (abs(_1970) <= (5.0 * _2010)))
                {
                    float _2184 = _1970 / _2010;
                    float _2208 = abs(_2184);
                    float _2212 = fma(_2208, 0.23164187371730804443359375, 1.0);
                    float _2213 = 1.0 / _2212;
                    float _2229 = (0.5 / _2212) * fma(_2213, fma(_2213, fma(_2213, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2212), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2234 = exp((_2208 * (-0.707106769084930419921875)) * (_2208 * 0.707106769084930419921875));
                    _2672 = fma(_2010, exp(((-0.5) * _2184) * _2184) * 0.398942291736602783203125, _1970 * ((_2184 >= 0.0) ? fma(-_2229, _2234, 1.0) : (_2229 * _2234)));
                }
                else
                {
                    _2672 = fast::max(_1970, 0.0);
                }
                float _2123 = fast::max(_2672, 0.0);
                _2673 = (_511.Weighting == 0u) ? _2123 : (_2123 / fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2123, _2021));
            }
            float _2262 = dot(_1256, _1256);
            float _2265 = dot(_1379, _1256);
            float _2277 = (0.5 * fast::max(1.0 - _2262, 0.0)) * fast::max(1.0 - ((_2265 * _2265) / _2262), 0.0);
            float _2305 = sqrt(fast::max(_2277, 0.0));
            float _2310 = sqrt(fma(0.5, fast::max(_2265, 0.0), 0.5));
            float _2440 = _511.Roughness * _511.Roughness;
            float _2452 = fma(_2310 * _2310, fma(_2440, _2440, -1.0), 1.0);
            float _2316 = (0.5 * _511.Roughness) * _511.Roughness;
            float _2690;
            if (_2265 > (3.0 * _2305))
            {
                float _2328 = ((_511.Roughness * _511.Roughness) * _511.Roughness) * _511.Roughness;
                float _2331 = fma(0.5, _2328, 0.5);
                float _2334 = fma(0.5, _2328, -0.5);
                float _2339 = fma(_2334, _2265, _2331);
                float _2691;
                if (_511.Weighting == 0u)
                {
                    _2691 = _2265 + ((((0.5 * _2277) * (-_2334)) * fma(4.0, _2331, -((2.0 * _2334) * _2265))) / (_2339 * _2339));
                }
                else
                {
                    float _2369 = fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2265, _2316);
                    float _2372 = _2265 / _2369;
                    _2691 = fma(0.5 * _2277, (((((_2372 * 6.0) * _2334) * _2334) / (_2339 * _2339)) - (((4.0 * _2334) * (_2316 / (_2369 * _2369))) / _2339)) + ((((-2.0) * fma(_511.Roughness * (-0.5), _511.Roughness, 1.0)) * _2316) / ((_2369 * _2369) * _2369)), _2372);
                }
                _2690 = _2691;
            }
            else
            {
                float _2689;
                if ((_2305 > 0.0) && (abs(_2265) <= (5.0 * _2305)))
                {
                    float _2479 = _2265 / _2305;
                    float _2503 = abs(_2479);
                    float _2507 = fma(_2503, 0.23164187371730804443359375, 1.0);
                    float _2508 = 1.0 / _2507;
                    float _2524 = (0.5 / _2507) * fma(_2508, fma(_2508, fma(_2508, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2507), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2529 = exp((_2503 * (-0.707106769084930419921875)) * (_2503 * 0.707106769084930419921875));
                    _2689 = fma(_2305, exp(((-0.5) * _2479) * _2479) * 0.398942291736602783203125, _2265 * ((_2479 >= 0.0) ? fma(-_2524, _2529, 1.0) : (_2524 * _2529)));
                }
                else
                {
                    _2689 = fast::max(_2265, 0.0);
                }
                float _2418 = fast::max(_2689, 0.0);
                _2690 = (_511.Weighting == 0u) ? _2418 : (_2418 / fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2418, _2316));
            }
            uint2 _1133 = _2632;
            uint _2552 = _1133.x;
            uint _2554 = _1133.y;
            uint _2562 = min(spvFindLSB(~(_2552 & _2554)), (_511.TopLevel - _2633));
            _1133 = _2632 >> uint2(_2562);
            uint _2569 = _2633 + _2562;
            uint _2753;
            if (_2569 == _511.TopLevel)
            {
                uint _2576 = spvFindLSB(_1181);
                uint _2581 = _1133.y;
                uint _2586 = _1133.x;
                uint _2588 = ((((_2627 << _2576) + _2581) << _2576) + _2586) + 1u;
                _1133 = uint2(_2588 & (_1181 - 1u), (_2588 >> _2576) & (_1181 - 1u));
                _2753 = _2588 >> (2u * _2576);
            }
            else
            {
                if ((_1133.x & 1u) == 0u)
                {
                    _1133.x++;
                }
                else
                {
                    _1133 += uint2(4294967295u, 1u);
                }
                _2753 = _2627;
            }
            _2804 = _2650 + 1u;
            _2803 = _2569;
            _2802 = _1133;
            _2799 = fma(_1106.w, ((_2440 * _2440) / ((3.1415927410125732421875 * _2452) * _2452)) * _2690, _2630);
            _2787 = _2628 + (_2639.xyz * (((_2145 * _2145) / ((3.1415927410125732421875 * _2157) * _2157)) * _2673));
            _2780 = _2753;
        }
        Prefiltered.write(float4(_2628 / float3(_2630), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

