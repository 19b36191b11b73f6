#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct EquirectToCubeParameter
{
    uint Supersample;
};

kernel void main0(constant EquirectToCubeParameter& _312 [[buffer(0)]], texture2d<float> Equirect [[texture(0)]], texture2d_array<float, access::write> Cube [[texture(1)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    uint3 param = gl_GlobalInvocationID;
    do
    {
        uint3 _399 = uint3(0u);
        uint3 _400 = uint3(Cube.get_width(), Cube.get_height(), Cube.get_array_size());
        _399.x = _400.x;
        _399.y = _400.y;
        _399.z = _400.z;
        if (any(gl_GlobalInvocationID >= _399))
        {
            break;
        }
        uint2 _401 = uint2(0u);
        uint2 _402 = uint2(Equirect.get_width(), Equirect.get_height());
        _401.x = _402.x;
        _401.y = _402.y;
        float3 _849;
        _849 = float3(0.0);
        float3 _858;
        for (uint _848 = 0u; _848 < _312.Supersample; _849 = _858, _848++)
        {
            _858 = _849;
            float3 _483;
            for (uint _850 = 0u; _850 < _312.Supersample; _858 = _483, _850++)
            {
                float2 _409 = (((float2(gl_GlobalInvocationID.xy) + ((float2(float(_850), float(_848)) + float2(0.5)) / float2(float(_312.Supersample)))) / float2(_399.xy)) - float2(0.5)) * float2(2.0, -2.0);
                float3 _852;
                if (param.z == 0u)
                {
                    _852 = float3(1.0, _409.y, -_409.x);
                }
                else
                {
                    float3 _853;
                    if (param.z == 1u)
                    {
                        _853 = float3(-1.0, _409.y, _409.x);
                    }
                    else
                    {
                        float3 _854;
                        if (param.z == 2u)
                        {
                            _854 = float3(_409.x, 1.0, -_409.y);
                        }
                        else
                        {
                            float3 _855;
                            if (param.z == 3u)
                            {
                                _855 = float3(_409.x, -1.0, _409.y);
                            }
                            else
                            {
                                float3 _856;
                                if (param.z == 4u)
                                {
                                    _856 = float3(_409.x, _409.y, 1.0);
                                }
                                else
                                {
                                    _856 = float3(-_409.x, _409.y, -1.0);
                                }
                                _855 = _856;
                            }
                            _854 = _855;
                        }
                        _853 = _854;
                    }
                    _852 = _853;
                }
                int2 _479 = int2(_401);
                float3 _577 = fast::normalize(_852);
                float2 _599 = fma(float2(fma(precise::atan2(_577.x, -_577.z), 0.15915493667125701904296875, 0.5), acos(fast::clamp(_577.y, -1.0, 1.0)) * 0.3183098733425140380859375), float2(_479), float2(-0.5));
                float2 _601 = floor(_599);
                float2 _579 = _599 - _601;
                int2 _606 = int2(_601);
                int2 _582 = _606;
                int2 _583 = _479;
                _582.x += ((_582.x < 0) ? _583.x : ((_582.x >= _583.x) ? (-_583.x) : 0));
                _582.x = clamp(_582.x, 0, _583.x - 1);
                _582.y = clamp(_582.y, 0, _583.y - 1);
                int2 _584 = _606 + int2(1, 0);
                int2 _585 = _479;
                _584.x += ((_584.x < 0) ? _585.x : ((_584.x >= _585.x) ? (-_585.x) : 0));
                _584.x = clamp(_584.x, 0, _585.x - 1);
                _584.y = clamp(_584.y, 0, _585.y - 1);
                int2 _587 = _606 + int2(0, 1);
                int2 _588 = _479;
                _587.x += ((_587.x < 0) ? _588.x : ((_587.x >= _588.x) ? (-_588.x) : 0));
                _587.x = clamp(_587.x, 0, _588.x - 1);
                _587.y = clamp(_587.y, 0, _588.y - 1);
                int2 _589 = _606 + int2(1);
                int2 _590 = _479;
                _589.x += ((_589.x < 0) ? _590.x : ((_589.x >= _590.x) ? (-_590.x) : 0));
                _589.x = clamp(_589.x, 0, _590.x - 1);
                _589.y = clamp(_589.y, 0, _590.y - 1);
                _483 = _858 + mix(mix(Equirect.read(uint2(int3(_582, 0).xy), 0).xyz, Equirect.read(uint2(int3(_584, 0).xy), 0).xyz, float3(_579.x)), mix(Equirect.read(uint2(int3(_587, 0).xy), 0).xyz, Equirect.read(uint2(int3(_589, 0).xy), 0).xyz, float3(_579.x)), float3(_579.y));
            }
        }
        Cube.write(float4(_849 / float3(float(_312.Supersample * _312.Supersample)), 1.0), uint2(gl_GlobalInvocationID.xy), uint(gl_GlobalInvocationID.z));
        break;
    } while(false);
}

