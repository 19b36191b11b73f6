#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct ClusterParameter
{
    uint Level;
};

kernel void main0(constant ClusterParameter& _213 [[buffer(0)]], texture2d_array<float> Source [[texture(0)]], texture2d_array<float> EnergyIn [[texture(1)]], texture2d_array<float> CentroidIn [[texture(2)]], texture2d_array<float> GeometryIn [[texture(3)]], texture2d_array<float, access::write> Energy [[texture(4)]], texture2d_array<float, access::write> Centroid [[texture(5)]], texture2d_array<float, access::write> Geometry [[texture(6)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _637 = uint3(0u);
        uint3 _638 = uint3(Energy.get_width(), Energy.get_height(), Energy.get_array_size());
        _637.x = _638.x;
        _637.y = _638.y;
        _637.z = _638.z;
        if (any(gl_GlobalInvocationID >= _637))
        {
            break;
        }
        if (_213.Level == 0u)
        {
            int3 _685 = int4(int3(gl_GlobalInvocationID), 0).xyz;
            float3 _694 = Source.read(uint2(_685.xy), uint(_685.z), 0).xyz;
            uint2 _641 = gl_GlobalInvocationID.xy;
            float _1054 = float(_637.x);
            float _1055 = 1.0 / _1054;
            float _1062 = fma(2.0 * float(_641.x), _1055, -1.0);
            float _1069 = fma(2.0 * float(_641.y), _1055, -1.0);
            float _1073 = _1062 + (2.0 / _1054);
            float _1077 = _1069 + (2.0 / _1054);
            float _1092 = ((precise::atan2(_1062 * _1069, sqrt(fma(_1062, _1062, _1069 * _1069) + 1.0)) - precise::atan2(_1062 * _1077, sqrt(fma(_1062, _1062, _1077 * _1077) + 1.0))) - precise::atan2(_1073 * _1069, sqrt(fma(_1073, _1073, _1069 * _1069) + 1.0))) + precise::atan2(_1073 * _1077, sqrt(fma(_1073, _1073, _1077 * _1077) + 1.0));
            float2 _645 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(float(_637.x))) - float2(0.5)) * float2(2.0, -2.0);
            float3 _1220;
            if (param.z == 0u)
            {
                _1220 = float3(1.0, _645.y, -_645.x);
            }
            else
            {
                float3 _1221;
                if (param.z == 1u)
                {
                    _1221 = float3(-1.0, _645.y, _645.x);
                }
                else
                {
                    float3 _1222;
                    if (param.z == 2u)
                    {
                        _1222 = float3(_645.x, 1.0, -_645.y);
                    }
                    else
                    {
                        float3 _1223;
                        if (param.z == 3u)
                        {
                            _1223 = float3(_645.x, -1.0, _645.y);
                        }
                        else
                        {
                            float3 _1224;
                            if (param.z == 4u)
                            {
                                _1224 = float3(_645.x, _645.y, 1.0);
                            }
                            else
                            {
                                _1224 = float3(-_645.x, _645.y, -1.0);
                            }
                            _1223 = _1224;
                        }
                        _1222 = _1223;
                    }
                    _1221 = _1222;
                }
                _1220 = _1221;
            }
            float3 _1219 = fast::normalize(_1220);
            float _717 = fast::max(dot(_694, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1092;
            Energy.write(float4(_694 * _1092, _1092), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Centroid.write(float4(_1219 * _717, _717), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            Geometry.write(float4(_1219 * _1092, _1092), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
            break;
        }
        int2 _756 = int2(gl_GlobalInvocationID.xy) * int2(2);
        int _760 = int(_213.Level) - 1;
        int3 _770 = int4(_756, int(param.z), _760).xyz;
        int3 _791 = int4(_756 + int2(1, 0), int(param.z), _760).xyz;
        int3 _814 = int4(_756 + int2(0, 1), int(param.z), _760).xyz;
        int3 _837 = int4(_756 + int2(1), int(param.z), _760).xyz;
        int3 _859 = int4(_756, int(param.z), _760).xyz;
        int3 _880 = int4(_756 + int2(1, 0), int(param.z), _760).xyz;
        int3 _903 = int4(_756 + int2(0, 1), int(param.z), _760).xyz;
        int3 _926 = int4(_756 + int2(1), int(param.z), _760).xyz;
        int3 _948 = int4(_756, int(param.z), _760).xyz;
        int3 _969 = int4(_756 + int2(1, 0), int(param.z), _760).xyz;
        int3 _992 = int4(_756 + int2(0, 1), int(param.z), _760).xyz;
        int3 _1015 = int4(_756 + int2(1), int(param.z), _760).xyz;
        Energy.write(((EnergyIn.read(uint2(_770.xy), uint(_770.z), _760) + EnergyIn.read(uint2(_791.xy), uint(_791.z), _760)) + EnergyIn.read(uint2(_814.xy), uint(_814.z), _760)) + EnergyIn.read(uint2(_837.xy), uint(_837.z), _760), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Centroid.write(((CentroidIn.read(uint2(_859.xy), uint(_859.z), _760) + CentroidIn.read(uint2(_880.xy), uint(_880.z), _760)) + CentroidIn.read(uint2(_903.xy), uint(_903.z), _760)) + CentroidIn.read(uint2(_926.xy), uint(_926.z), _760), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        Geometry.write(((GeometryIn.read(uint2(_948.xy), uint(_948.z), _760) + GeometryIn.read(uint2(_969.xy), uint(_969.z), _760)) + GeometryIn.read(uint2(_992.xy), uint(_992.z), _760)) + GeometryIn.read(uint2(_1015.xy), uint(_1015.z), _760), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

