#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct BrdfChunkParameter
{
    uint FirstSample;
    uint ChunkSamples;
    uint Resolve;
};

kernel void main0(constant BrdfChunkParameter& _258 [[buffer(0)]], texture2d<float, access::read_write> Accumulated [[texture(0)]], texture2d<float, access::write> Precomputed [[texture(1)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    do
    {
        uint2 _445 = uint2(0u);
        uint2 _446 = uint2(Precomputed.get_width(), Precomputed.get_height());
        _445.x = _446.x;
        _445.y = _446.y;
        if (any(gl_GlobalInvocationID.xy >= _445))
        {
            break;
        }
        float2 _447 = (float2(gl_GlobalInvocationID.xy) + float2(0.5)) / float2(_445);
        float3 _542 = float3(sqrt(fma(-_447.x, _447.x, 1.0)), 0.0, _447.x);
        float2 _800;
        _800 = float2(0.0);
        float2 _803;
        for (uint _799 = _258.FirstSample; _799 < (_258.FirstSample + _258.ChunkSamples); _800 = _803, _799++)
        {
            uint _630 = (_799 << uint(16)) | (_799 >> uint(16));
            uint _637 = ((_630 & 1431655765u) << uint(1)) | ((_630 & 2863311530u) >> uint(1));
            uint _644 = ((_637 & 858993459u) << uint(2)) | ((_637 & 3435973836u) >> uint(2));
            uint _651 = ((_644 & 252645135u) << uint(4)) | ((_644 & 4042322160u) >> uint(4));
            float2 _521 = float2(float(_799) * 0.0009765625, float(((_651 & 16711935u) << uint(8)) | ((_651 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            float3 _522 = float3(0.0, 0.0, 1.0);
            float _674 = _447.y * _447.y;
            float _677 = 6.283185482025146484375 * _521.x;
            float _690 = sqrt((1.0 - _521.y) / fma(fma(_674, _674, -1.0), _521.y, 1.0));
            float _695 = sqrt(fma(-_690, _690, 1.0));
            float3 _715 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_522.y) < 0.999000012874603271484375)), float3(0.0, 0.0, 1.0)));
            float3 _739 = fast::normalize(float3x3(_715, fast::normalize(cross(float3(0.0, 0.0, 1.0), _715)), float3(0.0, 0.0, 1.0)) * float3(cos(_677) * _695, sin(_677) * _695, _690));
            float3 _520 = _739;
            float3 _524 = fast::normalize((_739 * (2.0 * dot(_542, _739))) - _542);
            float _572 = fast::clamp(_524.z, 0.0, 1.0);
            float _579 = fast::clamp(dot(_542, _739), 0.0, 1.0);
            if (_572 > 0.0)
            {
                float _766 = _447.y * _447.y;
                float _787 = _447.y * _447.y;
                float _593 = (((_572 / fma(_572, fma(-_766, 0.5, 1.0), _766 * 0.5)) * (_447.x / fma(_447.x, fma(-_787, 0.5, 1.0), _787 * 0.5))) * _579) / (fast::clamp(_520.z, 0.0, 1.0) * _447.x);
                float _596 = pow(1.0 - _579, 5.0);
                _803 = _800 + float2((1.0 - _596) * _593, _596 * _593);
            }
            else
            {
                _803 = _800;
            }
        }
        float2 _801;
        if (_258.FirstSample > 0u)
        {
            _801 = _800 + float2(Accumulated.read(uint2(gl_GlobalInvocationID.xy)).xy);
        }
        else
        {
            _801 = _800;
        }
        Accumulated.write(_801.xyyy, uint2(gl_GlobalInvocationID.xy));
        if (_258.Resolve != 0u)
        {
            Precomputed.write((_801 * float2(0.0009765625)).xyyy, uint2(gl_GlobalInvocationID.xy));
        }
        break;
    } while(false);
}

