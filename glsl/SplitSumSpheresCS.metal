#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct Spheres
{
    float4 _data[1];
};

struct SplitSumParameter
{
    uint Columns;
    uint CellSize;
    uint SpecularMips;
    uint SpecularSize;
    uint LodMapping;
    float LodParameter;
    uint Direction;
    uint Lookup;
    uint LightCount;
    uint LightLevel;
    uint GlassTransmission;
    float GlassRoughnessScale;
};

constant float _5278 = {};

kernel void main0(constant SplitSumParameter& _1526 [[buffer(0)]], const device Spheres& Spheres_1 [[buffer(1)]], const device Spheres& Lights [[buffer(2)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float> LobeTable [[texture(3)]], texture2d<float> TransmissionTable [[texture(4)]], texture2d<float> SphereTransmissionTable [[texture(5)]], texture2d<float, access::write> SplitSum [[texture(6)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    do
    {
        uint2 _2040 = uint2(0u);
        uint2 _2041 = uint2(SplitSum.get_width(), SplitSum.get_height());
        _2040.x = _2041.x;
        _2040.y = _2041.y;
        if (any(gl_GlobalInvocationID.xy >= _2040))
        {
            break;
        }
        float2 _2215 = (((float2(gl_GlobalInvocationID.xy % uint2(_1526.CellSize)) + float2(0.5)) / float2(float(_1526.CellSize))) * 2.0) - float2(1.0);
        _2215.y = -_2215.y;
        float _2246 = dot(_2215, _2215);
        bool _2249 = (_2246 * 1.2345678806304931640625) < 1.0;
        float _2257 = sqrt(fast::max(fma(-_2246, 1.2345678806304931640625, 1.0), 0.0));
        float3 _2260 = float3(_2215 * float2(1.111111164093017578125), _2257);
        uint2 _2218 = gl_GlobalInvocationID.xy / uint2(_1526.CellSize);
        uint _2280 = 2u * ((_2218.y * _1526.Columns) + _2218.x);
        float4 _2268 = Spheres_1._data[_2280];
        float4 _2269 = Spheres_1._data[_2280 + 1u];
        float3 _5243;
        if (_2249 && (_2269.y > 0.0))
        {
            float3 _5242;
            do
            {
                float _2346 = fast::clamp(_2257, 0.0, 1.0);
                if (_1526.GlassTransmission == 2u)
                {
                    uint2 _2474 = uint2(SphereTransmissionTable.get_width(), SphereTransmissionTable.get_height());
                    float _2524 = float(_2474.y / _2474.x);
                    float _2530 = fast::clamp((_2269.z - 1.10000002384185791015625) * 5.0, 0.0, _2524 - 1.0);
                    float _2532 = floor(_2530);
                    float _2535 = 0.5 / float(_2474.x);
                    float _2540 = fast::clamp(_2268.w, _2535, 1.0 - _2535);
                    float3 _2307 = mix(SphereTransmissionTable.sample(LinearClamp, float2(_2346, (_2532 + _2540) / _2524), level(0.0)).xyz, SphereTransmissionTable.sample(LinearClamp, float2(_2346, (fast::min(_2532 + 1.0, _2524 - 1.0) + _2540) / _2524), level(0.0)).xyz, float3(_2530 - _2532));
                    float3 _2361 = _2260 - (float3(0.0, 0.0, 1.0) * _2346);
                    float _2364 = dot(_2361, _2361);
                    float3 _2385 = fast::normalize((float3(0.0, 0.0, 1.0) * (-cos(_2307.y))) + (select(float3(0.0), _2361 * rsqrt(_2364), bool3(_2364 > 9.9999999600419720025001879548654e-13)) * sin(_2307.y)));
                    float _5239;
                    do
                    {
                        float _2686 = float(_1526.SpecularMips - 1u);
                        float _2688 = fast::clamp(_2307.z, 0.0, 1.0);
                        if (_1526.LodMapping == 1u)
                        {
                            _5239 = (_2688 * (2.0 - _2688)) * _2686;
                            break;
                        }
                        if (_1526.LodMapping == 2u)
                        {
                            _5239 = pow(_2688, _1526.LodParameter) * _2686;
                            break;
                        }
                        if (_1526.LodMapping == 3u)
                        {
                            _5239 = (_2688 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_2688 * _2688) * float(_1526.SpecularSize)), 0.0, _2686) : 0.0;
                            break;
                        }
                        if (((_1526.LodMapping == 4u) && (_1526.SpecularMips >= 3u)) && (float(_1526.SpecularSize) > _1526.LodParameter))
                        {
                            float _2747 = float(_1526.SpecularSize);
                            _5239 = (_2688 > 0.0) ? fast::clamp(fma((_2686 - 1.0) / log2(_2747 / _1526.LodParameter), log2((_2688 * _2688) * _2747) - log2(_2747), _2686), 0.0, _2686) : 0.0;
                            break;
                        }
                        _5239 = _2688 * _2686;
                        break;
                    } while(false);
                    float _2839 = (_1526.LightCount > 0u) ? fast::clamp((_5239 - float(_1526.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                    float _2596 = fast::max(_2307.z * _2307.z, 1.0000000116860974230803549289703e-07);
                    float3 _5241;
                    _5241 = Specular.sample(LinearClamp, _2385, level(_5239)).xyz;
                    float3 _2621;
                    for (uint _5240 = 0u; _5240 < _1526.LightCount; _5241 = _2621, _5240++)
                    {
                        uint _2613 = 2u * _5240;
                        float4 _2577 = Lights._data[_2613];
                        float _2857 = tan(fast::min(0.5 * acos(fast::clamp(dot(_2385, Lights._data[_2613].xyz), -1.0, 1.0)), 1.5));
                        float _2867 = (0.5 * _2577.w) * pow(fma(_2857, _2857, 1.0), 0.75);
                        float _2882 = (_2867 * _2867) / (_2596 * _2596);
                        float _2889 = (_2857 * _2857) / (_2596 * _2596);
                        float _2893 = (_2882 + 1.0) - _2889;
                        _2621 = _5241 + ((Lights._data[(2u * _5240) + 1u].xyz * _2839) * fast::clamp(0.5 + (((_2882 - 1.0) - _2889) / (2.0 * sqrt(fma(_2893, _2893, 4.0 * _2889)))), 0.0, 1.0));
                    }
                    _5242 = _5241 * _2307.x;
                    break;
                }
                float _2398 = (1.0 - _2269.z) / (1.0 + _2269.z);
                float3 _2407 = refract(float3(-0.0, -0.0, -1.0), _2260, 1.0 / _2269.z);
                float3 _2416 = fast::normalize(_2260 - (_2407 * (2.0 * dot(_2260, _2407))));
                float3 _2421 = refract(_2407, -_2416, _2269.z);
                if (dot(_2421, _2421) == 0.0)
                {
                    _5242 = float3(0.0);
                    break;
                }
                float _5238;
                if (_1526.GlassTransmission == 1u)
                {
                    uint2 _2911 = uint2(TransmissionTable.get_width(), TransmissionTable.get_height());
                    float _2965 = float(_2911.y / _2911.x);
                    float _2971 = fast::clamp((_2269.z - 1.10000002384185791015625) * 5.0, 0.0, _2965 - 1.0);
                    float _2973 = floor(_2971);
                    float _2976 = 0.5 / float(_2911.x);
                    float _2981 = fast::clamp(_2268.w, _2976, 1.0 - _2976);
                    float _2441 = dot(_2416, _2407);
                    uint2 _3009 = uint2(TransmissionTable.get_width(), TransmissionTable.get_height());
                    float _3063 = float(_3009.y / _3009.x);
                    float _3069 = fast::clamp((_2269.z - 1.10000002384185791015625) * 5.0, 0.0, _3063 - 1.0);
                    float _3071 = floor(_3069);
                    float _3074 = 0.5 / float(_3009.x);
                    float _3079 = fast::clamp(_2268.w, _3074, 1.0 - _3074);
                    _5238 = mix(float2(TransmissionTable.sample(LinearClamp, float2(_2346, (_2973 + _2981) / _2965), level(0.0)).x, _5278), float2(TransmissionTable.sample(LinearClamp, float2(_2346, (fast::min(_2973 + 1.0, _2965 - 1.0) + _2981) / _2965), level(0.0)).x, _5278), float2(_2971 - _2973)).x * mix(float2(_5278, TransmissionTable.sample(LinearClamp, float2(_2441, (_3071 + _3079) / _3063), level(0.0)).y), float2(_5278, TransmissionTable.sample(LinearClamp, float2(_2441, (fast::min(_3071 + 1.0, _3063 - 1.0) + _3079) / _3063), level(0.0)).y), float2(_3069 - _3071)).y;
                }
                else
                {
                    _5238 = (1.0 - fma(_2398, _2398, fma(-_2398, _2398, 1.0) * pow(1.0 - fast::clamp(_2257, 0.0, 1.0), 5.0))) * (1.0 - fma(_2398, _2398, fma(-_2398, _2398, 1.0) * pow(1.0 - fast::clamp(dot(_2416, _2421), 0.0, 1.0), 5.0)));
                }
                float _2465 = _2268.w * _1526.GlassRoughnessScale;
                float _5233;
                do
                {
                    float _3249 = float(_1526.SpecularMips - 1u);
                    float _3251 = fast::clamp(_2465, 0.0, 1.0);
                    if (_1526.LodMapping == 1u)
                    {
                        _5233 = (_3251 * (2.0 - _3251)) * _3249;
                        break;
                    }
                    if (_1526.LodMapping == 2u)
                    {
                        _5233 = pow(_3251, _1526.LodParameter) * _3249;
                        break;
                    }
                    if (_1526.LodMapping == 3u)
                    {
                        _5233 = (_3251 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_3251 * _3251) * float(_1526.SpecularSize)), 0.0, _3249) : 0.0;
                        break;
                    }
                    if (((_1526.LodMapping == 4u) && (_1526.SpecularMips >= 3u)) && (float(_1526.SpecularSize) > _1526.LodParameter))
                    {
                        float _3310 = float(_1526.SpecularSize);
                        _5233 = (_3251 > 0.0) ? fast::clamp(fma((_3249 - 1.0) / log2(_3310 / _1526.LodParameter), log2((_3251 * _3251) * _3310) - log2(_3310), _3249), 0.0, _3249) : 0.0;
                        break;
                    }
                    _5233 = _3251 * _3249;
                    break;
                } while(false);
                float _3402 = (_1526.LightCount > 0u) ? fast::clamp((_5233 - float(_1526.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                float _3159 = fast::max(_2465 * _2465, 1.0000000116860974230803549289703e-07);
                float3 _5235;
                _5235 = Specular.sample(LinearClamp, _2421, level(_5233)).xyz;
                float3 _3184;
                for (uint _5234 = 0u; _5234 < _1526.LightCount; _5235 = _3184, _5234++)
                {
                    uint _3176 = 2u * _5234;
                    float4 _3140 = Lights._data[_3176];
                    float _3420 = tan(fast::min(0.5 * acos(fast::clamp(dot(_2421, Lights._data[_3176].xyz), -1.0, 1.0)), 1.5));
                    float _3430 = (0.5 * _3140.w) * pow(fma(_3420, _3420, 1.0), 0.75);
                    float _3445 = (_3430 * _3430) / (_3159 * _3159);
                    float _3452 = (_3420 * _3420) / (_3159 * _3159);
                    float _3456 = (_3445 + 1.0) - _3452;
                    _3184 = _5235 + ((Lights._data[(2u * _5234) + 1u].xyz * _3402) * fast::clamp(0.5 + (((_3445 - 1.0) - _3452) / (2.0 * sqrt(fma(_3456, _3456, 4.0 * _3452)))), 0.0, 1.0));
                }
                _5242 = _5235 * _5238;
                break;
            } while(false);
            _5243 = _5242;
        }
        else
        {
            float3 _5244;
            if (_2249)
            {
                float3 _5214;
                float _5215;
                do
                {
                    float3 _3640 = reflect(float3(-0.0, -0.0, -1.0), _2260);
                    float4 _3586 = LobeTable.sample(LinearClamp, float2(fast::clamp(_2257, 0.0, 1.0), _2268.w), level(0.0));
                    float3 _5203;
                    do
                    {
                        float _3762 = _2268.w * _2268.w;
                        if (_1526.Direction == 1u)
                        {
                            float _3768 = fast::clamp(fma(-_2268.w, _2268.w, 1.0), 0.0, 1.0);
                            _5203 = fast::normalize(mix(_2260, _3640, float3(_3768 * fma(_2268.w, _2268.w, sqrt(_3768)))));
                            break;
                        }
                        if (_1526.Direction == 2u)
                        {
                            _5203 = fast::normalize(mix(_3640, _2260, float3(_3762 * _3762)));
                            break;
                        }
                        if (_1526.Direction == 3u)
                        {
                            float3 _5202;
                            do
                            {
                                float _3817 = acos(fast::clamp(dot(_2260, _3640), -1.0, 1.0));
                                if (_3817 < 9.9999997473787516355514526367188e-05)
                                {
                                    _5202 = _3640;
                                    break;
                                }
                                _5202 = ((_2260 * sin((1.0 - _3586.x) * _3817)) + (_3640 * sin(_3586.x * _3817))) / float3(sin(_3817));
                                break;
                            } while(false);
                            _5203 = _5202;
                            break;
                        }
                        _5203 = _3640;
                        break;
                    } while(false);
                    if (_1526.Lookup == 0u)
                    {
                        float _5212;
                        do
                        {
                            float _3882 = float(_1526.SpecularMips - 1u);
                            float _3884 = fast::clamp(_2268.w, 0.0, 1.0);
                            if (_1526.LodMapping == 1u)
                            {
                                _5212 = (_3884 * (2.0 - _3884)) * _3882;
                                break;
                            }
                            if (_1526.LodMapping == 2u)
                            {
                                _5212 = pow(_3884, _1526.LodParameter) * _3882;
                                break;
                            }
                            if (_1526.LodMapping == 3u)
                            {
                                _5212 = (_3884 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_3884 * _3884) * float(_1526.SpecularSize)), 0.0, _3882) : 0.0;
                                break;
                            }
                            if (((_1526.LodMapping == 4u) && (_1526.SpecularMips >= 3u)) && (float(_1526.SpecularSize) > _1526.LodParameter))
                            {
                                float _3943 = float(_1526.SpecularSize);
                                _5212 = (_3884 > 0.0) ? fast::clamp(fma((_3882 - 1.0) / log2(_3943 / _1526.LodParameter), log2((_3884 * _3884) * _3943) - log2(_3943), _3882), 0.0, _3882) : 0.0;
                                break;
                            }
                            _5212 = _3884 * _3882;
                            break;
                        } while(false);
                        _5215 = (_1526.LightCount > 0u) ? fast::clamp((_5212 - float(_1526.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _5214 = Specular.sample(LinearClamp, _5203, level(_5212)).xyz * 1.0;
                        break;
                    }
                    if (_1526.Lookup == 1u)
                    {
                        float _5210;
                        do
                        {
                            float _4027 = float(_1526.SpecularMips - 1u);
                            float _4029 = fast::clamp(_3586.y, 0.0, 1.0);
                            if (_1526.LodMapping == 1u)
                            {
                                _5210 = (_4029 * (2.0 - _4029)) * _4027;
                                break;
                            }
                            if (_1526.LodMapping == 2u)
                            {
                                _5210 = pow(_4029, _1526.LodParameter) * _4027;
                                break;
                            }
                            if (_1526.LodMapping == 3u)
                            {
                                _5210 = (_4029 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_4029 * _4029) * float(_1526.SpecularSize)), 0.0, _4027) : 0.0;
                                break;
                            }
                            if (((_1526.LodMapping == 4u) && (_1526.SpecularMips >= 3u)) && (float(_1526.SpecularSize) > _1526.LodParameter))
                            {
                                float _4088 = float(_1526.SpecularSize);
                                _5210 = (_4029 > 0.0) ? fast::clamp(fma((_4027 - 1.0) / log2(_4088 / _1526.LodParameter), log2((_4029 * _4029) * _4088) - log2(_4088), _4027), 0.0, _4027) : 0.0;
                                break;
                            }
                            _5210 = _4029 * _4027;
                            break;
                        } while(false);
                        _5215 = (_1526.LightCount > 0u) ? fast::clamp((_5210 - float(_1526.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _5214 = Specular.sample(LinearClamp, _5203, level(_5210)).xyz * 1.0;
                        break;
                    }
                    float3 _3683 = cross(_2260, float3(0.0, 0.0, 1.0));
                    float _3685 = length(_3683);
                    float3 _3695 = select(float3(0.0), cross(_3683 / float3(_3685), _5203), bool3(_3685 > 9.9999999747524270787835121154785e-07));
                    float _5206;
                    do
                    {
                        float _4172 = float(_1526.SpecularMips - 1u);
                        float _4174 = fast::clamp(_3586.z, 0.0, 1.0);
                        if (_1526.LodMapping == 1u)
                        {
                            _5206 = (_4174 * (2.0 - _4174)) * _4172;
                            break;
                        }
                        if (_1526.LodMapping == 2u)
                        {
                            _5206 = pow(_4174, _1526.LodParameter) * _4172;
                            break;
                        }
                        if (_1526.LodMapping == 3u)
                        {
                            _5206 = (_4174 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_4174 * _4174) * float(_1526.SpecularSize)), 0.0, _4172) : 0.0;
                            break;
                        }
                        if (((_1526.LodMapping == 4u) && (_1526.SpecularMips >= 3u)) && (float(_1526.SpecularSize) > _1526.LodParameter))
                        {
                            float _4233 = float(_1526.SpecularSize);
                            _5206 = (_4174 > 0.0) ? fast::clamp(fma((_4172 - 1.0) / log2(_4233 / _1526.LodParameter), log2((_4174 * _4174) * _4233) - log2(_4233), _4172), 0.0, _4172) : 0.0;
                            break;
                        }
                        _5206 = _4174 * _4172;
                        break;
                    } while(false);
                    float _5208;
                    do
                    {
                        float _4317 = float(_1526.SpecularMips - 1u);
                        float _4319 = fast::clamp(_3586.z, 0.0, 1.0);
                        if (_1526.LodMapping == 1u)
                        {
                            _5208 = (_4319 * (2.0 - _4319)) * _4317;
                            break;
                        }
                        if (_1526.LodMapping == 2u)
                        {
                            _5208 = pow(_4319, _1526.LodParameter) * _4317;
                            break;
                        }
                        if (_1526.LodMapping == 3u)
                        {
                            _5208 = (_4319 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_4319 * _4319) * float(_1526.SpecularSize)), 0.0, _4317) : 0.0;
                            break;
                        }
                        if (((_1526.LodMapping == 4u) && (_1526.SpecularMips >= 3u)) && (float(_1526.SpecularSize) > _1526.LodParameter))
                        {
                            float _4378 = float(_1526.SpecularSize);
                            _5208 = (_4319 > 0.0) ? fast::clamp(fma((_4317 - 1.0) / log2(_4378 / _1526.LodParameter), log2((_4319 * _4319) * _4378) - log2(_4378), _4317), 0.0, _4317) : 0.0;
                            break;
                        }
                        _5208 = _4319 * _4317;
                        break;
                    } while(false);
                    _5215 = fma(0.5, (_1526.LightCount > 0u) ? fast::clamp((_5206 - float(_1526.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1526.LightCount > 0u) ? fast::clamp((_5208 - float(_1526.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                    _5214 = (Specular.sample(LinearClamp, fast::normalize((_5203 * cos(_3586.w)) + (_3695 * sin(_3586.w))), level(_5206)).xyz * 0.5) + (Specular.sample(LinearClamp, fast::normalize((_5203 * cos(_3586.w)) - (_3695 * sin(_3586.w))), level(_5208)).xyz * 0.5);
                    break;
                } while(false);
                float2 _3530 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_2257, 0.0, 1.0), _2268.w), level(0.0)).xy);
                float3 _2152 = mix(float3(0.039999999105930328369140625), Spheres_1._data[_2280].xyz, float3(_2269.x));
                float2 _4424 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_2257, 0.0, 1.0), _2268.w), level(0.0)).xy);
                float3 _4447 = (_2152 * _4424.x) + float3(_4424.y);
                float3 _5223;
                _5223 = fma(_5214, (mix(float3(0.039999999105930328369140625), Spheres_1._data[_2280].xyz, float3(_2269.x)) * _3530.x) + float3(_3530.y), (IrradianceMap.sample(LinearClamp, _2260, level(0.0)).xyz * Spheres_1._data[_2280].xyz) * (1.0 - _2269.x));
                float3 _2194;
                for (uint _5216 = 0u; _5216 < _1526.LightCount; _5223 = _2194, _5216++)
                {
                    uint _2176 = 2u * _5216;
                    uint _2179 = (2u * _5216) + 1u;
                    float4 _2082 = Lights._data[_2176];
                    float4 _2083 = Lights._data[_2179];
                    float3 _4448 = Lights._data[_2176].xyz;
                    float3 _4488 = fast::normalize(cross(select(float3(1.0, 0.0, 0.0), float3(0.0, 0.0, 1.0), bool3(abs(_4448.z) < 0.999000012874603271484375)), Lights._data[_2176].xyz));
                    float3 _4491 = cross(Lights._data[_2176].xyz, _4488);
                    float _4494 = tan(_2082.w);
                    float3 _5218;
                    _5218 = float3(0.0);
                    float3 _5245;
                    for (uint _5217 = 0u; _5217 < 19u; _5218 = _5245, _5217++)
                    {
                        float2 _5226;
                        do
                        {
                            if (_5217 == 0u)
                            {
                                _5226 = float2(0.0);
                                break;
                            }
                            bool _4602 = _5217 <= 6u;
                            float _4619 = _4602 ? (float(_5217 - 1u) * 1.0471975803375244140625) : ((float(_5217 - 7u) + 0.5) * 0.52359879016876220703125);
                            _5226 = float2(cos(_4619), sin(_4619)) * (_4602 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                            break;
                        } while(false);
                        float2 _4455 = _5226 * _4494;
                        float3 _4515 = fast::normalize((Lights._data[_2176].xyz + (_4488 * _4455.x)) + (_4491 * _4455.y));
                        if (dot(_2260, _4515) > 0.0)
                        {
                            float3 _5227;
                            do
                            {
                                float _4649 = dot(_2260, _4515);
                                float _4653 = fast::clamp(_2257, 0.0, 1.0);
                                if ((_4649 <= 0.0) || (_4653 <= 0.0))
                                {
                                    _5227 = float3(0.0);
                                    break;
                                }
                                float3 _4664 = fast::normalize(_4515 + float3(0.0, 0.0, 1.0));
                                float _4738 = _2268.w * _2268.w;
                                float _4759 = _2268.w * _2268.w;
                                float _4681 = fast::clamp(dot(_2260, _4664), 0.0, 1.0);
                                float _4780 = _2268.w * _2268.w;
                                float _4792 = fma(_4681 * _4681, fma(_4780, _4780, -1.0), 1.0);
                                _5227 = (_2152 + ((float3(1.0) - _2152) * pow(fast::clamp(1.0 - fast::clamp(_4664.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_4649 / fma(_4649, fma(-_4738, 0.5, 1.0), _4738 * 0.5)) * (_4653 / fma(_4653, fma(-_4759, 0.5, 1.0), _4759 * 0.5))) * ((_4780 * _4780) / ((3.1415927410125732421875 * _4792) * _4792))) / (4.0 * _4653));
                                break;
                            } while(false);
                            _5245 = _5218 + _5227;
                        }
                        else
                        {
                            _5245 = _5218;
                        }
                    }
                    float _4543 = fast::clamp((((2.0 * _2268.w) * _2268.w) / fast::max(_2082.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                    float4 _4470 = Lights._data[_2176];
                    float _4820 = 0.5 * _4470.w;
                    float _4822 = 0.5 * acos(fast::clamp(dot(reflect(float3(-0.0, -0.0, -1.0), _2260), Lights._data[_2176].xyz), -1.0, 1.0));
                    float _4826 = fast::max(_2268.w * _2268.w, 1.0000000116860974230803549289703e-07);
                    float _4840 = (_4820 * _4820) / (_4826 * _4826);
                    float _4847 = (_4822 * _4822) / (_4826 * _4826);
                    float _4851 = (_4840 + 1.0) - _4847;
                    float _4567 = sin(_2082.w);
                    float _4571 = dot(_2260, Lights._data[_2176].xyz);
                    float _4574 = _4567 * _4567;
                    float _5219;
                    do
                    {
                        if (((_4571 * _4571) > _4574) || (_4574 <= 0.0))
                        {
                            _5219 = (3.1415927410125732421875 * _4574) * fast::clamp(_4571, 0.0, 1.0);
                            break;
                        }
                        float _4896 = sqrt(fast::clamp(fma(-_4571, _4571, 1.0), 0.0, 1.0));
                        float _4900 = sqrt((1.0 / _4574) - 1.0);
                        float _4906 = (-_4900) * (_4571 / _4896);
                        float _4914 = _4896 * sqrt(fast::clamp(fma(-_4906, _4906, 1.0), 0.0, 1.0));
                        _5219 = fast::max(fma(fma(_4571, acos(fast::clamp(_4906, -1.0, 1.0)), -(_4900 * _4914)), _4574, atan(_4914 / _4900)), 0.0);
                        break;
                    } while(false);
                    _2194 = fma(((mix(select(float3(0.0), (_4447 * fast::clamp(0.5 + (((_4840 - 1.0) - _4847) / (2.0 * sqrt(fma(_4851, _4851, 4.0 * _4847)))), 0.0, 1.0)) / float3(_2083.w), bool3(_4543 < 1.0)), _5218 * 0.052631579339504241943359375, float3(_4543)) * _5215) * _2083.w) + ((Spheres_1._data[_2280].xyz * (1.0 - _2269.x)) * (_5219 * 0.3183098733425140380859375)), Lights._data[_2179].xyz, _5223);
                }
                _5244 = _5223;
            }
            else
            {
                _5244 = float3(0.0);
            }
            _5243 = _5244;
        }
        SplitSum.write(float4(_5243, float(_2249)), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

