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
            float4 _1831;
            float4 _1832;
            float4 _1833;
            if (_821.x == _826.x)
            {
                uint3 _830 = gl_GlobalInvocationID;
                uint2 _1192 = gl_GlobalInvocationID.xy;
                float _1259 = float(_826.x);
                float _1260 = 1.0 / _1259;
                float _1267 = fma(2.0 * float(_1192.x), _1260, -1.0);
                float _1274 = fma(2.0 * float(_1192.y), _1260, -1.0);
                float _1278 = _1267 + (2.0 / _1259);
                float _1282 = _1274 + (2.0 / _1259);
                float _1297 = ((precise::atan2(_1267 * _1274, sqrt(fma(_1267, _1267, _1274 * _1274) + 1.0)) - precise::atan2(_1267 * _1282, sqrt(fma(_1267, _1267, _1282 * _1282) + 1.0))) - precise::atan2(_1278 * _1274, sqrt(fma(_1278, _1278, _1274 * _1274) + 1.0))) + precise::atan2(_1278 * _1282, sqrt(fma(_1278, _1278, _1282 * _1282) + 1.0));
                if (_830.z == 0u)
                {
                    TexelSolidAngle.write(float4(_1297), uint2(gl_GlobalInvocationID.xy));
                }
                int3 _1223 = int4(int3(gl_GlobalInvocationID), 0).xyz;
                float3 _1232 = Source.read(uint2(_1223.xy), uint(_1223.z), 0).xyz;
                float2 _1360 = ((spvFAdd(float2(gl_GlobalInvocationID.xy), float2(0.5)) / float2(float(_826.x))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _1826;
                if (_830.z == 0u)
                {
                    _1826 = float3(1.0, _1360.y, -_1360.x);
                }
                else
                {
                    float3 _1827;
                    if (_830.z == 1u)
                    {
                        _1827 = float3(-1.0, _1360.y, _1360.x);
                    }
                    else
                    {
                        float3 _1828;
                        if (_830.z == 2u)
                        {
                            _1828 = float3(_1360.x, 1.0, -_1360.y);
                        }
                        else
                        {
                            float3 _1829;
                            if (_830.z == 3u)
                            {
                                _1829 = float3(_1360.x, -1.0, _1360.y);
                            }
                            else
                            {
                                float3 _1830;
                                if (_830.z == 4u)
                                {
                                    _1830 = float3(_1360.x, _1360.y, 1.0);
                                }
                                else
                                {
                                    _1830 = float3(-_1360.x, _1360.y, -1.0);
                                }
                                _1829 = _1830;
                            }
                            _1828 = _1829;
                        }
                        _1827 = _1828;
                    }
                    _1826 = _1827;
                }
                float3 _1474 = fast::normalize(_1826);
                float _1380 = spvFMul(fast::max(dot(_1232, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1297);
                _1833 = float4(_1474 * _1297, _1297);
                _1832 = float4(_1474 * _1380, _1380);
                _1831 = float4(_1232 * _1297, _1297);
            }
            else
            {
                uint3 _835 = gl_GlobalInvocationID;
                float4 _1794;
                float4 _1795;
                float4 _1796;
                _1796 = float4(0.0);
                _1795 = float4(0.0);
                _1794 = float4(0.0);
                float4 _1550;
                float4 _1553;
                float4 _1556;
                for (uint _1793 = 0u; _1793 < 4u; _1796 = _1556, _1795 = _1553, _1794 = _1550, _1793++)
                {
                    uint2 _1506 = (gl_GlobalInvocationID.xy * uint2(2u)) + uint2(_1793 & 1u, _1793 >> uint(1));
                    uint2 _1478 = _1506;
                    float _1577 = float(_826.x);
                    float _1578 = 1.0 / _1577;
                    float _1585 = fma(2.0 * float(_1478.x), _1578, -1.0);
                    float _1592 = fma(2.0 * float(_1478.y), _1578, -1.0);
                    float _1596 = _1585 + (2.0 / _1577);
                    float _1600 = _1592 + (2.0 / _1577);
                    float _1615 = ((precise::atan2(_1585 * _1592, sqrt(fma(_1585, _1585, _1592 * _1592) + 1.0)) - precise::atan2(_1585 * _1600, sqrt(fma(_1585, _1585, _1600 * _1600) + 1.0))) - precise::atan2(_1596 * _1592, sqrt(fma(_1596, _1596, _1592 * _1592) + 1.0))) + precise::atan2(_1596 * _1600, sqrt(fma(_1596, _1596, _1600 * _1600) + 1.0));
                    if (_835.z == 0u)
                    {
                        TexelSolidAngle.write(float4(_1615), uint2(_1506));
                    }
                    int3 _1527 = int4(int2(_1506), int(_835.z), 0).xyz;
                    float3 _1538 = Source.read(uint2(_1527.xy), uint(_1527.z), 0).xyz;
                    float2 _1678 = ((spvFAdd(float2(_1506), float2(0.5)) / float2(float(_826.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _1797;
                    if (_835.z == 0u)
                    {
                        _1797 = float3(1.0, _1678.y, -_1678.x);
                    }
                    else
                    {
                        float3 _1798;
                        if (_835.z == 1u)
                        {
                            _1798 = float3(-1.0, _1678.y, _1678.x);
                        }
                        else
                        {
                            float3 _1799;
                            if (_835.z == 2u)
                            {
                                _1799 = float3(_1678.x, 1.0, -_1678.y);
                            }
                            else
                            {
                                float3 _1800;
                                if (_835.z == 3u)
                                {
                                    _1800 = float3(_1678.x, -1.0, _1678.y);
                                }
                                else
                                {
                                    float3 _1801;
                                    if (_835.z == 4u)
                                    {
                                        _1801 = float3(_1678.x, _1678.y, 1.0);
                                    }
                                    else
                                    {
                                        _1801 = float3(-_1678.x, _1678.y, -1.0);
                                    }
                                    _1800 = _1801;
                                }
                                _1799 = _1800;
                            }
                            _1798 = _1799;
                        }
                        _1797 = _1798;
                    }
                    float3 _1792 = fast::normalize(_1797);
                    float _1698 = spvFMul(fast::max(dot(_1538, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1615);
                    _1550 = _1794 + float4(_1538 * _1615, _1615);
                    _1553 = _1795 + float4(_1792 * _1698, _1698);
                    _1556 = _1796 + float4(_1792 * _1615, _1615);
                }
                _1833 = _1796;
                _1832 = _1795;
                _1831 = _1794;
            }
            Energy.write(_1831, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Centroid.write(_1832, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Geometry.write(_1833, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
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

