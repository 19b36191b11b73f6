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

kernel void main0(constant PrefilterConvolutionParameter& _509 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d<float> TexelSolidAngle [[texture(1)]], texture2d_array<float> Energy [[texture(2)]], texture2d_array<float> Centroid [[texture(3)]], texture2d_array<float> Geometry [[texture(4)]], texture2d_array<float, access::write> Prefiltered [[texture(5)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _1100 = uint3(0u);
        uint3 _1101 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _1100.x = _1101.x;
        _1100.y = _1101.y;
        _1100.z = _1101.z;
        if (any(gl_GlobalInvocationID >= _1100))
        {
            break;
        }
        float2 _1104 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_1100.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _2652;
        if (param.z == 0u)
        {
            _2652 = float3(1.0, _1104.y, -_1104.x);
        }
        else
        {
            float3 _2653;
            if (param.z == 1u)
            {
                _2653 = float3(-1.0, _1104.y, _1104.x);
            }
            else
            {
                float3 _2654;
                if (param.z == 2u)
                {
                    _2654 = float3(_1104.x, 1.0, -_1104.y);
                }
                else
                {
                    float3 _2655;
                    if (param.z == 3u)
                    {
                        _2655 = float3(_1104.x, -1.0, _1104.y);
                    }
                    else
                    {
                        float3 _2656;
                        if (param.z == 4u)
                        {
                            _2656 = float3(_1104.x, _1104.y, 1.0);
                        }
                        else
                        {
                            _2656 = float3(-_1104.x, _1104.y, -1.0);
                        }
                        _2655 = _2656;
                    }
                    _2654 = _2655;
                }
                _2653 = _2654;
            }
            _2652 = _2653;
        }
        float3 _1393 = fast::normalize(_2652);
        uint3 _1108 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
        uint _1194 = max((_1108.x >> _509.TopLevel), 1u);
        uint _1196 = spvFindUMSB(_1108.x);
        float _2658;
        float _2659;
        _2659 = 0.0;
        _2658 = 0.0;
        float _1424;
        float _1428;
        for (uint _2657 = 0u; _2657 < 6u; _2659 = _1428, _2658 = _1424, _2657++)
        {
            float4 _2803;
            float4 _2804;
            do
            {
                if (_1196 == 0u)
                {
                    int3 _1459 = int4(0, 0, int(_2657), 0).xyz;
                    float4 _1482 = TexelSolidAngle.read(uint2(int2(0)), 0);
                    float _1483 = _1482.x;
                    float2 _1524 = ((spvFAdd(float2(0.0), float2(0.5)) / float2(float(_1108.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2798;
                    if (_2657 == 0u)
                    {
                        _2798 = float3(1.0, _1524.y, -_1524.x);
                    }
                    else
                    {
                        float3 _2799;
                        if (_2657 == 1u)
                        {
                            _2799 = float3(-1.0, _1524.y, _1524.x);
                        }
                        else
                        {
                            float3 _2800;
                            if (_2657 == 2u)
                            {
                                _2800 = float3(_1524.x, 1.0, -_1524.y);
                            }
                            else
                            {
                                float3 _2801;
                                if (_2657 == 3u)
                                {
                                    _2801 = float3(_1524.x, -1.0, _1524.y);
                                }
                                else
                                {
                                    float3 _2802;
                                    if (_2657 == 4u)
                                    {
                                        _2802 = float3(_1524.x, _1524.y, 1.0);
                                    }
                                    else
                                    {
                                        _2802 = float3(-_1524.x, _1524.y, -1.0);
                                    }
                                    _2801 = _2802;
                                }
                                _2800 = _2801;
                            }
                            _2799 = _2800;
                        }
                        _2798 = _2799;
                    }
                    float3 _1638 = fast::normalize(_2798);
                    float _1544 = spvFMul(fast::max(dot(Source.read(uint2(_1459.xy), uint(_1459.z), 0).xyz, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1483);
                    _2804 = float4(_1638 * _1483, _1483);
                    _2803 = float4(_1638 * _1544, _1544);
                    break;
                }
                int4 _1502 = int4(0, 0, int(_2657), int(_1196 - 1u));
                int4 _1445 = _1502;
                int3 _1511 = _1502.xyz;
                int3 _1517 = _1502.xyz;
                _2804 = Geometry.read(uint2(_1517.xy), uint(_1517.z), _1445.w);
                _2803 = Centroid.read(uint2(_1511.xy), uint(_1511.z), _1445.w);
                break;
            } while(false);
            float4 _1398 = _2803;
            float4 _1399 = _2804;
            _1424 = _2658 + _1398.w;
            _1428 = _2659 + _1399.w;
        }
        float _1435 = _2658 / _2659;
        uint _1205 = 3u + (2u * (_509.TopLevel - _509.FineLevel));
        uint _1220 = (65535u / _1205) - min(((((6u * _1194) * _1194) + (3u * _509.TopLevel)) + 1u), (65535u / _1205));
        float3 _2661;
        float _2663;
        uint2 _2671;
        _2671 = uint2(0u);
        _2663 = 0.0;
        _2661 = float3(0.0);
        float3 _1292;
        float _1302;
        uint _1304;
        uint2 _1311;
        uint _2792;
        uint _2794;
        for (uint _2660 = 0u, _2666 = _509.TopLevel, _2668 = 0u; _2660 < 6u; _2671 = _1311, _2668 = _1304, _2666 = _2792, _2663 = _1302, _2661 = _1292, _2660 = _2794)
        {
            uint _2665;
            uint2 _2670;
            _2670 = _2671;
            _2665 = _2666;
            uint2 _1252;
            uint _1254;
            for (;;)
            {
                uint _1241 = max((_1108.x >> _2665), 1u);
                float2 _1641 = (((float2(_2670) + float2(0.5)) / float2(float(_1241))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _2672;
                if (_2660 == 0u)
                {
                    _2672 = float3(1.0, _1641.y, -_1641.x);
                }
                else
                {
                    float3 _2673;
                    if (_2660 == 1u)
                    {
                        _2673 = float3(-1.0, _1641.y, _1641.x);
                    }
                    else
                    {
                        float3 _2674;
                        if (_2660 == 2u)
                        {
                            _2674 = float3(_1641.x, 1.0, -_1641.y);
                        }
                        else
                        {
                            float3 _2675;
                            if (_2660 == 3u)
                            {
                                _2675 = float3(_1641.x, -1.0, _1641.y);
                            }
                            else
                            {
                                float3 _2676;
                                if (_2660 == 4u)
                                {
                                    _2676 = float3(_1641.x, _1641.y, 1.0);
                                }
                                else
                                {
                                    _2676 = float3(-_1641.x, _1641.y, -1.0);
                                }
                                _2675 = _2676;
                            }
                            _2674 = _2675;
                        }
                        _2673 = _2674;
                    }
                    _2672 = _2673;
                }
                float _1662 = dot(_1393, fast::normalize(_2672));
                int4 _1672 = int4(int2(_2670), int(_2660), int(_2665 - 1u));
                int4 _1643 = _1672;
                int3 _1675 = _1672.xyz;
                int3 _1682 = _1672.xyz;
                float _1700 = ((_509.Refine * 2.0) / float(_1241)) * pow(fast::max(Centroid.read(uint2(_1675.xy), uint(_1675.z), _1643.w).w / fast::max(Geometry.read(uint2(_1682.xy), uint(_1682.z), _1643.w).w * _1435, 1.0000000031710768509710513471353e-30), 1.0), 0.3333333432674407958984375);
                if (((_2665 > _509.FineLevel) && (_2668 < _1220)) && ((fma(-2.0, _1662, 2.0) < (_1700 * _1700)) || ((_2665 > _509.HorizonLevel) && (abs(_1662) < (2.0 / float(_1241))))))
                {
                    _1252 = _2670 * uint2(2u);
                    _1254 = _2665 - 1u;
                    _2670 = _1252;
                    _2665 = _1254;
                    continue;
                }
                else
                {
                    break;
                }
            }
            float4 _2697;
            float4 _2698;
            float4 _2699;
            do
            {
                if (_2665 == 0u)
                {
                    int3 _1812 = int4(int2(_2670), int(_2660), 0).xyz;
                    float4 _1835 = TexelSolidAngle.read(uint2(int3(int2(_2670), 0).xy), 0);
                    float _1836 = _1835.x;
                    float3 _1837 = Source.read(uint2(_1812.xy), uint(_1812.z), 0).xyz;
                    float2 _1877 = ((spvFAdd(float2(_2670), float2(0.5)) / float2(float(_1108.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2692;
                    if (_2660 == 0u)
                    {
                        _2692 = float3(1.0, _1877.y, -_1877.x);
                    }
                    else
                    {
                        float3 _2693;
                        if (_2660 == 1u)
                        {
                            _2693 = float3(-1.0, _1877.y, _1877.x);
                        }
                        else
                        {
                            float3 _2694;
                            if (_2660 == 2u)
                            {
                                _2694 = float3(_1877.x, 1.0, -_1877.y);
                            }
                            else
                            {
                                float3 _2695;
                                if (_2660 == 3u)
                                {
                                    _2695 = float3(_1877.x, -1.0, _1877.y);
                                }
                                else
                                {
                                    float3 _2696;
                                    if (_2660 == 4u)
                                    {
                                        _2696 = float3(_1877.x, _1877.y, 1.0);
                                    }
                                    else
                                    {
                                        _2696 = float3(-_1877.x, _1877.y, -1.0);
                                    }
                                    _2695 = _2696;
                                }
                                _2694 = _2695;
                            }
                            _2693 = _2694;
                        }
                        _2692 = _2693;
                    }
                    float3 _1991 = fast::normalize(_2692);
                    float _1897 = spvFMul(fast::max(dot(_1837, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1836);
                    _2699 = float4(_1991 * _1836, _1836);
                    _2698 = float4(_1991 * _1897, _1897);
                    _2697 = float4(_1837 * _1836, _1836);
                    break;
                }
                int4 _1855 = int4(int2(_2670), int(_2660), int(_2665 - 1u));
                int4 _1798 = _1855;
                int3 _1858 = _1855.xyz;
                int3 _1864 = _1855.xyz;
                int3 _1870 = _1855.xyz;
                _2699 = Geometry.read(uint2(_1870.xy), uint(_1870.z), _1798.w);
                _2698 = Centroid.read(uint2(_1864.xy), uint(_1864.z), _1798.w);
                _2697 = Energy.read(uint2(_1858.xy), uint(_1858.z), _1798.w);
                break;
            } while(false);
            float4 _1127 = _2697;
            float4 _1128 = _2698;
            float4 _1129 = _2699;
            float3 _1270 = _2699.xyz / float3(_1129.w);
            float3 _1282 = select(_1270, _2698.xyz / float3(_1128.w), bool3(_1128.w > 0.0));
            float _2002 = dot(_1282, _1282);
            float _2005 = dot(_1393, _1282);
            float _2017 = (0.5 * fast::max(1.0 - _2002, 0.0)) * fast::max(1.0 - ((_2005 * _2005) / _2002), 0.0);
            float _2045 = sqrt(fast::max(_2017, 0.0));
            float _2050 = sqrt(fma(0.5, fast::max(_2005, 0.0), 0.5));
            float _2180 = _509.Roughness * _509.Roughness;
            float _2192 = fma(_2050 * _2050, fma(_2180, _2180, -1.0), 1.0);
            float _2056 = (0.5 * _509.Roughness) * _509.Roughness;
            float _2701;
            if (_2005 > (3.0 * _2045))
            {
                float _2068 = ((_509.Roughness * _509.Roughness) * _509.Roughness) * _509.Roughness;
                float _2071 = fma(0.5, _2068, 0.5);
                float _2074 = fma(0.5, _2068, -0.5);
                float _2079 = fma(_2074, _2005, _2071);
                float _2702;
                if (_509.Weighting == 0u)
                {
                    _2702 = _2005 + ((((0.5 * _2017) * (-_2074)) * fma(4.0, _2071, -((2.0 * _2074) * _2005))) / (_2079 * _2079));
                }
                else
                {
                    float _2109 = fma(fma(_509.Roughness * (-0.5), _509.Roughness, 1.0), _2005, _2056);
                    float _2112 = _2005 / _2109;
                    _2702 = fma(0.5 * _2017, (((((_2112 * 6.0) * _2074) * _2074) / (_2079 * _2079)) - (((4.0 * _2074) * (_2056 / (_2109 * _2109))) / _2079)) + ((((-2.0) * fma(_509.Roughness * (-0.5), _509.Roughness, 1.0)) * _2056) / ((_2109 * _2109) * _2109)), _2112);
                }
                _2701 = _2702;
            }
            else
            {
                float _2700;
                if ((_2045 > 0.0) && (abs(_2005) <= (5.0 * _2045)))
                {
                    float _2219 = _2005 / _2045;
                    float _2243 = abs(_2219);
                    float _2247 = fma(_2243, 0.23164187371730804443359375, 1.0);
                    float _2248 = 1.0 / _2247;
                    float _2264 = (0.5 / _2247) * fma(_2248, fma(_2248, fma(_2248, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2247), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2269 = exp((_2243 * (-0.707106769084930419921875)) * (_2243 * 0.707106769084930419921875));
                    _2700 = fma(_2045, exp(((-0.5) * _2219) * _2219) * 0.398942291736602783203125, _2005 * ((_2219 >= 0.0) ? fma(-_2264, _2269, 1.0) : (_2264 * _2269)));
                }
                else
                {
                    _2700 = fast::max(_2005, 0.0);
                }
                float _2158 = fast::max(_2700, 0.0);
                _2701 = (_509.Weighting == 0u) ? _2158 : (_2158 / fma(fma(_509.Roughness * (-0.5), _509.Roughness, 1.0), _2158, _2056));
            }
            _1292 = _2661 + (_2697.xyz * (((_2180 * _2180) / ((3.1415927410125732421875 * _2192) * _2192)) * _2701));
            float _2297 = dot(_1270, _1270);
            float _2300 = dot(_1393, _1270);
            float _2312 = (0.5 * fast::max(1.0 - _2297, 0.0)) * fast::max(1.0 - ((_2300 * _2300) / _2297), 0.0);
            float _2340 = sqrt(fast::max(_2312, 0.0));
            float _2345 = sqrt(fma(0.5, fast::max(_2300, 0.0), 0.5));
            float _2475 = _509.Roughness * _509.Roughness;
            float _2487 = fma(_2345 * _2345, fma(_2475, _2475, -1.0), 1.0);
            float _2351 = (0.5 * _509.Roughness) * _509.Roughness;
            float _2719;
            if (_2300 > (3.0 * _2340))
            {
                float _2363 = ((_509.Roughness * _509.Roughness) * _509.Roughness) * _509.Roughness;
                float _2366 = fma(0.5, _2363, 0.5);
                float _2369 = fma(0.5, _2363, -0.5);
                float _2374 = fma(_2369, _2300, _2366);
                float _2720;
                if (_509.Weighting == 0u)
                {
                    _2720 = _2300 + ((((0.5 * _2312) * (-_2369)) * fma(4.0, _2366, -((2.0 * _2369) * _2300))) / (_2374 * _2374));
                }
                else
                {
                    float _2404 = fma(fma(_509.Roughness * (-0.5), _509.Roughness, 1.0), _2300, _2351);
                    float _2407 = _2300 / _2404;
                    _2720 = fma(0.5 * _2312, (((((_2407 * 6.0) * _2369) * _2369) / (_2374 * _2374)) - (((4.0 * _2369) * (_2351 / (_2404 * _2404))) / _2374)) + ((((-2.0) * fma(_509.Roughness * (-0.5), _509.Roughness, 1.0)) * _2351) / ((_2404 * _2404) * _2404)), _2407);
                }
                _2719 = _2720;
            }
            else
            {
                float _2718;
                if ((_2340 > 0.0) && (abs(_2300) <= (5.0 * _2340)))
                {
                    float _2514 = _2300 / _2340;
                    float _2538 = abs(_2514);
                    float _2542 = fma(_2538, 0.23164187371730804443359375, 1.0);
                    float _2543 = 1.0 / _2542;
                    float _2559 = (0.5 / _2542) * fma(_2543, fma(_2543, fma(_2543, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2542), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2564 = exp((_2538 * (-0.707106769084930419921875)) * (_2538 * 0.707106769084930419921875));
                    _2718 = fma(_2340, exp(((-0.5) * _2514) * _2514) * 0.398942291736602783203125, _2300 * ((_2514 >= 0.0) ? fma(-_2559, _2564, 1.0) : (_2559 * _2564)));
                }
                else
                {
                    _2718 = fast::max(_2300, 0.0);
                }
                float _2453 = fast::max(_2718, 0.0);
                _2719 = (_509.Weighting == 0u) ? _2453 : (_2453 / fma(fma(_509.Roughness * (-0.5), _509.Roughness, 1.0), _2453, _2351));
            }
            _1302 = fma(_1127.w, ((_2475 * _2475) / ((3.1415927410125732421875 * _2487) * _2487)) * _2719, _2663);
            _1304 = _2668 + 1u;
            uint2 _1146 = _2670;
            _2792 = _2665;
            uint _2603;
            for (; (_2792 < _509.TopLevel) && (((_1146.x & _1146.y) & 1u) != 0u); _2792 = _2603)
            {
                _1146 = _1146 >> uint2(int2(1));
                _2603 = _2792 + 1u;
            }
            if (_2792 == _509.TopLevel)
            {
                uint _2615 = _1146.y;
                uint _2620 = _1146.x;
                uint _2622 = ((((_2660 * _1194) + _2615) * _1194) + _2620) + 1u;
                _1146 = uint2(_2622 % _1194, (_2622 / _1194) % _1194);
                _2794 = _2622 / (_1194 * _1194);
            }
            else
            {
                if ((_1146.x & 1u) == 0u)
                {
                    _1146.x++;
                }
                else
                {
                    _1146 += uint2(4294967295u, 1u);
                }
                _2794 = _2660;
            }
            _1311 = _1146;
        }
        Prefiltered.write(float4(_2661 / float3(_2663), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

