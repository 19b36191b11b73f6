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
};

constant int _1940 = {};

kernel void main0(constant PrefilterConvolutionParameter& _383 [[buffer(0)]], texture2d_array<float> Energy [[texture(0)]], texture2d_array<float> Centroid [[texture(1)]], texture2d_array<float> Geometry [[texture(2)]], texture2d_array<float, access::write> Prefiltered [[texture(3)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _846 = uint3(0u);
        uint3 _847 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _846.x = _847.x;
        _846.y = _847.y;
        _846.z = _847.z;
        if (any(gl_GlobalInvocationID >= _846))
        {
            break;
        }
        float2 _850 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_846.x))) - float2(0.5)) * float2(2.0, -2.0);
        float3 _1824;
        if (param.z == 0u)
        {
            _1824 = float3(1.0, _850.y, -_850.x);
        }
        else
        {
            float3 _1825;
            if (param.z == 1u)
            {
                _1825 = float3(-1.0, _850.y, _850.x);
            }
            else
            {
                float3 _1826;
                if (param.z == 2u)
                {
                    _1826 = float3(_850.x, 1.0, -_850.y);
                }
                else
                {
                    float3 _1827;
                    if (param.z == 3u)
                    {
                        _1827 = float3(_850.x, -1.0, _850.y);
                    }
                    else
                    {
                        float3 _1828;
                        if (param.z == 4u)
                        {
                            _1828 = float3(_850.x, _850.y, 1.0);
                        }
                        else
                        {
                            _1828 = float3(-_850.x, _850.y, -1.0);
                        }
                        _1827 = _1828;
                    }
                    _1826 = _1827;
                }
                _1825 = _1826;
            }
            _1824 = _1825;
        }
        float3 _1133 = fast::normalize(_1824);
        uint3 _854 = uint3(Energy.get_width(), Energy.get_height(), Energy.get_array_size());
        uint _932 = max((_854.x >> _383.TopLevel), 1u);
        uint _934 = spvFindUMSB(_854.x);
        float _1830;
        float _1831;
        _1831 = 0.0;
        _1830 = 0.0;
        float _1160;
        float _1177;
        for (uint _1829 = 0u; _1829 < 6u; _1831 = _1177, _1830 = _1160, _1829++)
        {
            int3 _1150 = int4(0, 0, int(_1829), _1940).xyz;
            _1160 = _1830 + Centroid.read(uint2(_1150.xy), uint(_1150.z), int(_934)).w;
            int3 _1167 = int4(0, 0, int(_1829), _1940).xyz;
            _1177 = _1831 + Geometry.read(uint2(_1167.xy), uint(_1167.z), int(_934)).w;
        }
        float _1184 = _1830 / _1831;
        uint _941 = 65000u - min(((6u * _932) * _932), 65000u);
        float3 _1833;
        float _1835;
        uint2 _1843;
        _1843 = uint2(0u);
        _1835 = 0.0;
        _1833 = float3(0.0);
        float3 _1032;
        float _1042;
        uint _1044;
        uint2 _1051;
        uint _1907;
        uint _1909;
        for (uint _1832 = 0u, _1838 = _383.TopLevel, _1840 = 0u; _1832 < 6u; _1843 = _1051, _1840 = _1044, _1838 = _1907, _1835 = _1042, _1833 = _1032, _1832 = _1909)
        {
            uint _1837;
            uint2 _1842;
            _1842 = _1843;
            _1837 = _1838;
            uint2 _973;
            uint _975;
            for (;;)
            {
                uint _962 = max((_854.x >> _1837), 1u);
                float2 _1187 = (((float2(_1842) + float2(0.5)) / float2(float(_962))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _1844;
                if (_1832 == 0u)
                {
                    _1844 = float3(1.0, _1187.y, -_1187.x);
                }
                else
                {
                    float3 _1845;
                    if (_1832 == 1u)
                    {
                        _1845 = float3(-1.0, _1187.y, _1187.x);
                    }
                    else
                    {
                        float3 _1846;
                        if (_1832 == 2u)
                        {
                            _1846 = float3(_1187.x, 1.0, -_1187.y);
                        }
                        else
                        {
                            float3 _1847;
                            if (_1832 == 3u)
                            {
                                _1847 = float3(_1187.x, -1.0, _1187.y);
                            }
                            else
                            {
                                float3 _1848;
                                if (_1832 == 4u)
                                {
                                    _1848 = float3(_1187.x, _1187.y, 1.0);
                                }
                                else
                                {
                                    _1848 = float3(-_1187.x, _1187.y, -1.0);
                                }
                                _1847 = _1848;
                            }
                            _1846 = _1847;
                        }
                        _1845 = _1846;
                    }
                    _1844 = _1845;
                }
                float _1208 = dot(_1133, fast::normalize(_1844));
                int4 _1217 = int4(int2(_1842), int(_1832), int(_1837));
                int4 _1189 = _1217;
                int3 _1220 = _1217.xyz;
                int3 _1227 = _1217.xyz;
                float _1245 = ((_383.Refine * 2.0) / float(_962)) * pow(fast::max(Centroid.read(uint2(_1220.xy), uint(_1220.z), _1189.w).w / fast::max(Geometry.read(uint2(_1227.xy), uint(_1227.z), _1189.w).w * _1184, 1.0000000031710768509710513471353e-30), 1.0), 0.3333333432674407958984375);
                if (((_1837 > _383.FineLevel) && (_1840 < _941)) && ((fma(-2.0, _1208, 2.0) < (_1245 * _1245)) || ((_1837 > _383.HorizonLevel) && (abs(_1208) < (2.0 / float(_962))))))
                {
                    _973 = _1842 * uint2(2u);
                    _975 = _1837 - 1u;
                    _1842 = _973;
                    _1837 = _975;
                    continue;
                }
                else
                {
                    break;
                }
            }
            int4 _986 = int4(int2(_1842), int(_1832), int(_1837));
            int4 _871 = _986;
            int3 _989 = _986.xyz;
            float4 _992 = Energy.read(uint2(_989.xy), uint(_989.z), _871.w);
            float4 _872 = _992;
            int3 _995 = _986.xyz;
            float4 _998 = Centroid.read(uint2(_995.xy), uint(_995.z), _871.w);
            float4 _873 = _998;
            int3 _1001 = _986.xyz;
            float4 _1004 = Geometry.read(uint2(_1001.xy), uint(_1001.z), _871.w);
            float4 _874 = _1004;
            float3 _1010 = _1004.xyz / float3(_874.w);
            float3 _1022 = select(_1010, _998.xyz / float3(_873.w), bool3(_873.w > 0.0));
            float _1344 = dot(_1022, _1022);
            float _1347 = dot(_1133, _1022);
            float _1359 = (0.5 * fast::max(1.0 - _1344, 0.0)) * fast::max(1.0 - ((_1347 * _1347) / _1344), 0.0);
            float _1379 = sqrt(fast::max(_1359, 0.0));
            float _1384 = sqrt(fma(0.5, fast::max(_1347, 0.0), 0.5));
            float _1447 = _383.Roughness * _383.Roughness;
            float _1459 = fma(_1384 * _1384, fma(_1447, _1447, -1.0), 1.0);
            float _1865;
            if (_1347 > (3.0 * _1379))
            {
                float _1398 = ((_383.Roughness * _383.Roughness) * _383.Roughness) * _383.Roughness;
                float _1401 = fma(0.5, _1398, 0.5);
                float _1404 = fma(0.5, _1398, -0.5);
                float _1409 = fma(_1404, _1347, _1401);
                _1865 = _1347 + ((((0.5 * _1359) * (-_1404)) * fma(4.0, _1401, -((2.0 * _1404) * _1347))) / (_1409 * _1409));
            }
            else
            {
                float _1864;
                if ((_1379 > 0.0) && (abs(_1347) <= (5.0 * _1379)))
                {
                    float _1486 = _1347 / _1379;
                    float _1510 = abs(_1486);
                    float _1514 = fma(_1510, 0.23164187371730804443359375, 1.0);
                    float _1515 = 1.0 / _1514;
                    float _1531 = (0.5 / _1514) * fma(_1515, fma(_1515, fma(_1515, (-1.45315206050872802734375) + (1.0614054203033447265625 / _1514), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _1536 = exp((_1510 * (-0.707106769084930419921875)) * (_1510 * 0.707106769084930419921875));
                    _1864 = fma(_1379, exp(((-0.5) * _1486) * _1486) * 0.398942291736602783203125, _1347 * ((_1486 >= 0.0) ? fma(-_1531, _1536, 1.0) : (_1531 * _1536)));
                }
                else
                {
                    _1864 = fast::max(_1347, 0.0);
                }
                _1865 = fast::max(_1864, 0.0);
            }
            _1032 = _1833 + (_992.xyz * (((_1447 * _1447) / ((3.1415927410125732421875 * _1459) * _1459)) * _1865));
            float _1554 = dot(_1010, _1010);
            float _1557 = dot(_1133, _1010);
            float _1569 = (0.5 * fast::max(1.0 - _1554, 0.0)) * fast::max(1.0 - ((_1557 * _1557) / _1554), 0.0);
            float _1589 = sqrt(fast::max(_1569, 0.0));
            float _1594 = sqrt(fma(0.5, fast::max(_1557, 0.0), 0.5));
            float _1657 = _383.Roughness * _383.Roughness;
            float _1669 = fma(_1594 * _1594, fma(_1657, _1657, -1.0), 1.0);
            float _1875;
            if (_1557 > (3.0 * _1589))
            {
                float _1608 = ((_383.Roughness * _383.Roughness) * _383.Roughness) * _383.Roughness;
                float _1611 = fma(0.5, _1608, 0.5);
                float _1614 = fma(0.5, _1608, -0.5);
                float _1619 = fma(_1614, _1557, _1611);
                _1875 = _1557 + ((((0.5 * _1569) * (-_1614)) * fma(4.0, _1611, -((2.0 * _1614) * _1557))) / (_1619 * _1619));
            }
            else
            {
                float _1874;
                if ((_1589 > 0.0) && (abs(_1557) <= (5.0 * _1589)))
                {
                    float _1696 = _1557 / _1589;
                    float _1720 = abs(_1696);
                    float _1724 = fma(_1720, 0.23164187371730804443359375, 1.0);
                    float _1725 = 1.0 / _1724;
                    float _1741 = (0.5 / _1724) * fma(_1725, fma(_1725, fma(_1725, (-1.45315206050872802734375) + (1.0614054203033447265625 / _1724), 1.42141377925872802734375), -0.284496724605560302734375), 0.254829585552215576171875);
                    float _1746 = exp((_1720 * (-0.707106769084930419921875)) * (_1720 * 0.707106769084930419921875));
                    _1874 = fma(_1589, exp(((-0.5) * _1696) * _1696) * 0.398942291736602783203125, _1557 * ((_1696 >= 0.0) ? fma(-_1741, _1746, 1.0) : (_1741 * _1746)));
                }
                else
                {
                    _1874 = fast::max(_1557, 0.0);
                }
                _1875 = fast::max(_1874, 0.0);
            }
            _1042 = fma(_872.w, ((_1657 * _1657) / ((3.1415927410125732421875 * _1669) * _1669)) * _1875, _1835);
            _1044 = _1840 + 1u;
            uint2 _884 = _1842;
            _1907 = _1837;
            uint _1775;
            for (; (_1907 < _383.TopLevel) && (((_884.x & _884.y) & 1u) != 0u); _1907 = _1775)
            {
                _884 = _884 >> uint2(int2(1));
                _1775 = _1907 + 1u;
            }
            if (_1907 == _383.TopLevel)
            {
                uint _1787 = _884.y;
                uint _1792 = _884.x;
                uint _1794 = ((((_1832 * _932) + _1787) * _932) + _1792) + 1u;
                _884 = uint2(_1794 % _932, (_1794 / _932) % _932);
                _1909 = _1794 / (_932 * _932);
            }
            else
            {
                if ((_884.x & 1u) == 0u)
                {
                    _884.x++;
                }
                else
                {
                    _884 += uint2(4294967295u, 1u);
                }
                _1909 = _1832;
            }
            _1051 = _884;
        }
        Prefiltered.write(float4(_1833 / float3(_1835), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

