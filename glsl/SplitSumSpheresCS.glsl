#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

float _5119;

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
    uint GlassTransmission;
    float GlassRoughnessScale;
} _1830;

layout(binding = 1, std430) readonly buffer Lights
{
    vec4 _data[];
} Lights_1;

layout(binding = 0, rgba32f) uniform writeonly image2D SplitSum;
layout(binding = 7) uniform sampler2D SphereTransmissionTable;
layout(binding = 6) uniform sampler2D SphereTransmissionTable_LinearClamp;
layout(binding = 5) uniform sampler2D TransmissionTable;
layout(binding = 4) uniform sampler2D TransmissionTable_LinearClamp;
layout(binding = 0) uniform samplerCube Specular_LinearClamp;
layout(binding = 3) uniform sampler2D LobeTable_LinearClamp;
layout(binding = 2) uniform sampler2D BrdfLut_LinearClamp;
layout(binding = 1) uniform samplerCube IrradianceMap_LinearClamp;

void main()
{
    do
    {
        uvec2 _2181 = uvec2(0u);
        uvec2 _2182 = uvec2(imageSize(SplitSum));
        _2181.x = _2182.x;
        _2181.y = _2182.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _2181)))
        {
            break;
        }
        vec2 _2356 = (((vec2(gl_GlobalInvocationID.xy % uvec2(_1830.CellSize)) + vec2(0.5)) / vec2(float(_1830.CellSize))) * 2.0) - vec2(1.0);
        _2356.y = -_2356.y;
        float _2387 = dot(_2356, _2356);
        bool _2390 = (_2387 * 1.2345678806304931640625) < 1.0;
        float _2398 = sqrt(max(fma(-_2387, 1.2345678806304931640625, 1.0), 0.0));
        vec3 _2401 = vec3(_2356 * vec2(1.111111164093017578125), _2398);
        uvec2 _2359 = gl_GlobalInvocationID.xy / uvec2(_1830.CellSize);
        uint _2421 = 2u * ((_2359.y * _1830.Columns) + _2359.x);
        vec4 _2409 = Spheres_1._data[_2421];
        vec4 _2410 = Spheres_1._data[_2421 + 1u];
        vec3 _5084;
        if (_2390 && (_2410.y > 0.0))
        {
            float _5078;
            float _5079;
            vec3 _5080;
            do
            {
                if (_1830.GlassTransmission == 2u)
                {
                    float _2572 = clamp(_2398, 0.0, 1.0);
                    uvec2 _2618 = uvec2(textureSize(SphereTransmissionTable, 0));
                    float _2668 = float(_2618.y / _2618.x);
                    float _2674 = clamp((_2410.z - 1.10000002384185791015625) * 5.0, 0.0, _2668 - 1.0);
                    float _2676 = floor(_2674);
                    float _2679 = 0.5 / float(_2618.x);
                    float _2684 = clamp(_2409.w, _2679, 1.0 - _2679);
                    vec3 _2558 = mix(textureLod(SphereTransmissionTable_LinearClamp, vec2(_2572, (_2676 + _2684) / _2668), 0.0).xyz, textureLod(SphereTransmissionTable_LinearClamp, vec2(_2572, (min(_2676 + 1.0, _2668 - 1.0) + _2684) / _2668), 0.0).xyz, vec3(_2674 - _2676));
                    vec3 _2583 = _2401 - (vec3(0.0, 0.0, 1.0) * _2572);
                    float _2586 = dot(_2583, _2583);
                    _5080 = normalize((vec3(0.0, 0.0, 1.0) * (-cos(_2558.y))) + (mix(vec3(0.0), _2583 * inversesqrt(_2586), bvec3(_2586 > 9.9999999600419720025001879548654e-13)) * sin(_2558.y)));
                    _5079 = _2558.z;
                    _5078 = _2558.x;
                    break;
                }
                float _2765;
                float _5075;
                vec3 _5077;
                do
                {
                    float _2739 = (1.0 - _2410.z) / (1.0 + _2410.z);
                    vec3 _2748 = refract(vec3(-0.0, -0.0, -1.0), _2401, 1.0 / _2410.z);
                    vec3 _2757 = normalize(_2401 - (_2748 * (2.0 * dot(_2401, _2748))));
                    vec3 _2762 = refract(_2748, -_2757, _2410.z);
                    _2765 = _2409.w * _1830.GlassRoughnessScale;
                    if (dot(_2762, _2762) == 0.0)
                    {
                        _5077 = vec3(-0.0, -0.0, -1.0);
                        _5075 = 0.0;
                        break;
                    }
                    float _5073;
                    if (_1830.GlassTransmission == 1u)
                    {
                        float _2786 = clamp(_2398, 0.0, 1.0);
                        uvec2 _2823 = uvec2(textureSize(TransmissionTable, 0));
                        float _2877 = float(_2823.y / _2823.x);
                        float _2883 = clamp((_2410.z - 1.10000002384185791015625) * 5.0, 0.0, _2877 - 1.0);
                        float _2885 = floor(_2883);
                        float _2888 = 0.5 / float(_2823.x);
                        float _2893 = clamp(_2409.w, _2888, 1.0 - _2888);
                        float _2795 = dot(_2757, _2748);
                        uvec2 _2921 = uvec2(textureSize(TransmissionTable, 0));
                        float _2975 = float(_2921.y / _2921.x);
                        float _2981 = clamp((_2410.z - 1.10000002384185791015625) * 5.0, 0.0, _2975 - 1.0);
                        float _2983 = floor(_2981);
                        float _2986 = 0.5 / float(_2921.x);
                        float _2991 = clamp(_2409.w, _2986, 1.0 - _2986);
                        _5073 = mix(vec2(textureLod(TransmissionTable_LinearClamp, vec2(_2786, (_2885 + _2893) / _2877), 0.0).x, _5119), vec2(textureLod(TransmissionTable_LinearClamp, vec2(_2786, (min(_2885 + 1.0, _2877 - 1.0) + _2893) / _2877), 0.0).x, _5119), vec2(_2883 - _2885)).x * mix(vec2(_5119, textureLod(TransmissionTable_LinearClamp, vec2(_2795, (_2983 + _2991) / _2975), 0.0).y), vec2(_5119, textureLod(TransmissionTable_LinearClamp, vec2(_2795, (min(_2983 + 1.0, _2975 - 1.0) + _2991) / _2975), 0.0).y), vec2(_2981 - _2983)).y;
                    }
                    else
                    {
                        _5073 = (1.0 - fma(_2739, _2739, fma(-_2739, _2739, 1.0) * pow(1.0 - clamp(_2398, 0.0, 1.0), 5.0))) * (1.0 - fma(_2739, _2739, fma(-_2739, _2739, 1.0) * pow(1.0 - clamp(dot(_2757, _2762), 0.0, 1.0), 5.0)));
                    }
                    _5077 = _2762;
                    _5075 = _5073;
                    break;
                } while(false);
                _5080 = _5077;
                _5079 = _2765;
                _5078 = _5075;
                break;
            } while(false);
            float _5081;
            do
            {
                float _3122 = float(_1830.SpecularMips - 1u);
                float _3124 = clamp(_5079, 0.0, 1.0);
                if (_1830.LodMapping == 1u)
                {
                    _5081 = (_3124 * (2.0 - _3124)) * _3122;
                    break;
                }
                if (_1830.LodMapping == 2u)
                {
                    _5081 = pow(_3124, _1830.LodParameter) * _3122;
                    break;
                }
                if (_1830.LodMapping == 3u)
                {
                    _5081 = (_3124 > 0.0) ? clamp(0.800000011920928955078125 * log2((_3124 * _3124) * float(_1830.SpecularSize)), 0.0, _3122) : 0.0;
                    break;
                }
                if (((_1830.LodMapping == 4u) && (_1830.SpecularMips >= 3u)) && (float(_1830.SpecularSize) > _1830.LodParameter))
                {
                    float _3183 = float(_1830.SpecularSize);
                    _5081 = (_3124 > 0.0) ? clamp(fma((_3122 - 1.0) / log2(_3183 / _1830.LodParameter), log2((_3124 * _3124) * _3183) - log2(_3183), _3122), 0.0, _3122) : 0.0;
                    break;
                }
                _5081 = _3124 * _3122;
                break;
            } while(false);
            float _3228 = (_1830.LightCount > 0u) ? clamp((_5081 - float(_1830.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
            vec3 _5083;
            _5083 = textureLod(Specular_LinearClamp, _5080, _5081).xyz;
            vec3 _2507;
            for (uint _5082 = 0u; _5082 < _1830.LightCount; _5083 = _2507, _5082++)
            {
                uint _2495 = 2u * _5082;
                float _3240 = max(_5079 * _5079, 1.0000000116860974230803549289703e-07);
                vec4 _3232 = Lights_1._data[_2495];
                float _3268 = tan(min(0.5 * acos(clamp(dot(_5080, Lights_1._data[_2495].xyz), -1.0, 1.0)), 1.5));
                float _3278 = (0.5 * _3232.w) * pow(fma(_3268, _3268, 1.0), 0.75);
                float _3293 = (_3278 * _3278) / (_3240 * _3240);
                float _3300 = (_3268 * _3268) / (_3240 * _3240);
                float _3304 = (_3293 + 1.0) - _3300;
                _2507 = _5083 + ((Lights_1._data[(2u * _5082) + 1u].xyz * _3228) * clamp(0.5 + (((_3293 - 1.0) - _3300) / (2.0 * sqrt(fma(_3304, _3304, 4.0 * _3300)))), 0.0, 1.0));
            }
            _5084 = _5083 * _5078;
        }
        else
        {
            vec3 _5085;
            if (_2390)
            {
                vec3 _5054;
                float _5055;
                do
                {
                    vec3 _3488 = reflect(vec3(-0.0, -0.0, -1.0), _2401);
                    vec4 _3434 = textureLod(LobeTable_LinearClamp, vec2(clamp(_2398, 0.0, 1.0), _2409.w), 0.0);
                    vec3 _5043;
                    do
                    {
                        float _3610 = _2409.w * _2409.w;
                        if (_1830.Direction == 1u)
                        {
                            float _3616 = clamp(fma(-_2409.w, _2409.w, 1.0), 0.0, 1.0);
                            _5043 = normalize(mix(_2401, _3488, vec3(_3616 * fma(_2409.w, _2409.w, sqrt(_3616)))));
                            break;
                        }
                        if (_1830.Direction == 2u)
                        {
                            _5043 = normalize(mix(_3488, _2401, vec3(_3610 * _3610)));
                            break;
                        }
                        if (_1830.Direction == 3u)
                        {
                            vec3 _5042;
                            do
                            {
                                float _3665 = acos(clamp(dot(_2401, _3488), -1.0, 1.0));
                                if (_3665 < 9.9999997473787516355514526367188e-05)
                                {
                                    _5042 = _3488;
                                    break;
                                }
                                _5042 = ((_2401 * sin((1.0 - _3434.x) * _3665)) + (_3488 * sin(_3434.x * _3665))) / vec3(sin(_3665));
                                break;
                            } while(false);
                            _5043 = _5042;
                            break;
                        }
                        _5043 = _3488;
                        break;
                    } while(false);
                    if (_1830.Lookup == 0u)
                    {
                        float _5052;
                        do
                        {
                            float _3730 = float(_1830.SpecularMips - 1u);
                            float _3732 = clamp(_2409.w, 0.0, 1.0);
                            if (_1830.LodMapping == 1u)
                            {
                                _5052 = (_3732 * (2.0 - _3732)) * _3730;
                                break;
                            }
                            if (_1830.LodMapping == 2u)
                            {
                                _5052 = pow(_3732, _1830.LodParameter) * _3730;
                                break;
                            }
                            if (_1830.LodMapping == 3u)
                            {
                                _5052 = (_3732 > 0.0) ? clamp(0.800000011920928955078125 * log2((_3732 * _3732) * float(_1830.SpecularSize)), 0.0, _3730) : 0.0;
                                break;
                            }
                            if (((_1830.LodMapping == 4u) && (_1830.SpecularMips >= 3u)) && (float(_1830.SpecularSize) > _1830.LodParameter))
                            {
                                float _3791 = float(_1830.SpecularSize);
                                _5052 = (_3732 > 0.0) ? clamp(fma((_3730 - 1.0) / log2(_3791 / _1830.LodParameter), log2((_3732 * _3732) * _3791) - log2(_3791), _3730), 0.0, _3730) : 0.0;
                                break;
                            }
                            _5052 = _3732 * _3730;
                            break;
                        } while(false);
                        _5055 = (_1830.LightCount > 0u) ? clamp((_5052 - float(_1830.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _5054 = textureLod(Specular_LinearClamp, _5043, _5052).xyz * 1.0;
                        break;
                    }
                    if (_1830.Lookup == 1u)
                    {
                        float _5050;
                        do
                        {
                            float _3875 = float(_1830.SpecularMips - 1u);
                            float _3877 = clamp(_3434.y, 0.0, 1.0);
                            if (_1830.LodMapping == 1u)
                            {
                                _5050 = (_3877 * (2.0 - _3877)) * _3875;
                                break;
                            }
                            if (_1830.LodMapping == 2u)
                            {
                                _5050 = pow(_3877, _1830.LodParameter) * _3875;
                                break;
                            }
                            if (_1830.LodMapping == 3u)
                            {
                                _5050 = (_3877 > 0.0) ? clamp(0.800000011920928955078125 * log2((_3877 * _3877) * float(_1830.SpecularSize)), 0.0, _3875) : 0.0;
                                break;
                            }
                            if (((_1830.LodMapping == 4u) && (_1830.SpecularMips >= 3u)) && (float(_1830.SpecularSize) > _1830.LodParameter))
                            {
                                float _3936 = float(_1830.SpecularSize);
                                _5050 = (_3877 > 0.0) ? clamp(fma((_3875 - 1.0) / log2(_3936 / _1830.LodParameter), log2((_3877 * _3877) * _3936) - log2(_3936), _3875), 0.0, _3875) : 0.0;
                                break;
                            }
                            _5050 = _3877 * _3875;
                            break;
                        } while(false);
                        _5055 = (_1830.LightCount > 0u) ? clamp((_5050 - float(_1830.LightLevel)) + 1.0, 0.0, 1.0) : 0.0;
                        _5054 = textureLod(Specular_LinearClamp, _5043, _5050).xyz * 1.0;
                        break;
                    }
                    vec3 _3531 = cross(_2401, vec3(0.0, 0.0, 1.0));
                    float _3533 = length(_3531);
                    vec3 _3543 = mix(vec3(0.0), cross(_3531 / vec3(_3533), _5043), bvec3(_3533 > 9.9999999747524270787835121154785e-07));
                    float _5046;
                    do
                    {
                        float _4020 = float(_1830.SpecularMips - 1u);
                        float _4022 = clamp(_3434.z, 0.0, 1.0);
                        if (_1830.LodMapping == 1u)
                        {
                            _5046 = (_4022 * (2.0 - _4022)) * _4020;
                            break;
                        }
                        if (_1830.LodMapping == 2u)
                        {
                            _5046 = pow(_4022, _1830.LodParameter) * _4020;
                            break;
                        }
                        if (_1830.LodMapping == 3u)
                        {
                            _5046 = (_4022 > 0.0) ? clamp(0.800000011920928955078125 * log2((_4022 * _4022) * float(_1830.SpecularSize)), 0.0, _4020) : 0.0;
                            break;
                        }
                        if (((_1830.LodMapping == 4u) && (_1830.SpecularMips >= 3u)) && (float(_1830.SpecularSize) > _1830.LodParameter))
                        {
                            float _4081 = float(_1830.SpecularSize);
                            _5046 = (_4022 > 0.0) ? clamp(fma((_4020 - 1.0) / log2(_4081 / _1830.LodParameter), log2((_4022 * _4022) * _4081) - log2(_4081), _4020), 0.0, _4020) : 0.0;
                            break;
                        }
                        _5046 = _4022 * _4020;
                        break;
                    } while(false);
                    float _5048;
                    do
                    {
                        float _4165 = float(_1830.SpecularMips - 1u);
                        float _4167 = clamp(_3434.z, 0.0, 1.0);
                        if (_1830.LodMapping == 1u)
                        {
                            _5048 = (_4167 * (2.0 - _4167)) * _4165;
                            break;
                        }
                        if (_1830.LodMapping == 2u)
                        {
                            _5048 = pow(_4167, _1830.LodParameter) * _4165;
                            break;
                        }
                        if (_1830.LodMapping == 3u)
                        {
                            _5048 = (_4167 > 0.0) ? clamp(0.800000011920928955078125 * log2((_4167 * _4167) * float(_1830.SpecularSize)), 0.0, _4165) : 0.0;
                            break;
                        }
                        if (((_1830.LodMapping == 4u) && (_1830.SpecularMips >= 3u)) && (float(_1830.SpecularSize) > _1830.LodParameter))
                        {
                            float _4226 = float(_1830.SpecularSize);
                            _5048 = (_4167 > 0.0) ? clamp(fma((_4165 - 1.0) / log2(_4226 / _1830.LodParameter), log2((_4167 * _4167) * _4226) - log2(_4226), _4165), 0.0, _4165) : 0.0;
                            break;
                        }
                        _5048 = _4167 * _4165;
                        break;
                    } while(false);
                    _5055 = fma(0.5, (_1830.LightCount > 0u) ? clamp((_5046 - float(_1830.LightLevel)) + 1.0, 0.0, 1.0) : 0.0, 0.5 * ((_1830.LightCount > 0u) ? clamp((_5048 - float(_1830.LightLevel)) + 1.0, 0.0, 1.0) : 0.0));
                    _5054 = (textureLod(Specular_LinearClamp, normalize((_5043 * cos(_3434.w)) + (_3543 * sin(_3434.w))), _5046).xyz * 0.5) + (textureLod(Specular_LinearClamp, normalize((_5043 * cos(_3434.w)) - (_3543 * sin(_3434.w))), _5048).xyz * 0.5);
                    break;
                } while(false);
                vec2 _3378 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_2398, 0.0, 1.0), _2409.w), 0.0).xy);
                vec3 _2293 = mix(vec3(0.039999999105930328369140625), Spheres_1._data[_2421].xyz, vec3(_2410.x));
                vec2 _4272 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_2398, 0.0, 1.0), _2409.w), 0.0).xy);
                vec3 _4295 = (_2293 * _4272.x) + vec3(_4272.y);
                vec3 _5063;
                _5063 = fma(_5054, (mix(vec3(0.039999999105930328369140625), Spheres_1._data[_2421].xyz, vec3(_2410.x)) * _3378.x) + vec3(_3378.y), (textureLod(IrradianceMap_LinearClamp, _2401, 0.0).xyz * Spheres_1._data[_2421].xyz) * (1.0 - _2410.x));
                vec3 _2335;
                for (uint _5056 = 0u; _5056 < _1830.LightCount; _5063 = _2335, _5056++)
                {
                    uint _2317 = 2u * _5056;
                    uint _2320 = (2u * _5056) + 1u;
                    vec4 _2223 = Lights_1._data[_2317];
                    vec4 _2224 = Lights_1._data[_2320];
                    vec3 _4296 = Lights_1._data[_2317].xyz;
                    vec3 _4336 = normalize(cross(mix(vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), bvec3(abs(_4296.z) < 0.999000012874603271484375)), Lights_1._data[_2317].xyz));
                    vec3 _4339 = cross(Lights_1._data[_2317].xyz, _4336);
                    float _4342 = tan(_2223.w);
                    vec3 _5058;
                    _5058 = vec3(0.0);
                    vec3 _5086;
                    for (uint _5057 = 0u; _5057 < 19u; _5058 = _5086, _5057++)
                    {
                        vec2 _5066;
                        do
                        {
                            if (_5057 == 0u)
                            {
                                _5066 = vec2(0.0);
                                break;
                            }
                            bool _4450 = _5057 <= 6u;
                            float _4467 = _4450 ? (float(_5057 - 1u) * 1.0471975803375244140625) : ((float(_5057 - 7u) + 0.5) * 0.52359879016876220703125);
                            _5066 = vec2(cos(_4467), sin(_4467)) * (_4450 ? 0.4588314592838287353515625 : 0.827170193195343017578125);
                            break;
                        } while(false);
                        vec2 _4303 = _5066 * _4342;
                        vec3 _4363 = normalize((Lights_1._data[_2317].xyz + (_4336 * _4303.x)) + (_4339 * _4303.y));
                        if (dot(_2401, _4363) > 0.0)
                        {
                            vec3 _5067;
                            do
                            {
                                float _4497 = dot(_2401, _4363);
                                float _4501 = clamp(_2398, 0.0, 1.0);
                                if ((_4497 <= 0.0) || (_4501 <= 0.0))
                                {
                                    _5067 = vec3(0.0);
                                    break;
                                }
                                vec3 _4512 = normalize(_4363 + vec3(0.0, 0.0, 1.0));
                                float _4586 = _2409.w * _2409.w;
                                float _4607 = _2409.w * _2409.w;
                                float _4529 = clamp(dot(_2401, _4512), 0.0, 1.0);
                                float _4628 = _2409.w * _2409.w;
                                float _4640 = fma(_4529 * _4529, fma(_4628, _4628, -1.0), 1.0);
                                _5067 = (_2293 + ((vec3(1.0) - _2293) * pow(clamp(1.0 - clamp(_4512.z, 0.0, 1.0), 0.0, 1.0), 5.0))) * ((((_4497 / fma(_4497, fma(-_4586, 0.5, 1.0), _4586 * 0.5)) * (_4501 / fma(_4501, fma(-_4607, 0.5, 1.0), _4607 * 0.5))) * ((_4628 * _4628) / ((3.1415927410125732421875 * _4640) * _4640))) / (4.0 * _4501));
                                break;
                            } while(false);
                            _5086 = _5058 + _5067;
                        }
                        else
                        {
                            _5086 = _5058;
                        }
                    }
                    float _4391 = clamp((((2.0 * _2409.w) * _2409.w) / max(_2223.w, 9.9999999747524270787835121154785e-07)) - 1.0, 0.0, 1.0);
                    vec4 _4318 = Lights_1._data[_2317];
                    float _4668 = 0.5 * _4318.w;
                    float _4670 = 0.5 * acos(clamp(dot(reflect(vec3(-0.0, -0.0, -1.0), _2401), Lights_1._data[_2317].xyz), -1.0, 1.0));
                    float _4674 = max(_2409.w * _2409.w, 1.0000000116860974230803549289703e-07);
                    float _4688 = (_4668 * _4668) / (_4674 * _4674);
                    float _4695 = (_4670 * _4670) / (_4674 * _4674);
                    float _4699 = (_4688 + 1.0) - _4695;
                    float _4415 = sin(_2223.w);
                    float _4419 = dot(_2401, Lights_1._data[_2317].xyz);
                    float _4422 = _4415 * _4415;
                    float _5059;
                    do
                    {
                        if (((_4419 * _4419) > _4422) || (_4422 <= 0.0))
                        {
                            _5059 = (3.1415927410125732421875 * _4422) * clamp(_4419, 0.0, 1.0);
                            break;
                        }
                        float _4744 = sqrt(clamp(fma(-_4419, _4419, 1.0), 0.0, 1.0));
                        float _4748 = sqrt((1.0 / _4422) - 1.0);
                        float _4754 = (-_4748) * (_4419 / _4744);
                        float _4762 = _4744 * sqrt(clamp(fma(-_4754, _4754, 1.0), 0.0, 1.0));
                        _5059 = max(fma(fma(_4419, acos(clamp(_4754, -1.0, 1.0)), -(_4748 * _4762)), _4422, atan(_4762 / _4748)), 0.0);
                        break;
                    } while(false);
                    _2335 = fma(((mix(mix(vec3(0.0), (_4295 * clamp(0.5 + (((_4688 - 1.0) - _4695) / (2.0 * sqrt(fma(_4699, _4699, 4.0 * _4695)))), 0.0, 1.0)) / vec3(_2224.w), bvec3(_4391 < 1.0)), _5058 * 0.052631579339504241943359375, vec3(_4391)) * _5055) * _2224.w) + ((Spheres_1._data[_2421].xyz * (1.0 - _2410.x)) * (_5059 * 0.3183098733425140380859375)), Lights_1._data[_2320].xyz, _5063);
                }
                _5085 = _5063;
            }
            else
            {
                _5085 = vec3(0.0);
            }
            _5084 = _5085;
        }
        imageStore(SplitSum, ivec2(gl_GlobalInvocationID.xy), vec4(_5084, float(_2390)));
        break;
    } while(false);
}

