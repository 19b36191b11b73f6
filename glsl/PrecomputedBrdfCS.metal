#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

kernel void main0(texture2d<float, access::write> Precomputed [[texture(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint2 _405 = uint2(0u);
    uint2 _406 = uint2(Precomputed.get_width(), Precomputed.get_height());
    _405.x = _406.x;
    _405.y = _406.y;
    if (all(uint2(gl_GlobalInvocationID.xy) < _405))
    {
        float2 _407 = (float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_405);
        float3 _476 = float3(sqrt(fma(-_407.x, _407.x, 1.0)), 0.0, _407.x);
        float _734;
        float _735;
        _735 = 0.0;
        _734 = 0.0;
        float _737;
        float _738;
        for (uint _733 = 0u; _733 < 1024u; _735 = _738, _734 = _737, _733++)
        {
            uint _564 = (_733 << uint(16)) | (_733 >> uint(16));
            uint _571 = ((_564 & 1431655765u) << uint(1)) | ((_564 & 2863311530u) >> uint(1));
            uint _578 = ((_571 & 858993459u) << uint(2)) | ((_571 & 3435973836u) >> uint(2));
            uint _585 = ((_578 & 252645135u) << uint(4)) | ((_578 & 4042322160u) >> uint(4));
            float2 _455 = float2(float(_733) * 0.0009765625, float(((_585 & 16711935u) << uint(8)) | ((_585 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            float3 _456 = float3(0.0, 0.0, 1.0);
            float _608 = _407.y * _407.y;
            float _611 = 6.283185482025146484375 * _455.x;
            float _624 = sqrt((1.0 - _455.y) / fma(fma(_608, _608, -1.0), _455.y, 1.0));
            float _629 = sqrt(fma(-_624, _624, 1.0));
            float3 _649 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_456.y) < 0.999000012874603271484375)), float3(0.0, 0.0, 1.0)));
            float3 _673 = fast::normalize(float3x3(_649, fast::normalize(cross(float3(0.0, 0.0, 1.0), _649)), float3(0.0, 0.0, 1.0)) * float3(cos(_611) * _629, sin(_611) * _629, _624));
            float3 _454 = _673;
            float3 _458 = fast::normalize((_673 * (2.0 * dot(_476, _673))) - _476);
            float _499 = fast::clamp(_458.z, 0.0, 1.0);
            float _506 = fast::clamp(dot(_476, _673), 0.0, 1.0);
            if (_499 > 0.0)
            {
                float _700 = _407.y * _407.y;
                float _721 = _407.y * _407.y;
                float _520 = (((_499 / fma(_499, fma(-_700, 0.5, 1.0), _700 * 0.5)) * (_407.x / fma(_407.x, fma(-_721, 0.5, 1.0), _721 * 0.5))) * _506) / (fast::clamp(_454.z, 0.0, 1.0) * _407.x);
                float _523 = pow(1.0 - _506, 5.0);
                _738 = fma(_523, _520, _735);
                _737 = fma(1.0 - _523, _520, _734);
            }
            else
            {
                _738 = _735;
                _737 = _734;
            }
        }
        Precomputed.write(float2(_734 * 0.0009765625, _735 * 0.0009765625).xyyy, uint2(gl_GlobalInvocationID.xy));
    }
}

