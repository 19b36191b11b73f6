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

constant float _5135 = {};

kernel void main0(constant SplitSumParameter& _1836 [[buffer(0)]], const device Spheres& Spheres_1 [[buffer(1)]], const device Spheres& Lights [[buffer(2)]], texturecube<float> Specular [[texture(0)]], texturecube<float> IrradianceMap [[texture(1)]], texture2d<float> BrdfLut [[texture(2)]], texture2d<float> LobeTable [[texture(3)]], texture2d<float> TransmissionTable [[texture(4)]], texture2d<float> SphereTransmissionTable [[texture(5)]], texture2d<float, access::write> SplitSum [[texture(6)]], sampler LinearClamp [[sampler(0)]], uint3 gl_GlobalInvocationID [[thread_position_in_grid]])
{
    do
    {
        uint2 _2193 = uint2(0u);
        uint2 _2194 = uint2(SplitSum.get_width(), SplitSum.get_height());
        _2193.x = _2194.x;
        _2193.y = _2194.y;
        if (any(gl_GlobalInvocationID.xy >= _2193))
        {
            break;
        }
        float2 _2251 = (((float2(gl_GlobalInvocationID.xy % uint2(_1836.CellSize)) + float2(0.5)) / float2(float(_1836.CellSize))) * 2.0) - float2(1.0);
        _2251.y = -_2251.y;
        float _2282 = dot(_2251, _2251);
        bool _2285 = (_2282 * 1.2345678806304931640625) < 1.0;
        float _2293 = sqrt(fast::max(fma(-_2282, 1.2345678806304931640625, 1.0), 0.0));
        float3 _2296 = float3(_2251 * float2(1.111111164093017578125), _2293);
        uint2 _2254 = gl_GlobalInvocationID.xy / uint2(_1836.CellSize);
        uint _2316 = 2u * ((_2254.y * _1836.Columns) + _2254.x);
        float4 _2304 = Spheres_1._data[_2316];
        float4 _2305 = Spheres_1._data[_2316 + 1u];
        float3 _5101;
        do
        {
            if (_2305.y > 0.0)
            {
                float _5095;
                float _5096;
                float3 _5097;
                do
                {
                    if (_1836.GlassTransmission == 2u)
                    {
                        float _2589 = fast::clamp(_2293, 0.0, 1.0);
                        uint2 _2635 = uint2(SphereTransmissionTable.get_width(), SphereTransmissionTable.get_height());
                        float _2685 = float(_2635.y / _2635.x);
                        float _2691 = fast::clamp((_2305.z - 1.10000002384185791015625) * 5.0, 0.0, _2685 - 1.0);
                        float _2693 = floor(_2691);
                        float _2696 = 0.5 / float(_2635.x);
                        float _2701 = fast::clamp(_2304.w, _2696, 1.0 - _2696);
                        float3 _2575 = mix(SphereTransmissionTable.sample(LinearClamp, float2(_2589, (_2693 + _2701) / _2685), level(0.0)).xyz, SphereTransmissionTable.sample(LinearClamp, float2(_2589, (fast::min(_2693 + 1.0, _2685 - 1.0) + _2701) / _2685), level(0.0)).xyz, float3(_2691 - _2693));
                        float3 _2600 = _2296 - (float3(0.0, 0.0, 1.0) * _2589);
                        float _2603 = dot(_2600, _2600);
                        _5097 = fast::normalize((float3(0.0, 0.0, 1.0) * (-cos(_2575.y))) + (select(float3(0.0), _2600 * rsqrt(_2603), bool3(_2603 > 9.9999999600419720025001879548654e-13)) * sin(_2575.y)));
                        _5096 = _2575.z;
                        _5095 = _2575.x;
                        break;
                    }
                    float _2782;
                    float _5092;
                    float3 _5094;
                    do
                    {
                        float _2756 = (1.0 - _2305.z) / (1.0 + _2305.z);
                        float3 _2765 = refract(float3(-0.0, -0.0, -1.0), _2296, 1.0 / _2305.z);
                        float3 _2774 = fast::normalize(_2296 - (_2765 * (2.0 * dot(_2296, _2765))));
                        float3 _2779 = refract(_2765, -_2774, _2305.z);
                        _2782 = _2304.w * _1836.GlassRoughnessScale;
                        if (dot(_2779, _2779) == 0.0)
                        {
                            _5094 = float3(-0.0, -0.0, -1.0);
                            _5092 = 0.0;
                            break;
                        }
                        float _5090;
                        if (_1836.GlassTransmission == 1u)
                        {
                            float _2803 = fast::clamp(_2293, 0.0, 1.0);
                            uint2 _2840 = uint2(TransmissionTable.get_width(), TransmissionTable.get_height());
                            float _2894 = float(_2840.y / _2840.x);
                            float _2900 = fast::clamp((_2305.z - 1.10000002384185791015625) * 5.0, 0.0, _2894 - 1.0);
                            float _2902 = floor(_2900);
                            float _2905 = 0.5 / float(_2840.x);
                            float _2910 = fast::clamp(_2304.w, _2905, 1.0 - _2905);
                            float _2812 = dot(_2774, _2765);
                            uint2 _2938 = uint2(TransmissionTable.get_width(), TransmissionTable.get_height());
                            float _2992 = float(_2938.y / _2938.x);
                            float _2998 = fast::clamp((_2305.z - 1.10000002384185791015625) * 5.0, 0.0, _2992 - 1.0);
                            float _3000 = floor(_2998);
                            float _3003 = 0.5 / float(_2938.x);
                            float _3008 = fast::clamp(_2304.w, _3003, 1.0 - _3003);
                            _5090 = mix(float2(TransmissionTable.sample(LinearClamp, float2(_2803, (_2902 + _2910) / _2894), level(0.0)).x, _5135), float2(TransmissionTable.sample(LinearClamp, float2(_2803, (fast::min(_2902 + 1.0, _2894 - 1.0) + _2910) / _2894), level(0.0)).x, _5135), float2(_2900 - _2902)).x * mix(float2(_5135, TransmissionTable.sample(LinearClamp, float2(_2812, (_3000 + _3008) / _2992), level(0.0)).y), float2(_5135, TransmissionTable.sample(LinearClamp, float2(_2812, (fast::min(_3000 + 1.0, _2992 - 1.0) + _3008) / _2992), level(0.0)).y), float2(_2998 - _3000)).y;
                        }
                        else
                        {
                            _5090 = (1.0 - fma(_2756, _2756, fma(-_2756, _2756, 1.0) * pow(1.0 - fast::clamp(_2293, 0.0, 1.0), 5.0))) * (1.0 - fma(_2756, _2756, fma(-_2756, _2756, 1.0) * pow(1.0 - fast::clamp(dot(_2774, _2779), 0.0, 1.0), 5.0)));
                        }
                        _5094 = _2779;
                        _5092 = _5090;
                        break;
                    } while(false);
                    _5097 = _5094;
                    _5096 = _2782;
                    _5095 = _5092;
                    break;
                } while(false);
                float _5098;
                do
                {
                    float _3139 = float(_1836.SpecularMips - 1u);
                    float _3141 = fast::clamp(_5096, 0.0, 1.0);
                    if (_1836.LodMapping == 1u)
                    {
                        _5098 = (_3141 * (2.0 - _3141)) * _3139;
                        break;
                    }
                    if (_1836.LodMapping == 2u)
                    {
                        _5098 = pow(_3141, _1836.LodParameter) * _3139;
                        break;
                    }
                    if (_1836.LodMapping == 3u)
                    {
                        _5098 = (_3141 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_3141 * _3141) * float(_1836.SpecularSize)), 0.0, _3139) : 0.0;
                        break;
                    }
                    if (((_1836.LodMapping == 4u) && (_1836.SpecularMips >= 3u)) && (float(_1836.SpecularSize) > _1836.LodParameter))
                    {
                        float _3200 = float(_1836.SpecularSize);
                        _5098 = (_3141 > 0.0) ? fast::clamp(fma((_3139 - 1.0) / log2(_3200 / _1836.LodParameter), log2((_3141 * _3141) * _3200) - log2(_3200), _3139), 0.0, _3139) : 0.0;
                        break;
                    }
                    _5098 = _3141 * _3139;
                    break;
                } while(false);
                float _3245 = (_1836.LightCount > 0u) ? fast::clamp((_5098 - float(_1836.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                float3 _5100;
                _5100 = Specular.sample(LinearClamp, _5097, level(_5098)).xyz;
                float3 _2524;
                for (uint _5099 = 0u; _5099 < _1836.LightCount; _5100 = _2524, _5099++)
                {
                    uint _2512 = 2u * _5099;
                    float _3257 = fast::max(_5096 * _5096, 1.0000000116860974230803549289703e-07);
                    float4 _3249 = Lights._data[_2512];
                    float _3285 = tan(fast::min(0.5 * acos(fast::clamp(dot(_5097, Lights._data[_2512].xyz), -1.0, 1.0)), 1.5));
                    float _3295 = (0.5 * _3249.w) * pow(fma(_3285, _3285, 1.0), 0.75);
                    float _3310 = (_3295 * _3295) / (_3257 * _3257);
                    float _3317 = (_3285 * _3285) / (_3257 * _3257);
                    float _3321 = (_3310 + 1.0) - _3317;
                    _2524 = _5100 + ((Lights._data[(2u * _5099) + 1u].xyz * _3245) * fast::clamp(0.5 + (((_3310 - 1.0) - _3317) / (2.0 * sqrt(fma(_3321, _3321, 4.0 * _3317)))), 0.0, 1.0));
                }
                _5101 = _5100 * _5095;
                break;
            }
            float3 _5071;
            float _5072;
            do
            {
                float3 _3505 = reflect(float3(-0.0, -0.0, -1.0), _2296);
                float4 _3451 = LobeTable.sample(LinearClamp, float2(fast::clamp(_2293, 0.0, 1.0), _2304.w), level(0.0));
                float3 _5060;
                do
                {
                    float _3627 = _2304.w * _2304.w;
                    if (_1836.Direction == 1u)
                    {
                        float _3633 = fast::clamp(fma(-_2304.w, _2304.w, 1.0), 0.0, 1.0);
                        _5060 = fast::normalize(mix(_2296, _3505, float3(_3633 * fma(_2304.w, _2304.w, sqrt(_3633)))));
                        break;
                    }
                    if (_1836.Direction == 2u)
                    {
                        _5060 = fast::normalize(mix(_3505, _2296, float3(_3627 * _3627)));
                        break;
                    }
                    if (_1836.Direction == 3u)
                    {
                        float3 _5059;
                        do
                        {
                            float _3682 = acos(fast::clamp(dot(_2296, _3505), -1.0, 1.0));
                            if (_3682 < 9.9999997473787516355514526367188e-05)
                            {
                                _5059 = _3505;
                                break;
                            }
                            _5059 = ((_2296 * sin((1.0 - _3451.x) * _3682)) + (_3505 * sin(_3451.x * _3682))) / float3(sin(_3682));
                            break;
                        } while(false);
                        _5060 = _5059;
                        break;
                    }
                    _5060 = _3505;
                    break;
                } while(false);
                if (_1836.Lookup == 0u)
                {
                    float _5069;
                    do
                    {
                        float _3747 = float(_1836.SpecularMips - 1u);
                        float _3749 = fast::clamp(_2304.w, 0.0, 1.0);
                        if (_1836.LodMapping == 1u)
                        {
                            _5069 = (_3749 * (2.0 - _3749)) * _3747;
                            break;
                        }
                        if (_1836.LodMapping == 2u)
                        {
                            _5069 = pow(_3749, _1836.LodParameter) * _3747;
                            break;
                        }
                        if (_1836.LodMapping == 3u)
                        {
                            _5069 = (_3749 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_3749 * _3749) * float(_1836.SpecularSize)), 0.0, _3747) : 0.0;
                            break;
                        }
                        if (((_1836.LodMapping == 4u) && (_1836.SpecularMips >= 3u)) && (float(_1836.SpecularSize) > _1836.LodParameter))
                        {
                            float _3808 = float(_1836.SpecularSize);
                            _5069 = (_3749 > 0.0) ? fast::clamp(fma((_3747 - 1.0) / log2(_3808 / _1836.LodParameter), log2((_3749 * _3749) * _3808) - log2(_3808), _3747), 0.0, _3747) : 0.0;
                            break;
                        }
                        _5069 = _3749 * _3747;
                        break;
                    } while(false);
                    _5072 = (_1836.LightCount > 0u) ? fast::clamp((_5069 - float(_1836.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                    _5071 = Specular.sample(LinearClamp, _5060, level(_5069)).xyz * 1.0;
                    break;
                }
                if (_1836.Lookup == 1u)
                {
                    float _5067;
                    do
                    {
                        float _3892 = float(_1836.SpecularMips - 1u);
                        float _3894 = fast::clamp(_3451.y, 0.0, 1.0);
                        if (_1836.LodMapping == 1u)
                        {
                            _5067 = (_3894 * (2.0 - _3894)) * _3892;
                            break;
                        }
                        if (_1836.LodMapping == 2u)
                        {
                            _5067 = pow(_3894, _1836.LodParameter) * _3892;
                            break;
                        }
                        if (_1836.LodMapping == 3u)
                        {
                            _5067 = (_3894 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_3894 * _3894) * float(_1836.SpecularSize)), 0.0, _3892) : 0.0;
                            break;
                        }
                        if (((_1836.LodMapping == 4u) && (_1836.SpecularMips >= 3u)) && (float(_1836.SpecularSize) > _1836.LodParameter))
                        {
                            float _3953 = float(_1836.SpecularSize);
                            _5067 = (_3894 > 0.0) ? fast::clamp(fma((_3892 - 1.0) / log2(_3953 / _1836.LodParameter), log2((_3894 * _3894) * _3953) - log2(_3953), _3892), 0.0, _3892) : 0.0;
                            break;
                        }
                        _5067 = _3894 * _3892;
                        break;
                    } while(false);
                    _5072 = (_1836.LightCount > 0u) ? fast::clamp((_5067 - float(_1836.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                    _5071 = Specular.sample(LinearClamp, _5060, level(_5067)).xyz * 1.0;
                    break;
                }
                float3 _3548 = cross(_2296, float3(0.0, 0.0, 1.0));
                float _3550 = length(_3548);
                float3 _3560 = select(float3(0.0), cross(_3548 / float3(_3550), _5060), bool3(_3550 > 9.9999999747524270787835121154785e-07));
                float _5063;
                do
                {
                    float _4037 = float(_1836.SpecularMips - 1u);
                    float _4039 = fast::clamp(_3451.z, 0.0, 1.0);
                    if (_1836.LodMapping == 1u)
                    {
                        _5063 = (_4039 * (2.0 - _4039)) * _4037;
                        break;
                    }
                    if (_1836.LodMapping == 2u)
                    {
                        _5063 = pow(_4039, _1836.LodParameter) * _4037;
                        break;
                    }
                    if (_1836.LodMapping == 3u)
                    {
                        _5063 = (_4039 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_4039 * _4039) * float(_1836.SpecularSize)), 0.0, _4037) : 0.0;
                        break;
                    }
                    if (((_1836.LodMapping == 4u) && (_1836.SpecularMips >= 3u)) && (float(_1836.SpecularSize) > _1836.LodParameter))
                    {
                        float _4098 = float(_1836.SpecularSize);
                        _5063 = (_4039 > 0.0) ? fast::clamp(fma((_4037 - 1.0) / log2(_4098 / _1836.LodParameter), log2((_4039 * _4039) * _4098) - log2(_4098), _4037), 0.0, _4037) : 0.0;
                        break;
                    }
                    _5063 = _4039 * _4037;
                    break;
                } while(false);
                float _5065;
                do
                {
                    float _4182 = float(_1836.SpecularMips - 1u);
                    float _4184 = fast::clamp(_3451.z, 0.0, 1.0);
                    if (_1836.LodMapping == 1u)
                    {
                        _5065 = (_4184 * (2.0 - _4184)) * _4182;
                        break;
                    }
                    if (_1836.LodMapping == 2u)
                    {
                        _5065 = pow(_4184, _1836.LodParameter) * _4182;
                        break;
                    }
                    if (_1836.LodMapping == 3u)
                    {
                        _5065 = (_4184 > 0.0) ? fast::clamp(0.800000011920928955078125 * log2((_4184 * _4184) * float(_1836.SpecularSize)), 0.0, _4182) : 0.0;
                        break;
                    }
                    if (((_1836.LodMapping == 4u) && (_1836.SpecularMips >= 3u)) && (float(_1836.SpecularSize) > _1836.LodParameter))
                    {
                        float _4243 = float(_1836.SpecularSize);
                        _5065 = (_4184 > 0.0) ? fast::clamp(fma((_4182 - 1.0) / log2(_4243 / _1836.LodParameter), log2((_4184 * _4184) * _4243) - log2(_4243), _4182), 0.0, _4182) : 0.0;
                        break;
                    }
                    _5065 = _4184 * _4182;
                    break;
                } while(false);
                _5072 = fma(0.5, (_1836.LightCount > 0u) ? fast::clamp((_5063 - float(_1836.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1836.LightCount > 0u) ? fast::clamp((_5065 - float(_1836.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                _5071 = (Specular.sample(LinearClamp, fast::normalize((_5060 * cos(_3451.w)) + (_3560 * sin(_3451.w))), level(_5063)).xyz * 0.5) + (Specular.sample(LinearClamp, fast::normalize((_5060 * cos(_3451.w)) - (_3560 * sin(_3451.w))), level(_5065)).xyz * 0.5);
                break;
            } while(false);
            float2 _3395 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_2293, 0.0, 1.0), _2304.w), level(0.0)).xy);
            float3 _2414 = mix(float3(0.039999999105930328369140625), Spheres_1._data[_2316].xyz, float3(_2305.x));
            float2 _4289 = float2(BrdfLut.sample(LinearClamp, float2(fast::clamp(_2293, 0.0, 1.0), _2304.w), level(0.0)).xy);
            float3 _4312 = (_2414 * _4289.x) + float3(_4289.y);
            float3 _5074;
            _5074 = fma(_5071, (mix(float3(0.039999999105930328369140625), Spheres_1._data[_2316].xyz, float3(_2305.x)) * _3395.x) + float3(_3395.y), (IrradianceMap.sample(LinearClamp, _2296, level(0.0)).xyz * Spheres_1._data[_2316].xyz) * (1.0 - _2305.x));
            float3 _2454;
            for (uint _5073 = 0u; _5073 < _1836.LightCount; _5074 = _2454, _5073++)
            {
                uint _2437 = 2u * _5073;
                uint _2440 = (2u * _5073) + 1u;
                float4 _2376 = Lights._data[_2437];
                float4 _2377 = Lights._data[_2440];
                float3 _4313 = Lights._data[_2437].xyz;
                float3 _4353 = fast::normalize(cross(select(float3(1.0, 0.0, 0.0), float3(0.0, 0.0, 1.0), bool3(abs(_4313.z) < 0.999000012874603271484375)), Lights._data[_2437].xyz));
                float3 _4356 = cross(Lights._data[_2437].xyz, _4353);
                float _4359 = tan(_2376.w);
                float3 _5076;
                _5076 = float3(0.0);
                float3 _5102;
                for (uint _5075 = 0u; _5075 < 19u; _5076 = _5102, _5075++)
                {
                    float2 _5083;
                    do
                    {
                        if (_5075 == 0u)
                        {
                            _5083 = float2(0.0);
                            break;
                        }
                        bool _4467 = _5075 <= 6u;
                        float _4484 = _4467 ? (float(_5075 - 1u) * 1.0471975803375244140625) : ((float(_5075 - 7u) + 0.5) * 0.52359879016876220703125);
                        _5083 = float2(cos(_4484), sin(_4484)) * (_4467 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                        break;
                    } while(false);
                    float2 _4320 = _5083 * _4359;
                    float3 _4380 = fast::normalize((Lights._data[_2437].xyz + (_4353 * _4320.x)) + (_4356 * _4320.y));
                    if (dot(_2296, _4380) > 0.0)
                    {
                        float3 _5084;
                        do
                        {
                            float _4514 = dot(_2296, _4380);
                            float _4518 = fast::clamp(_2293, 0.0, 1.0);
                            if ((_4514 <= 0.0) || (_4518 <= 0.0))
                            {
                                _5084 = float3(0.0);
                                break;
                            }
                            float3 _4529 = fast::normalize(_4380 + float3(0.0, 0.0, 1.0));
                            float _4603 = _2304.w * _2304.w;
                            float _4624 = _2304.w * _2304.w;
                            float _4546 = fast::clamp(dot(_2296, _4529), 0.0, 1.0);
                            float _4645 = _2304.w * _2304.w;
                            float _4657 = fma(_4546 * _4546, fma(_4645, _4645, -1.0), 1.0);
                            _5084 = (_2414 + ((float3(1.0) - _2414) * pow(fast::clamp(1.0 - fast::clamp(_4529.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_4514 / fma(_4514, fma(-_4603, 0.5, 1.0), _4603 * 0.5)) * (_4518 / fma(_4518, fma(-_4624, 0.5, 1.0), _4624 * 0.5))) * ((_4645 * _4645) / ((3.1415927410125732421875 * _4657) * _4657))) / (4.0 * _4518));
                            break;
                        } while(false);
                        _5102 = _5076 + _5084;
                    }
                    else
                    {
                        _5102 = _5076;
                    }
                }
                float _4408 = fast::clamp((((2.0 * _2304.w) * _2304.w) / fast::max(_2376.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                float4 _4335 = Lights._data[_2437];
                float _4685 = 0.5 * _4335.w;
                float _4687 = 0.5 * acos(fast::clamp(dot(reflect(float3(-0.0, -0.0, -1.0), _2296), Lights._data[_2437].xyz), -1.0, 1.0));
                float _4691 = fast::max(_2304.w * _2304.w, 1.0000000116860974230803549289703e-07);
                float _4705 = (_4685 * _4685) / (_4691 * _4691);
                float _4712 = (_4687 * _4687) / (_4691 * _4691);
                float _4716 = (_4705 + 1.0) - _4712;
                float _4432 = sin(_2376.w);
                float _4436 = dot(_2296, Lights._data[_2437].xyz);
                float _4439 = _4432 * _4432;
                float _5077;
                do
                {
                    if (((_4436 * _4436) > _4439) || (_4439 <= 0.0))
                    {
                        _5077 = (3.1415927410125732421875 * _4439) * fast::clamp(_4436, 0.0, 1.0);
                        break;
                    }
                    float _4761 = sqrt(fast::clamp(fma(-_4436, _4436, 1.0), 0.0, 1.0));
                    float _4765 = sqrt((1.0 / _4439) - 1.0);
                    float _4771 = (-_4765) * (_4436 / _4761);
                    float _4779 = _4761 * sqrt(fast::clamp(fma(-_4771, _4771, 1.0), 0.0, 1.0));
                    _5077 = fast::max(fma(fma(_4436, acos(fast::clamp(_4771, -1.0, 1.0)), -(_4765 * _4779)), _4439, atan(_4779 / _4765)), 0.0);
                    break;
                } while(false);
                _2454 = fma(((mix(select(float3(0.0), (_4312 * fast::clamp(0.5 + (((_4705 - 1.0) - _4712) / (2.0 * sqrt(fma(_4716, _4716, 4.0 * _4712)))), 0.0, 1.0)) / float3(_2377.w), bool3(_4408 < 1.0)), _5076 * 0.052631579339504241943359375, float3(_4408)) * _5072) * _2377.w) + ((Spheres_1._data[_2316].xyz * (1.0 - _2305.x)) * (_5077 * 0.3183098733425140380859375)), Lights._data[_2440].xyz, _5074);
            }
            _5101 = _5074;
            break;
        } while(false);
        SplitSum.write(float4(select(float3(0.0), _5101, bool3(_2285)), float(_2285)), uint2(gl_GlobalInvocationID.xy));
        break;
    } while(false);
}

