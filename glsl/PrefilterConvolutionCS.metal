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

kernel void main0(constant PrefilterConvolutionParameter& _523 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d<float> TexelSolidAngle [[texture(1)]], texture2d_array<float> Energy [[texture(2)]], texture2d_array<float> Centroid [[texture(3)]], texture2d_array<float> Geometry [[texture(4)]], texture2d_array<float, access::write> Prefiltered [[texture(5)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _1123 = uint3(0u);
        uint3 _1124 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _1123.x = _1124.x;
        _1123.y = _1124.y;
        _1123.z = _1124.z;
        if (any(gl_GlobalInvocationID >= _1123))
        {
            break;
        }
        float2 _1366 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_1123.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _2691;
        if (param.z == 0u)
        {
            _2691 = float3(1.0, _1366.y, -_1366.x);
        }
        else
        {
            float3 _2692;
            if (param.z == 1u)
            {
                _2692 = float3(-1.0, _1366.y, _1366.x);
            }
            else
            {
                float3 _2693;
                if (param.z == 2u)
                {
                    _2693 = float3(_1366.x, 1.0, -_1366.y);
                }
                else
                {
                    float3 _2694;
                    if (param.z == 3u)
                    {
                        _2694 = float3(_1366.x, -1.0, _1366.y);
                    }
                    else
                    {
                        float3 _2695;
                        if (param.z == 4u)
                        {
                            _2695 = float3(_1366.x, _1366.y, 1.0);
                        }
                        else
                        {
                            _2695 = float3(-_1366.x, _1366.y, -1.0);
                        }
                        _2694 = _2695;
                    }
                    _2693 = _2694;
                }
                _2692 = _2693;
            }
            _2691 = _2692;
        }
        float3 _1372 = fast::normalize(_2691);
        uint3 _1131 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
        uint _1224 = max((_1131.x >> _523.TopLevel), 1u);
        uint _1226 = spvFindUMSB(_1131.x);
        float _2697;
        float _2698;
        _2698 = 0.0;
        _2697 = 0.0;
        float _1469;
        float _1473;
        for (uint _2696 = 0u; _2696 < 6u; _2698 = _1473, _2697 = _1469, _2696++)
        {
            float4 _2832;
            float4 _2833;
            do
            {
                if (_1226 == 0u)
                {
                    int3 _1504 = int4(0, 0, int(_2696), 0).xyz;
                    float4 _1527 = TexelSolidAngle.read(uint2(int2(0)), 0);
                    float _1528 = _1527.x;
                    float2 _1618 = ((spvFAdd(float2(0.0), float2(0.5)) / float2(float(_1131.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2827;
                    if (_2696 == 0u)
                    {
                        _2827 = float3(1.0, _1618.y, -_1618.x);
                    }
                    else
                    {
                        float3 _2828;
                        if (_2696 == 1u)
                        {
                            _2828 = float3(-1.0, _1618.y, _1618.x);
                        }
                        else
                        {
                            float3 _2829;
                            if (_2696 == 2u)
                            {
                                _2829 = float3(_1618.x, 1.0, -_1618.y);
                            }
                            else
                            {
                                float3 _2830;
                                if (_2696 == 3u)
                                {
                                    _2830 = float3(_1618.x, -1.0, _1618.y);
                                }
                                else
                                {
                                    float3 _2831;
                                    if (_2696 == 4u)
                                    {
                                        _2831 = float3(_1618.x, _1618.y, 1.0);
                                    }
                                    else
                                    {
                                        _2831 = float3(-_1618.x, _1618.y, -1.0);
                                    }
                                    _2830 = _2831;
                                }
                                _2829 = _2830;
                            }
                            _2828 = _2829;
                        }
                        _2827 = _2828;
                    }
                    float3 _1624 = fast::normalize(_2827);
                    float _1589 = spvFMul(fast::max(dot(Source.read(uint2(_1504.xy), uint(_1504.z), 0).xyz, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1528);
                    _2833 = float4(_1624 * _1528, _1528);
                    _2832 = float4(_1624 * _1589, _1589);
                    break;
                }
                int4 _1547 = int4(0, 0, int(_2696), int(_1226 - 1u));
                int4 _1490 = _1547;
                int3 _1556 = _1547.xyz;
                int3 _1562 = _1547.xyz;
                _2833 = Geometry.read(uint2(_1562.xy), uint(_1562.z), _1490.w);
                _2832 = Centroid.read(uint2(_1556.xy), uint(_1556.z), _1490.w);
                break;
            } while(false);
            float4 _1443 = _2832;
            float4 _1444 = _2833;
            _1469 = _2697 + _1443.w;
            _1473 = _2698 + _1444.w;
        }
        float _1480 = _2697 / _2698;
        uint _1236 = 3u + (2u * (_523.TopLevel - _523.FineLevel));
        uint _1251 = (65535u / _1236) - min(((((6u * _1224) * _1224) + (3u * _523.TopLevel)) + 1u), (65535u / _1236));
        float _1254 = 0.5 / _523.Refine;
        float3 _2700;
        float _2702;
        uint2 _2704;
        _2704 = uint2(0u);
        _2702 = 0.0;
        _2700 = float3(0.0);
        uint _2852;
        float3 _2859;
        float _2871;
        uint2 _2874;
        uint _2875;
        uint _2876;
        for (uint _2699 = 0u, _2705 = _523.TopLevel, _2722 = 0u; _2699 < 6u; _2722 = _2876, _2705 = _2875, _2704 = _2874, _2702 = _2871, _2700 = _2859, _2699 = _2852)
        {
            float4 _2711;
            float4 _2712;
            float4 _2713;
            do
            {
                if (_2705 == 0u)
                {
                    int3 _1714 = int4(int2(_2704), int(_2699), 0).xyz;
                    float4 _1737 = TexelSolidAngle.read(uint2(int3(int2(_2704), 0).xy), 0);
                    float _1738 = _1737.x;
                    float3 _1739 = Source.read(uint2(_1714.xy), uint(_1714.z), 0).xyz;
                    float2 _1828 = ((spvFAdd(float2(_2704), float2(0.5)) / float2(float(_1131.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2706;
                    if (_2699 == 0u)
                    {
                        _2706 = float3(1.0, _1828.y, -_1828.x);
                    }
                    else
                    {
                        float3 _2707;
                        if (_2699 == 1u)
                        {
                            _2707 = float3(-1.0, _1828.y, _1828.x);
                        }
                        else
                        {
                            float3 _2708;
                            if (_2699 == 2u)
                            {
                                _2708 = float3(_1828.x, 1.0, -_1828.y);
                            }
                            else
                            {
                                float3 _2709;
                                if (_2699 == 3u)
                                {
                                    _2709 = float3(_1828.x, -1.0, _1828.y);
                                }
                                else
                                {
                                    float3 _2710;
                                    if (_2699 == 4u)
                                    {
                                        _2710 = float3(_1828.x, _1828.y, 1.0);
                                    }
                                    else
                                    {
                                        _2710 = float3(-_1828.x, _1828.y, -1.0);
                                    }
                                    _2709 = _2710;
                                }
                                _2708 = _2709;
                            }
                            _2707 = _2708;
                        }
                        _2706 = _2707;
                    }
                    float3 _1834 = fast::normalize(_2706);
                    float _1799 = spvFMul(fast::max(dot(_1739, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1738);
                    _2713 = float4(_1834 * _1738, _1738);
                    _2712 = float4(_1834 * _1799, _1799);
                    _2711 = float4(_1739 * _1738, _1738);
                    break;
                }
                int4 _1757 = int4(int2(_2704), int(_2699), int(_2705 - 1u));
                int4 _1700 = _1757;
                int3 _1760 = _1757.xyz;
                int3 _1766 = _1757.xyz;
                int3 _1772 = _1757.xyz;
                _2713 = Geometry.read(uint2(_1772.xy), uint(_1772.z), _1700.w);
                _2712 = Centroid.read(uint2(_1766.xy), uint(_1766.z), _1700.w);
                _2711 = Energy.read(uint2(_1760.xy), uint(_1760.z), _1700.w);
                break;
            } while(false);
            float4 _1146 = _2711;
            float4 _1147 = _2712;
            float4 _1148 = _2713;
            float _1906 = as_type<float>((127u - (_1226 - _2705)) << uint(23));
            float4 _1165 = _2712;
            float4 _1166 = _2713;
            float2 _1909 = (((float2(_2704) + float2(0.5)) * _1906) - float2(0.5)) * float2(2.0, -2.0);
            float3 _2739;
            if (_2699 == 0u)
            {
                _2739 = float3(1.0, _1909.y, -_1909.x);
            }
            else
            {
                float3 _2740;
                if (_2699 == 1u)
                {
                    _2740 = float3(-1.0, _1909.y, _1909.x);
                }
                else
                {
                    float3 _2741;
                    if (_2699 == 2u)
                    {
                        _2741 = float3(_1909.x, 1.0, -_1909.y);
                    }
                    else
                    {
                        float3 _2742;
                        if (_2699 == 3u)
                        {
                            _2742 = float3(_1909.x, -1.0, _1909.y);
                        }
                        else
                        {
                            float3 _2743;
                            if (_2699 == 4u)
                            {
                                _2743 = float3(_1909.x, _1909.y, 1.0);
                            }
                            else
                            {
                                _2743 = float3(-_1909.x, _1909.y, -1.0);
                            }
                            _2742 = _2743;
                        }
                        _2741 = _2742;
                    }
                    _2740 = _2741;
                }
                _2739 = _2740;
            }
            float _1934 = dot(_1372, _2739) * (1.0 / sqrt(dot(_2739, _2739)));
            float _1943 = fast::max(_1165.w / fast::max(_1166.w * _1480, 1.0000000031710768509710513471353e-30), 1.0);
            float _1947 = float(max((_1131.x >> _2705), 1u)) * _1254;
            float _1954 = (fma(-2.0, _1934, 2.0) * _1947) * _1947;
            if (((_2705 > _523.FineLevel) && (_2722 < _1251)) && ((((_1954 * _1954) * _1954) < (_1943 * _1943)) || ((_2705 > _523.HorizonLevel) && (abs(_1934) < (2.0 * _1906)))))
            {
                _2876 = _2722;
                _2875 = _2705 - 1u;
                _2874 = _2704 * uint2(2u);
                _2871 = _2702;
                _2859 = _2700;
                _2852 = _2699;
                continue;
            }
            float3 _1308 = _2713.xyz * (1.0 / _1148.w);
            float3 _1320 = select(_1308, _2712.xyz * (1.0 / _1147.w), bool3(_1147.w > 0.0));
            float _2053 = dot(_1320, _1320);
            float _2056 = dot(_1372, _1320);
            float _2068 = (0.5 * fast::max(1.0 - _2053, 0.0)) * fast::max(1.0 - ((_2056 * _2056) / _2053), 0.0);
            float _2096 = sqrt(fast::max(_2068, 0.0));
            float _2101 = sqrt(fma(0.5, fast::max(_2056, 0.0), 0.5));
            float _2229 = _523.Roughness * _523.Roughness;
            float _2241 = fma(_2101 * _2101, fma(_2229, _2229, -1.0), 1.0);
            float _2107 = (0.5 * _523.Roughness) * _523.Roughness;
            float _2745;
            if (_2056 > (3.0 * _2096))
            {
                float _2119 = ((_523.Roughness * _523.Roughness) * _523.Roughness) * _523.Roughness;
                float _2122 = fma(0.5, _2119, 0.5);
                float _2125 = fma(0.5, _2119, -0.5);
                float _2131 = 1.0 / fma(_2125, _2056, _2122);
                float _2746;
                if (_523.Weighting == 0u)
                {
                    _2746 = fma((((0.5 * _2068) * (-_2125)) * fma(4.0, _2122, -((2.0 * _2125) * _2056))) * _2131, _2131, _2056);
                }
                else
                {
                    float _2162 = 1.0 / fma(fma(_523.Roughness * (-0.5), _523.Roughness, 1.0), _2056, _2107);
                    float _2170 = (_2107 * _2162) * _2162;
                    _2746 = fma(_2056, _2162, (0.5 * _2068) * fma(((-2.0) * fma(_523.Roughness * (-0.5), _523.Roughness, 1.0)) * _2170, _2162, fma(((((_2056 * _2162) * 6.0) * _2125) * _2125) * _2131, _2131, -(((4.0 * _2125) * _2170) * _2131))));
                }
                _2745 = _2746;
            }
            else
            {
                float _2744;
                if ((_2096 > 0.0) && (abs(_2056) <= (5.0 * _2096)))
                {
                    float _2269 = _2056 / _2096;
                    float _2274 = exp(((-0.5) * _2269) * _2269);
                    float _2295 = fma(0.23164188861846923828125, abs(_2269), 1.0);
                    float _2296 = 1.0 / _2295;
                    float _2312 = (0.5 / _2295) * fma(_2296, fma(_2296, fma(_2296, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2295), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    _2744 = fma(_2096 * _2274, 0.398942291736602783203125, _2056 * ((_2269 >= 0.0) ? fma(-_2312, _2274, 1.0) : (_2312 * _2274)));
                }
                else
                {
                    _2744 = fast::max(_2056, 0.0);
                }
                float _2207 = fast::max(_2744, 0.0);
                _2745 = (_523.Weighting == 0u) ? _2207 : (_2207 / fma(fma(_523.Roughness * (-0.5), _523.Roughness, 1.0), _2207, _2107));
            }
            float _2341 = dot(_1308, _1308);
            float _2344 = dot(_1372, _1308);
            float _2356 = (0.5 * fast::max(1.0 - _2341, 0.0)) * fast::max(1.0 - ((_2344 * _2344) / _2341), 0.0);
            float _2384 = sqrt(fast::max(_2356, 0.0));
            float _2389 = sqrt(fma(0.5, fast::max(_2344, 0.0), 0.5));
            float _2517 = _523.Roughness * _523.Roughness;
            float _2529 = fma(_2389 * _2389, fma(_2517, _2517, -1.0), 1.0);
            float _2395 = (0.5 * _523.Roughness) * _523.Roughness;
            float _2762;
            if (_2344 > (3.0 * _2384))
            {
                float _2407 = ((_523.Roughness * _523.Roughness) * _523.Roughness) * _523.Roughness;
                float _2410 = fma(0.5, _2407, 0.5);
                float _2413 = fma(0.5, _2407, -0.5);
                float _2419 = 1.0 / fma(_2413, _2344, _2410);
                float _2763;
                if (_523.Weighting == 0u)
                {
                    _2763 = fma((((0.5 * _2356) * (-_2413)) * fma(4.0, _2410, -((2.0 * _2413) * _2344))) * _2419, _2419, _2344);
                }
                else
                {
                    float _2450 = 1.0 / fma(fma(_523.Roughness * (-0.5), _523.Roughness, 1.0), _2344, _2395);
                    float _2458 = (_2395 * _2450) * _2450;
                    _2763 = fma(_2344, _2450, (0.5 * _2356) * fma(((-2.0) * fma(_523.Roughness * (-0.5), _523.Roughness, 1.0)) * _2458, _2450, fma(((((_2344 * _2450) * 6.0) * _2413) * _2413) * _2419, _2419, -(((4.0 * _2413) * _2458) * _2419))));
                }
                _2762 = _2763;
            }
            else
            {
                float _2761;
                if ((_2384 > 0.0) && (abs(_2344) <= (5.0 * _2384)))
                {
                    float _2557 = _2344 / _2384;
                    float _2562 = exp(((-0.5) * _2557) * _2557);
                    float _2583 = fma(0.23164188861846923828125, abs(_2557), 1.0);
                    float _2584 = 1.0 / _2583;
                    float _2600 = (0.5 / _2583) * fma(_2584, fma(_2584, fma(_2584, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2583), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    _2761 = fma(_2384 * _2562, 0.398942291736602783203125, _2344 * ((_2557 >= 0.0) ? fma(-_2600, _2562, 1.0) : (_2600 * _2562)));
                }
                else
                {
                    _2761 = fast::max(_2344, 0.0);
                }
                float _2495 = fast::max(_2761, 0.0);
                _2762 = (_523.Weighting == 0u) ? _2495 : (_2495 / fma(fma(_523.Roughness * (-0.5), _523.Roughness, 1.0), _2495, _2395));
            }
            uint2 _1176 = _2704;
            uint _2624 = _1176.x;
            uint _2626 = _1176.y;
            uint _2634 = min(spvFindLSB(~(_2624 & _2626)), (_523.TopLevel - _2705));
            _1176 = _2704 >> uint2(_2634);
            uint _2641 = _2705 + _2634;
            uint _2825;
            if (_2641 == _523.TopLevel)
            {
                uint _2648 = spvFindLSB(_1224);
                uint _2653 = _1176.y;
                uint _2658 = _1176.x;
                uint _2660 = ((((_2699 << _2648) + _2653) << _2648) + _2658) + 1u;
                _1176 = uint2(_2660 & (_1224 - 1u), (_2660 >> _2648) & (_1224 - 1u));
                _2825 = _2660 >> (2u * _2648);
            }
            else
            {
                if ((_1176.x & 1u) == 0u)
                {
                    _1176.x++;
                }
                else
                {
                    _1176 += uint2(4294967295u, 1u);
                }
                _2825 = _2699;
            }
            _2876 = _2722 + 1u;
            _2875 = _2641;
            _2874 = _1176;
            _2871 = fma(_1146.w, ((_2517 * _2517) / ((3.1415927410125732421875 * _2529) * _2529)) * _2762, _2702);
            _2859 = _2700 + (_2711.xyz * (((_2229 * _2229) / ((3.1415927410125732421875 * _2241) * _2241)) * _2745));
            _2852 = _2825;
        }
        Prefiltered.write(float4(_2700 / float3(_2702), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

