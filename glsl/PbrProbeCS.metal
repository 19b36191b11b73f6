#pragma clang diagnostic ignored "-Wmissing-prototypes"
#pragma clang diagnostic ignored "-Wmissing-braces"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

template<typename T, size_t Num>
struct spvUnsafeArray
{
    T elements[Num ? Num : 1];
    
    thread T& operator [] (size_t pos) thread
    {
        return elements[pos];
    }
    constexpr const thread T& operator [] (size_t pos) const thread
    {
        return elements[pos];
    }
    
    device T& operator [] (size_t pos) device
    {
        return elements[pos];
    }
    constexpr const device T& operator [] (size_t pos) const device
    {
        return elements[pos];
    }
    
    constexpr const constant T& operator [] (size_t pos) const constant
    {
        return elements[pos];
    }
    
    threadgroup T& operator [] (size_t pos) threadgroup
    {
        return elements[pos];
    }
    constexpr const threadgroup T& operator [] (size_t pos) const threadgroup
    {
        return elements[pos];
    }
};

struct ProbeParameter
{
    uint ArgumentCount;
};

struct Arguments
{
    float4 _data[1];
};

struct Results
{
    float4 _data[1];
};

struct SampleIndices
{
    uint2 _data[1];
};

constant spvUnsafeArray<float3, 5> _503 = spvUnsafeArray<float3, 5>({ float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), float3(0.0, 0.99899947643280029296875, 0.04472135007381439208984375), float3(0.0, -0.999000132083892822265625, 0.0447072684764862060546875), float3(0.57735025882720947265625) });

kernel void main0(constant ProbeParameter& _420 [[buffer(0)]], const device Arguments& Arguments_1 [[buffer(1)]], const device SampleIndices& SampleIndices_1 [[buffer(2)]], device Results& Results_1 [[buffer(3)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        if (param.x >= _420.ArgumentCount)
        {
            break;
        }
        float4 _597 = Arguments_1._data[param.x];
        float4 _565 = _597;
        float _673 = _565.y * _565.y;
        float _685 = fma(_565.x * _565.x, fma(_673, _673, -1.0), 1.0);
        float _728 = _565.y * _565.y;
        float _749 = _565.y * _565.y;
        float _770 = _565.y * _565.y;
        Results_1._data[4u * param.x] = float4((_673 * _673) / ((3.1415927410125732421875 * _685) * _685), (_565.z / fma(_565.z, fma(-_728, 0.5, 1.0), _728 * 0.5)) * (_565.x / fma(_565.x, fma(-_749, 0.5, 1.0), _749 * 0.5)), _565.x / fma(_565.x, fma(-_770, 0.5, 1.0), _770 * 0.5), 0.0);
        Results_1._data[(4u * param.x) + 1u] = float4(float3(0.039999999105930328369140625, 0.5, 1.0) + (float3(0.959999978542327880859375, 0.5, 0.0) * pow(fast::clamp(1.0 - _565.w, 0.0, 1.0), 5.0)), 0.0);
        uint _632 = param.x % 5u;
        float2 _577 = _597.zw;
        float3 _578 = _503[_632];
        float _806 = _565.y * _565.y;
        float _809 = 6.283185482025146484375 * _577.x;
        float _822 = sqrt((1.0 - _577.y) / fma(fma(_806, _806, -1.0), _577.y, 1.0));
        float _827 = sqrt(fma(-_822, _822, 1.0));
        float3 _847 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_578.y) < 0.999000012874603271484375)), _503[_632]));
        Results_1._data[(4u * param.x) + 2u] = float4(fast::normalize(float3x3(_847, fast::normalize(cross(_503[_632], _847)), _503[_632]) * float3(cos(_809) * _827, sin(_809) * _827, _822)), 0.0);
        uint _889 = (((device uint*)&SampleIndices_1._data[param.x])[0u] << uint(16)) | (((device uint*)&SampleIndices_1._data[param.x])[0u] >> uint(16));
        uint _896 = ((_889 & 1431655765u) << uint(1)) | ((_889 & 2863311530u) >> uint(1));
        uint _903 = ((_896 & 858993459u) << uint(2)) | ((_896 & 3435973836u) >> uint(2));
        uint _910 = ((_903 & 252645135u) << uint(4)) | ((_903 & 4042322160u) >> uint(4));
        float3 _951 = float3(sqrt(fma(-_565.x, _565.x, 1.0)), 0.0, _565.x);
        float _1209;
        float _1210;
        _1210 = 0.0;
        _1209 = 0.0;
        float _1212;
        float _1213;
        for (uint _1208 = 0u; _1208 < 1024u; _1210 = _1213, _1209 = _1212, _1208++)
        {
            uint _1039 = (_1208 << uint(16)) | (_1208 >> uint(16));
            uint _1046 = ((_1039 & 1431655765u) << uint(1)) | ((_1039 & 2863311530u) >> uint(1));
            uint _1053 = ((_1046 & 858993459u) << uint(2)) | ((_1046 & 3435973836u) >> uint(2));
            uint _1060 = ((_1053 & 252645135u) << uint(4)) | ((_1053 & 4042322160u) >> uint(4));
            float2 _930 = float2(float(_1208) * 0.0009765625, float(((_1060 & 16711935u) << uint(8)) | ((_1060 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            float3 _931 = float3(0.0, 0.0, 1.0);
            float _1083 = _565.y * _565.y;
            float _1086 = 6.283185482025146484375 * _930.x;
            float _1099 = sqrt((1.0 - _930.y) / fma(fma(_1083, _1083, -1.0), _930.y, 1.0));
            float _1104 = sqrt(fma(-_1099, _1099, 1.0));
            float3 _1124 = fast::normalize(cross(select(float3(0.0, 0.0, 1.0), float3(0.0, 1.0, 0.0), bool3(abs(_931.y) < 0.999000012874603271484375)), float3(0.0, 0.0, 1.0)));
            float3 _1148 = fast::normalize(float3x3(_1124, fast::normalize(cross(float3(0.0, 0.0, 1.0), _1124)), float3(0.0, 0.0, 1.0)) * float3(cos(_1086) * _1104, sin(_1086) * _1104, _1099));
            float3 _929 = _1148;
            float3 _933 = fast::normalize((_1148 * (2.0 * dot(_951, _1148))) - _951);
            float _974 = fast::clamp(_933.z, 0.0, 1.0);
            float _981 = fast::clamp(dot(_951, _1148), 0.0, 1.0);
            if (_974 > 0.0)
            {
                float _1175 = _565.y * _565.y;
                float _1196 = _565.y * _565.y;
                float _995 = (((_974 / fma(_974, fma(-_1175, 0.5, 1.0), _1175 * 0.5)) * (_565.x / fma(_565.x, fma(-_1196, 0.5, 1.0), _1196 * 0.5))) * _981) / (fast::clamp(_929.z, 0.0, 1.0) * _565.x);
                float _998 = pow(1.0 - _981, 5.0);
                _1213 = fma(_998, _995, _1210);
                _1212 = fma(1.0 - _998, _995, _1209);
            }
            else
            {
                _1213 = _1210;
                _1212 = _1209;
            }
        }
        Results_1._data[(4u * param.x) + 3u] = float4(float(((device uint*)&SampleIndices_1._data[param.x])[0u]) / float(((device uint*)&SampleIndices_1._data[param.x])[1u]), float(((_910 & 16711935u) << uint(8)) | ((_910 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10, _1209 * 0.0009765625, _1210 * 0.0009765625);
        break;
    } while(false);
}

