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

kernel void main0(constant PrefilterConvolutionParameter& _505 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d<float> TexelSolidAngle [[texture(1)]], texture2d_array<float> Energy [[texture(2)]], texture2d_array<float> Centroid [[texture(3)]], texture2d_array<float> Geometry [[texture(4)]], texture2d_array<float, access::write> Prefiltered [[texture(5)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
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
        float3 _2616;
        if (param.z == 0u)
        {
            _2616 = float3(1.0, _1089.y, -_1089.x);
        }
        else
        {
            float3 _2617;
            if (param.z == 1u)
            {
                _2617 = float3(-1.0, _1089.y, _1089.x);
            }
            else
            {
                float3 _2618;
                if (param.z == 2u)
                {
                    _2618 = float3(_1089.x, 1.0, -_1089.y);
                }
                else
                {
                    float3 _2619;
                    if (param.z == 3u)
                    {
                        _2619 = float3(_1089.x, -1.0, _1089.y);
                    }
                    else
                    {
                        float3 _2620;
                        if (param.z == 4u)
                        {
                            _2620 = float3(_1089.x, _1089.y, 1.0);
                        }
                        else
                        {
                            _2620 = float3(-_1089.x, _1089.y, -1.0);
                        }
                        _2619 = _2620;
                    }
                    _2618 = _2619;
                }
                _2617 = _2618;
            }
            _2616 = _2617;
        }
        float3 _1379 = fast::normalize(_2616);
        uint3 _1093 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
        uint _1181 = max((_1093.x >> _505.TopLevel), 1u);
        uint _1183 = spvFindUMSB(_1093.x);
        float _2622;
        float _2623;
        _2623 = 0.0;
        _2622 = 0.0;
        float _1410;
        float _1414;
        for (uint _2621 = 0u; _2621 < 6u; _2623 = _1414, _2622 = _1410, _2621++)
        {
            float4 _2757;
            float4 _2758;
            do
            {
                if (_1183 == 0u)
                {
                    int3 _1445 = int4(0, 0, int(_2621), 0).xyz;
                    float4 _1468 = TexelSolidAngle.read(uint2(int2(0)), 0);
                    float _1469 = _1468.x;
                    float2 _1510 = ((spvFAdd(float2(0.0), float2(0.5)) / float2(float(_1093.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2752;
                    if (_2621 == 0u)
                    {
                        _2752 = float3(1.0, _1510.y, -_1510.x);
                    }
                    else
                    {
                        float3 _2753;
                        if (_2621 == 1u)
                        {
                            _2753 = float3(-1.0, _1510.y, _1510.x);
                        }
                        else
                        {
                            float3 _2754;
                            if (_2621 == 2u)
                            {
                                _2754 = float3(_1510.x, 1.0, -_1510.y);
                            }
                            else
                            {
                                float3 _2755;
                                if (_2621 == 3u)
                                {
                                    _2755 = float3(_1510.x, -1.0, _1510.y);
                                }
                                else
                                {
                                    float3 _2756;
                                    if (_2621 == 4u)
                                    {
                                        _2756 = float3(_1510.x, _1510.y, 1.0);
                                    }
                                    else
                                    {
                                        _2756 = float3(-_1510.x, _1510.y, -1.0);
                                    }
                                    _2755 = _2756;
                                }
                                _2754 = _2755;
                            }
                            _2753 = _2754;
                        }
                        _2752 = _2753;
                    }
                    float3 _1624 = fast::normalize(_2752);
                    float _1530 = spvFMul(fast::max(dot(Source.read(uint2(_1445.xy), uint(_1445.z), 0).xyz, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1469);
                    _2758 = float4(_1624 * _1469, _1469);
                    _2757 = float4(_1624 * _1530, _1530);
                    break;
                }
                int4 _1488 = int4(0, 0, int(_2621), int(_1183 - 1u));
                int4 _1431 = _1488;
                int3 _1497 = _1488.xyz;
                int3 _1503 = _1488.xyz;
                _2758 = Geometry.read(uint2(_1503.xy), uint(_1503.z), _1431.w);
                _2757 = Centroid.read(uint2(_1497.xy), uint(_1497.z), _1431.w);
                break;
            } while(false);
            float4 _1384 = _2757;
            float4 _1385 = _2758;
            _1410 = _2622 + _1384.w;
            _1414 = _2623 + _1385.w;
        }
        float _1421 = _2622 / _2623;
        uint _1192 = 3u + (2u * (_505.TopLevel - _505.FineLevel));
        uint _1207 = (65535u / _1192) - min(((((6u * _1181) * _1181) + (3u * _505.TopLevel)) + 1u), (65535u / _1192));
        float3 _2625;
        float _2627;
        uint2 _2629;
        _2629 = uint2(0u);
        _2627 = 0.0;
        _2625 = float3(0.0);
        uint _2777;
        float3 _2784;
        float _2796;
        uint2 _2799;
        uint _2800;
        uint _2801;
        for (uint _2624 = 0u, _2630 = _505.TopLevel, _2647 = 0u; _2624 < 6u; _2647 = _2801, _2630 = _2800, _2629 = _2799, _2627 = _2796, _2625 = _2784, _2624 = _2777)
        {
            float4 _2636;
            float4 _2637;
            float4 _2638;
            do
            {
                if (_2630 == 0u)
                {
                    int3 _1648 = int4(int2(_2629), int(_2624), 0).xyz;
                    float4 _1671 = TexelSolidAngle.read(uint2(int3(int2(_2629), 0).xy), 0);
                    float _1672 = _1671.x;
                    float3 _1673 = Source.read(uint2(_1648.xy), uint(_1648.z), 0).xyz;
                    float2 _1713 = ((spvFAdd(float2(_2629), float2(0.5)) / float2(float(_1093.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _2631;
                    if (_2624 == 0u)
                    {
                        _2631 = float3(1.0, _1713.y, -_1713.x);
                    }
                    else
                    {
                        float3 _2632;
                        if (_2624 == 1u)
                        {
                            _2632 = float3(-1.0, _1713.y, _1713.x);
                        }
                        else
                        {
                            float3 _2633;
                            if (_2624 == 2u)
                            {
                                _2633 = float3(_1713.x, 1.0, -_1713.y);
                            }
                            else
                            {
                                float3 _2634;
                                if (_2624 == 3u)
                                {
                                    _2634 = float3(_1713.x, -1.0, _1713.y);
                                }
                                else
                                {
                                    float3 _2635;
                                    if (_2624 == 4u)
                                    {
                                        _2635 = float3(_1713.x, _1713.y, 1.0);
                                    }
                                    else
                                    {
                                        _2635 = float3(-_1713.x, _1713.y, -1.0);
                                    }
                                    _2634 = _2635;
                                }
                                _2633 = _2634;
                            }
                            _2632 = _2633;
                        }
                        _2631 = _2632;
                    }
                    float3 _1827 = fast::normalize(_2631);
                    float _1733 = spvFMul(fast::max(dot(_1673, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1672);
                    _2638 = float4(_1827 * _1672, _1672);
                    _2637 = float4(_1827 * _1733, _1733);
                    _2636 = float4(_1673 * _1672, _1672);
                    break;
                }
                int4 _1691 = int4(int2(_2629), int(_2624), int(_2630 - 1u));
                int4 _1634 = _1691;
                int3 _1694 = _1691.xyz;
                int3 _1700 = _1691.xyz;
                int3 _1706 = _1691.xyz;
                _2638 = Geometry.read(uint2(_1706.xy), uint(_1706.z), _1634.w);
                _2637 = Centroid.read(uint2(_1700.xy), uint(_1700.z), _1634.w);
                _2636 = Energy.read(uint2(_1694.xy), uint(_1694.z), _1634.w);
                break;
            } while(false);
            float4 _1106 = _2636;
            float4 _1107 = _2637;
            float4 _1108 = _2638;
            uint _1234 = max((_1093.x >> _2630), 1u);
            float4 _1122 = _2637;
            float4 _1123 = _2638;
            float2 _1830 = (((float2(_2629) + float2(0.5)) / float2(float(_1234))) - float2(0.5)) * float2(2.0, -2.0);
            float3 _2664;
            if (_2624 == 0u)
            {
                _2664 = float3(1.0, _1830.y, -_1830.x);
            }
            else
            {
                float3 _2665;
                if (_2624 == 1u)
                {
                    _2665 = float3(-1.0, _1830.y, _1830.x);
                }
                else
                {
                    float3 _2666;
                    if (_2624 == 2u)
                    {
                        _2666 = float3(_1830.x, 1.0, -_1830.y);
                    }
                    else
                    {
                        float3 _2667;
                        if (_2624 == 3u)
                        {
                            _2667 = float3(_1830.x, -1.0, _1830.y);
                        }
                        else
                        {
                            float3 _2668;
                            if (_2624 == 4u)
                            {
                                _2668 = float3(_1830.x, _1830.y, 1.0);
                            }
                            else
                            {
                                _2668 = float3(-_1830.x, _1830.y, -1.0);
                            }
                            _2667 = _2668;
                        }
                        _2666 = _2667;
                    }
                    _2665 = _2666;
                }
                _2664 = _2665;
            }
            float _1851 = dot(_1379, fast::normalize(_2664));
            float _1857 = (_505.Refine * 2.0) / float(_1234);
            float _1866 = fast::max(_1122.w / fast::max(_1123.w * _1421, 1.0000000031710768509710513471353e-30), 1.0);
            float _1873 = fma(-2.0, _1851, 2.0) / (_1857 * _1857);
            if (((_2630 > _505.FineLevel) && (_2647 < _1207)) && ((((_1873 * _1873) * _1873) < (_1866 * _1866)) || ((_2630 > _505.HorizonLevel) && (abs(_1851) < (2.0 / float(_1234))))))
            {
                _2801 = _2647;
                _2800 = _2630 - 1u;
                _2799 = _2629 * uint2(2u);
                _2796 = _2627;
                _2784 = _2625;
                _2777 = _2624;
                continue;
            }
            float3 _1256 = _2638.xyz / float3(_1108.w);
            float3 _1268 = select(_1256, _2637.xyz / float3(_1107.w), bool3(_1107.w > 0.0));
            float _1974 = dot(_1268, _1268);
            float _1977 = dot(_1379, _1268);
            float _1989 = (0.5 * fast::max(1.0 - _1974, 0.0)) * fast::max(1.0 - ((_1977 * _1977) / _1974), 0.0);
            float _2017 = sqrt(fast::max(_1989, 0.0));
            float _2022 = sqrt(fma(0.5, fast::max(_1977, 0.0), 0.5));
            float _2152 = _505.Roughness * _505.Roughness;
            float _2164 = fma(_2022 * _2022, fma(_2152, _2152, -1.0), 1.0);
            float _2028 = (0.5 * _505.Roughness) * _505.Roughness;
            float _2670;
            if (_1977 > (3.0 * _2017))
            {
                float _2040 = ((_505.Roughness * _505.Roughness) * _505.Roughness) * _505.Roughness;
                float _2043 = fma(0.5, _2040, 0.5);
                float _2046 = fma(0.5, _2040, -0.5);
                float _2051 = fma(_2046, _1977, _2043);
                float _2671;
                if (_505.Weighting == 0u)
                {
                    _2671 = _1977 + ((((0.5 * _1989) * (-_2046)) * fma(4.0, _2043, -((2.0 * _2046) * _1977))) / (_2051 * _2051));
                }
                else
                {
                    float _2081 = fma(fma(_505.Roughness * (-0.5), _505.Roughness, 1.0), _1977, _2028);
                    float _2084 = _1977 / _2081;
                    _2671 = fma(0.5 * _1989, (((((_2084 * 6.0) * _2046) * _2046) / (_2051 * _2051)) - (((4.0 * _2046) * (_2028 / (_2081 * _2081))) / _2051)) + ((((-2.0) * fma(_505.Roughness * (-0.5), _505.Roughness, 1.0)) * _2028) / ((_2081 * _2081) * _2081)), _2084);
                }
                _2670 = _2671;
            }
            else
            {
                float _2669;
                if ((_2017 > 0.0) && (abs(_1977) <= (5.0 * _2017)))
                {
                    float _2192 = _1977 / _2017;
                    float _2197 = exp(((-0.5) * _2192) * _2192);
                    float _2218 = fma(0.23164188861846923828125, abs(_2192), 1.0);
                    float _2219 = 1.0 / _2218;
                    float _2235 = (0.5 / _2218) * fma(_2219, fma(_2219, fma(_2219, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2218), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    _2669 = fma(_2017 * _2197, 0.398942291736602783203125, _1977 * ((_2192 >= 0.0) ? fma(-_2235, _2197, 1.0) : (_2235 * _2197)));
                }
                else
                {
                    _2669 = fast::max(_1977, 0.0);
                }
                float _2130 = fast::max(_2669, 0.0);
                _2670 = (_505.Weighting == 0u) ? _2130 : (_2130 / fma(fma(_505.Roughness * (-0.5), _505.Roughness, 1.0), _2130, _2028));
            }
            float _2264 = dot(_1256, _1256);
            float _2267 = dot(_1379, _1256);
            float _2279 = (0.5 * fast::max(1.0 - _2264, 0.0)) * fast::max(1.0 - ((_2267 * _2267) / _2264), 0.0);
            float _2307 = sqrt(fast::max(_2279, 0.0));
            float _2312 = sqrt(fma(0.5, fast::max(_2267, 0.0), 0.5));
            float _2442 = _505.Roughness * _505.Roughness;
            float _2454 = fma(_2312 * _2312, fma(_2442, _2442, -1.0), 1.0);
            float _2318 = (0.5 * _505.Roughness) * _505.Roughness;
            float _2687;
            if (_2267 > (3.0 * _2307))
            {
                float _2330 = ((_505.Roughness * _505.Roughness) * _505.Roughness) * _505.Roughness;
                float _2333 = fma(0.5, _2330, 0.5);
                float _2336 = fma(0.5, _2330, -0.5);
                float _2341 = fma(_2336, _2267, _2333);
                float _2688;
                if (_505.Weighting == 0u)
                {
                    _2688 = _2267 + ((((0.5 * _2279) * (-_2336)) * fma(4.0, _2333, -((2.0 * _2336) * _2267))) / (_2341 * _2341));
                }
                else
                {
                    float _2371 = fma(fma(_505.Roughness * (-0.5), _505.Roughness, 1.0), _2267, _2318);
                    float _2374 = _2267 / _2371;
                    _2688 = fma(0.5 * _2279, (((((_2374 * 6.0) * _2336) * _2336) / (_2341 * _2341)) - (((4.0 * _2336) * (_2318 / (_2371 * _2371))) / _2341)) + ((((-2.0) * fma(_505.Roughness * (-0.5), _505.Roughness, 1.0)) * _2318) / ((_2371 * _2371) * _2371)), _2374);
                }
                _2687 = _2688;
            }
            else
            {
                float _2686;
                if ((_2307 > 0.0) && (abs(_2267) <= (5.0 * _2307)))
                {
                    float _2482 = _2267 / _2307;
                    float _2487 = exp(((-0.5) * _2482) * _2482);
                    float _2508 = fma(0.23164188861846923828125, abs(_2482), 1.0);
                    float _2509 = 1.0 / _2508;
                    float _2525 = (0.5 / _2508) * fma(_2509, fma(_2509, fma(_2509, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2508), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    _2686 = fma(_2307 * _2487, 0.398942291736602783203125, _2267 * ((_2482 >= 0.0) ? fma(-_2525, _2487, 1.0) : (_2525 * _2487)));
                }
                else
                {
                    _2686 = fast::max(_2267, 0.0);
                }
                float _2420 = fast::max(_2686, 0.0);
                _2687 = (_505.Weighting == 0u) ? _2420 : (_2420 / fma(fma(_505.Roughness * (-0.5), _505.Roughness, 1.0), _2420, _2318));
            }
            uint2 _1133 = _2629;
            uint _2549 = _1133.x;
            uint _2551 = _1133.y;
            uint _2559 = min(spvFindLSB(~(_2549 & _2551)), (_505.TopLevel - _2630));
            _1133 = _2629 >> uint2(_2559);
            uint _2566 = _2630 + _2559;
            uint _2750;
            if (_2566 == _505.TopLevel)
            {
                uint _2573 = spvFindLSB(_1181);
                uint _2578 = _1133.y;
                uint _2583 = _1133.x;
                uint _2585 = ((((_2624 << _2573) + _2578) << _2573) + _2583) + 1u;
                _1133 = uint2(_2585 & (_1181 - 1u), (_2585 >> _2573) & (_1181 - 1u));
                _2750 = _2585 >> (2u * _2573);
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
                _2750 = _2624;
            }
            _2801 = _2647 + 1u;
            _2800 = _2566;
            _2799 = _1133;
            _2796 = fma(_1106.w, ((_2442 * _2442) / ((3.1415927410125732421875 * _2454) * _2454)) * _2687, _2627);
            _2784 = _2625 + (_2636.xyz * (((_2152 * _2152) / ((3.1415927410125732421875 * _2164) * _2164)) * _2670));
            _2777 = _2750;
        }
        Prefiltered.write(float4(_2625 / float3(_2627), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

