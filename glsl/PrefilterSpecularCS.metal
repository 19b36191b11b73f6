#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterSpecularParameter
{
    float Roughness;
};

kernel void main0(constant PrefilterSpecularParameter& _384 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    uint3 _419 = uint3(0u);
    uint3 _420 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
    _419.x = _420.x;
    _419.y = _420.y;
    _419.z = _420.z;
    if (all(gl_GlobalInvocationID < _419))
    {
        float2 _421 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_419.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _731;
        if (param.z == 0u)
        {
            _731 = float3(1.0, _421.y, -_421.x);
        }
        else
        {
            float3 _732;
            if (param.z == 1u)
            {
                _732 = float3(-1.0, _421.y, _421.x);
            }
            else
            {
                float3 _733;
                if (param.z == 2u)
                {
                    _733 = float3(_421.x, 1.0, -_421.y);
                }
                else
                {
                    float3 _734;
                    if (param.z == 3u)
                    {
                        _734 = float3(_421.x, -1.0, _421.y);
                    }
                    else
                    {
                        float3 _735;
                        if (param.z == 4u)
                        {
                            _735 = float3(_421.x, _421.y, 1.0);
                        }
                        else
                        {
                            _735 = float3(-_421.x, _421.y, -1.0);
                        }
                        _734 = _735;
                    }
                    _733 = _734;
                }
                _732 = _733;
            }
            _731 = _732;
        }
        float3 _523 = fast::normalize(_731);
        float3 _737;
        float _738;
        _738 = 0.0;
        _737 = float3(0.0);
        float3 _740;
        float _741;
        for (uint _736 = 0u; _736 < 1024u; _738 = _741, _737 = _740, _736++)
        {
            uint _621 = (_736 << uint(16)) | (_736 >> uint(16));
            uint _628 = ((_621 & 1431655765u) << uint(1)) | ((_621 & 2863311530u) >> uint(1));
            uint _635 = ((_628 & 858993459u) << uint(2)) | ((_628 & 3435973836u) >> uint(2));
            uint _642 = ((_635 & 252645135u) << uint(4)) | ((_635 & 4042322160u) >> uint(4));
            float2 _547 = float2(float(_736) * 0.0009765625, float(((_642 & 16711935u) << uint(8)) | ((_642 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            float3 _548 = _523;
            float _665 = _384.Roughness * _384.Roughness;
            float _668 = 6.283185482025146484375 * _547.x;
            float _681 = sqrt((1.0 - _547.y) / fma(fma(_665, _665, -1.0), _547.y, 1.0));
            float _686 = sqrt(fma(-_681, _681, 1.0));
            float3 _706 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_548.y) < 0.999000012874603271484375)), _523));
            float3 _730 = fast::normalize(float3x3(_706, fast::normalize(cross(_523, _706)), _523) * float3(cos(_668) * _686, sin(_668) * _686, _681));
            float3 _574 = fast::normalize((_730 * (2.0 * dot(_523, _730))) - _523);
            float _578 = fast::clamp(dot(_523, _574), 0.0, 1.0);
            if (_578 > 0.0)
            {
                _741 = _738 + _578;
                _740 = _737 + (EnvMap.sample(EnvMapSampler, _574, level(0.0)).xyz * _578);
            }
            else
            {
                _741 = _738;
                _740 = _737;
            }
        }
        Prefiltered.write(float4(_737 / float3(_738), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
    }
}

