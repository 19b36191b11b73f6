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
} _1243;

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
        uvec2 _1592 = uvec2(0u);
        uvec2 _1593 = uvec2(imageSize(SplitSum));
        _1592.x = _1593.x;
        _1592.y = _1593.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _1592)))
        {
            break;
        }
        vec2 _1767 = (((vec2(gl_GlobalInvocationID.xy % uvec2(_1243.CellSize)) + vec2(0.5)) / vec2(float(_1243.CellSize))) * 2.0) - vec2(1.0);
        _1767.y = -_1767.y;
        float _1798 = dot(_1767, _1767);
        bool _1801 = (_1798 * 1.2345678806304931640625) < 1.0;
        float _1809 = sqrt(max(fma(-_1798, 1.2345678806304931640625, 1.0), 0.0));
        vec3 _1812 = vec3(_1767 * vec2(1.111111164093017578125), _1809);
        uvec2 _1770 = gl_GlobalInvocationID.xy / uvec2(_1243.CellSize);
        uint _1832 = 2u * ((_1770.y * _1243.Columns) + _1770.x);
        vec4 _1820 = Spheres_1._data[_1832];
        vec4 _1821 = Spheres_1._data[_1832 + 1u];
        vec3 _3692;
        if (_1801 && (_1821.y > 0.0))
        {
            vec3 _3691;
            do
            {
                float _1877 = (1.0 - _1821.z) / (1.0 + _1821.z);
                vec3 _1886 = refract(vec3(-0.0, -0.0, -1.0), _1812, 1.0 / _1821.z);
                vec3 _1895 = normalize(_1812 - (_1886 * (2.0 * dot(_1812, _1886))));
                vec3 _1900 = refract(_1886, -_1895, _1821.z);
                if (dot(_1900, _1900) == 0.0)
                {
                    _3691 = vec3(0.0);
                    break;
                }
                float _3690;
                do
                {
                    float _2015 = float(_1243.SpecularMips - 1u);
                    float _2017 = clamp(_1820.w, 0.0, 1.0);
                    if (_1243.LodMapping == 1u)
                    {
                        _3690 = (_2017 * (2.0 - _2017)) * _2015;
                        break;
                    }
                    if (_1243.LodMapping == 2u)
                    {
                        _3690 = pow(_2017, _1243.LodParameter) * _2015;
                        break;
                    }
                    if (_1243.LodMapping == 3u)
                    {
                        _3690 = (_2017 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2017 * _2017) * float(_1243.SpecularSize)), 0.0, _2015) : 0.0;
                        break;
                    }
                    if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                    {
                        float _2076 = float(_1243.SpecularSize);
                        _3690 = (_2017 > 0.0) ? clamp(fma((_2015 - 1.0) / log2(_2076 / _1243.LodParameter), log2((_2017 * _2017) * _2076) - log2(_2076), _2015), 0.0, _2015) : 0.0;
                        break;
                    }
                    _3690 = _2017 * _2015;
                    break;
                } while(false);
                _3691 = textureLod(Specular_LinearClamp, _1900, _3690).xyz * ((1.0 - fma(_1877, _1877, fma(-_1877, _1877, 1.0) * pow(1.0 - clamp(_1809, 0.0, 1.0), 5.0))) * (1.0 - fma(_1877, _1877, fma(-_1877, _1877, 1.0) * pow(1.0 - clamp(dot(_1895, _1900), 0.0, 1.0), 5.0))));
                break;
            } while(false);
            _3692 = _3691;
        }
        else
        {
            vec3 _3693;
            if (_1801)
            {
                vec3 _3672;
                float _3673;
                do
                {
                    vec3 _2277 = reflect(vec3(-0.0, -0.0, -1.0), _1812);
                    vec4 _2223 = textureLod(LobeTable_LinearClamp, vec2(clamp(_1809, 0.0, 1.0), _1820.w), 0.0);
                    vec3 _3661;
                    do
                    {
                        float _2399 = _1820.w * _1820.w;
                        if (_1243.Direction == 1u)
                        {
                            float _2405 = clamp(fma(-_1820.w, _1820.w, 1.0), 0.0, 1.0);
                            _3661 = normalize(mix(_1812, _2277, vec3(_2405 * fma(_1820.w, _1820.w, sqrt(_2405)))));
                            break;
                        }
                        if (_1243.Direction == 2u)
                        {
                            _3661 = normalize(mix(_2277, _1812, vec3(_2399 * _2399)));
                            break;
                        }
                        if (_1243.Direction == 3u)
                        {
                            vec3 _3660;
                            do
                            {
                                float _2454 = acos(clamp(dot(_1812, _2277), -1.0, 1.0));
                                if (_2454 < 9.9999997473787516355514526367188e-05)
                                {
                                    _3660 = _2277;
                                    break;
                                }
                                _3660 = ((_1812 * sin((1.0 - _2223.x) * _2454)) + (_2277 * sin(_2223.x * _2454))) / vec3(sin(_2454));
                                break;
                            } while(false);
                            _3661 = _3660;
                            break;
                        }
                        _3661 = _2277;
                        break;
                    } while(false);
                    if (_1243.Lookup == 0u)
                    {
                        float _3670;
                        do
                        {
                            float _2519 = float(_1243.SpecularMips - 1u);
                            float _2521 = clamp(_1820.w, 0.0, 1.0);
                            if (_1243.LodMapping == 1u)
                            {
                                _3670 = (_2521 * (2.0 - _2521)) * _2519;
                                break;
                            }
                            if (_1243.LodMapping == 2u)
                            {
                                _3670 = pow(_2521, _1243.LodParameter) * _2519;
                                break;
                            }
                            if (_1243.LodMapping == 3u)
                            {
                                _3670 = (_2521 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2521 * _2521) * float(_1243.SpecularSize)), 0.0, _2519) : 0.0;
                                break;
                            }
                            if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                            {
                                float _2580 = float(_1243.SpecularSize);
                                _3670 = (_2521 > 0.0) ? clamp(fma((_2519 - 1.0) / log2(_2580 / _1243.LodParameter), log2((_2521 * _2521) * _2580) - log2(_2580), _2519), 0.0, _2519) : 0.0;
                                break;
                            }
                            _3670 = _2521 * _2519;
                            break;
                        } while(false);
                        _3673 = (_1243.LightCount > 0u) ? clamp((_3670 - float(_1243.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3672 = textureLod(Specular_LinearClamp, _3661, _3670).xyz * 1.0;
                        break;
                    }
                    if (_1243.Lookup == 1u)
                    {
                        float _3668;
                        do
                        {
                            float _2664 = float(_1243.SpecularMips - 1u);
                            float _2666 = clamp(_2223.y, 0.0, 1.0);
                            if (_1243.LodMapping == 1u)
                            {
                                _3668 = (_2666 * (2.0 - _2666)) * _2664;
                                break;
                            }
                            if (_1243.LodMapping == 2u)
                            {
                                _3668 = pow(_2666, _1243.LodParameter) * _2664;
                                break;
                            }
                            if (_1243.LodMapping == 3u)
                            {
                                _3668 = (_2666 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2666 * _2666) * float(_1243.SpecularSize)), 0.0, _2664) : 0.0;
                                break;
                            }
                            if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                            {
                                float _2725 = float(_1243.SpecularSize);
                                _3668 = (_2666 > 0.0) ? clamp(fma((_2664 - 1.0) / log2(_2725 / _1243.LodParameter), log2((_2666 * _2666) * _2725) - log2(_2725), _2664), 0.0, _2664) : 0.0;
                                break;
                            }
                            _3668 = _2666 * _2664;
                            break;
                        } while(false);
                        _3673 = (_1243.LightCount > 0u) ? clamp((_3668 - float(_1243.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _3672 = textureLod(Specular_LinearClamp, _3661, _3668).xyz * 1.0;
                        break;
                    }
                    vec3 _2320 = cross(_1812, vec3(0.0, 0.0, 1.0));
                    float _2322 = length(_2320);
                    vec3 _2332 = mix(vec3(0.0), cross(_2320 / vec3(_2322), _3661), bvec3(_2322 > 9.9999999747524270787835121154785e-07));
                    float _3664;
                    do
                    {
                        float _2809 = float(_1243.SpecularMips - 1u);
                        float _2811 = clamp(_2223.z, 0.0, 1.0);
                        if (_1243.LodMapping == 1u)
                        {
                            _3664 = (_2811 * (2.0 - _2811)) * _2809;
                            break;
                        }
                        if (_1243.LodMapping == 2u)
                        {
                            _3664 = pow(_2811, _1243.LodParameter) * _2809;
                            break;
                        }
                        if (_1243.LodMapping == 3u)
                        {
                            _3664 = (_2811 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2811 * _2811) * float(_1243.SpecularSize)), 0.0, _2809) : 0.0;
                            break;
                        }
                        if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                        {
                            float _2870 = float(_1243.SpecularSize);
                            _3664 = (_2811 > 0.0) ? clamp(fma((_2809 - 1.0) / log2(_2870 / _1243.LodParameter), log2((_2811 * _2811) * _2870) - log2(_2870), _2809), 0.0, _2809) : 0.0;
                            break;
                        }
                        _3664 = _2811 * _2809;
                        break;
                    } while(false);
                    float _3666;
                    do
                    {
                        float _2954 = float(_1243.SpecularMips - 1u);
                        float _2956 = clamp(_2223.z, 0.0, 1.0);
                        if (_1243.LodMapping == 1u)
                        {
                            _3666 = (_2956 * (2.0 - _2956)) * _2954;
                            break;
                        }
                        if (_1243.LodMapping == 2u)
                        {
                            _3666 = pow(_2956, _1243.LodParameter) * _2954;
                            break;
                        }
                        if (_1243.LodMapping == 3u)
                        {
                            _3666 = (_2956 > 0.0) ? clamp(0.800000011920928955078125 * log2((_2956 * _2956) * float(_1243.SpecularSize)), 0.0, _2954) : 0.0;
                            break;
                        }
                        if (((_1243.LodMapping == 4u) && (_1243.SpecularMips >= 3u)) && (float(_1243.SpecularSize) > _1243.LodParameter))
                        {
                            float _3015 = float(_1243.SpecularSize);
                            _3666 = (_2956 > 0.0) ? clamp(fma((_2954 - 1.0) / log2(_3015 / _1243.LodParameter), log2((_2956 * _2956) * _3015) - log2(_3015), _2954), 0.0, _2954) : 0.0;
                            break;
                        }
                        _3666 = _2956 * _2954;
                        break;
                    } while(false);
                    _3673 = fma(0.5, (_1243.LightCount > 0u) ? clamp((_3664 - float(_1243.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1243.LightCount > 0u) ? clamp((_3666 - float(_1243.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                    _3672 = (textureLod(Specular_LinearClamp, normalize((_3661 * cos(_2223.w)) + (_2332 * sin(_2223.w))), _3664).xyz * 0.5) + (textureLod(Specular_LinearClamp, normalize((_3661 * cos(_2223.w)) - (_2332 * sin(_2223.w))), _3666).xyz * 0.5);
                    break;
                } while(false);
                vec2 _2167 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_1809, 0.0, 1.0), _1820.w), 0.0).xy);
                vec3 _1704 = mix(vec3(0.039999999105930328369140625), Spheres_1._data[_1832].xyz, vec3(_1821.x));
                vec2 _3061 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_1809, 0.0, 1.0), _1820.w), 0.0).xy);
                vec3 _3084 = (_1704 * _3061.x) + vec3(_3061.y);
                vec3 _3679;
                _3679 = fma(_3672, (mix(vec3(0.039999999105930328369140625), Spheres_1._data[_1832].xyz, vec3(_1821.x)) * _2167.x) + vec3(_2167.y), (textureLod(IrradianceMap_LinearClamp, _1812, 0.0).xyz * Spheres_1._data[_1832].xyz) * (1.0 - _1821.x));
                vec3 _1746;
                for (uint _3674 = 0u; _3674 < _1243.LightCount; _3679 = _1746, _3674++)
                {
                    vec3 _1726 = Spheres_1._data[_1832].xyz * (1.0 - _1821.x);
                    uint _1728 = 2u * _3674;
                    uint _1731 = (2u * _3674) + 1u;
                    vec4 _1634 = Lights_1._data[_1728];
                    vec4 _1635 = Lights_1._data[_1731];
                    vec3 _3085 = Lights_1._data[_1728].xyz;
                    vec3 _3123 = normalize(cross(mix(vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), bvec3(abs(_3085.z) < 0.999000012874603271484375)), Lights_1._data[_1728].xyz));
                    vec3 _3126 = cross(Lights_1._data[_1728].xyz, _3123);
                    float _3129 = tan(_1634.w);
                    vec3 _3676;
                    vec3 _3677;
                    _3677 = vec3(0.0);
                    _3676 = vec3(0.0);
                    vec3 _3694;
                    vec3 _3695;
                    for (uint _3675 = 0u; _3675 < 19u; _3677 = _3695, _3676 = _3694, _3675++)
                    {
                        vec2 _3681;
                        do
                        {
                            if (_3675 == 0u)
                            {
                                _3681 = vec2(0.0);
                                break;
                            }
                            bool _3233 = _3675 <= 6u;
                            float _3250 = _3233 ? (float(_3675 - 1u) * 1.0471975803375244140625) : ((float(_3675 - 7u) + 0.5) * 0.52359879016876220703125);
                            _3681 = vec2(cos(_3250), sin(_3250)) * (_3233 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                            break;
                        } while(false);
                        vec2 _3093 = _3681 * _3129;
                        vec3 _3150 = normalize((Lights_1._data[_1728].xyz + (_3123 * _3093.x)) + (_3126 * _3093.y));
                        float _3153 = dot(_1812, _3150);
                        if (_3153 <= 0.0)
                        {
                            _3695 = _3677;
                            _3694 = _3676;
                            continue;
                        }
                        vec3 _3682;
                        do
                        {
                            float _3280 = dot(_1812, _3150);
                            float _3284 = clamp(_1809, 0.0, 1.0);
                            if ((_3280 <= 0.0) || (_3284 <= 0.0))
                            {
                                _3682 = vec3(0.0);
                                break;
                            }
                            vec3 _3295 = normalize(_3150 + vec3(0.0, 0.0, 1.0));
                            float _3369 = _1820.w * _1820.w;
                            float _3390 = _1820.w * _1820.w;
                            float _3312 = clamp(dot(_1812, _3295), 0.0, 1.0);
                            float _3411 = _1820.w * _1820.w;
                            float _3423 = fma(_3312 * _3312, fma(_3411, _3411, -1.0), 1.0);
                            _3682 = (_1704 + ((vec3(1.0) - _1704) * pow(clamp(1.0 - clamp(_3295.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_3280 / fma(_3280, fma(-_3369, 0.5, 1.0), _3369 * 0.5)) * (_3284 / fma(_3284, fma(-_3390, 0.5, 1.0), _3390 * 0.5))) * ((_3411 * _3411) / ((3.1415927410125732421875 * _3423) * _3423))) / (4.0 * _3284));
                            break;
                        } while(false);
                        _3695 = _3677 + (_1726 * (_3153 * 0.3183098733425140380859375));
                        _3694 = _3676 + _3682;
                    }
                    float _3185 = clamp((((2.0 * _1820.w) * _1820.w) / max(_1634.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                    vec4 _3109 = Lights_1._data[_1728];
                    float _3451 = 0.5 * _3109.w;
                    float _3453 = 0.5 * acos(clamp(dot(reflect(vec3(-0.0, -0.0, -1.0), _1812), Lights_1._data[_1728].xyz), -1.0, 1.0));
                    float _3457 = max(_1820.w * _1820.w, 1.0000000116860974230803549289703e-07);
                    float _3471 = (_3451 * _3451) / (_3457 * _3457);
                    float _3478 = (_3453 * _3453) / (_3457 * _3457);
                    float _3482 = (_3471 + 1.0) - _3478;
                    _1746 = _3679 + ((((mix(mix(vec3(0.0), (_3084 * clamp(0.5 + (((_3471 - 1.0) - _3478) / (2.0 * sqrt(fma(_3482, _3482, 4.0 * _3478)))), 0.0, 1.0)) / vec3(_1635.w), bvec3(_3185 < 1.0)), _3676 * 0.052631579339504241943359375, vec3(_3185)) * _3673) + (_3677 * 0.052631579339504241943359375)) * Lights_1._data[_1731].xyz) * _1635.w);
                }
                _3693 = _3679;
            }
            else
            {
                _3693 = vec3(0.0);
            }
            _3692 = _3693;
        }
        imageStore(SplitSum, ivec2(gl_GlobalInvocationID.xy), vec4(_3692, float(_1801)));
        break;
    } while(false);
}

