#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct IrradianceParameter
{
    uint MomentSize;
};

struct Moments
{
    float4 _data[1];
};

kernel void main0(constant IrradianceParameter& _133 [[buffer(0)]], const device Moments& Moments_1 [[buffer(1)]], texture2d_array<float, access::write> Irradiance [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]], uint gl_LocalInvocationIndex [[thread_index_in_threadgroup]])
{
    threadgroup float3 ChunkEnergy[64];
    threadgroup float3 ChunkDirection[64];
    uint3 param = gl_GlobalInvocationID;
    uint3 _266 = uint3(0u);
    uint3 _267 = uint3(Irradiance.get_width(), Irradiance.get_height(), Irradiance.get_array_size());
    _266.x = _267.x;
    _266.y = _267.y;
    _266.z = _267.z;
    uint3 _293 = _266;
    uint _301 = (6u * _133.MomentSize) * _133.MomentSize;
    float2 _272 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_293.xy)) - float2(0.5)) * float2(2.0, -2.0);
    float3 _450;
    if (param.z == 0u)
    {
        _450 = float3(1.0, _272.y, -_272.x);
    }
    else
    {
        float3 _451;
        if (param.z == 1u)
        {
            _451 = float3(-1.0, _272.y, _272.x);
        }
        else
        {
            float3 _452;
            if (param.z == 2u)
            {
                _452 = float3(_272.x, 1.0, -_272.y);
            }
            else
            {
                float3 _453;
                if (param.z == 3u)
                {
                    _453 = float3(_272.x, -1.0, _272.y);
                }
                else
                {
                    float3 _454;
                    if (param.z == 4u)
                    {
                        _454 = float3(_272.x, _272.y, 1.0);
                    }
                    else
                    {
                        _454 = float3(-_272.x, _272.y, -1.0);
                    }
                    _453 = _454;
                }
                _452 = _453;
            }
            _451 = _452;
        }
        _450 = _451;
    }
    float3 _449 = fast::normalize(_450);
    float3 _456;
    _456 = float3(0.0);
    float3 _462;
    for (uint _455 = 0u; _455 < _301; _456 = _462, _455 += 64u)
    {
        uint _322 = _455 + gl_LocalInvocationIndex;
        float3 _457;
        float3 _458;
        if (_322 < _301)
        {
            _458 = Moments_1._data[(2u * _322) + 1u].xyz;
            _457 = Moments_1._data[2u * _322].xyz;
        }
        else
        {
            _458 = float3(0.0);
            _457 = float3(0.0);
        }
        ChunkEnergy[gl_LocalInvocationIndex] = _457;
        ChunkDirection[gl_LocalInvocationIndex] = _458;
        threadgroup_barrier(mem_flags::mem_threadgroup);
        _462 = _456;
        float3 _361;
        for (uint _459 = 0u; _459 < 64u; _462 = _361, _459++)
        {
            _361 = _462 + (ChunkEnergy[_459] * fast::max(dot(_449, ChunkDirection[_459]), 0.0));
        }
        threadgroup_barrier(mem_flags::mem_threadgroup);
    }
    if (all(gl_GlobalInvocationID < _293))
    {
        Irradiance.write(float4(_456 * float3(0.3183098733425140380859375), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
    }
}

