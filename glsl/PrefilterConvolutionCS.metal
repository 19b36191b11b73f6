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

kernel void main0(constant PrefilterConvolutionParameter& _522 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d<float> TexelSolidAngle [[texture(1)]], texture2d_array<float> Energy [[texture(2)]], texture2d_array<float> Centroid [[texture(3)]], texture2d_array<float> Geometry [[texture(4)]], texture2d_array<float, access::write> Prefiltered [[texture(5)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _1124 = uint3(0u);
        uint3 _1125 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _1124.x = _1125.x;
        _1124.y = _1125.y;
        _1124.z = _1125.z;
        if (any(gl_GlobalInvocationID >= _1124))
        {
            break;
        }
        float2 _1358 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_1124.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _2694;
        if (param.z == 0u)
        {
            _2694 = float3(1.0, _1358.y, -_1358.x);
        }
        else
        {
            float3 _2695;
            if (param.z == 1u)
            {
                _2695 = float3(-1.0, _1358.y, _1358.x);
            }
            else
            {
                float3 _2696;
                if (param.z == 2u)
                {
                    _2696 = float3(_1358.x, 1.0, -_1358.y);
                }
                else
                {
                    float3 _2697;
                    if (param.z == 3u)
                    {
                        _2697 = float3(_1358.x, -1.0, _1358.y);
                    }
                    else
                    {
                        float3 _2698;
                        if (param.z == 4u)
                        {
                            _2698 = float3(_1358.x, _1358.y, 1.0);
                        }
                        else
                        {
                            _2698 = float3(-_1358.x, _1358.y, -1.0);
                        }
                        _2697 = _2698;
                    }
                    _2696 = _2697;
                }
                _2695 = _2696;
            }
            _2694 = _2695;
        }
        float3 _1364 = fast::normalize(_2694);
        uint3 _1132 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
        uint _1223 = max((_1132.x >> _522.TopLevel), 1u);
        uint _1225 = spvFindUMSB(_1132.x);
        float _2700;
        float _2701;
        _2701 = 0.0;
        _2700 = 0.0;
        float _1461;
        float _1465;
        for (uint _2699 = 0u; _2699 < 6u; _2701 = _1465, _2700 = _1461, _2699++)
        {
            float4 _2835;
            float4 _2836;
            do
            {
                if (_1225 == 0u)
                {
                    int3 _1496 = int4(0, 0, int(_2699), 0).xyz;
                    float4 _1519 = TexelSolidAngle.read(uint2(int2(0)), 0);
                    float _1520 = _1519.x;
                    float2 _1610 = ((spvFAdd(float2(0.0), float2(0.5)) / float2(float(_1132.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2830;
                    if (_2699 == 0u)
                    {
                        _2830 = float3(1.0, _1610.y, -_1610.x);
                    }
                    else
                    {
                        float3 _2831;
                        if (_2699 == 1u)
                        {
                            _2831 = float3(-1.0, _1610.y, _1610.x);
                        }
                        else
                        {
                            float3 _2832;
                            if (_2699 == 2u)
                            {
                                _2832 = float3(_1610.x, 1.0, -_1610.y);
                            }
                            else
                            {
                                float3 _2833;
                                if (_2699 == 3u)
                                {
                                    _2833 = float3(_1610.x, -1.0, _1610.y);
                                }
                                else
                                {
                                    float3 _2834;
                                    if (_2699 == 4u)
                                    {
                                        _2834 = float3(_1610.x, _1610.y, 1.0);
                                    }
                                    else
                                    {
                                        _2834 = float3(-_1610.x, _1610.y, -1.0);
                                    }
                                    _2833 = _2834;
                                }
                                _2832 = _2833;
                            }
                            _2831 = _2832;
                        }
                        _2830 = _2831;
                    }
                    float3 _1616 = fast::normalize(_2830);
                    float _1581 = spvFMul(fast::max(dot(Source.read(uint2(_1496.xy), uint(_1496.z), 0).xyz, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1520);
                    _2836 = float4(_1616 * _1520, _1520);
                    _2835 = float4(_1616 * _1581, _1581);
                    break;
                }
                int4 _1539 = int4(0, 0, int(_2699), int(_1225 - 1u));
                int4 _1482 = _1539;
                int3 _1548 = _1539.xyz;
                int3 _1554 = _1539.xyz;
                _2836 = Geometry.read(uint2(_1554.xy), uint(_1554.z), _1482.w);
                _2835 = Centroid.read(uint2(_1548.xy), uint(_1548.z), _1482.w);
                break;
            } while(false);
            float4 _1435 = _2835;
            float4 _1436 = _2836;
            _1461 = _2700 + _1435.w;
            _1465 = _2701 + _1436.w;
        }
        float _1472 = _2700 / _2701;
        uint _1235 = 3u + (2u * (_522.TopLevel - _522.FineLevel));
        uint _1250 = (65535u / _1235) - min(((((6u * _1223) * _1223) + (3u * _522.TopLevel)) + 1u), (65535u / _1235));
        float _1253 = 0.5 / _522.Refine;
        float3 _2703;
        float _2705;
        uint2 _2707;
        _2707 = uint2(0u);
        _2705 = 0.0;
        _2703 = float3(0.0);
        uint _2855;
        float3 _2862;
        float _2874;
        uint2 _2877;
        uint _2878;
        uint _2879;
        for (uint _2702 = 0u, _2708 = _522.TopLevel, _2725 = 0u; _2702 < 6u; _2725 = _2879, _2708 = _2878, _2707 = _2877, _2705 = _2874, _2703 = _2862, _2702 = _2855)
        {
            float4 _2714;
            float4 _2715;
            float4 _2716;
            do
            {
                if (_2708 == 0u)
                {
                    int3 _1706 = int4(int2(_2707), int(_2702), 0).xyz;
                    float4 _1729 = TexelSolidAngle.read(uint2(int3(int2(_2707), 0).xy), 0);
                    float _1730 = _1729.x;
                    float3 _1731 = Source.read(uint2(_1706.xy), uint(_1706.z), 0).xyz;
                    float2 _1820 = ((spvFAdd(float2(_2707), float2(0.5)) / float2(float(_1132.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2709;
                    if (_2702 == 0u)
                    {
                        _2709 = float3(1.0, _1820.y, -_1820.x);
                    }
                    else
                    {
                        float3 _2710;
                        if (_2702 == 1u)
                        {
                            _2710 = float3(-1.0, _1820.y, _1820.x);
                        }
                        else
                        {
                            float3 _2711;
                            if (_2702 == 2u)
                            {
                                _2711 = float3(_1820.x, 1.0, -_1820.y);
                            }
                            else
                            {
                                float3 _2712;
                                if (_2702 == 3u)
                                {
                                    _2712 = float3(_1820.x, -1.0, _1820.y);
                                }
                                else
                                {
                                    float3 _2713;
                                    if (_2702 == 4u)
                                    {
                                        _2713 = float3(_1820.x, _1820.y, 1.0);
                                    }
                                    else
                                    {
                                        _2713 = float3(-_1820.x, _1820.y, -1.0);
                                    }
                                    _2712 = _2713;
                                }
                                _2711 = _2712;
                            }
                            _2710 = _2711;
                        }
                        _2709 = _2710;
                    }
                    float3 _1826 = fast::normalize(_2709);
                    float _1791 = spvFMul(fast::max(dot(_1731, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1730);
                    _2716 = float4(_1826 * _1730, _1730);
                    _2715 = float4(_1826 * _1791, _1791);
                    _2714 = float4(_1731 * _1730, _1730);
                    break;
                }
                int4 _1749 = int4(int2(_2707), int(_2702), int(_2708 - 1u));
                int4 _1692 = _1749;
                int3 _1752 = _1749.xyz;
                int3 _1758 = _1749.xyz;
                int3 _1764 = _1749.xyz;
                _2716 = Geometry.read(uint2(_1764.xy), uint(_1764.z), _1692.w);
                _2715 = Centroid.read(uint2(_1758.xy), uint(_1758.z), _1692.w);
                _2714 = Energy.read(uint2(_1752.xy), uint(_1752.z), _1692.w);
                break;
            } while(false);
            float4 _1147 = _2714;
            float4 _1148 = _2715;
            float4 _1149 = _2716;
            float4 _1164 = _2715;
            float4 _1165 = _2716;
            uint _1910 = _1225 - _2708;
            float _1979 = as_type<float>((127u - _1910) << uint(23));
            float2 _1899 = (((float2(_2707) + float2(0.5)) * _1979) - float2(0.5)) * float2(2.0, -2.0);
            float3 _2742;
            if (_2702 == 0u)
            {
                _2742 = float3(1.0, _1899.y, -_1899.x);
            }
            else
            {
                float3 _2743;
                if (_2702 == 1u)
                {
                    _2743 = float3(-1.0, _1899.y, _1899.x);
                }
                else
                {
                    float3 _2744;
                    if (_2702 == 2u)
                    {
                        _2744 = float3(_1899.x, 1.0, -_1899.y);
                    }
                    else
                    {
                        float3 _2745;
                        if (_2702 == 3u)
                        {
                            _2745 = float3(_1899.x, -1.0, _1899.y);
                        }
                        else
                        {
                            float3 _2746;
                            if (_2702 == 4u)
                            {
                                _2746 = float3(_1899.x, _1899.y, 1.0);
                            }
                            else
                            {
                                _2746 = float3(-_1899.x, _1899.y, -1.0);
                            }
                            _2745 = _2746;
                        }
                        _2744 = _2745;
                    }
                    _2743 = _2744;
                }
                _2742 = _2743;
            }
            float _1932 = dot(_1364, _2742) * (1.0 / sqrt(dot(_2742, _2742)));
            float _1941 = fast::max(_1164.w / fast::max(_1165.w * _1472, 1.0000000031710768509710513471353e-30), 1.0);
            float _1944 = float(1u << _1910) * _1253;
            float _1951 = (fma(-2.0, _1932, 2.0) * _1944) * _1944;
            if (((_2708 > _522.FineLevel) && (_2725 < _1250)) && ((((_1951 * _1951) * _1951) < (_1941 * _1941)) || ((_2708 > _522.HorizonLevel) && (abs(_1932) < (2.0 * _1979)))))
            {
                _2879 = _2725;
                _2878 = _2708 - 1u;
                _2877 = _2707 * uint2(2u);
                _2874 = _2705;
                _2862 = _2703;
                _2855 = _2702;
                continue;
            }
            float3 _1300 = _2716.xyz * (1.0 / _1149.w);
            float3 _1312 = select(_1300, _2715.xyz * (1.0 / _1148.w), bool3(_1148.w > 0.0));
            float _2056 = dot(_1312, _1312);
            float _2059 = dot(_1364, _1312);
            float _2071 = (0.5 * fast::max(1.0 - _2056, 0.0)) * fast::max(1.0 - ((_2059 * _2059) / _2056), 0.0);
            float _2099 = sqrt(fast::max(_2071, 0.0));
            float _2104 = sqrt(fma(0.5, fast::max(_2059, 0.0), 0.5));
            float _2232 = _522.Roughness * _522.Roughness;
            float _2244 = fma(_2104 * _2104, fma(_2232, _2232, -1.0), 1.0);
            float _2110 = (0.5 * _522.Roughness) * _522.Roughness;
            float _2748;
            if (_2059 > (3.0 * _2099))
            {
                float _2122 = ((_522.Roughness * _522.Roughness) * _522.Roughness) * _522.Roughness;
                float _2125 = fma(0.5, _2122, 0.5);
                float _2128 = fma(0.5, _2122, -0.5);
                float _2134 = 1.0 / fma(_2128, _2059, _2125);
                float _2749;
                if (_522.Weighting == 0u)
                {
                    _2749 = fma((((0.5 * _2071) * (-_2128)) * fma(4.0, _2125, -((2.0 * _2128) * _2059))) * _2134, _2134, _2059);
                }
                else
                {
                    float _2165 = 1.0 / fma(fma(_522.Roughness * (-0.5), _522.Roughness, 1.0), _2059, _2110);
                    float _2173 = (_2110 * _2165) * _2165;
                    _2749 = fma(_2059, _2165, (0.5 * _2071) * fma(((-2.0) * fma(_522.Roughness * (-0.5), _522.Roughness, 1.0)) * _2173, _2165, fma(((((_2059 * _2165) * 6.0) * _2128) * _2128) * _2134, _2134, -(((4.0 * _2128) * _2173) * _2134))));
                }
                _2748 = _2749;
            }
            else
            {
                float _2747;
                if ((_2099 > 0.0) && (abs(_2059) <= (5.0 * _2099)))
                {
                    float _2272 = _2059 / _2099;
                    float _2277 = exp(((-0.5) * _2272) * _2272);
                    float _2298 = fma(0.23164188861846923828125, abs(_2272), 1.0);
                    float _2299 = 1.0 / _2298;
                    float _2315 = (0.5 / _2298) * fma(_2299, fma(_2299, fma(_2299, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2298), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    _2747 = fma(_2099 * _2277, 0.398942291736602783203125, _2059 * ((_2272 >= 0.0) ? fma(-_2315, _2277, 1.0) : (_2315 * _2277)));
                }
                else
                {
                    _2747 = fast::max(_2059, 0.0);
                }
                float _2210 = fast::max(_2747, 0.0);
                _2748 = (_522.Weighting == 0u) ? _2210 : (_2210 / fma(fma(_522.Roughness * (-0.5), _522.Roughness, 1.0), _2210, _2110));
            }
            float _2344 = dot(_1300, _1300);
            float _2347 = dot(_1364, _1300);
            float _2359 = (0.5 * fast::max(1.0 - _2344, 0.0)) * fast::max(1.0 - ((_2347 * _2347) / _2344), 0.0);
            float _2387 = sqrt(fast::max(_2359, 0.0));
            float _2392 = sqrt(fma(0.5, fast::max(_2347, 0.0), 0.5));
            float _2520 = _522.Roughness * _522.Roughness;
            float _2532 = fma(_2392 * _2392, fma(_2520, _2520, -1.0), 1.0);
            float _2398 = (0.5 * _522.Roughness) * _522.Roughness;
            float _2765;
            if (_2347 > (3.0 * _2387))
            {
                float _2410 = ((_522.Roughness * _522.Roughness) * _522.Roughness) * _522.Roughness;
                float _2413 = fma(0.5, _2410, 0.5);
                float _2416 = fma(0.5, _2410, -0.5);
                float _2422 = 1.0 / fma(_2416, _2347, _2413);
                float _2766;
                if (_522.Weighting == 0u)
                {
                    _2766 = fma((((0.5 * _2359) * (-_2416)) * fma(4.0, _2413, -((2.0 * _2416) * _2347))) * _2422, _2422, _2347);
                }
                else
                {
                    float _2453 = 1.0 / fma(fma(_522.Roughness * (-0.5), _522.Roughness, 1.0), _2347, _2398);
                    float _2461 = (_2398 * _2453) * _2453;
                    _2766 = fma(_2347, _2453, (0.5 * _2359) * fma(((-2.0) * fma(_522.Roughness * (-0.5), _522.Roughness, 1.0)) * _2461, _2453, fma(((((_2347 * _2453) * 6.0) * _2416) * _2416) * _2422, _2422, -(((4.0 * _2416) * _2461) * _2422))));
                }
                _2765 = _2766;
            }
            else
            {
                float _2764;
                if ((_2387 > 0.0) && (abs(_2347) <= (5.0 * _2387)))
                {
                    float _2560 = _2347 / _2387;
                    float _2565 = exp(((-0.5) * _2560) * _2560);
                    float _2586 = fma(0.23164188861846923828125, abs(_2560), 1.0);
                    float _2587 = 1.0 / _2586;
                    float _2603 = (0.5 / _2586) * fma(_2587, fma(_2587, fma(_2587, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2586), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    _2764 = fma(_2387 * _2565, 0.398942291736602783203125, _2347 * ((_2560 >= 0.0) ? fma(-_2603, _2565, 1.0) : (_2603 * _2565)));
                }
                else
                {
                    _2764 = fast::max(_2347, 0.0);
                }
                float _2498 = fast::max(_2764, 0.0);
                _2765 = (_522.Weighting == 0u) ? _2498 : (_2498 / fma(fma(_522.Roughness * (-0.5), _522.Roughness, 1.0), _2498, _2398));
            }
            uint2 _1175 = _2707;
            uint _2627 = _1175.x;
            uint _2629 = _1175.y;
            uint _2637 = min(spvFindLSB(~(_2627 & _2629)), (_522.TopLevel - _2708));
            _1175 = _2707 >> uint2(_2637);
            uint _2644 = _2708 + _2637;
            uint _2828;
            if (_2644 == _522.TopLevel)
            {
                uint _2651 = spvFindLSB(_1223);
                uint _2656 = _1175.y;
                uint _2661 = _1175.x;
                uint _2663 = ((((_2702 << _2651) + _2656) << _2651) + _2661) + 1u;
                _1175 = uint2(_2663 & (_1223 - 1u), (_2663 >> _2651) & (_1223 - 1u));
                _2828 = _2663 >> (2u * _2651);
            }
            else
            {
                if ((_1175.x & 1u) == 0u)
                {
                    _1175.x++;
                }
                else
                {
                    _1175 += uint2(4294967295u, 1u);
                }
                _2828 = _2702;
            }
            _2879 = _2725 + 1u;
            _2878 = _2644;
            _2877 = _1175;
            _2874 = fma(_1147.w, ((_2520 * _2520) / ((3.1415927410125732421875 * _2532) * _2532)) * _2765, _2705);
            _2862 = _2703 + (_2714.xyz * (((_2232 * _2232) / ((3.1415927410125732421875 * _2244) * _2244)) * _2748));
            _2855 = _2828;
        }
        Prefiltered.write(float4(_2703 / float3(_2705), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

