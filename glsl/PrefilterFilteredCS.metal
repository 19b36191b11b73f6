#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterSpecularParameter
{
    float Roughness;
};

kernel void main0(constant PrefilterSpecularParameter& _327 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _547 = uint3(0u);
        uint3 _548 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _547.x = _548.x;
        _547.y = _548.y;
        _547.z = _548.z;
        if (any(gl_GlobalInvocationID >= _547))
        {
            break;
        }
        uint2 _549 = uint2(EnvMap.get_width(), EnvMap.get_height());
        float _589 = 4.0 / (float(_549.x) * float(_549.x));
        float2 _614 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_547.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _964;
        if (param.z == 0u)
        {
            _964 = float3(1.0, _614.y, -_614.x);
        }
        else
        {
            float3 _965;
            if (param.z == 1u)
            {
                _965 = float3(-1.0, _614.y, _614.x);
            }
            else
            {
                float3 _966;
                if (param.z == 2u)
                {
                    _966 = float3(_614.x, 1.0, -_614.y);
                }
                else
                {
                    float3 _967;
                    if (param.z == 3u)
                    {
                        _967 = float3(_614.x, -1.0, _614.y);
                    }
                    else
                    {
                        float3 _968;
                        if (param.z == 4u)
                        {
                            _968 = float3(_614.x, _614.y, 1.0);
                        }
                        else
                        {
                            _968 = float3(-_614.x, _614.y, -1.0);
                        }
                        _967 = _968;
                    }
                    _966 = _967;
                }
                _965 = _966;
            }
            _964 = _965;
        }
        float3 _620 = fast::normalize(_964);
        float3 _970;
        float _971;
        _971 = 0.0;
        _970 = float3(0.0);
        float3 _973;
        float _974;
        for (uint _969 = 0u; _969 < 1024u; _971 = _974, _970 = _973, _969++)
        {
            uint _798 = (_969 << uint(16)) | (_969 >> uint(16));
            uint _805 = ((_798 & 1431655765u) << uint(1)) | ((_798 & 2863311530u) >> uint(1));
            uint _812 = ((_805 & 858993459u) << uint(2)) | ((_805 & 3435973836u) >> uint(2));
            uint _819 = ((_812 & 252645135u) << uint(4)) | ((_812 & 4042322160u) >> uint(4));
            float2 _695 = float2(float(_969) * 0.0009765625, float(((_819 & 16711935u) << uint(8)) | ((_819 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            float3 _696 = _620;
            float _842 = _327.Roughness * _327.Roughness;
            float _845 = 6.283185482025146484375 * _695.x;
            float _858 = sqrt((1.0 - _695.y) / fma(fma(_842, _842, -1.0), _695.y, 1.0));
            float _863 = sqrt(fma(-_858, _858, 1.0));
            float3 _883 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_696.y) < 0.999000012874603271484375)), _620));
            float3 _907 = fast::normalize(float3x3(_883, fast::normalize(cross(_620, _883)), _620) * float3(cos(_845) * _863, sin(_845) * _863, _858));
            float3 _728 = fast::normalize((_907 * (2.0 * dot(_620, _907))) - _620);
            float _732 = fast::clamp(dot(_620, _728), 0.0, 1.0);
            if (_732 > 0.0)
            {
                float3 _700 = abs(_728);
                float _745 = fast::max(_700.x, fast::max(_700.y, _700.z));
                float _749 = fast::clamp(dot(_620, _907), 0.0, 1.0);
                float _944 = _327.Roughness * _327.Roughness;
                float _956 = fma(_749 * _749, fma(_944, _944, -1.0), 1.0);
                float _963 = (_944 * _944) / ((3.1415927410125732421875 * _956) * _956);
                float _926 = 0.5 * log2(4.0 / ((1024.0 * _963) * (((_589 * _745) * _745) * _745)));
                _974 = _971 + _732;
                _973 = _970 + (EnvMap.sample(EnvMapSampler, _728, level(((_963 > 0.0) && (_926 > 0.0)) ? _926 : 0.0)).xyz * _732);
            }
            else
            {
                _974 = _971;
                _973 = _970;
            }
        }
        Prefiltered.write(float4(_970 / float3(_971), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

