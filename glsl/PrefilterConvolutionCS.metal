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

constant int _2255 = {};

kernel void main0(constant PrefilterConvolutionParameter& _333 [[buffer(0)]], texture2d_array<float> Energy [[texture(0)]], texture2d_array<float> Centroid [[texture(1)]], texture2d_array<float> Geometry [[texture(2)]], texture2d_array<float, access::write> Prefiltered [[texture(3)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _954 = uint3(0u);
        uint3 _955 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _954.x = _955.x;
        _954.y = _955.y;
        _954.z = _955.z;
        if (any(gl_GlobalInvocationID >= _954))
        {
            break;
        }
        float2 _958 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_954.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _2119;
        if (param.z == 0u)
        {
            _2119 = float3(1.0, _958.y, -_958.x);
        }
        else
        {
            float3 _2120;
            if (param.z == 1u)
            {
                _2120 = float3(-1.0, _958.y, _958.x);
            }
            else
            {
                float3 _2121;
                if (param.z == 2u)
                {
                    _2121 = float3(_958.x, 1.0, -_958.y);
                }
                else
                {
                    float3 _2122;
                    if (param.z == 3u)
                    {
                        _2122 = float3(_958.x, -1.0, _958.y);
                    }
                    else
                    {
                        float3 _2123;
                        if (param.z == 4u)
                        {
                            _2123 = float3(_958.x, _958.y, 1.0);
                        }
                        else
                        {
                            _2123 = float3(-_958.x, _958.y, -1.0);
                        }
                        _2122 = _2123;
                    }
                    _2121 = _2122;
                }
                _2120 = _2121;
            }
            _2119 = _2120;
        }
        float3 _1258 = fast::normalize(_2119);
        uint3 _962 = uint3(Energy.get_width(), Energy.get_height(), Energy.get_array_size());
        uint _1041 = max((_962.x >> _333.TopLevel), 1u);
        uint _1043 = spvFindUMSB(_962.x);
        float _2125;
        float _2126;
        _2126 = 0.0;
        _2125 = 0.0;
        float _1285;
        float _1302;
        for (uint _2124 = 0u; _2124 < 6u; _2126 = _1302, _2125 = _1285, _2124++)
        {
            int3 _1275 = int4(0, 0, int(_2124), _2255).xyz;
            _1285 = _2125 + Centroid.read(uint2(_1275.xy), uint(_1275.z), int(_1043)).w;
            int3 _1292 = int4(0, 0, int(_2124), _2255).xyz;
            _1302 = _2126 + Geometry.read(uint2(_1292.xy), uint(_1292.z), int(_1043)).w;
        }
        float _1309 = _2125 / _2126;
        uint _1051 = 3u + (2u * (_333.TopLevel - _333.FineLevel));
        uint _1066 = (65535u / _1051) - min(((((6u * _1041) * _1041) + (3u * _333.TopLevel)) + 1u), (65535u / _1051));
        float3 _2128;
        float _2130;
        uint2 _2138;
        _2138 = uint2(0u);
        _2130 = 0.0;
        _2128 = float3(0.0);
        float3 _1157;
        float _1167;
        uint _1169;
        uint2 _1176;
        uint _2215;
        uint _2217;
        for (uint _2127 = 0u, _2133 = _333.TopLevel, _2135 = 0u; _2127 < 6u; _2138 = _1176, _2135 = _1169, _2133 = _2215, _2130 = _1167, _2128 = _1157, _2127 = _2217)
        {
            uint _2132;
            uint2 _2137;
            _2137 = _2138;
            _2132 = _2133;
            uint2 _1098;
            uint _1100;
            for (;;)
            {
                uint _1087 = max((_962.x >> _2132), 1u);
                float2 _1312 = (((float2(_2137) + float2(0.5)) / float2(float(_1087))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _2139;
                if (_2127 == 0u)
                {
                    _2139 = float3(1.0, _1312.y, -_1312.x);
                }
                else
                {
                    float3 _2140;
                    if (_2127 == 1u)
                    {
                        _2140 = float3(-1.0, _1312.y, _1312.x);
                    }
                    else
                    {
                        float3 _2141;
                        if (_2127 == 2u)
                        {
                            _2141 = float3(_1312.x, 1.0, -_1312.y);
                        }
                        else
                        {
                            float3 _2142;
                            if (_2127 == 3u)
                            {
                                _2142 = float3(_1312.x, -1.0, _1312.y);
                            }
                            else
                            {
                                float3 _2143;
                                if (_2127 == 4u)
                                {
                                    _2143 = float3(_1312.x, _1312.y, 1.0);
                                }
                                else
                                {
                                    _2143 = float3(-_1312.x, _1312.y, -1.0);
                                }
                                _2142 = _2143;
                            }
                            _2141 = _2142;
                        }
                        _2140 = _2141;
                    }
                    _2139 = _2140;
                }
                float _1333 = dot(_1258, fast::normalize(_2139));
                int4 _1342 = int4(int2(_2137), int(_2127), int(_2132));
                int4 _1314 = _1342;
                int3 _1345 = _1342.xyz;
                int3 _1352 = _1342.xyz;
                float _1370 = ((_333.Refine * 2.0) / float(_1087)) * pow(fast::max(Centroid.read(uint2(_1345.xy), uint(_1345.z), _1314.w).w / fast::max(Geometry.read(uint2(_1352.xy), uint(_1352.z), _1314.w).w * _1309, 1.0000000031710768509710513471353e-30), 1.0), 0.3333333432674407958984375);
                if (((_2132 > _333.FineLevel) && (_2135 < _1066)) && ((fma(-2.0, _1333, 2.0) < (_1370 * _1370)) || ((_2132 > _333.HorizonLevel) && (abs(_1333) < (2.0 / float(_1087))))))
                {
                    _1098 = _2137 * uint2(2u);
                    _1100 = _2132 - 1u;
                    _2137 = _1098;
                    _2132 = _1100;
                    continue;
                }
                else
                {
                    break;
                }
            }
            int4 _1111 = int4(int2(_2137), int(_2127), int(_2132));
            int4 _980 = _1111;
            int3 _1114 = _1111.xyz;
            float4 _1117 = Energy.read(uint2(_1114.xy), uint(_1114.z), _980.w);
            float4 _981 = _1117;
            int3 _1120 = _1111.xyz;
            float4 _1123 = Centroid.read(uint2(_1120.xy), uint(_1120.z), _980.w);
            float4 _982 = _1123;
            int3 _1126 = _1111.xyz;
            float4 _1129 = Geometry.read(uint2(_1126.xy), uint(_1126.z), _980.w);
            float4 _983 = _1129;
            float3 _1135 = _1129.xyz / float3(_983.w);
            float3 _1147 = select(_1135, _1123.xyz / float3(_982.w), bool3(_982.w > 0.0));
            float _1469 = dot(_1147, _1147);
            float _1472 = dot(_1258, _1147);
            float _1484 = (0.5 * fast::max(1.0 - _1469, 0.0)) * fast::max(1.0 - ((_1472 * _1472) / _1469), 0.0);
            float _1512 = sqrt(fast::max(_1484, 0.0));
            float _1517 = sqrt(fma(0.5, fast::max(_1472, 0.0), 0.5));
            float _1647 = _333.Roughness * _333.Roughness;
            float _1659 = fma(_1517 * _1517, fma(_1647, _1647, -1.0), 1.0);
            float _1523 = (0.5 * _333.Roughness) * _333.Roughness;
            float _2160;
            if (_1472 > (3.0 * _1512))
            {
                float _1535 = ((_333.Roughness * _333.Roughness) * _333.Roughness) * _333.Roughness;
                float _1538 = fma(0.5, _1535, 0.5);
                float _1541 = fma(0.5, _1535, -0.5);
                float _1546 = fma(_1541, _1472, _1538);
                float _2161;
                if (_333.Weighting == 0u)
                {
                    _2161 = _1472 + ((((0.5 * _1484) * (-_1541)) * fma(4.0, _1538, -((2.0 * _1541) * _1472))) / (_1546 * _1546));
                }
                else
                {
                    float _1576 = fma(fma(_333.Roughness * (-0.5), _333.Roughness, 1.0), _1472, _1523);
                    float _1579 = _1472 / _1576;
                    _2161 = fma(0.5 * _1484, (((((_1579 * 6.0) * _1541) * _1541) / (_1546 * _1546)) - (((4.0 * _1541) * (_1523 / (_1576 * _1576))) / _1546)) + ((((-2.0) * fma(_333.Roughness * (-0.5), _333.Roughness, 1.0)) * _1523) / ((_1576 * _1576) * _1576)), _1579);
                }
                _2160 = _2161;
            }
            else
            {
                float _2159;
                if ((_1512 > 0.0) && (abs(_1472) <= (5.0 * _1512)))
                {
                    float _1686 = _1472 / _1512;
                    float _1710 = abs(_1686);
                    float _1714 = fma(_1710, 0.23164187371730804443359375, 1.0);
                    float _1715 = 1.0 / _1714;
                    float _1731 = (0.5 / _1714) * fma(_1715, fma(_1715, fma(_1715, (-1.45315206050872802734375) + (1.0614054203033447265625 / _1714), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _1736 = exp((_1710 * (-0.707106769084930419921875)) * (_1710 * 0.707106769084930419921875));
                    _2159 = fma(_1512, exp(((-0.5) * _1686) * _1686) * 0.398942291736602783203125, _1472 * ((_1686 >= 0.0) ? fma(-_1731, _1736, 1.0) : (_1731 * _1736)));
                }
                else
                {
                    _2159 = fast::max(_1472, 0.0);
                }
                float _1625 = fast::max(_2159, 0.0);
                _2160 = (_333.Weighting == 0u) ? _1625 : (_1625 / fma(fma(_333.Roughness * (-0.5), _333.Roughness, 1.0), _1625, _1523));
            }
            _1157 = _2128 + (_1117.xyz * (((_1647 * _1647) / ((3.1415927410125732421875 * _1659) * _1659)) * _2160));
            float _1764 = dot(_1135, _1135);
            float _1767 = dot(_1258, _1135);
            float _1779 = (0.5 * fast::max(1.0 - _1764, 0.0)) * fast::max(1.0 - ((_1767 * _1767) / _1764), 0.0);
            float _1807 = sqrt(fast::max(_1779, 0.0));
            float _1812 = sqrt(fma(0.5, fast::max(_1767, 0.0), 0.5));
            float _1942 = _333.Roughness * _333.Roughness;
            float _1954 = fma(_1812 * _1812, fma(_1942, _1942, -1.0), 1.0);
            float _1818 = (0.5 * _333.Roughness) * _333.Roughness;
            float _2172;
            if (_1767 > (3.0 * _1807))
            {
                float _1830 = ((_333.Roughness * _333.Roughness) * _333.Roughness) * _333.Roughness;
                float _1833 = fma(0.5, _1830, 0.5);
                float _1836 = fma(0.5, _1830, -0.5);
                float _1841 = fma(_1836, _1767, _1833);
                float _2173;
                if (_333.Weighting == 0u)
                {
                    _2173 = _1767 + ((((0.5 * _1779) * (-_1836)) * fma(4.0, _1833, -((2.0 * _1836) * _1767))) / (_1841 * _1841));
                }
                else
                {
                    float _1871 = fma(fma(_333.Roughness * (-0.5), _333.Roughness, 1.0), _1767, _1818);
                    float _1874 = _1767 / _1871;
                    _2173 = fma(0.5 * _1779, (((((_1874 * 6.0) * _1836) * _1836) / (_1841 * _1841)) - (((4.0 * _1836) * (_1818 / (_1871 * _1871))) / _1841)) + ((((-2.0) * fma(_333.Roughness * (-0.5), _333.Roughness, 1.0)) * _1818) / ((_1871 * _1871) * _1871)), _1874);
                }
                _2172 = _2173;
            }
            else
            {
                float _2171;
                if ((_1807 > 0.0) && (abs(_1767) <= (5.0 * _1807)))
                {
                    float _1981 = _1767 / _1807;
                    float _2005 = abs(_1981);
                    float _2009 = fma(_2005, 0.23164187371730804443359375, 1.0);
                    float _2010 = 1.0 / _2009;
                    float _2026 = (0.5 / _2009) * fma(_2010, fma(_2010, fma(_2010, (-1.45315206050872802734375) + (1.0614054203033447265625 / _2009), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _2031 = exp((_2005 * (-0.707106769084930419921875)) * (_2005 * 0.707106769084930419921875));
                    _2171 = fma(_1807, exp(((-0.5) * _1981) * _1981) * 0.398942291736602783203125, _1767 * ((_1981 >= 0.0) ? fma(-_2026, _2031, 1.0) : (_2026 * _2031)));
                }
                else
                {
                    _2171 = fast::max(_1767, 0.0);
                }
                float _1920 = fast::max(_2171, 0.0);
                _2172 = (_333.Weighting == 0u) ? _1920 : (_1920 / fma(fma(_333.Roughness * (-0.5), _333.Roughness, 1.0), _1920, _1818));
            }
            _1167 = fma(_981.w, ((_1942 * _1942) / ((3.1415927410125732421875 * _1954) * _1954)) * _2172, _2130);
            _1169 = _2135 + 1u;
            uint2 _993 = _2137;
            _2215 = _2132;
            uint _2070;
            for (; (_2215 < _333.TopLevel) && (((_993.x & _993.y) & 1u) != 0u); _2215 = _2070)
            {
                _993 = _993 >> uint2(int2(1));
                _2070 = _2215 + 1u;
            }
            if (_2215 == _333.TopLevel)
            {
                uint _2082 = _993.y;
                uint _2087 = _993.x;
                uint _2089 = ((((_2127 * _1041) + _2082) * _1041) + _2087) + 1u;
                _993 = uint2(_2089 % _1041, (_2089 / _1041) % _1041);
                _2217 = _2089 / (_1041 * _1041);
            }
            else
            {
                if ((_993.x & 1u) == 0u)
                {
                    _993.x++;
                }
                else
                {
                    _993 += uint2(4294967295u, 1u);
                }
                _2217 = _2127;
            }
            _1176 = _993;
        }
        Prefiltered.write(float4(_2128 / float3(_2130), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

