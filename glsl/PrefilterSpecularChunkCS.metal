#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterChunkParameter
{
    float Roughness;
    uint FirstSample;
    uint ChunkSamples;
    uint Resolve;
};

kernel void main0(constant PrefilterChunkParameter& _282 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::read_write> Accumulated [[texture(1)]], texture2d_array<float, access::write> Prefiltered [[texture(2)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _454 = uint3(0u);
        uint3 _455 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _454.x = _455.x;
        _454.y = _455.y;
        _454.z = _455.z;
        if (any(gl_GlobalInvocationID >= _454))
        {
            break;
        }
        float2 _458 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_454.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _792;
        if (param.z == 0u)
        {
            _792 = float3(1.0, _458.y, -_458.x);
        }
        else
        {
            float3 _793;
            if (param.z == 1u)
            {
                _793 = float3(-1.0, _458.y, _458.x);
            }
            else
            {
                float3 _794;
                if (param.z == 2u)
                {
                    _794 = float3(_458.x, 1.0, -_458.y);
                }
                else
                {
                    float3 _795;
                    if (param.z == 3u)
                    {
                        _795 = float3(_458.x, -1.0, _458.y);
                    }
                    else
                    {
                        float3 _796;
                        if (param.z == 4u)
                        {
                            _796 = float3(_458.x, _458.y, 1.0);
                        }
                        else
                        {
                            _796 = float3(-_458.x, _458.y, -1.0);
                        }
                        _795 = _796;
                    }
                    _794 = _795;
                }
                _793 = _794;
            }
            _792 = _793;
        }
        float3 _593 = fast::normalize(_792);
        float4 _798;
        _798 = float4(0.0);
        float4 _800;
        for (uint _797 = _282.FirstSample; _797 < (_282.FirstSample + _282.ChunkSamples); _798 = _800, _797++)
        {
            uint _682 = (_797 << uint(16)) | (_797 >> uint(16));
            uint _689 = ((_682 & 1431655765u) << uint(1)) | ((_682 & 2863311530u) >> uint(1));
            uint _696 = ((_689 & 858993459u) << uint(2)) | ((_689 & 3435973836u) >> uint(2));
            uint _703 = ((_696 & 252645135u) << uint(4)) | ((_696 & 4042322160u) >> uint(4));
            float2 _601 = float2(float(_797) * 0.0009765625, float(((_703 & 16711935u) << uint(8)) | ((_703 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            float3 _602 = _593;
            float _726 = _282.Roughness * _282.Roughness;
            float _729 = 6.283185482025146484375 * _601.x;
            float _742 = sqrt((1.0 - _601.y) / fma(fma(_726, _726, -1.0), _601.y, 1.0));
            float _747 = sqrt(fma(-_742, _742, 1.0));
            float3 _767 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_602.y) < 0.999000012874603271484375)), _593));
            float3 _791 = fast::normalize(float3x3(_767, fast::normalize(cross(_593, _767)), _593) * float3(cos(_729) * _747, sin(_729) * _747, _742));
            float3 _636 = fast::normalize((_791 * (2.0 * dot(_593, _791))) - _593);
            float _640 = fast::clamp(dot(_593, _636), 0.0, 1.0);
            if (_640 > 0.0)
            {
                _800 = _798 + float4(EnvMap.sample(EnvMapSampler, _636, level(0.0)).xyz * _640, _640);
            }
            else
            {
                _800 = _798;
            }
        }
        float4 _459 = _798;
        if (_282.FirstSample > 0u)
        {
            _459 += Accumulated.read(uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        }
        Accumulated.write(_459, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        if (_282.Resolve != 0u)
        {
            Prefiltered.write(float4(_459.xyz / float3(_459.w), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        }
        break;
    } while(false);
}

