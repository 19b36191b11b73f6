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

struct PrefilterConvolutionParameter
{
    float Roughness;
    uint TopLevel;
    uint FineLevel;
    float Refine;
    uint HorizonLevel;
    uint Weighting;
};

constant int _2221 = {};

kernel void main0(constant PrefilterConvolutionParameter& _333 [[buffer(0)]], texture2d_array<float> Energy [[texture(0)]], texture2d_array<float> Centroid [[texture(1)]], texture2d_array<float> Geometry [[texture(2)]], texture2d_array<float, access::write> Prefiltered [[texture(3)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _937 = uint3(0u);
        uint3 _938 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _937.x = _938.x;
        _937.y = _938.y;
        _937.z = _938.z;
        if (any(gl_GlobalInvocationID >= _937))
        {
            break;
        }
        float2 _941 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_937.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _2085;
        if (param.z == 0u)
        {
            _2085 = float3(1.0, _941.y, -_941.x);
        }
        else
        {
            float3 _2086;
            if (param.z == 1u)
            {
                _2086 = float3(-1.0, _941.y, _941.x);
            }
            else
            {
                float3 _2087;
                if (param.z == 2u)
                {
                    _2087 = float3(_941.x, 1.0, -_941.y);
                }
                else
                {
                    float3 _2088;
                    if (param.z == 3u)
                    {
                        _2088 = float3(_941.x, -1.0, _941.y);
                    }
                    else
                    {
                        float3 _2089;
                        if (param.z == 4u)
                        {
                            _2089 = float3(_941.x, _941.y, 1.0);
                        }
                        else
                        {
                            _2089 = float3(-_941.x, _941.y, -1.0);
                        }
                        _2088 = _2089;
                    }
                    _2087 = _2088;
                }
                _2086 = _2087;
            }
            _2085 = _2086;
        }
        float3 _1224 = fast::normalize(_2085);
        uint3 _945 = uint3(Energy.get_width(), Energy.get_height(), Energy.get_array_size());
        uint _1023 = max((_945.x >> _333.TopLevel), 1u);
        uint _1025 = spvFindUMSB(_945.x);
        float _2091;
        float _2092;
        _2092 = 0.0;
        _2091 = 0.0;
        float _1251;
        float _1268;
        for (uint _2090 = 0u; _2090 < 6u; _2092 = _1268, _2091 = _1251, _2090++)
        {
            int3 _1241 = int4(0, 0, int(_2090), _2221).xyz;
            _1251 = _2091 + Centroid.read(uint2(_1241.xy), uint(_1241.z), int(_1025)).w;
            int3 _1258 = int4(0, 0, int(_2090), _2221).xyz;
            _1268 = _2092 + Geometry.read(uint2(_1258.xy), uint(_1258.z), int(_1025)).w;
        }
        float _1275 = _2091 / _2092;
        uint _1032 = 65000u - min(((6u * _1023) * _1023), 65000u);
        float3 _2094;
        float _2096;
        uint2 _2104;
        _2104 = uint2(0u);
        _2096 = 0.0;
        _2094 = float3(0.0);
        float3 _1123;
        float _1133;
        uint _1135;
        uint2 _1142;
        uint _2181;
        uint _2183;
        for (uint _2093 = 0u, _2099 = _333.TopLevel, _2101 = 0u; _2093 < 6u; _2104 = _1142, _2101 = _1135, _2099 = _2181, _2096 = _1133, _2094 = _1123, _2093 = _2183)
        {
            uint _2098;
            uint2 _2103;
            _2103 = _2104;
            _2098 = _2099;
            uint2 _1064;
            uint _1066;
            for (;;)
            {
                uint _1053 = max((_945.x >> _2098), 1u);
                float2 _1278 = (((float2(_2103) + float2(0.5)) / float2(float(_1053))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _2105;
                if (_2093 == 0u)
                {
                    _2105 = float3(1.0, _1278.y, -_1278.x);
                }
                else
                {
                    float3 _2106;
                    if (_2093 == 1u)
                    {
                        _2106 = float3(-1.0, _1278.y, _1278.x);
                    }
                    else
                    {
                        float3 _2107;
                        if (_2093 == 2u)
                        {
                            _2107 = float3(_1278.x, 1.0, -_1278.y);
                        }
                        else
                        {
                            float3 _2108;
                            if (_2093 == 3u)
                            {
                                _2108 = float3(_1278.x, -1.0, _1278.y);
                            }
                            else
                            {
                                float3 _2109;
                                if (_2093 == 4u)
                                {
                                    _2109 = float3(_1278.x, _1278.y, 1.0);
                                }
                                else
                                {
                                    _2109 = float3(-_1278.x, _1278.y, -1.0);
                                }
                                _2108 = _2109;
                            }
                            _2107 = _2108;
                        }
                        _2106 = _2107;
                    }
                    _2105 = _2106;
                }
                float _1299 = dot(_1224, fast::normalize(_2105));
                int4 _1308 = int4(int2(_2103), int(_2093), int(_2098));
                int4 _1280 = _1308;
                int3 _1311 = _1308.xyz;
                int3 _1318 = _1308.xyz;
                float _1336 = ((_333.Refine * 2.0) / float(_1053)) * pow(fast::max(Centroid.read(uint2(_1311.xy), uint(_1311.z), _1280.w).w / fast::max(Geometry.read(uint2(_1318.xy), uint(_1318.z), _1280.w).w * _1275, 1.0000000031710768509710513471353e-30), 1.0), 0.3333333432674407958984375);
                if (((_2098 > _333.FineLevel) && (_2101 < _1032)) && ((fma(-2.0, _1299, 2.0) < (_1336 * _1336)) || ((_2098 > _333.HorizonLevel) && (abs(_1299) < (2.0 / float(_1053))))))
                {
                    _1064 = _2103 * uint2(2u);
                    _1066 = _2098 - 1u;
                    _2103 = _1064;
                    _2098 = _1066;
                    continue;
                }
                else
                {
                    break;
                }
            }
            int4 _1077 = int4(int2(_2103), int(_2093), int(_2098));
            int4 _962 = _1077;
            int3 _1080 = _1077.xyz;
            float4 _1083 = Energy.read(uint2(_1080.xy), uint(_1080.z), _962.w);
            float4 _963 = _1083;
            int3 _1086 = _1077.xyz;
            float4 _1089 = Centroid.read(uint2(_1086.xy), uint(_1086.z), _962.w);
            float4 _964 = _1089;
            int3 _1092 = _1077.xyz;
            float4 _1095 = Geometry.read(uint2(_1092.xy), uint(_1092.z), _962.w);
            float4 _965 = _1095;
            float3 _1101 = _1095.xyz / float3(_965.w);
            float3 _1113 = select(_1101, _1089.xyz / float3(_964.w), bool3(_964.w > 0.0));
            float _1435 = dot(_1113, _1113);
            float _1438 = dot(_1224, _1113);
            float _1450 = (0.5 * fast::max(1.0 - _1435, 0.0)) * fast::max(1.0 - ((_1438 * _1438) / _1435), 0.0);
            float _1478 = sqrt(fast::max(_1450, 0.0));
            float _1483 = sqrt(fma(0.5, fast::max(_1438, 0.0), 0.5));
            float _1613 = _333.Roughness * _333.Roughness;
            float _1625 = fma(_1483 * _1483, fma(_1613, _1613, -1.0), 1.0);
            float _1489 = (0.5 * _333.Roughness) * _333.Roughness;
            float _2126;
            if (_1438 > (3.0 * _1478))
            {
                float _1501 = ((_333.Roughness * _333.Roughness) * _333.Roughness) * _333.Roughness;
                float _1504 = fma(0.5, _1501, 0.5);
                float _1507 = fma(0.5, _1501, -0.5);
                float _1512 = fma(_1507, _1438, _1504);
                float _2127;
                if (_333.Weighting == 0u)
                {
                    _2127 = _1438 + ((((0.5 * _1450) * (-_1507)) * fma(4.0, _1504, -((2.0 * _1507) * _1438))) / (_1512 * _1512));
                }
                else
                {
                    float _1542 = fma(fma(_333.Roughness * (-0.5), _333.Roughness, 1.0), _1438, _1489);
                    float _1545 = _1438 / _1542;
                    _2127 = fma(0.5 * _1450, (((((_1545 * 6.0) * _1507) * _1507) / (_1512 * _1512)) - (((4.0 * _1507) * (_1489 / (_1542 * _1542))) / _1512)) + ((((-2.0) * fma(_333.Roughness * (-0.5), _333.Roughness, 1.0)) * _1489) / ((_1542 * _1542) * _1542)), _1545);
                }
                _2126 = _2127;
            }
            else
            {
                float _2125;
                if ((_1478 > 0.0) && (abs(_1438) <= (5.0 * _1478)))
                {
                    float _1652 = _1438 / _1478;
                    float _1676 = abs(_1652);
                    float _1680 = fma(_1676, 0.23164187371730804443359375, 1.0);
                    float _1681 = 1.0 / _1680;
                    float _1697 = (0.5 / _1680) * fma(_1681, fma(_1681, fma(_1681, (-1.45315206050872802734375) + (1.0614054203033447265625 / _1680), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _1702 = exp((_1676 * (-0.707106769084930419921875)) * (_1676 * 0.707106769084930419921875));
                    _2125 = fma(_1478, exp(((-0.5) * _1652) * _1652) * 0.398942291736602783203125, _1438 * ((_1652 >= 0.0) ? fma(-_1697, _1702, 1.0) : (_1697 * _1702)));
                }
                else
                {
                    _2125 = fast::max(_1438, 0.0);
                }
                float _1591 = fast::max(_2125, 0.0);
                _2126 = (_333.Weighting == 0u) ? _1591 : (_1591 / fma(fma(_333.Roughness * (-0.5), _333.Roughness, 1.0), _1591, _1489));
            }
            _1123 = _2094 + (_1083.xyz * (((_1613 * _1613) / ((3.1415927410125732421875 * _1625) * _1625)) * _2126));
            float _1730 = dot(_1101, _1101);
            float _1733 = dot(_1224, _1101);
            float _1745 = (0.5 * fast::max(1.0 - _1730, 0.0)) * fast::max(1.0 - ((_1733 * _1733) / _1730), 0.0);
            float _1773 = sqrt(fast::max(_1745, 0.0));
            float _1778 = sqrt(fma(0.5, fast::max(_1733, 0.0), 0.5));
            float _1908 = _333.Roughness * _333.Roughness;
            float _1920 = fma(_1778 * _1778, fma(_1908, _1908, -1.0), 1.0);
            float _1784 = (0.5 * _333.Roughness) * _333.Roughness;
            float _2138;
            if (_1733 > (3.0 * _1773))
            {
                float _1796 = ((_333.Roughness * _333.Roughness) * _333.Roughness) * _333.Roughness;
                float _1799 = fma(0.5, _1796, 0.5);
                float _1802 = fma(0.5, _1796, -0.5);
                float _1807 = fma(_1802, _1733, _1799);
                float _2139;
                if (_333.Weighting == 0u)
                {
                    _2139 = _1733 + ((((0.5 * _1745) * (-_1802)) * fma(4.0, _1799, -((2.0 * _1802) * _1733))) / (_1807 * _1807));
                }
                else
                {
                    float _1837 = fma(fma(_333.Roughness * (-0.5), _333.Roughness, 1.0), _1733, _1784);
                    float _1840 = _1733 / _1837;
                    _2139 = fma(0.5 * _1745, (((((_1840 * 6.0) * _1802) * _1802) / (_1807 * _1807)) - (((4.0 * _1802) * (_1784 / (_1837 * _1837))) / _1807)) + ((((-2.0) * fma(_333.Roughness * (-0.5), _333.Roughness, 1.0)) * _1784) / ((_1837 * _1837) * _1837)), _1840);
                }
                _2138 = _2139;
            }
            else
            {
                float _2137;
                if ((_1773 > 0.0) && (abs(_1733) <= (5.0 * _1773)))
                {
                    float _1947 = _1733 / _1773;
                    float _1971 = abs(_1947);
                    float _1975 = fma(_1971, 0.23164187371730804443359375, 1.0);
                    float _1976 = 1.0 / _1975;
                    float _1992 = (0.5 / _1975) * fma(_1976, fma(_1976, fma(_1976, (-1.45315206050872802734375) + (1.0614054203033447265625 / _1975), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _1997 = exp((_1971 * (-0.707106769084930419921875)) * (_1971 * 0.707106769084930419921875));
                    _2137 = fma(_1773, exp(((-0.5) * _1947) * _1947) * 0.398942291736602783203125, _1733 * ((_1947 >= 0.0) ? fma(-_1992, _1997, 1.0) : (_1992 * _1997)));
                }
                else
                {
                    _2137 = fast::max(_1733, 0.0);
                }
                float _1886 = fast::max(_2137, 0.0);
                _2138 = (_333.Weighting == 0u) ? _1886 : (_1886 / fma(fma(_333.Roughness * (-0.5), _333.Roughness, 1.0), _1886, _1784));
            }
            _1133 = fma(_963.w, ((_1908 * _1908) / ((3.1415927410125732421875 * _1920) * _1920)) * _2138, _2096);
            _1135 = _2101 + 1u;
            uint2 _975 = _2103;
            _2181 = _2098;
            uint _2036;
            for (; (_2181 < _333.TopLevel) && (((_975.x & _975.y) & 1u) != 0u); _2181 = _2036)
            {
                _975 = _975 >> uint2(int2(1));
                _2036 = _2181 + 1u;
            }
            if (_2181 == _333.TopLevel)
            {
                uint _2048 = _975.y;
                uint _2053 = _975.x;
                uint _2055 = ((((_2093 * _1023) + _2048) * _1023) + _2053) + 1u;
                _975 = uint2(_2055 % _1023, (_2055 / _1023) % _1023);
                _2183 = _2055 / (_1023 * _1023);
            }
            else
            {
                if ((_975.x & 1u) == 0u)
                {
                    _975.x++;
                }
                else
                {
                    _975 += uint2(4294967295u, 1u);
                }
                _2183 = _2093;
            }
            _1142 = _975;
        }
        Prefiltered.write(float4(_2094 / float3(_2096), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

