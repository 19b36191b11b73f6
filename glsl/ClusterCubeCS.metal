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

kernel void main0(constant ClusterParameter& _433 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d_array<float> EnergyIn [[texture(1)]], texture2d_array<float> CentroidIn [[texture(2)]], texture2d_array<float> GeometryIn [[texture(3)]], texture2d_array<float, access::write> Energy [[texture(4)]], texture2d_array<float, access::write> Centroid [[texture(5)]], texture2d_array<float, access::write> Geometry [[texture(6)]], texture2d<float, access::write> TexelSolidAngle [[texture(7)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _810 = uint3(0u);
        uint3 _811 = uint3(Energy.get_width(), Energy.get_height(), Energy.get_array_size());
        _810.x = _811.x;
        _810.y = _811.y;
        _810.z = _811.z;
        if (any(gl_GlobalInvocationID >= _810))
        {
            break;
        }
        if (_433.Level == 0u)
        {
            uint3 _815 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
            float4 _1809;
            float4 _1810;
            float4 _1811;
            if (_810.x == _815.x)
            {
                uint3 _819 = gl_GlobalInvocationID;
                int3 _1198 = int4(int3(gl_GlobalInvocationID), 0).xyz;
                uint2 _1180 = gl_GlobalInvocationID.xy;
                float _1237 = float(_815.x);
                float _1238 = 1.0 / _1237;
                float _1245 = fma(2.0 * float(_1180.x), _1238, -1.0);
                float _1252 = fma(2.0 * float(_1180.y), _1238, -1.0);
                float _1256 = _1245 + (2.0 / _1237);
                float _1260 = _1252 + (2.0 / _1237);
                float _1275 = ((precise::atan2(_1245 * _1252, sqrt(fma(_1245, _1245, _1252 * _1252) + 1.0)) - precise::atan2(_1245 * _1260, sqrt(fma(_1245, _1245, _1260 * _1260) + 1.0))) - precise::atan2(_1256 * _1252, sqrt(fma(_1256, _1256, _1252 * _1252) + 1.0))) + precise::atan2(_1256 * _1260, sqrt(fma(_1256, _1256, _1260 * _1260) + 1.0));
                float3 _1211 = Source.read(uint2(_1198.xy), uint(_1198.z), 0).xyz;
                float2 _1338 = ((spvFAdd(float2(gl_GlobalInvocationID.xy), float2(0.5)) / float2(float(_815.x))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _1804;
                if (_819.z == 0u)
                {
                    _1804 = float3(1.0, _1338.y, -_1338.x);
                }
                else
                {
                    float3 _1805;
                    if (_819.z == 1u)
                    {
                        _1805 = float3(-1.0, _1338.y, _1338.x);
                    }
                    else
                    {
                        float3 _1806;
                        if (_819.z == 2u)
                        {
                            _1806 = float3(_1338.x, 1.0, -_1338.y);
                        }
                        else
                        {
                            float3 _1807;
                            if (_819.z == 3u)
                            {
                                _1807 = float3(_1338.x, -1.0, _1338.y);
                            }
                            else
                            {
                                float3 _1808;
                                if (_819.z == 4u)
                                {
                                    _1808 = float3(_1338.x, _1338.y, 1.0);
                                }
                                else
                                {
                                    _1808 = float3(-_1338.x, _1338.y, -1.0);
                                }
                                _1807 = _1808;
                            }
                            _1806 = _1807;
                        }
                        _1805 = _1806;
                    }
                    _1804 = _1805;
                }
                float3 _1452 = fast::normalize(_1804);
                float _1358 = spvFMul(fast::max(dot(_1211, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1275);
                _1811 = float4(_1452 * _1275, _1275);
                _1810 = float4(_1452 * _1358, _1358);
                _1809 = float4(_1211 * _1275, _1275);
            }
            else
            {
                uint3 _824 = gl_GlobalInvocationID;
                float4 _1772;
                float4 _1773;
                float4 _1774;
                _1774 = float4(0.0);
                _1773 = float4(0.0);
                _1772 = float4(0.0);
                float4 _1528;
                float4 _1531;
                float4 _1534;
                for (uint _1771 = 0u; _1771 < 4u; _1774 = _1534, _1773 = _1531, _1772 = _1528, _1771++)
                {
                    uint2 _1484 = (gl_GlobalInvocationID.xy * uint2(2u)) + uint2(_1771 & 1u, _1771 >> uint(1));
                    uint2 _1456 = _1484;
                    float _1555 = float(_815.x);
                    float _1556 = 1.0 / _1555;
                    float _1563 = fma(2.0 * float(_1456.x), _1556, -1.0);
                    float _1570 = fma(2.0 * float(_1456.y), _1556, -1.0);
                    float _1574 = _1563 + (2.0 / _1555);
                    float _1578 = _1570 + (2.0 / _1555);
                    float _1593 = ((precise::atan2(_1563 * _1570, sqrt(fma(_1563, _1563, _1570 * _1570) + 1.0)) - precise::atan2(_1563 * _1578, sqrt(fma(_1563, _1563, _1578 * _1578) + 1.0))) - precise::atan2(_1574 * _1570, sqrt(fma(_1574, _1574, _1570 * _1570) + 1.0))) + precise::atan2(_1574 * _1578, sqrt(fma(_1574, _1574, _1578 * _1578) + 1.0));
                    if (_824.z == 0u)
                    {
                        TexelSolidAngle.write(float4(_1593), uint2(_1484));
                    }
                    int3 _1505 = int4(int2(_1484), int(_824.z), 0).xyz;
                    float3 _1516 = Source.read(uint2(_1505.xy), uint(_1505.z), 0).xyz;
                    float2 _1656 = ((spvFAdd(float2(_1484), float2(0.5)) / float2(float(_815.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _1775;
                    if (_824.z == 0u)
                    {
                        _1775 = float3(1.0, _1656.y, -_1656.x);
                    }
                    else
                    {
                        float3 _1776;
                        if (_824.z == 1u)
                        {
                            _1776 = float3(-1.0, _1656.y, _1656.x);
                        }
                        else
                        {
                            float3 _1777;
                            if (_824.z == 2u)
                            {
                                _1777 = float3(_1656.x, 1.0, -_1656.y);
                            }
                            else
                            {
                                float3 _1778;
                                if (_824.z == 3u)
                                {
                                    _1778 = float3(_1656.x, -1.0, _1656.y);
                                }
                                else
                                {
                                    float3 _1779;
                                    if (_824.z == 4u)
                                    {
                                        _1779 = float3(_1656.x, _1656.y, 1.0);
                                    }
                                    else
                                    {
                                        _1779 = float3(-_1656.x, _1656.y, -1.0);
                                    }
                                    _1778 = _1779;
                                }
                                _1777 = _1778;
                            }
                            _1776 = _1777;
                        }
                        _1775 = _1776;
                    }
                    float3 _1770 = fast::normalize(_1775);
                    float _1676 = spvFMul(fast::max(dot(_1516, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1593);
                    _1528 = _1772 + float4(_1516 * _1593, _1593);
                    _1531 = _1773 + float4(_1770 * _1676, _1676);
                    _1534 = _1774 + float4(_1770 * _1593, _1593);
                }
                _1811 = _1774;
                _1810 = _1773;
                _1809 = _1772;
            }
            Energy.write(_1809, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Centroid.write(_1810, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Geometry.write(_1811, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            break;
        }
        int2 _898 = int2(gl_GlobalInvocationID.xy) * int2(2);
        int _902 = int(_433.Level) - 1;
        int3 _912 = int4(_898, int(param.z), _902).xyz;
        int3 _933 = int4(_898 + int2(1, 0), int(param.z), _902).xyz;
        int3 _956 = int4(_898 + int2(0, 1), int(param.z), _902).xyz;
        int3 _979 = int4(_898 + int2(1), int(param.z), _902).xyz;
        int3 _1001 = int4(_898, int(param.z), _902).xyz;
        int3 _1022 = int4(_898 + int2(1, 0), int(param.z), _902).xyz;
        int3 _1045 = int4(_898 + int2(0, 1), int(param.z), _902).xyz;
        int3 _1068 = int4(_898 + int2(1), int(param.z), _902).xyz;
        int3 _1090 = int4(_898, int(param.z), _902).xyz;
        int3 _1111 = int4(_898 + int2(1, 0), int(param.z), _902).xyz;
        int3 _1134 = int4(_898 + int2(0, 1), int(param.z), _902).xyz;
        int3 _1157 = int4(_898 + int2(1), int(param.z), _902).xyz;
        Energy.write(((EnergyIn.read(uint2(_912.xy), uint(_912.z), _902) + EnergyIn.read(uint2(_933.xy), uint(_933.z), _902)) + EnergyIn.read(uint2(_956.xy), uint(_956.z), _902)) + EnergyIn.read(uint2(_979.xy), uint(_979.z), _902), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Centroid.write(((CentroidIn.read(uint2(_1001.xy), uint(_1001.z), _902) + CentroidIn.read(uint2(_1022.xy), uint(_1022.z), _902)) + CentroidIn.read(uint2(_1045.xy), uint(_1045.z), _902)) + CentroidIn.read(uint2(_1068.xy), uint(_1068.z), _902), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Geometry.write(((GeometryIn.read(uint2(_1090.xy), uint(_1090.z), _902) + GeometryIn.read(uint2(_1111.xy), uint(_1111.z), _902)) + GeometryIn.read(uint2(_1134.xy), uint(_1134.z), _902)) + GeometryIn.read(uint2(_1157.xy), uint(_1157.z), _902), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

