#pragma clang diagnostic ignored "-Wmissing-prototypes"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

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

struct ClusterParameter
{
    uint Level;
};

kernel void main0(constant ClusterParameter& _444 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d_array<float> EnergyIn [[texture(1)]], texture2d_array<float> CentroidIn [[texture(2)]], texture2d_array<float> GeometryIn [[texture(3)]], texture2d_array<float, access::write> Energy [[texture(4)]], texture2d_array<float, access::write> Centroid [[texture(5)]], texture2d_array<float, access::write> Geometry [[texture(6)]], texture2d<float, access::write> TexelSolidAngle [[texture(7)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _821 = uint3(0u);
        uint3 _822 = uint3(Energy.get_width(), Energy.get_height(), Energy.get_array_size());
        _821.x = _822.x;
        _821.y = _822.y;
        _821.z = _822.z;
        if (any(gl_GlobalInvocationID >= _821))
        {
            break;
        }
        if (_444.Level == 0u)
        {
            uint3 _826 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
            float4 _1834;
            float4 _1835;
            float4 _1836;
            if (_821.x == _826.x)
            {
                uint3 _830 = gl_GlobalInvocationID;
                int3 _1209 = int4(int3(gl_GlobalInvocationID), 0).xyz;
                uint2 _1191 = gl_GlobalInvocationID.xy;
                float _1248 = float(_826.x);
                float _1249 = 1.0 / _1248;
                float _1256 = fma(2.0 * float(_1191.x), _1249, -1.0);
                float _1263 = fma(2.0 * float(_1191.y), _1249, -1.0);
                float _1267 = _1256 + (2.0 / _1248);
                float _1271 = _1263 + (2.0 / _1248);
                float _1286 = ((precise::atan2(_1256 * _1263, sqrt(fma(_1256, _1256, _1263 * _1263) + 1.0)) - precise::atan2(_1256 * _1271, sqrt(fma(_1256, _1256, _1271 * _1271) + 1.0))) - precise::atan2(_1267 * _1263, sqrt(fma(_1267, _1267, _1263 * _1263) + 1.0))) + precise::atan2(_1267 * _1271, sqrt(fma(_1267, _1267, _1271 * _1271) + 1.0));
                float3 _1222 = Source.read(uint2(_1209.xy), uint(_1209.z), 0).xyz;
                float2 _1398 = ((spvFAdd(float2(gl_GlobalInvocationID.xy), float2(0.5)) / float2(float(_826.x))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _1829;
                if (_830.z == 0u)
                {
                    _1829 = float3(1.0, _1398.y, -_1398.x);
                }
                else
                {
                    float3 _1830;
                    if (_830.z == 1u)
                    {
                        _1830 = float3(-1.0, _1398.y, _1398.x);
                    }
                    else
                    {
                        float3 _1831;
                        if (_830.z == 2u)
                        {
                            _1831 = float3(_1398.x, 1.0, -_1398.y);
                        }
                        else
                        {
                            float3 _1832;
                            if (_830.z == 3u)
                            {
                                _1832 = float3(_1398.x, -1.0, _1398.y);
                            }
                            else
                            {
                                float3 _1833;
                                if (_830.z == 4u)
                                {
                                    _1833 = float3(_1398.x, _1398.y, 1.0);
                                }
                                else
                                {
                                    _1833 = float3(-_1398.x, _1398.y, -1.0);
                                }
                                _1832 = _1833;
                            }
                            _1831 = _1832;
                        }
                        _1830 = _1831;
                    }
                    _1829 = _1830;
                }
                float3 _1404 = fast::normalize(_1829);
                float _1369 = spvFMul(fast::max(dot(_1222, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1286);
                _1836 = float4(_1404 * _1286, _1286);
                _1835 = float4(_1404 * _1369, _1369);
                _1834 = float4(_1222 * _1286, _1286);
            }
            else
            {
                uint3 _835 = gl_GlobalInvocationID;
                float4 _1797;
                float4 _1798;
                float4 _1799;
                _1799 = float4(0.0);
                _1798 = float4(0.0);
                _1797 = float4(0.0);
                float4 _1546;
                float4 _1549;
                float4 _1552;
                for (uint _1796 = 0u; _1796 < 4u; _1799 = _1552, _1798 = _1549, _1797 = _1546, _1796++)
                {
                    uint2 _1502 = (gl_GlobalInvocationID.xy * uint2(2u)) + uint2(_1796 & 1u, _1796 >> uint(1));
                    uint2 _1474 = _1502;
                    float _1573 = float(_826.x);
                    float _1574 = 1.0 / _1573;
                    float _1581 = fma(2.0 * float(_1474.x), _1574, -1.0);
                    float _1588 = fma(2.0 * float(_1474.y), _1574, -1.0);
                    float _1592 = _1581 + (2.0 / _1573);
                    float _1596 = _1588 + (2.0 / _1573);
                    float _1611 = ((precise::atan2(_1581 * _1588, sqrt(fma(_1581, _1581, _1588 * _1588) + 1.0)) - precise::atan2(_1581 * _1596, sqrt(fma(_1581, _1581, _1596 * _1596) + 1.0))) - precise::atan2(_1592 * _1588, sqrt(fma(_1592, _1592, _1588 * _1588) + 1.0))) + precise::atan2(_1592 * _1596, sqrt(fma(_1592, _1592, _1596 * _1596) + 1.0));
                    if (_835.z == 0u)
                    {
                        TexelSolidAngle.write(float4(_1611), uint2(_1502));
                    }
                    int3 _1523 = int4(int2(_1502), int(_835.z), 0).xyz;
                    float3 _1534 = Source.read(uint2(_1523.xy), uint(_1523.z), 0).xyz;
                    float2 _1723 = ((spvFAdd(float2(_1502), float2(0.5)) / float2(float(_826.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _1800;
                    if (_835.z == 0u)
                    {
                        _1800 = float3(1.0, _1723.y, -_1723.x);
                    }
                    else
                    {
                        float3 _1801;
                        if (_835.z == 1u)
                        {
                            _1801 = float3(-1.0, _1723.y, _1723.x);
                        }
                        else
                        {
                            float3 _1802;
                            if (_835.z == 2u)
                            {
                                _1802 = float3(_1723.x, 1.0, -_1723.y);
                            }
                            else
                            {
                                float3 _1803;
                                if (_835.z == 3u)
                                {
                                    _1803 = float3(_1723.x, -1.0, _1723.y);
                                }
                                else
                                {
                                    float3 _1804;
                                    if (_835.z == 4u)
                                    {
                                        _1804 = float3(_1723.x, _1723.y, 1.0);
                                    }
                                    else
                                    {
                                        _1804 = float3(-_1723.x, _1723.y, -1.0);
                                    }
                                    _1803 = _1804;
                                }
                                _1802 = _1803;
                            }
                            _1801 = _1802;
                        }
                        _1800 = _1801;
                    }
                    float3 _1729 = fast::normalize(_1800);
                    float _1694 = spvFMul(fast::max(dot(_1534, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1611);
                    _1546 = _1797 + float4(_1534 * _1611, _1611);
                    _1549 = _1798 + float4(_1729 * _1694, _1694);
                    _1552 = _1799 + float4(_1729 * _1611, _1611);
                }
                _1836 = _1799;
                _1835 = _1798;
                _1834 = _1797;
            }
            Energy.write(_1834, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Centroid.write(_1835, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Geometry.write(_1836, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            break;
        }
        int2 _909 = int2(gl_GlobalInvocationID.xy) * int2(2);
        int _913 = int(_444.Level) - 1;
        int3 _923 = int4(_909, int(param.z), _913).xyz;
        int3 _944 = int4(_909 + int2(1, 0), int(param.z), _913).xyz;
        int3 _967 = int4(_909 + int2(0, 1), int(param.z), _913).xyz;
        int3 _990 = int4(_909 + int2(1), int(param.z), _913).xyz;
        int3 _1012 = int4(_909, int(param.z), _913).xyz;
        int3 _1033 = int4(_909 + int2(1, 0), int(param.z), _913).xyz;
        int3 _1056 = int4(_909 + int2(0, 1), int(param.z), _913).xyz;
        int3 _1079 = int4(_909 + int2(1), int(param.z), _913).xyz;
        int3 _1101 = int4(_909, int(param.z), _913).xyz;
        int3 _1122 = int4(_909 + int2(1, 0), int(param.z), _913).xyz;
        int3 _1145 = int4(_909 + int2(0, 1), int(param.z), _913).xyz;
        int3 _1168 = int4(_909 + int2(1), int(param.z), _913).xyz;
        Energy.write(((EnergyIn.read(uint2(_923.xy), uint(_923.z), _913) + EnergyIn.read(uint2(_944.xy), uint(_944.z), _913)) + EnergyIn.read(uint2(_967.xy), uint(_967.z), _913)) + EnergyIn.read(uint2(_990.xy), uint(_990.z), _913), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Centroid.write(((CentroidIn.read(uint2(_1012.xy), uint(_1012.z), _913) + CentroidIn.read(uint2(_1033.xy), uint(_1033.z), _913)) + CentroidIn.read(uint2(_1056.xy), uint(_1056.z), _913)) + CentroidIn.read(uint2(_1079.xy), uint(_1079.z), _913), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Geometry.write(((GeometryIn.read(uint2(_1101.xy), uint(_1101.z), _913) + GeometryIn.read(uint2(_1122.xy), uint(_1122.z), _913)) + GeometryIn.read(uint2(_1145.xy), uint(_1145.z), _913)) + GeometryIn.read(uint2(_1168.xy), uint(_1168.z), _913), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

