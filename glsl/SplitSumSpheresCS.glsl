#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std430) readonly buffer Spheres
{
    vec4 _data[];
} Spheres_1;

layout(binding = 0, std140) uniform SplitSumParameter
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
} _1213;

layout(binding = 1, std430) readonly buffer Lights
{
    vec4 _data[];
} Lights_1;

layout(binding = 0, rgba32f) uniform writeonly image2D SplitSum;
layout(binding = 0) uniform samplerCube Specular_LinearClamp;
layout(binding = 3) uniform sampler2D LobeTable_LinearClamp;
layout(binding = 2) uniform sampler2D BrdfLut_LinearClamp;
layout(binding = 1) uniform samplerCube IrradianceMap_LinearClamp;

void main()
{
    do
    {
        uvec2 _1562 = uvec2(0u);
        uvec2 _1563 = uvec2(imageSize(SplitSum));
        _1562.x = _1563.x;
        _1562.y = _1563.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _1562)))
        {
            break;
        }
        vec2 _1737 = (((vec2(gl_GlobalInvocationID.xy % uvec2(_1213.CellSize)) + vec2(0.5)) / vec2(float(_1213.CellSize))) * 2.0) - vec2(1.0);
        _1737.y = -_1737.y;
        float _1768 = dot(_1737, _1737);
        bool _1771 = (_1768 * 1.2345678806304931640625) < 1.0;
        float _1779 = sqrt(max(fma(-_1768, 1.2345678806304931640625, 1.0), 0.0));
        vec3 _1782 = vec3(_1737 * vec2(1.111111164093017578125), _1779);
        uvec2 _1740 = gl_GlobalInvocationID.xy / uvec2(_1213.CellSize);
        uint _1802 = 2u * ((_1740.y * _1213.Columns) + _1740.x);
        vec4 _1790 = Spheres_1._data[_1802];
        vec4 _1791 = Spheres_1._data[_1802 + 1u];
        vec3 _3624;
        if (_1771 && (_1791.y > 0.0))
        {
            vec3 _3623;
            do
            {
                float _1847 = (1.0 - _1791.z) / (1.0 + _1791.z);
                vec3 _1856 = refract(vec3(-0.0, -0.0, -1.0), _1782, 1.0 / _1791.z);
                vec3 _1865 = normalize(_1782 - (_1856 * (2.0 * dot(_1782, _1856))));
                vec3 _1870 = refract(_1856, -_1865, _1791.z);
                if (dot(_1870, _1870) == 0.0)
                {
                    _3623 = vec3(0.0);
                    break;
                }
                float _3622;
                do
                {
                    float _1966 = float(_1213.SpecularMips - 1u);
                    float _1968 = clamp(_1790.w, 0.0, 1.0);
                    if (_1213.LodMapping == 1u)
                    {
                        _3622 = (_1968 * (2.0 - _1968)) * _1966;
                        break;
                    }
                    if (_1213.LodMapping == 2u)
                    {
                        _3622 = pow(_1968, _1213.LodParameter) * _1966;
                        break;
                    }
                    if (_1213.LodMapping == 3u)
                    {
                        _3622 = (_1968 > 0.0) ? clamp(0.800000011920928955078125 * log2((_1968 * _1968) * float(_1213.SpecularSize)), 0.0, _1966) : 0.0;
                        break;
                    }
                    if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                    {
                        float _2027 = float(_1213.SpecularSize);
                        _3622 = (_1968 > 0.0) ? clamp(fma((_1966 - 1.0) / log2(_2027 / _1213.LodParameter), log2((_1968 * _1968) * _2027) - log2(_2027), _1966), 0.0, _1966) : 0.0;
                        break;
                    }
                    _3622 = _1968 * _1966;
                    break;
                } while(false);
                _3623 = textureLod(Specular_LinearClamp, _1870, _3622).xyz * ((1.0 - fma(_1847, _1847, fma(-_1847, _1847, 1.0) * pow(1.0 - clamp(_1779, 0.0, 1.0), 5.0))) * (1.0 - fma(_1847, _1847, fma(-_1847, _1847, 1.0) * pow(1.0 - clamp(dot(_1865, _1870), 0.0, 1.0), 5.0))));
                break;
            } while(false);
            _3624 = _3623;
        }
        else
        {
            vec3 _3625;
            if (_1771)
            {
                vec3 _3604;
                float _3605;
                do
                {
                    vec3 _2209 = reflect(vec3(-0.0, -0.0, -1.0), _1782);
                    vec4 _2155 = textureLod(LobeTable_LinearClamp, vec2(clamp(_1779, 0.0, 1.0), _1790.w), 0.0);
                    vec3 _3593;
                    do
                    {
                        float _2331 = _1790.w * _1790.w;
                        if (_1213.Direction == 1u)
                        {
                            float _2337 = clamp(fma(-_1790.w, _1790.w, 1.0), 0.0, 1.0);
                            _3593 = normalize(mix(_1782, _2209, vec3(_2337 * fma(_1790.w, _1790.w, sqrt(_2337)))));
                            break;
                        }
                        if (_1213.Direction == 2u)
                        {
                            _3593 = normalize(mix(_2209, _1782, vec3(_2331 * _2331)));
                            break;
                        }
                        if (_1213.Direction == 3u)
                        {
                            vec3 _3592;
                            do
                            {
                                float _2386 = acos(clamp(dot(_1782, _2209), -1.0, 1.0));
                                if (_2386 < 9.9999997473787516355514526367188e-05)
                                {
                                    _3592 = _2209;
                                    break;
                                }
                                _3592 = ((_1782 * sin((1.0 - _2155.x) * _2386)) + (_2209 * sin(_2155.x * _2386))) / vec3(sin(_2386));
                                break;
                            } while(false);
                            _3593 = _3592;
                            break;
                        }
                        _3593 = _2209;
                        break;
                    } while(false);
                    if (_1213.Lookup == 0u)
                    {
                        float _3602;
                        do
                        {
                            float _2451 = float(_1213.SpecularMips - 1u);
                            float _2453 = clamp(_1790.w, 0.0, 1.0);
                            if (_1213.LodMapping == 1u)
                            {
                                _3602 = (_2453 * (2.0 - _2453)) * _2451;
                                break;
                            }
                            if (_1213.LodMapping == 2u)
                            {
                                _3602 = pow(_2453, _1213.LodParameter) * _2451;
                                break;
                            }
                            if (_1213.LodMapping == 3u)
                            {
                                _3602 = (_2453 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2453 * _2453) * float(_1213.SpecularSize)), 0.0, _2451) : 0.0;
                                break;
                            }
                            if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                            {
                                float _2512 = float(_1213.SpecularSize);
                                _3602 = (_2453 > 0.0) ? clamp(fma((_2451 - 1.0) / log2(_2512 / _1213.LodParameter), log2((_2453 * _2453) * _2512) - log2(_2512), _2451), 0.0, _2451) : 0.0;
                                break;
                            }
                            _3602 = _2453 * _2451;
                            break;
                        } while(false);
                        _3605 = (_1213.LightCount > 0u) ? clamp((_3602 - float(_1213.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3604 = textureLod(Specular_LinearClamp, _3593, _3602).xyz * 1.0;
                        break;
                    }
                    if (_1213.Lookup == 1u)
                    {
                        float _3600;
                        do
                        {
                            float _2596 = float(_1213.SpecularMips - 1u);
                            float _2598 = clamp(_2155.y, 0.0, 1.0);
                            if (_1213.LodMapping == 1u)
                            {
                                _3600 = (_2598 * (2.0 - _2598)) * _2596;
                                break;
                            }
                            if (_1213.LodMapping == 2u)
                            {
                                _3600 = pow(_2598, _1213.LodParameter) * _2596;
                                break;
                            }
                            if (_1213.LodMapping == 3u)
                            {
                                _3600 = (_2598 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2598 * _2598) * float(_1213.SpecularSize)), 0.0, _2596) : 0.0;
                                break;
                            }
                            if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                            {
                                float _2657 = float(_1213.SpecularSize);
                                _3600 = (_2598 > 0.0) ? clamp(fma((_2596 - 1.0) / log2(_2657 / _1213.LodParameter), log2((_2598 * _2598) * _2657) - log2(_2657), _2596), 0.0, _2596) : 0.0;
                                break;
                            }
                            _3600 = _2598 * _2596;
                            break;
                        } while(false);
                        _3605 = (_1213.LightCount > 0u) ? clamp((_3600 - float(_1213.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3604 = textureLod(Specular_LinearClamp, _3593, _3600).xyz * 1.0;
                        break;
                    }
                    vec3 _2252 = cross(_1782, vec3(0.0, 0.0, 1.0));
                    float _2254 = length(_2252);
                    vec3 _2264 = mix(vec3(0.0), cross(_2252 / vec3(_2254), _3593), bvec3(_2254 > 9.9999999747524270787835121154785e-07));
                    float _3596;
                    do
                    {
                        float _2741 = float(_1213.SpecularMips - 1u);
                        float _2743 = clamp(_2155.z, 0.0, 1.0);
                        if (_1213.LodMapping == 1u)
                        {
                            _3596 = (_2743 * (2.0 - _2743)) * _2741;
                            break;
                        }
                        if (_1213.LodMapping == 2u)
                        {
                            _3596 = pow(_2743, _1213.LodParameter) * _2741;
                            break;
                        }
                        if (_1213.LodMapping == 3u)
                        {
                            _3596 = (_2743 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2743 * _2743) * float(_1213.SpecularSize)), 0.0, _2741) : 0.0;
                            break;
                        }
                        if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                        {
                            float _2802 = float(_1213.SpecularSize);
                            _3596 = (_2743 > 0.0) ? clamp(fma((_2741 - 1.0) / log2(_2802 / _1213.LodParameter), log2((_2743 * _2743) * _2802) - log2(_2802), _2741), 0.0, _2741) : 0.0;
                            break;
                        }
                        _3596 = _2743 * _2741;
                        break;
                    } while(false);
                    float _3598;
                    do
                    {
                        float _2886 = float(_1213.SpecularMips - 1u);
                        float _2888 = clamp(_2155.z, 0.0, 1.0);
                        if (_1213.LodMapping == 1u)
                        {
                            _3598 = (_2888 * (2.0 - _2888)) * _2886;
                            break;
                        }
                        if (_1213.LodMapping == 2u)
                        {
                            _3598 = pow(_2888, _1213.LodParameter) * _2886;
                            break;
                        }
                        if (_1213.LodMapping == 3u)
                        {
                            _3598 = (_2888 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2888 * _2888) * float(_1213.SpecularSize)), 0.0, _2886) : 0.0;
                            break;
                        }
                        if (((_1213.LodMapping == 4u) && (_1213.SpecularMips >= 3u)) && (float(_1213.SpecularSize) > _1213.LodParameter))
                        {
                            float _2947 = float(_1213.SpecularSize);
                            _3598 = (_2888 > 0.0) ? clamp(fma((_2886 - 1.0) / log2(_2947 / _1213.LodParameter), log2((_2888 * _2888) * _2947) - log2(_2947), _2886), 0.0, _2886) : 0.0;
                            break;
                        }
                        _3598 = _2888 * _2886;
                        break;
                    } while(false);
                    _3605 = fma(0.5, (_1213.LightCount > 0u) ? clamp((_3596 - float(_1213.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1213.LightCount > 0u) ? clamp((_3598 - float(_1213.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                    _3604 = (textureLod(Specular_LinearClamp, normalize((_3593 * cos(_2155.w)) + (_2264 * sin(_2155.w))), _3596).xyz * 0.5) + (textureLod(Specular_LinearClamp, normalize((_3593 * cos(_2155.w)) - (_2264 * sin(_2155.w))), _3598).xyz * 0.5);
                    break;
                } while(false);
                vec2 _2099 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_1779, 0.0, 1.0), _1790.w), 0.0).xy);
                vec3 _1674 = mix(vec3(0.039999999105930328369140625), Spheres_1._data[_1802].xyz, vec3(_1791.x));
                vec2 _2993 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_1779, 0.0, 1.0), _1790.w), 0.0).xy);
                vec3 _3016 = (_1674 * _2993.x) + vec3(_2993.y);
                vec3 _3611;
                _3611 = fma(_3604, (mix(vec3(0.039999999105930328369140625), Spheres_1._data[_1802].xyz, vec3(_1791.x)) * _2099.x) + vec3(_2099.y), (textureLod(IrradianceMap_LinearClamp, _1782, 0.0).xyz * Spheres_1._data[_1802].xyz) * (1.0 - _1791.x));
                vec3 _1716;
                for (uint _3606 = 0u; _3606 < _1213.LightCount; _3611 = _1716, _3606++)
                {
                    vec3 _1696 = Spheres_1._data[_1802].xyz * (1.0 - _1791.x);
                    uint _1698 = 2u * _3606;
                    uint _1701 = (2u * _3606) + 1u;
                    vec4 _1604 = Lights_1._data[_1698];
                    vec4 _1605 = Lights_1._data[_1701];
                    vec3 _3017 = Lights_1._data[_1698].xyz;
                    vec3 _3055 = normalize(cross(mix(vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), bvec3(abs(_3017.z) < 0.999000012874603271484375)), Lights_1._data[_1698].xyz));
                    vec3 _3058 = cross(Lights_1._data[_1698].xyz, _3055);
                    float _3061 = tan(_1604.w);
                    vec3 _3608;
                    vec3 _3609;
                    _3609 = vec3(0.0);
                    _3608 = vec3(0.0);
                    vec3 _3626;
                    vec3 _3627;
                    for (uint _3607 = 0u; _3607 < 19u; _3609 = _3627, _3608 = _3626, _3607++)
                    {
                        vec2 _3613;
                        do
                        {
                            if (_3607 == 0u)
                            {
                                _3613 = vec2(0.0);
                                break;
                            }
                            bool _3165 = _3607 <= 6u;
                            float _3182 = _3165 ? (float(_3607 - 1u) * 1.0471975803375244140625) : ((float(_3607 - 7u) + 0.5) * 0.52359879016876220703125);
                            _3613 = vec2(cos(_3182), sin(_3182)) * (_3165 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                            break;
                        } while(false);
                        vec2 _3025 = _3613 * _3061;
                        vec3 _3082 = normalize((Lights_1._data[_1698].xyz + (_3055 * _3025.x)) + (_3058 * _3025.y));
                        float _3085 = dot(_1782, _3082);
                        if (_3085 <= 0.0)
                        {
                            _3627 = _3609;
                            _3626 = _3608;
                            continue;
                        }
                        vec3 _3614;
                        do
                        {
                            float _3212 = dot(_1782, _3082);
                            float _3216 = clamp(_1779, 0.0, 1.0);
                            if ((_3212 <= 0.0) || (_3216 <= 0.0))
                            {
                                _3614 = vec3(0.0);
                                break;
                            }
                            vec3 _3227 = normalize(_3082 + vec3(0.0, 0.0, 1.0));
                            float _3301 = _1790.w * _1790.w;
                            float _3322 = _1790.w * _1790.w;
                            float _3244 = clamp(dot(_1782, _3227), 0.0, 1.0);
                            float _3343 = _1790.w * _1790.w;
                            float _3355 = fma(_3244 * _3244, fma(_3343, _3343, -1.0), 1.0);
                            _3614 = (_1674 + ((vec3(1.0) - _1674) * pow(clamp(1.0 - clamp(_3227.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_3212 / fma(_3212, fma(-_3301, 0.5, 1.0), _3301 * 0.5)) * (_3216 / fma(_3216, fma(-_3322, 0.5, 1.0), _3322 * 0.5))) * ((_3343 * _3343) / ((3.1415927410125732421875 * _3355) * _3355))) / (4.0 * _3216));
                            break;
                        } while(false);
                        _3627 = _3609 + (_1696 * (_3085 * 0.3183098733425140380859375));
                        _3626 = _3608 + _3614;
                    }
                    float _3117 = clamp((((2.0 * _1790.w) * _1790.w) / max(_1604.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                    vec4 _3041 = Lights_1._data[_1698];
                    float _3383 = 0.5 * _3041.w;
                    float _3385 = 0.5 * acos(clamp(dot(reflect(vec3(-0.0, -0.0, -1.0), _1782), Lights_1._data[_1698].xyz), -1.0, 1.0));
                    float _3389 = max(_1790.w * _1790.w, 1.0000000116860974230803549289703e-07);
                    float _3403 = (_3383 * _3383) / (_3389 * _3389);
                    float _3410 = (_3385 * _3385) / (_3389 * _3389);
                    float _3414 = (_3403 + 1.0) - _3410;
                    _1716 = _3611 + ((((mix(mix(vec3(0.0), (_3016 * clamp(0.5 + (((_3403 - 1.0) - _3410) / (2.0 * sqrt(fma(_3414, _3414, 4.0 * _3410)))), 0.0, 1.0)) / vec3(_1605.w), bvec3(_3117 < 1.0)), _3608 * 0.052631579339504241943359375, vec3(_3117)) * _3605) + (_3609 * 0.052631579339504241943359375)) * Lights_1._data[_1701].xyz) * _1605.w);
                }
                _3625 = _3611;
            }
            else
            {
                _3625 = vec3(0.0);
            }
            _3624 = _3625;
        }
        imageStore(SplitSum, ivec2(gl_GlobalInvocationID.xy), vec4(_3624, float(_1771)));
        break;
    } while(false);
}

