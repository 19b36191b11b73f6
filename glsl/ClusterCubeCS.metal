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

kernel void main0(constant ClusterParameter& _456 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d_array<float> EnergyIn [[texture(1)]], texture2d_array<float> CentroidIn [[texture(2)]], texture2d_array<float> GeometryIn [[texture(3)]], texture2d_array<float, access::write> Energy [[texture(4)]], texture2d_array<float, access::write> Centroid [[texture(5)]], texture2d_array<float, access::write> Geometry [[texture(6)]], texture2d<float, access::write> TexelSolidAngle [[texture(7)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _831 = uint3(0u);
        uint3 _832 = uint3(Energy.get_width(), Energy.get_height(), Energy.get_array_size());
        _831.x = _832.x;
        _831.y = _832.y;
        _831.z = _832.z;
        if (any(gl_GlobalInvocationID >= _831))
        {
            break;
        }
        if (_456.Level == 0u)
        {
            uint3 _836 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
            float4 _1851;
            float4 _1852;
            float4 _1853;
            if (_831.x == _836.x)
            {
                uint3 _840 = gl_GlobalInvocationID;
                uint2 _1200 = gl_GlobalInvocationID.xy;
                float _1267 = float(_836.x);
                float _1268 = 1.0 / _1267;
                float _1275 = fma(2.0 * float(_1200.x), _1268, -1.0);
                float _1282 = fma(2.0 * float(_1200.y), _1268, -1.0);
                float _1286 = _1275 + (2.0 / _1267);
                float _1290 = _1282 + (2.0 / _1267);
                float _1305 = ((precise::atan2(_1275 * _1282, sqrt(fma(_1275, _1275, _1282 * _1282) + 1.0)) - precise::atan2(_1275 * _1290, sqrt(fma(_1275, _1275, _1290 * _1290) + 1.0))) - precise::atan2(_1286 * _1282, sqrt(fma(_1286, _1286, _1282 * _1282) + 1.0))) + precise::atan2(_1286 * _1290, sqrt(fma(_1286, _1286, _1290 * _1290) + 1.0));
                if (_840.z == 0u)
                {
                    TexelSolidAngle.write(float4(_1305), uint2(gl_GlobalInvocationID.xy));
                }
                int3 _1231 = int4(int3(gl_GlobalInvocationID), 0).xyz;
                float3 _1240 = Source.read(uint2(_1231.xy), uint(_1231.z), 0).xyz;
                float2 _1368 = ((spvFAdd(float2(gl_GlobalInvocationID.xy), float2(0.5)) / float2(float(_836.x))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _1846;
                if (_840.z == 0u)
                {
                    _1846 = float3(1.0, _1368.y, -_1368.x);
                }
                else
                {
                    float3 _1847;
                    if (_840.z == 1u)
                    {
                        _1847 = float3(-1.0, _1368.y, _1368.x);
                    }
                    else
                    {
                        float3 _1848;
                        if (_840.z == 2u)
                        {
                            _1848 = float3(_1368.x, 1.0, -_1368.y);
                        }
                        else
                        {
                            float3 _1849;
                            if (_840.z == 3u)
                            {
                                _1849 = float3(_1368.x, -1.0, _1368.y);
                            }
                            else
                            {
                                float3 _1850;
                                if (_840.z == 4u)
                                {
                                    _1850 = float3(_1368.x, _1368.y, 1.0);
                                }
                                else
                                {
                                    _1850 = float3(-_1368.x, _1368.y, -1.0);
                                }
                                _1849 = _1850;
                            }
                            _1848 = _1849;
                        }
                        _1847 = _1848;
                    }
                    _1846 = _1847;
                }
                float3 _1482 = fast::normalize(_1846);
                float _1388 = spvFMul(fast::max(dot(_1240, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1305);
                _1853 = float4(_1482 * _1305, _1305);
                _1852 = float4(_1482 * _1388, _1388);
                _1851 = float4(_1240 * _1305, _1305);
            }
            else
            {
                uint3 _845 = gl_GlobalInvocationID;
                uint3 _1486 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
                float4 _1814;
                float4 _1815;
                float4 _1816;
                _1816 = float4(0.0);
                _1815 = float4(0.0);
                _1814 = float4(0.0);
                float4 _1570;
                float4 _1573;
                float4 _1576;
                for (uint _1813 = 0u; _1813 < 4u; _1816 = _1576, _1815 = _1573, _1814 = _1570, _1813++)
                {
                    uint2 _1526 = (gl_GlobalInvocationID.xy * uint2(2u)) + uint2(_1813 & 1u, _1813 >> uint(1));
                    uint2 _1490 = _1526;
                    float _1597 = float(_1486.x);
                    float _1598 = 1.0 / _1597;
                    float _1605 = fma(2.0 * float(_1490.x), _1598, -1.0);
                    float _1612 = fma(2.0 * float(_1490.y), _1598, -1.0);
                    float _1616 = _1605 + (2.0 / _1597);
                    float _1620 = _1612 + (2.0 / _1597);
                    float _1635 = ((precise::atan2(_1605 * _1612, sqrt(fma(_1605, _1605, _1612 * _1612) + 1.0)) - precise::atan2(_1605 * _1620, sqrt(fma(_1605, _1605, _1620 * _1620) + 1.0))) - precise::atan2(_1616 * _1612, sqrt(fma(_1616, _1616, _1612 * _1612) + 1.0))) + precise::atan2(_1616 * _1620, sqrt(fma(_1616, _1616, _1620 * _1620) + 1.0));
                    if (_845.z == 0u)
                    {
                        TexelSolidAngle.write(float4(_1635), uint2(_1526));
                    }
                    int3 _1547 = int4(int2(_1526), int(_845.z), 0).xyz;
                    float3 _1558 = Source.read(uint2(_1547.xy), uint(_1547.z), 0).xyz;
                    float2 _1698 = ((spvFAdd(float2(_1526), float2(0.5)) / float2(float(_1486.x))) - float2(0.5)) * float2(2.0, -2.0);
                    float3 _1817;
                    if (_845.z == 0u)
                    {
                        _1817 = float3(1.0, _1698.y, -_1698.x);
                    }
                    else
                    {
                        float3 _1818;
                        if (_845.z == 1u)
                        {
                            _1818 = float3(-1.0, _1698.y, _1698.x);
                        }
                        else
                        {
                            float3 _1819;
                            if (_845.z == 2u)
                            {
                                _1819 = float3(_1698.x, 1.0, -_1698.y);
                            }
                            else
                            {
                                float3 _1820;
                                if (_845.z == 3u)
                                {
                                    _1820 = float3(_1698.x, -1.0, _1698.y);
                                }
                                else
                                {
                                    float3 _1821;
                                    if (_845.z == 4u)
                                    {
                                        _1821 = float3(_1698.x, _1698.y, 1.0);
                                    }
                                    else
                                    {
                                        _1821 = float3(-_1698.x, _1698.y, -1.0);
                                    }
                                    _1820 = _1821;
                                }
                                _1819 = _1820;
                            }
                            _1818 = _1819;
                        }
                        _1817 = _1818;
                    }
                    float3 _1812 = fast::normalize(_1817);
                    float _1718 = spvFMul(fast::max(dot(_1558, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1635);
                    _1570 = _1814 + float4(_1558 * _1635, _1635);
                    _1573 = _1815 + float4(_1812 * _1718, _1718);
                    _1576 = _1816 + float4(_1812 * _1635, _1635);
                }
                _1853 = _1816;
                _1852 = _1815;
                _1851 = _1814;
            }
            Energy.write(_1851, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Centroid.write(_1852, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Geometry.write(_1853, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            break;
        }
        int2 _917 = int2(gl_GlobalInvocationID.xy) * int2(2);
        int _921 = int(_456.Level) - 1;
        int3 _931 = int4(_917, int(param.z), _921).xyz;
        int3 _952 = int4(_917 + int2(1, 0), int(param.z), _921).xyz;
        int3 _975 = int4(_917 + int2(0, 1), int(param.z), _921).xyz;
        int3 _998 = int4(_917 + int2(1), int(param.z), _921).xyz;
        int3 _1020 = int4(_917, int(param.z), _921).xyz;
        int3 _1041 = int4(_917 + int2(1, 0), int(param.z), _921).xyz;
        int3 _1064 = int4(_917 + int2(0, 1), int(param.z), _921).xyz;
        int3 _1087 = int4(_917 + int2(1), int(param.z), _921).xyz;
        int3 _1109 = int4(_917, int(param.z), _921).xyz;
        int3 _1130 = int4(_917 + int2(1, 0), int(param.z), _921).xyz;
        int3 _1153 = int4(_917 + int2(0, 1), int(param.z), _921).xyz;
        int3 _1176 = int4(_917 + int2(1), int(param.z), _921).xyz;
        Energy.write(((EnergyIn.read(uint2(_931.xy), uint(_931.z), _921) + EnergyIn.read(uint2(_952.xy), uint(_952.z), _921)) + EnergyIn.read(uint2(_975.xy), uint(_975.z), _921)) + EnergyIn.read(uint2(_998.xy), uint(_998.z), _921), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Centroid.write(((CentroidIn.read(uint2(_1020.xy), uint(_1020.z), _921) + CentroidIn.read(uint2(_1041.xy), uint(_1041.z), _921)) + CentroidIn.read(uint2(_1064.xy), uint(_1064.z), _921)) + CentroidIn.read(uint2(_1087.xy), uint(_1087.z), _921), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Geometry.write(((GeometryIn.read(uint2(_1109.xy), uint(_1109.z), _921) + GeometryIn.read(uint2(_1130.xy), uint(_1130.z), _921)) + GeometryIn.read(uint2(_1153.xy), uint(_1153.z), _921)) + GeometryIn.read(uint2(_1176.xy), uint(_1176.z), _921), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

