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

kernel void main0(constant ClusterParameter& _397 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d_array<float> EnergyIn [[texture(1)]], texture2d_array<float> CentroidIn [[texture(2)]], texture2d_array<float> GeometryIn [[texture(3)]], texture2d_array<float, access::write> Energy [[texture(4)]], texture2d_array<float, access::write> Centroid [[texture(5)]], texture2d_array<float, access::write> Geometry [[texture(6)]], texture2d<float, access::write> TexelSolidAngle [[texture(7)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _742 = uint3(0u);
        uint3 _743 = uint3(Energy.get_width(), Energy.get_height(), Energy.get_array_size());
        _742.x = _743.x;
        _742.y = _743.y;
        _742.z = _743.z;
        if (any(gl_GlobalInvocationID >= _742))
        {
            break;
        }
        if (_397.Level == 0u)
        {
            uint3 _747 = gl_GlobalInvocationID;
            uint3 _1083 = uint3(Source.get_width(), Source.get_height(), Source.get_array_size());
            float4 _1411;
            float4 _1412;
            float4 _1413;
            _1413 = float4(0.0);
            _1412 = float4(0.0);
            _1411 = float4(0.0);
            float4 _1167;
            float4 _1170;
            float4 _1173;
            for (uint _1410 = 0u; _1410 < 4u; _1413 = _1173, _1412 = _1170, _1411 = _1167, _1410++)
            {
                uint2 _1123 = (gl_GlobalInvocationID.xy * uint2(2u)) + uint2(_1410 & 1u, _1410 >> uint(1));
                uint2 _1087 = _1123;
                float _1194 = float(_1083.x);
                float _1195 = 1.0 / _1194;
                float _1202 = fma(2.0 * float(_1087.x), _1195, -1.0);
                float _1209 = fma(2.0 * float(_1087.y), _1195, -1.0);
                float _1213 = _1202 + (2.0 / _1194);
                float _1217 = _1209 + (2.0 / _1194);
                float _1232 = ((precise::atan2(_1202 * _1209, sqrt(fma(_1202, _1202, _1209 * _1209) + 1.0)) - precise::atan2(_1202 * _1217, sqrt(fma(_1202, _1202, _1217 * _1217) + 1.0))) - precise::atan2(_1213 * _1209, sqrt(fma(_1213, _1213, _1209 * _1209) + 1.0))) + precise::atan2(_1213 * _1217, sqrt(fma(_1213, _1213, _1217 * _1217) + 1.0));
                if (_747.z == 0u)
                {
                    TexelSolidAngle.write(float4(_1232), uint2(_1123));
                }
                int3 _1144 = int4(int2(_1123), int(_747.z), 0).xyz;
                float3 _1155 = Source.read(uint2(_1144.xy), uint(_1144.z), 0).xyz;
                float2 _1295 = ((spvFAdd(float2(_1123), float2(0.5)) / float2(float(_1083.x))) - float2(0.5)) * float2(2.0, -2.0);
                float3 _1414;
                if (_747.z == 0u)
                {
                    _1414 = float3(1.0, _1295.y, -_1295.x);
                }
                else
                {
                    float3 _1415;
                    if (_747.z == 1u)
                    {
                        _1415 = float3(-1.0, _1295.y, _1295.x);
                    }
                    else
                    {
                        float3 _1416;
                        if (_747.z == 2u)
                        {
                            _1416 = float3(_1295.x, 1.0, -_1295.y);
                        }
                        else
                        {
                            float3 _1417;
                            if (_747.z == 3u)
                            {
                                _1417 = float3(_1295.x, -1.0, _1295.y);
                            }
                            else
                            {
                                float3 _1418;
                                if (_747.z == 4u)
                                {
                                    _1418 = float3(_1295.x, _1295.y, 1.0);
                                }
                                else
                                {
                                    _1418 = float3(-_1295.x, _1295.y, -1.0);
                                }
                                _1417 = _1418;
                            }
                            _1416 = _1417;
                        }
                        _1415 = _1416;
                    }
                    _1414 = _1415;
                }
                float3 _1409 = fast::normalize(_1414);
                float _1315 = spvFMul(fast::max(dot(_1155, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0), _1232);
                _1167 = _1411 + float4(_1155 * _1232, _1232);
                _1170 = _1412 + float4(_1409 * _1315, _1315);
                _1173 = _1413 + float4(_1409 * _1232, _1232);
            }
            Energy.write(_1411, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Centroid.write(_1412, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Geometry.write(_1413, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            break;
        }
        int2 _798 = int2(gl_GlobalInvocationID.xy) * int2(2);
        int _802 = int(_397.Level) - 1;
        int3 _812 = int4(_798, int(param.z), _802).xyz;
        int3 _833 = int4(_798 + int2(1, 0), int(param.z), _802).xyz;
        int3 _856 = int4(_798 + int2(0, 1), int(param.z), _802).xyz;
        int3 _879 = int4(_798 + int2(1), int(param.z), _802).xyz;
        int3 _901 = int4(_798, int(param.z), _802).xyz;
        int3 _922 = int4(_798 + int2(1, 0), int(param.z), _802).xyz;
        int3 _945 = int4(_798 + int2(0, 1), int(param.z), _802).xyz;
        int3 _968 = int4(_798 + int2(1), int(param.z), _802).xyz;
        int3 _990 = int4(_798, int(param.z), _802).xyz;
        int3 _1011 = int4(_798 + int2(1, 0), int(param.z), _802).xyz;
        int3 _1034 = int4(_798 + int2(0, 1), int(param.z), _802).xyz;
        int3 _1057 = int4(_798 + int2(1), int(param.z), _802).xyz;
        Energy.write(((EnergyIn.read(uint2(_812.xy), uint(_812.z), _802) + EnergyIn.read(uint2(_833.xy), uint(_833.z), _802)) + EnergyIn.read(uint2(_856.xy), uint(_856.z), _802)) + EnergyIn.read(uint2(_879.xy), uint(_879.z), _802), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Centroid.write(((CentroidIn.read(uint2(_901.xy), uint(_901.z), _802) + CentroidIn.read(uint2(_922.xy), uint(_922.z), _802)) + CentroidIn.read(uint2(_945.xy), uint(_945.z), _802)) + CentroidIn.read(uint2(_968.xy), uint(_968.z), _802), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Geometry.write(((GeometryIn.read(uint2(_990.xy), uint(_990.z), _802) + GeometryIn.read(uint2(_1011.xy), uint(_1011.z), _802)) + GeometryIn.read(uint2(_1034.xy), uint(_1034.z), _802)) + GeometryIn.read(uint2(_1057.xy), uint(_1057.z), _802), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

