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
        uint3 _1087 = uint3(0u);
        uint3 _1088 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _1087.x = _1088.x;
        _1087.y = _1088.y;
        _1087.z = _1088.z;
        if (any(gl_GlobalInvocationID >= _1087))
        {
            break;
        }
        float2 _1091 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_1087.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _2623;
        if (param.z == 0u)
        {
            _2623 = float3(1.0, _1091.y, -_1091.x);
        }
        else
        {
            float3 _2624;
            if (param.z == 1u)
            {
                _2624 = float3(-1.0, _1091.y, _1091.x);
            }
            else
            {
                float3 _2625;
                if (param.z == 2u)
                {
                    _2625 = float3(_1091.x, 1.0, -_1091.y);
                }
                else
                {
                    float3 _2626;
                    if (param.z == 3u)
                    {
                        _2626 = float3(_1091.x, -1.0, _1091.y);
                    }
                    else
                    {
                        float3 _2627;
                        if (param.z == 4u)
                        {
                            _2627 = float3(_1091.x, _1091.y, 1.0);
                        }
                        else
                        {
                            _2627 = float3(-_1091.x, _1091.y, -1.0);
                        }
                        _2626 = _2627;
                    }
                    _2625 = _2626;
                }
                _2624 = _2625;
            }
            _2623 = _2624;
        }
        float3 _1381 = fast::normalize(_2623);
        uint3 _1095 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
        uint _1183 = max((_1095.x >> _511.TopLevel), 1u);
        uint _1185 = spvFindUMSB(_1095.x);
        float _2629;
        float _2630;
        _2630 = 0.0;
        _2629 = 0.0;
        float _1412;
        float _1416;
        for (uint _2628 = 0u; _2628 < 6u; _2630 = _1416, _2629 = _1412, _2628++)
        {
            float4 _2768;
            float4 _2769;
            do
            {
                if (_1185 == 0u)
                {
                    int3 _1447 = int4(0, 0, int(_2628), 0).xyz;
                    float4 _1470 = TexelSolidAngle.read(uint2(int2(0)), 0);
                    float _1471 = _1470.x;
                    float2 _1512 = ((spvFAdd(float2(0.0), float2(0.5)) / float2(float(_1095.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2763;
                    if (_2628 == 0u)
                    {
                        _2763 = float3(1.0, _1512.y, -_1512.x);
                    }
                    else
                    {
                        float3 _2764;
                        if (_2628 == 1u)
                        {
                            _2764 = float3(-1.0, _1512.y, _1512.x);
                        }
                        else
                        {
                            float3 _2765;
                            if (_2628 == 2u)
                            {
                                _2765 = float3(_1512.x, 1.0, -_1512.y);
                            }
                            else
                            {
                                float3 _2766;
                                if (_2628 == 3u)
                                {
                                    _2766 = float3(_1512.x, -1.0, _1512.y);
                                }
                                else
                                {
                                    float3 _2767;
                                    if (_2628 == 4u)
                                    {
                                        _2767 = float3(_1512.x, _1512.y, 1.0);
                                    }
                                    else
                                    {
                                        _2767 = float3(-_1512.x, _1512.y, -1.0);
                                    }
                                    _2766 = _2767;
                                }
                                _2765 = _2766;
                            }
                            _2764 = _2765;
                        }
                        _2763 = _2764;
                    }
                    float3 _1626 = fast::normalize(_2763);
                    float _1532 = spvFMul(fast::max(dot(Source.read(uint2(_1447.xy), uint(_1447.z), 0).xyz, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1471);
                    _2769 = float4(_1626 * _1471, _1471);
                    _2768 = float4(_1626 * _1532, _1532);
                    break;
                }
                int4 _1490 = int4(0, 0, int(_2628), int(_1185 - 1u));
                int4 _1433 = _1490;
                int3 _1499 = _1490.xyz;
                int3 _1505 = _1490.xyz;
                _2769 = Geometry.read(uint2(_1505.xy), uint(_1505.z), _1433.w);
                _2768 = Centroid.read(uint2(_1499.xy), uint(_1499.z), _1433.w);
                break;
            } while(false);
            float4 _1386 = _2768;
            float4 _1387 = _2769;
            _1412 = _2629 + _1386.w;
            _1416 = _2630 + _1387.w;
        }
        float _1423 = _2629 / _2630;
        uint _1194 = 3u + (2u * (_511.TopLevel - _511.FineLevel));
        uint _1209 = (65535u / _1194) - min(((((6u * _1183) * _1183) + (3u * _511.TopLevel)) + 1u), (65535u / _1194));
        float3 _2632;
        float _2634;
        uint2 _2636;
        _2636 = uint2(0u);
        _2634 = 0.0;
        _2632 = float3(0.0);
        uint _2788;
        float3 _2795;
        float _2808;
        uint2 _2812;
        uint _2813;
        uint _2814;
        for (uint _2631 = 0u, _2637 = _511.TopLevel, _2654 = 0u; _2631 < 6u; _2654 = _2814, _2637 = _2813, _2636 = _2812, _2634 = _2808, _2632 = _2795, _2631 = _2788)
        {
            float4 _2643;
            float4 _2644;
            float4 _2645;
            do
            {
                if (_2637 == 0u)
                {
                    int3 _1650 = int4(int2(_2636), int(_2631), 0).xyz;
                    float4 _1673 = TexelSolidAngle.read(uint2(int3(int2(_2636), 0).xy), 0);
                    float _1674 = _1673.x;
                    float3 _1675 = Source.read(uint2(_1650.xy), uint(_1650.z), 0).xyz;
                    float2 _1715 = ((spvFAdd(float2(_2636), float2(0.5)) / float2(float(_1095.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2638;
                    if (_2631 == 0u)
                    {
                        _2638 = float3(1.0, _1715.y, -_1715.x);
                    }
                    else
                    {
                        float3 _2639;
                        if (_2631 == 1u)
                        {
                            _2639 = float3(-1.0, _1715.y, _1715.x);
                        }
                        else
                        {
                            float3 _2640;
                            if (_2631 == 2u)
                            {
                                _2640 = float3(_1715.x, 1.0, -_1715.y);
                            }
                            else
                            {
                                float3 _2641;
                                if (_2631 == 3u)
                                {
                                    _2641 = float3(_1715.x, -1.0, _1715.y);
                                }
                                else
                                {
                                    float3 _2642;
                                    if (_2631 == 4u)
                                    {
                                        _2642 = float3(_1715.x, _1715.y, 1.0);
                                    }
                                    else
                                    {
                                        _2642 = float3(-_1715.x, _1715.y, -1.0);
                                    }
                                    _2641 = _2642;
                                }
                                _2640 = _2641;
                            }
                            _2639 = _2640;
                        }
                        _2638 = _2639;
                    }
                    float3 _1829 = fast::normalize(_2638);
                    float _1735 = spvFMul(fast::max(dot(_1675, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1674);
                    _2645 = float4(_1829 * _1674, _1674);
                    _2644 = float4(_1829 * _1735, _1735);
                    _2643 = float4(_1675 * _1674, _1674);
                    break;
                }
                int4 _1693 = int4(int2(_2636), int(_2631), int(_2637 - 1u));
                int4 _1636 = _1693;
                int3 _1696 = _1693.xyz;
                int3 _1702 = _1693.xyz;
                int3 _1708 = _1693.xyz;
                _2645 = Geometry.read(uint2(_1708.xy), uint(_1708.z), _1636.w);
                _2644 = Centroid.read(uint2(_1702.xy), uint(_1702.z), _1636.w);
                _2643 = Energy.read(uint2(_1696.xy), uint(_1696.z), _1636.w);
                break;
            } while(false);
            float4 _1108 = _2643;
            float4 _1109 = _2644;
            float4 _1110 = _2645;
            uint _1236 = max((_1095.x >> _2637), 1u);
            float4 _1124 = _2644;
            float4 _1125 = _2645;
            float2 _1832 = (((float2(_2636) + float2(0.5)) / float2(float(_1236))) - float2(0.5)) * float2(2.0, -2.0);
            float3 _2671;
            if (_2631 == 0u)
            {
                _2671 = float3(1.0, _1832.y, -_1832.x);
            }
            else
            {
                float3 _2672;
                if (_2631 == 1u)
                {
                    _2672 = float3(-1.0, _1832.y, _1832.x);
                }
                else
                {
                    float3 _2673;
                    if (_2631 == 2u)
                    {
                        _2673 = float3(_1832.x, 1.0, -_1832.y);
                    }
                    else
                    {
                        float3 _2674;
                        if (_2631 == 3u)
                        {
                            _2674 = float3(_1832.x, -1.0, _1832.y);
                        }
                        else
                        {
                            float3 _2675;
                            if (_2631 == 4u)
                            {
                                _2675 = float3(_1832.x, _1832.y, 1.0);
                            }
                            else
                            {
                                _2675 = float3(-_1832.x, _1832.y, -1.0);
                            }
                            _2674 = _2675;
                        }
                        _2673 = _2674;
                    }
                    _2672 = _2673;
                }
                _2671 = _2672;
            }
            float _1852 = dot(_1381, fast::normalize(_2671));
            float _1870 = ((_511.Refine * 2.0) / float(_1236)) * pow(fast::max(_1124.w / fast::max(_1125.w * _1423, 1.0000000031710768509710513471353e-30), 1.0), 0.3333333432674407958984375);
            if (((_2637 > _511.FineLevel) && (_2654 < _1209)) && ((fma(-2.0, _1852, 2.0) < (_1870 * _1870)) || ((_2637 > _511.HorizonLevel) && (abs(_1852) < (2.0 / float(_1236))))))
            {
                _2814 = _2654;
                _2813 = _2637 - 1u;
                _2812 = _2636 * uint2(2u);
                _2808 = _2634;
                _2795 = _2632;
                _2788 = _2631;
                continue;
            }
            float3 _1258 = _2645.xyz / float3(_1110.w);
            float3 _1270 = select(_1258, _2644.xyz / float3(_1109.w), bool3(_1109.w > 0.0));
            float _1969 = dot(_1270, _1270);
            float _1972 = dot(_1381, _1270);
            float _1984 = (0.5 * fast::max(1.0 - _1969, 0.0)) * fast::max(1.0 - ((_1972 * _1972) / _1969), 0.0);
            float _2012 = sqrt(fast::max(_1984, 0.0));
            float _2017 = sqrt(fma(0.5, fast::max(_1972, 0.0), 0.5));
            float _2147 = _511.Roughness * _511.Roughness;
            float _2159 = fma(_2017 * _2017, fma(_2147, _2147, -1.0), 1.0);
            float _2023 = (0.5 * _511.Roughness) * _511.Roughness;
            float _2677;
            if (_1972 > (3.0 * _2012))
            {
                float _2035 = ((_511.Roughness * _511.Roughness) * _511.Roughness) * _511.Roughness;
                float _2038 = fma(0.5, _2035, 0.5);
                float _2041 = fma(0.5, _2035, -0.5);
                float _2046 = fma(_2041, _1972, _2038);
                float _2678;
                if (_511.Weighting == 0u)
                {
                    _2678 = _1972 + ((((0.5 * _1984) * (-_2041)) * fma(4.0, _2038, -((2.0 * _2041) * _1972))) / (_2046 * _2046));
                }
                else
                {
                    float _2076 = fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _1972, _2023);
                    float _2079 = _1972 / _2076;
                    _2678 = fma(0.5 * _1984, (((((_2079 * 6.0) * _2041) * _2041) / (_2046 * _2046)) - (((4.0 * _2041) * (_2023 / (_2076 * _2076))) / _2046)) + ((((-2.0) * fma(_511.Roughness * (-0.5), _511.Roughness, 1.0)) * _2023) / ((_2076 * _2076) * _2076)), _2079);
                }
                _2677 = _2678;
            }
            else
            {
                float _2676;
                if ((_2012 > 0.0) && (abs(_1972) <= (5.0 * _2012)))
                {
                    float _2186 = _1972 / _2012;
                    float _2210 = abs(_2186);
                    float _2214 = fma(_2210, 0.23164187371730804443359375, 1.0);
                    float _2215 = 1.0 / _2214;
                    float _2231 = (0.5 / _2214) * fma(_2215, fma(_2215, fma(_2215, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2214), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2236 = exp((_2210 * (-0.707106769084930419921875)) * (_2210 * 0.707106769084930419921875));
                    _2676 = fma(_2012, exp(((-0.5) * _2186) * _2186) * 0.398942291736602783203125, _1972 * ((_2186 >= 0.0) ? fma(-_2231, _2236, 1.0) : (_2231 * _2236)));
                }
                else
                {
                    _2676 = fast::max(_1972, 0.0);
                }
                float _2125 = fast::max(_2676, 0.0);
                _2677 = (_511.Weighting == 0u) ? _2125 : (_2125 / fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2125, _2023));
            }
            float _2264 = dot(_1258, _1258);
            float _2267 = dot(_1381, _1258);
            float _2279 = (0.5 * fast::max(1.0 - _2264, 0.0)) * fast::max(1.0 - ((_2267 * _2267) / _2264), 0.0);
            float _2307 = sqrt(fast::max(_2279, 0.0));
            float _2312 = sqrt(fma(0.5, fast::max(_2267, 0.0), 0.5));
            float _2442 = _511.Roughness * _511.Roughness;
            float _2454 = fma(_2312 * _2312, fma(_2442, _2442, -1.0), 1.0);
            float _2318 = (0.5 * _511.Roughness) * _511.Roughness;
            float _2694;
            if (_2267 > (3.0 * _2307))
            {
                float _2330 = ((_511.Roughness * _511.Roughness) * _511.Roughness) * _511.Roughness;
                float _2333 = fma(0.5, _2330, 0.5);
                float _2336 = fma(0.5, _2330, -0.5);
                float _2341 = fma(_2336, _2267, _2333);
                float _2695;
                if (_511.Weighting == 0u)
                {
                    _2695 = _2267 + ((((0.5 * _2279) * (-_2336)) * fma(4.0, _2333, -((2.0 * _2336) * _2267))) / (_2341 * _2341));
                }
                else
                {
                    float _2371 = fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2267, _2318);
                    float _2374 = _2267 / _2371;
                    _2695 = fma(0.5 * _2279, (((((_2374 * 6.0) * _2336) * _2336) / (_2341 * _2341)) - (((4.0 * _2336) * (_2318 / (_2371 * _2371))) / _2341)) + ((((-2.0) * fma(_511.Roughness * (-0.5), _511.Roughness, 1.0)) * _2318) / ((_2371 * _2371) * _2371)), _2374);
                }
                _2694 = _2695;
            }
            else
            {
                float _2693;
                if ((_2307 > 0.0) && (abs(_2267) <= (5.0 * _2307)))
                {
                    float _2481 = _2267 / _2307;
                    float _2505 = abs(_2481);
                    float _2509 = fma(_2505, 0.23164187371730804443359375, 1.0);
                    float _2510 = 1.0 / _2509;
                    float _2526 = (0.5 / _2509) * fma(_2510, fma(_2510, fma(_2510, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2509), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2531 = exp((_2505 * (-0.707106769084930419921875)) * (_2505 * 0.707106769084930419921875));
                    _2693 = fma(_2307, exp(((-0.5) * _2481) * _2481) * 0.398942291736602783203125, _2267 * ((_2481 >= 0.0) ? fma(-_2526, _2531, 1.0) : (_2526 * _2531)));
                }
                else
                {
                    _2693 = fast::max(_2267, 0.0);
                }
                float _2420 = fast::max(_2693, 0.0);
                _2694 = (_511.Weighting == 0u) ? _2420 : (_2420 / fma(fma(_511.Roughness * (-0.5), _511.Roughness, 1.0), _2420, _2318));
            }
            uint2 _1135 = _2636;
            uint _2757;
            _2757 = _2637;
            uint _2571;
            for (; (_2757 < _511.TopLevel) && (((_1135.x & _1135.y) & 1u) != 0u); _2757 = _2571)
            {
                _1135 = _1135 >> uint2(int2(1));
                _2571 = _2757 + 1u;
            }
            uint _2759;
            if (_2757 == _511.TopLevel)
            {
                uint _2580 = spvFindLSB(_1183);
                uint _2585 = _1135.y;
                uint _2590 = _1135.x;
                uint _2592 = ((((_2631 << _2580) + _2585) << _2580) + _2590) + 1u;
                _1135 = uint2(_2592 & (_1183 - 1u), (_2592 >> _2580) & (_1183 - 1u));
                _2759 = _2592 >> (2u * _2580);
            }
            else
            {
                if ((_1135.x & 1u) == 0u)
                {
                    _1135.x++;
                }
                else
                {
                    _1135 += uint2(4294967295u, 1u);
                }
                _2759 = _2631;
            }
            _2814 = _2654 + 1u;
            _2813 = _2757;
            _2812 = _1135;
            _2808 = fma(_1108.w, ((_2442 * _2442) / ((3.1415927410125732421875 * _2454) * _2454)) * _2694, _2634);
            _2795 = _2632 + (_2643.xyz * (((_2147 * _2147) / ((3.1415927410125732421875 * _2159) * _2159)) * _2677));
            _2788 = _2759;
        }
        Prefiltered.write(float4(_2632 / float3(_2634), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

