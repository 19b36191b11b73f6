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

kernel void main0(constant PrefilterChunkParameter& _293 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::read_write> Accumulated [[texture(1)]], texture2d_array<float, access::write> Prefiltered [[texture(2)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _465 = uint3(0u);
        uint3 _466 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _465.x = _466.x;
        _465.y = _466.y;
        _465.z = _466.z;
        if (any(gl_GlobalInvocationID >= _465))
        {
            break;
        }
        float2 _539 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_465.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _810;
        if (param.z == 0u)
        {
            _810 = float3(1.0, _539.y, -_539.x);
        }
        else
        {
            float3 _811;
            if (param.z == 1u)
            {
                _811 = float3(-1.0, _539.y, _539.x);
            }
            else
            {
                float3 _812;
                if (param.z == 2u)
                {
                    _812 = float3(_539.x, 1.0, -_539.y);
                }
                else
                {
                    float3 _813;
                    if (param.z == 3u)
                    {
                        _813 = float3(_539.x, -1.0, _539.y);
                    }
                    else
                    {
                        float3 _814;
                        if (param.z == 4u)
                        {
                            _814 = float3(_539.x, _539.y, 1.0);
                        }
                        else
                        {
                            _814 = float3(-_539.x, _539.y, -1.0);
                        }
                        _813 = _814;
                    }
                    _812 = _813;
                }
                _811 = _812;
            }
            _810 = _811;
        }
        float3 _545 = fast::normalize(_810);
        float4 _816;
        _816 = float4(0.0);
        float4 _818;
        for (uint _815 = _293.FirstSample; _815 < (_293.FirstSample + _293.ChunkSamples); _816 = _818, _815++)
        {
            uint _700 = (_815 << uint(16)) | (_815 >> uint(16));
            uint _707 = ((_700 & 1431655765u) << uint(1)) | ((_700 & 2863311530u) >> uint(1));
            uint _714 = ((_707 & 858993459u) << uint(2)) | ((_707 & 3435973836u) >> uint(2));
            uint _721 = ((_714 & 252645135u) << uint(4)) | ((_714 & 4042322160u) >> uint(4));
            float2 _619 = float2(float(_815) * 0.0009765625, float(((_721 & 16711935u) << uint(8)) | ((_721 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            float3 _620 = _545;
            float _744 = _293.Roughness * _293.Roughness;
            float _747 = 6.283185482025146484375 * _619.x;
            float _760 = sqrt((1.0 - _619.y) / fma(fma(_744, _744, -1.0), _619.y, 1.0));
            float _765 = sqrt(fma(-_760, _760, 1.0));
            float3 _785 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_620.y) < 0.999000012874603271484375)), _545));
            float3 _809 = fast::normalize(float3x3(_785, fast::normalize(cross(_545, _785)), _545) * float3(cos(_747) * _765, sin(_747) * _765, _760));
            float3 _654 = fast::normalize((_809 * (2.0 * dot(_545, _809))) - _545);
            float _658 = fast::clamp(dot(_545, _654), 0.0, 1.0);
            if (_658 > 0.0)
            {
                _818 = _816 + float4(EnvMap.sample(EnvMapSampler, _654, level(0.0)).xyz * _658, _658);
            }
            else
            {
                _818 = _816;
            }
        }
        float4 _470 = _816;
        if (_293.FirstSample > 0u)
        {
            _470 += Accumulated.read(uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        }
        Accumulated.write(_470, uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        if (_293.Resolve != 0u)
        {
            Prefiltered.write(float4(_470.xyz / float3(_470.w), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        }
        break;
    } while(false);
}

