#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

int _843;

layout(binding = 0, std140) uniform IrradianceParameter
{
    uint SourceMip;
} _222;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Irradiance;
layout(binding = 0) uniform sampler2DArray Source;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _382 = uvec3(0u);
        uvec3 _383 = uvec3(imageSize(Irradiance));
        _382.x = _383.x;
        _382.y = _383.y;
        _382.z = _383.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _382)))
        {
            break;
        }
        uvec3 _388 = uvec3(textureSize(Source, int(_222.SourceMip)));
        vec2 _391 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_382.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _792;
        if (param.z == 0u)
        {
            _792 = vec3(1.0, _391.y, -_391.x);
        }
        else
        {
            vec3 _793;
            if (param.z == 1u)
            {
                _793 = vec3(-1.0, _391.y, _391.x);
            }
            else
            {
                vec3 _794;
                if (param.z == 2u)
                {
                    _794 = vec3(_391.x, 1.0, -_391.y);
                }
                else
                {
                    vec3 _795;
                    if (param.z == 3u)
                    {
                        _795 = vec3(_391.x, -1.0, _391.y);
                    }
                    else
                    {
                        vec3 _796;
                        if (param.z == 4u)
                        {
                            _796 = vec3(_391.x, _391.y, 1.0);
                        }
                        else
                        {
                            _796 = vec3(-_391.x, _391.y, -1.0);
                        }
                        _795 = _796;
                    }
                    _794 = _795;
                }
                _793 = _794;
            }
            _792 = _793;
        }
        vec3 _609 = normalize(_792);
        vec3 _798;
        _798 = vec3(0.0);
        vec3 _826;
        for (uint _797 = 0u; _797 < 6u; _798 = _826, _797++)
        {
            _826 = _798;
            vec3 _825;
            for (uint _799 = 0u; _799 < _388.y; _799++, _826 = _825)
            {
                _825 = _826;
                vec3 _834;
                for (uint _801 = 0u; _801 < _388.x; _825 = _834, _801++)
                {
                    vec2 _398 = (((vec2(float(_801), float(_799)) + vec2(0.5)) / vec2(float(_388.x))) - vec2(0.5)) * vec2(2.0, -2.0);
                    vec3 _804;
                    if (_797 == 0u)
                    {
                        _804 = vec3(1.0, _398.y, -_398.x);
                    }
                    else
                    {
                        vec3 _805;
                        if (_797 == 1u)
                        {
                            _805 = vec3(-1.0, _398.y, _398.x);
                        }
                        else
                        {
                            vec3 _806;
                            if (_797 == 2u)
                            {
                                _806 = vec3(_398.x, 1.0, -_398.y);
                            }
                            else
                            {
                                vec3 _807;
                                if (_797 == 3u)
                                {
                                    _807 = vec3(_398.x, -1.0, _398.y);
                                }
                                else
                                {
                                    vec3 _808;
                                    if (_797 == 4u)
                                    {
                                        _808 = vec3(_398.x, _398.y, 1.0);
                                    }
                                    else
                                    {
                                        _808 = vec3(-_398.x, _398.y, -1.0);
                                    }
                                    _807 = _808;
                                }
                                _806 = _807;
                            }
                            _805 = _806;
                        }
                        _804 = _805;
                    }
                    float _479 = dot(_609, normalize(_804));
                    if (_479 > 0.0)
                    {
                        uvec2 _401 = uvec2(_801, _799);
                        float _693 = float(_388.x);
                        float _694 = 1.0 / _693;
                        float _701 = fma(2.0 * float(_401.x), _694, -1.0);
                        float _708 = fma(2.0 * float(_401.y), _694, -1.0);
                        float _712 = _701 + (2.0 / _693);
                        float _716 = _708 + (2.0 / _693);
                        _834 = _825 + (texelFetch(Source, ivec4(int(_801), int(_799), int(_797), _843).xyz, int(_222.SourceMip)).xyz * (_479 * (((atan(_701 * _708, sqrt(fma(_701, _701, _708 * _708) + 1.0)) - atan(_701 * _716, sqrt(fma(_701, _701, _716 * _716) + 1.0))) - atan(_712 * _708, sqrt(fma(_712, _712, _708 * _708) + 1.0))) + atan(_712 * _716, sqrt(fma(_712, _712, _716 * _716) + 1.0)))));
                    }
                    else
                    {
                        _834 = _825;
                    }
                }
            }
        }
        imageStore(Irradiance, ivec3(gl_GlobalInvocationID), vec4(_798 * vec3(0.3183098733425140380859375), 1.0));
        break;
    } while(false);
}

