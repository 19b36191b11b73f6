#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct PrefilterSpecularParameter
{
    float Roughness;
};

kernel void main0(constant PrefilterSpecularParameter& _316 [[buffer(0)]], texturecube<float> EnvMap [[texture(0)]], texture2d_array<float, access::write> Prefiltered [[texture(1)]], sampler EnvMapSampler [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _536 = uint3(0u);
        uint3 _537 = uint3(Prefiltered.get_width(), Prefiltered.get_height(), Prefiltered.get_array_size());
        _536.x = _537.x;
        _536.y = _537.y;
        _536.z = _537.z;
        if (any(gl_GlobalInvocationID >= _536))
        {
            break;
        }
        uint2 _538 = uint2(EnvMap.get_width(), EnvMap.get_height());
        float _578 = 4.0 / (float(_538.x) * float(_538.x));
        float2 _544 = (((float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_536.xy)) - float2(0.5)) * float2(2.0, -2.0);
        float3 _946;
        if (param.z == 0u)
        {
            _946 = float3(1.0, _544.y, -_544.x);
        }
        else
        {
            float3 _947;
            if (param.z == 1u)
            {
                _947 = float3(-1.0, _544.y, _544.x);
            }
            else
            {
                float3 _948;
                if (param.z == 2u)
                {
                    _948 = float3(_544.x, 1.0, -_544.y);
                }
                else
                {
                    float3 _949;
                    if (param.z == 3u)
                    {
                        _949 = float3(_544.x, -1.0, _544.y);
                    }
                    else
                    {
                        float3 _950;
                        if (param.z == 4u)
                        {
                            _950 = float3(_544.x, _544.y, 1.0);
                        }
                        else
                        {
                            _950 = float3(-_544.x, _544.y, -1.0);
                        }
                        _949 = _950;
                    }
                    _948 = _949;
                }
                _947 = _948;
            }
            _946 = _947;
        }
        float3 _668 = fast::normalize(_946);
        float3 _952;
        float _953;
        _953 = 0.0;
        _952 = float3(0.0);
        float3 _955;
        float _956;
        for (uint _951 = 0u; _951 < 1024u; _953 = _956, _952 = _955, _951++)
        {
            uint _780 = (_951 << uint(16)) | (_951 >> uint(16));
            uint _787 = ((_780 & 1431655765u) << uint(1)) | ((_780 & 2863311530u) >> uint(1));
            uint _794 = ((_787 & 858993459u) << uint(2)) | ((_787 & 3435973836u) >> uint(2));
            uint _801 = ((_794 & 252645135u) << uint(4)) | ((_794 & 4042322160u) >> uint(4));
            float2 _677 = float2(float(_951) * 0.0009765625, float(((_801 & 16711935u) << uint(8)) | ((_801 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            float3 _678 = _668;
            float _824 = _316.Roughness * _316.Roughness;
            float _827 = 6.283185482025146484375 * _677.x;
            float _840 = sqrt((1.0 - _677.y) / fma(fma(_824, _824, -1.0), _677.y, 1.0));
            float _845 = sqrt(fma(-_840, _840, 1.0));
            float3 _865 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_678.y) < 0.999000012874603271484375)), _668));
            float3 _889 = fast::normalize(float3x3(_865, fast::normalize(cross(_668, _865)), _668) * float3(cos(_827) * _845, sin(_827) * _845, _840));
            float3 _710 = fast::normalize((_889 * (2.0 * dot(_668, _889))) - _668);
            float _714 = fast::clamp(dot(_668, _710), 0.0, 1.0);
            if (_714 > 0.0)
            {
                float3 _682 = abs(_710);
                float _727 = fast::max(_682.x, fast::max(_682.y, _682.z));
                float _731 = fast::clamp(dot(_668, _889), 0.0, 1.0);
                float _926 = _316.Roughness * _316.Roughness;
                float _938 = fma(_731 * _731, fma(_926, _926, -1.0), 1.0);
                float _945 = (_926 * _926) / ((3.1415927410125732421875 * _938) * _938);
                float _908 = 0.5 * log2(4.0 / ((1024.0 * _945) * (((_578 * _727) * _727) * _727)));
                _956 = _953 + _714;
                _955 = _952 + (EnvMap.sample(EnvMapSampler, _710, level(((_945 > 0.0) && (_908 > 0.0)) ? _908 : 0.0)).xyz * _714);
            }
            else
            {
                _956 = _953;
                _955 = _952;
            }
        }
        Prefiltered.write(float4(_952 / float3(_953), 0.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

