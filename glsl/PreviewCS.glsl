#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PreviewParameter
{
    uint Columns;
    uint Rows;
    uint CellSize;
    uint SpecularMips;
    uint StripPanelWidth;
    float Exposure;
    uint SpecularSize;
    uint LodMapping;
    float LodParameter;
    uint Direction;
    uint Lookup;
    uint LightCount;
    uint LightLevel;
} _1238;

layout(binding = 0, std430) readonly buffer Lights
{
    vec4 _data[];
} Lights_1;

layout(binding = 0, rgba32f) uniform writeonly image2D Preview;
layout(binding = 3) uniform sampler2D LobeTable_LinearClamp;
layout(binding = 0) uniform samplerCube Specular_LinearClamp;
layout(binding = 2) uniform sampler2D BrdfLut_LinearClamp;
layout(binding = 1) uniform samplerCube IrradianceMap_LinearClamp;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec2 _1685 = uvec2(0u);
        uvec2 _1686 = uvec2(imageSize(Preview));
        _1685.x = _1686.x;
        _1685.y = _1686.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _1685)))
        {
            break;
        }
        uint _1714 = _1238.Rows * _1238.CellSize;
        vec3 _3616;
        if (param.x >= (_1238.Columns * _1238.CellSize))
        {
            _3616 = vec3(0.0199999995529651641845703125);
        }
        else
        {
            vec3 _3617;
            if (param.y < _1714)
            {
                vec3 _3615;
                do
                {
                    uvec2 _1757 = gl_GlobalInvocationID.xy / uvec2(_1238.CellSize);
                    vec2 _1758 = (((vec2(gl_GlobalInvocationID.xy % uvec2(_1238.CellSize)) + vec2(0.5)) / vec2(float(_1238.CellSize))) * 2.0) - vec2(1.0);
                    _1758.y = -_1758.y;
                    float _1830 = dot(_1758, _1758);
                    if ((_1830 * 1.2345678806304931640625) >= 1.0)
                    {
                        _3615 = vec3(0.0199999995529651641845703125);
                        break;
                    }
                    float _1922 = (_1238.Columns > 1u) ? (float(_1757.x) / float(_1238.Columns - 1u)) : 0.0;
                    float _1933 = (_1238.Rows > 1u) ? (float(_1757.y) / float(_1238.Rows - 1u)) : 0.0;
                    float _1851 = sqrt(fma(-_1830, 1.2345678806304931640625, 1.0));
                    vec3 _1854 = vec3(_1758 * vec2(1.111111164093017578125), _1851);
                    vec3 _3596;
                    float _3597;
                    do
                    {
                        vec3 _2102 = reflect(vec3(-0.0, -0.0, -1.0), _1854);
                        vec4 _2048 = textureLod(LobeTable_LinearClamp, vec2(clamp(_1851, 0.0, 1.0), _1922), 0.0);
                        vec3 _3585;
                        do
                        {
                            float _2224 = _1922 * _1922;
                            if (_1238.Direction == 1u)
                            {
                                float _2230 = clamp(fma(-_1922, _1922, 1.0), 0.0, 1.0);
                                _3585 = normalize(mix(_1854, _2102, vec3(_2230 * fma(_1922, _1922, sqrt(_2230)))));
                                break;
                            }
                            if (_1238.Direction == 2u)
                            {
                                _3585 = normalize(mix(_2102, _1854, vec3(_2224 * _2224)));
                                break;
                            }
                            if (_1238.Direction == 3u)
                            {
                                vec3 _3584;
                                do
                                {
                                    float _2279 = acos(clamp(dot(_1854, _2102), -1.0, 1.0));
                                    if (_2279 < 9.9999997473787516355514526367188e-05)
                                    {
                                        _3584 = _2102;
                                        break;
                                    }
                                    _3584 = ((_1854 * sin((1.0 - _2048.x) * _2279)) + (_2102 * sin(_2048.x * _2279))) / vec3(sin(_2279));
                                    break;
                                } while(false);
                                _3585 = _3584;
                                break;
                            }
                            _3585 = _2102;
                            break;
                        } while(false);
                        if (_1238.Lookup == 0u)
                        {
                            float _3594;
                            do
                            {
                                float _2344 = float(_1238.SpecularMips - 1u);
                                float _2346 = clamp(_1922, 0.0, 1.0);
                                if (_1238.LodMapping == 1u)
                                {
                                    _3594 = (_2346 * (2.0 - _2346)) * _2344;
                                    break;
                                }
                                if (_1238.LodMapping == 2u)
                                {
                                    _3594 = pow(_2346, _1238.LodParameter) * _2344;
                                    break;
                                }
                                if (_1238.LodMapping == 3u)
                                {
                                    _3594 = (_2346 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2346 * _2346) * float(_1238.SpecularSize)), 0.0, _2344) : 0.0;
                                    break;
                                }
                                if (((_1238.LodMapping == 4u) && (_1238.SpecularMips >= 3u)) && (float(_1238.SpecularSize) > _1238.LodParameter))
                                {
                                    float _2405 = float(_1238.SpecularSize);
                                    _3594 = (_2346 > 0.0) ? clamp(fma((_2344 - 1.0) / log2(_2405 / _1238.LodParameter), log2((_2346 * _2346) * _2405) - log2(_2405), _2344), 0.0, _2344) : 0.0;
                                    break;
                                }
                                _3594 = _2346 * _2344;
                                break;
                            } while(false);
                            _3597 = (_1238.LightCount > 0u) ? clamp((_3594 - float(_1238.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                            _3596 = textureLod(Specular_LinearClamp, _3585, _3594).xyz * 1.0;
                            break;
                        }
                        if (_1238.Lookup == 1u)
                        {
                            float _3592;
                            do
                            {
                                float _2489 = float(_1238.SpecularMips - 1u);
                                float _2491 = clamp(_2048.y, 0.0, 1.0);
                                if (_1238.LodMapping == 1u)
                                {
                                    _3592 = (_2491 * (2.0 - _2491)) * _2489;
                                    break;
                                }
                                if (_1238.LodMapping == 2u)
                                {
                                    _3592 = pow(_2491, _1238.LodParameter) * _2489;
                                    break;
                                }
                                if (_1238.LodMapping == 3u)
                                {
                                    _3592 = (_2491 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2491 * _2491) * float(_1238.SpecularSize)), 0.0, _2489) : 0.0;
                                    break;
                                }
                                if (((_1238.LodMapping == 4u) && (_1238.SpecularMips >= 3u)) && (float(_1238.SpecularSize) > _1238.LodParameter))
                                {
                                    float _2550 = float(_1238.SpecularSize);
                                    _3592 = (_2491 > 0.0) ? clamp(fma((_2489 - 1.0) / log2(_2550 / _1238.LodParameter), log2((_2491 * _2491) * _2550) - log2(_2550), _2489), 0.0, _2489) : 0.0;
                                    break;
                                }
                                _3592 = _2491 * _2489;
                                break;
                            } while(false);
                            _3597 = (_1238.LightCount > 0u) ? clamp((_3592 - float(_1238.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                            _3596 = textureLod(Specular_LinearClamp, _3585, _3592).xyz * 1.0;
                            break;
                        }
                        vec3 _2145 = cross(_1854, vec3(0.0, 0.0, 1.0));
                        float _2147 = length(_2145);
                        vec3 _2157 = mix(vec3(0.0), cross(_2145 / vec3(_2147), _3585), bvec3(_2147 > 9.9999999747524270787835121154785e-07));
                        float _3588;
                        do
                        {
                            float _2634 = float(_1238.SpecularMips - 1u);
                            float _2636 = clamp(_2048.z, 0.0, 1.0);
                            if (_1238.LodMapping == 1u)
                            {
                                _3588 = (_2636 * (2.0 - _2636)) * _2634;
                                break;
                            }
                            if (_1238.LodMapping == 2u)
                            {
                                _3588 = pow(_2636, _1238.LodParameter) * _2634;
                                break;
                            }
                            if (_1238.LodMapping == 3u)
                            {
                                _3588 = (_2636 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2636 * _2636) * float(_1238.SpecularSize)), 0.0, _2634) : 0.0;
                                break;
                            }
                            if (((_1238.LodMapping == 4u) && (_1238.SpecularMips >= 3u)) && (float(_1238.SpecularSize) > _1238.LodParameter))
                            {
                                float _2695 = float(_1238.SpecularSize);
                                _3588 = (_2636 > 0.0) ? clamp(fma((_2634 - 1.0) / log2(_2695 / _1238.LodParameter), log2((_2636 * _2636) * _2695) - log2(_2695), _2634), 0.0, _2634) : 0.0;
                                break;
                            }
                            _3588 = _2636 * _2634;
                            break;
                        } while(false);
                        float _3590;
                        do
                        {
                            float _2779 = float(_1238.SpecularMips - 1u);
                            float _2781 = clamp(_2048.z, 0.0, 1.0);
                            if (_1238.LodMapping == 1u)
                            {
                                _3590 = (_2781 * (2.0 - _2781)) * _2779;
                                break;
                            }
                            if (_1238.LodMapping == 2u)
                            {
                                _3590 = pow(_2781, _1238.LodParameter) * _2779;
                                break;
                            }
                            if (_1238.LodMapping == 3u)
                            {
                                _3590 = (_2781 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2781 * _2781) * float(_1238.SpecularSize)), 0.0, _2779) : 0.0;
                                break;
                            }
                            if (((_1238.LodMapping == 4u) && (_1238.SpecularMips >= 3u)) && (float(_1238.SpecularSize) > _1238.LodParameter))
                            {
                                float _2840 = float(_1238.SpecularSize);
                                _3590 = (_2781 > 0.0) ? clamp(fma((_2779 - 1.0) / log2(_2840 / _1238.LodParameter), log2((_2781 * _2781) * _2840) - log2(_2840), _2779), 0.0, _2779) : 0.0;
                                break;
                            }
                            _3590 = _2781 * _2779;
                            break;
                        } while(false);
                        _3597 = fma(0.5, (_1238.LightCount > 0u) ? clamp((_3588 - float(_1238.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1238.LightCount > 0u) ? clamp((_3590 - float(_1238.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                        _3596 = (textureLod(Specular_LinearClamp, normalize((_3585 * cos(_2048.w)) + (_2157 * sin(_2048.w))), _3588).xyz * 0.5) + (textureLod(Specular_LinearClamp, normalize((_3585 * cos(_2048.w)) - (_2157 * sin(_2048.w))), _3590).xyz * 0.5);
                        break;
                    } while(false);
                    vec2 _1992 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_1851, 0.0, 1.0), _1922), 0.0).xy);
                    vec3 _1869 = mix(vec3(0.039999999105930328369140625), vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), vec3(_1933));
                    vec2 _2886 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_1851, 0.0, 1.0), _1922), 0.0).xy);
                    vec3 _2909 = (_1869 * _2886.x) + vec3(_2886.y);
                    vec3 _3599;
                    _3599 = fma(_3596, (mix(vec3(0.039999999105930328369140625), vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), vec3(_1933)) * _1992.x) + vec3(_1992.y), (textureLod(IrradianceMap_LinearClamp, _1854, 0.0).xyz * vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125)) * (1.0 - _1933));
                    vec3 _1904;
                    for (uint _3598 = 0u; _3598 < _1238.LightCount; _3599 = _1904, _3598++)
                    {
                        uint _1888 = 2u * _3598;
                        uint _1891 = (2u * _3598) + 1u;
                        vec4 _1798 = Lights_1._data[_1888];
                        vec4 _1799 = Lights_1._data[_1891];
                        vec3 _2910 = Lights_1._data[_1888].xyz;
                        vec3 _2950 = normalize(cross(mix(vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), bvec3(abs(_2910.z) < 0.999000012874603271484375)), Lights_1._data[_1888].xyz));
                        vec3 _2953 = cross(Lights_1._data[_1888].xyz, _2950);
                        float _2956 = tan(_1798.w);
                        vec3 _3601;
                        _3601 = vec3(0.0);
                        vec3 _3618;
                        for (uint _3600 = 0u; _3600 < 19u; _3601 = _3618, _3600++)
                        {
                            vec2 _3608;
                            do
                            {
                                if (_3600 == 0u)
                                {
                                    _3608 = vec2(0.0);
                                    break;
                                }
                                bool _3064 = _3600 <= 6u;
                                float _3081 = _3064 ? (float(_3600 - 1u) * 1.0471975803375244140625) : ((float(_3600 - 7u) + 0.5) * 0.52359879016876220703125);
                                _3608 = vec2(cos(_3081), sin(_3081)) * (_3064 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                                break;
                            } while(false);
                            vec2 _2917 = _3608 * _2956;
                            vec3 _2977 = normalize((Lights_1._data[_1888].xyz + (_2950 * _2917.x)) + (_2953 * _2917.y));
                            if (dot(_1854, _2977) > 0.0)
                            {
                                vec3 _3609;
                                do
                                {
                                    float _3111 = dot(_1854, _2977);
                                    float _3115 = clamp(_1851, 0.0, 1.0);
                                    if ((_3111 <= 0.0) || (_3115 <= 0.0))
                                    {
                                        _3609 = vec3(0.0);
                                        break;
                                    }
                                    vec3 _3126 = normalize(_2977 + vec3(0.0, 0.0, 1.0));
                                    float _3200 = _1922 * _1922;
                                    float _3221 = _1922 * _1922;
                                    float _3143 = clamp(dot(_1854, _3126), 0.0, 1.0);
                                    float _3242 = _1922 * _1922;
                                    float _3254 = fma(_3143 * _3143, fma(_3242, _3242, -1.0), 1.0);
                                    _3609 = (_1869 + ((vec3(1.0) - _1869) * pow(clamp(1.0 - clamp(_3126.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_3111 / fma(_3111, fma(-_3200, 0.5, 1.0), _3200 * 0.5)) * (_3115 / fma(_3115, fma(-_3221, 0.5, 1.0), _3221 * 0.5))) * ((_3242 * _3242) / ((3.1415927410125732421875 * _3254) * _3254))) / (4.0 * _3115));
                                    break;
                                } while(false);
                                _3618 = _3601 + _3609;
                            }
                            else
                            {
                                _3618 = _3601;
                            }
                        }
                        float _3005 = clamp((((2.0 * _1922) * _1922) / max(_1798.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                        vec4 _2932 = Lights_1._data[_1888];
                        float _3282 = 0.5 * _2932.w;
                        float _3284 = 0.5 * acos(clamp(dot(reflect(vec3(-0.0, -0.0, -1.0), _1854), Lights_1._data[_1888].xyz), -1.0, 1.0));
                        float _3288 = max(_1922 * _1922, 1.0000000116860974230803549289703e-07);
                        float _3302 = (_3282 * _3282) / (_3288 * _3288);
                        float _3309 = (_3284 * _3284) / (_3288 * _3288);
                        float _3313 = (_3302 + 1.0) - _3309;
                        float _3029 = sin(_1798.w);
                        float _3033 = dot(_1854, Lights_1._data[_1888].xyz);
                        float _3036 = _3029 * _3029;
                        float _3602;
                        do
                        {
                            if (((_3033 * _3033) > _3036) || (_3036 <= 0.0))
                            {
                                _3602 = (3.1415927410125732421875 * _3036) * clamp(_3033, 0.0, 1.0);
                                break;
                            }
                            float _3358 = sqrt(clamp(fma(-_3033, _3033, 1.0), 0.0, 1.0));
                            float _3362 = sqrt((1.0 / _3036) - 1.0);
                            float _3368 = (-_3362) * (_3033 / _3358);
                            float _3376 = _3358 * sqrt(clamp(fma(-_3368, _3368, 1.0), 0.0, 1.0));
                            _3602 = max(fma(fma(_3033, acos(clamp(_3368, -1.0, 1.0)), -(_3362 * _3376)), _3036, atan(_3376 / _3362)), 0.0);
                            break;
                        } while(false);
                        _1904 = fma(((mix(mix(vec3(0.0), (_2909 * clamp(0.5 + (((_3302 - 1.0) - _3309) / (2.0 * sqrt(fma(_3313, _3313, 4.0 * _3309)))), 0.0, 1.0)) / vec3(_1799.w), bvec3(_3005 < 1.0)), _3601 * 0.052631579339504241943359375, vec3(_3005)) * _3597) * _1799.w) + ((vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125) * (1.0 - _1933)) * (_3602 * 0.3183098733425140380859375)), Lights_1._data[_1891].xyz, _3599);
                    }
                    _3615 = _3599;
                    break;
                } while(false);
                _3617 = _3615;
            }
            else
            {
                uvec2 _1690 = uvec2(param.x, param.y - _1714);
                vec3 _3583;
                do
                {
                    uint _3408 = _1690.x / _1238.StripPanelWidth;
                    if (_3408 >= _1238.SpecularMips)
                    {
                        _3583 = vec3(0.0199999995529651641845703125);
                        break;
                    }
                    vec2 _3400 = (vec2(float(_1690.x % _1238.StripPanelWidth), float(_1690.y)) + vec2(0.5)) / vec2(float(_1238.StripPanelWidth), float(_1238.StripPanelWidth / 2u));
                    float _3455 = (_3400.x - 0.5) * 6.283185482025146484375;
                    float _3458 = _3400.y * 3.1415927410125732421875;
                    _3583 = textureLod(Specular_LinearClamp, vec3(sin(_3458) * sin(_3455), cos(_3458), (-sin(_3458)) * cos(_3455)), float(_3408)).xyz;
                    break;
                } while(false);
                _3617 = _3583;
            }
            _3616 = _3617;
        }
        vec3 _3481 = _3616 * _1238.Exposure;
        vec3 _3499 = clamp((_3481 * ((_3481 * 2.5099999904632568359375) + vec3(0.02999999932944774627685546875))) / fma(_3481, (_3481 * 2.4300000667572021484375) + vec3(0.589999973773956298828125), vec3(0.14000000059604644775390625)), vec3(0.0), vec3(1.0));
        imageStore(Preview, ivec2(gl_GlobalInvocationID.xy), vec4(mix((pow(_3499, vec3(0.4166666567325592041015625)) * 1.05499994754791259765625) - vec3(0.054999999701976776123046875), _3499 * 12.9200000762939453125, step(_3499, vec3(0.003130800090730190277099609375))), 1.0));
        break;
    } while(false);
}

