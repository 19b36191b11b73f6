#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform EquirectToCubeParameter
{
    uint Supersample;
} _298;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Cube;
layout(binding = 0) uniform sampler2D Equirect;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _385 = uvec3(0u);
        uvec3 _386 = uvec3(imageSize(Cube));
        _385.x = _386.x;
        _385.y = _386.y;
        _385.z = _386.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _385)))
        {
            break;
        }
        uvec2 _387 = uvec2(0u);
        uvec2 _388 = uvec2(textureSize(Equirect, 0));
        _387.x = _388.x;
        _387.y = _388.y;
        vec3 _779;
        _779 = vec3(0.0);
        vec3 _788;
        for (uint _778 = 0u; _778 < _298.Supersample; _779 = _788, _778++)
        {
            _788 = _779;
            vec3 _469;
            for (uint _780 = 0u; _780 < _298.Supersample; _788 = _469, _780++)
            {
                vec2 _395 = (((vec2(gl_GlobalInvocationID.xy) + ((vec2(float(_780), float(_778)) + vec2(0.5)) / vec2(float(_298.Supersample)))) / vec2(_385.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _782;
                if (param.z == 0u)
                {
                    _782 = vec3(1.0, _395.y, -_395.x);
                }
                else
                {
                    vec3 _783;
                    if (param.z == 1u)
                    {
                        _783 = vec3(-1.0, _395.y, _395.x);
                    }
                    else
                    {
                        vec3 _784;
                        if (param.z == 2u)
                        {
                            _784 = vec3(_395.x, 1.0, -_395.y);
                        }
                        else
                        {
                            vec3 _785;
                            if (param.z == 3u)
                            {
                                _785 = vec3(_395.x, -1.0, _395.y);
                            }
                            else
                            {
                                vec3 _786;
                                if (param.z == 4u)
                                {
                                    _786 = vec3(_395.x, _395.y, 1.0);
                                }
                                else
                                {
                                    _786 = vec3(-_395.x, _395.y, -1.0);
                                }
                                _785 = _786;
                            }
                            _784 = _785;
                        }
                        _783 = _784;
                    }
                    _782 = _783;
                }
                ivec2 _465 = ivec2(_387);
                vec3 _563 = normalize(_782);
                vec2 _585 = fma(vec2(fma(atan(_563.x, -_563.z), 0.15915493667125701904296875, 0.5), acos(clamp(_563.y, -1.0, 1.0)) * 0.3183098733425140380859375), vec2(_465), vec2(-0.5));
                vec2 _587 = floor(_585);
                vec2 _565 = _585 - _587;
                ivec2 _592 = ivec2(_587);
                ivec2 _568 = _592;
                ivec2 _569 = _465;
                _568.x = ((_568.x % _569.x) + _569.x) % _569.x;
                _568.y = clamp(_568.y, 0, _569.y - 1);
                ivec2 _570 = _592 + ivec2(1, 0);
                ivec2 _571 = _465;
                _570.x = ((_570.x % _571.x) + _571.x) % _571.x;
                _570.y = clamp(_570.y, 0, _571.y - 1);
                ivec2 _573 = _592 + ivec2(0, 1);
                ivec2 _574 = _465;
                _573.x = ((_573.x % _574.x) + _574.x) % _574.x;
                _573.y = clamp(_573.y, 0, _574.y - 1);
                ivec2 _575 = _592 + ivec2(1);
                ivec2 _576 = _465;
                _575.x = ((_575.x % _576.x) + _576.x) % _576.x;
                _575.y = clamp(_575.y, 0, _576.y - 1);
                _469 = _788 + mix(mix(texelFetch(Equirect, ivec3(_568, 0).xy, 0).xyz, texelFetch(Equirect, ivec3(_570, 0).xy, 0).xyz, vec3(_565.x)), mix(texelFetch(Equirect, ivec3(_573, 0).xy, 0).xyz, texelFetch(Equirect, ivec3(_575, 0).xy, 0).xyz, vec3(_565.x)), vec3(_565.y));
            }
        }
        imageStore(Cube, ivec3(gl_GlobalInvocationID), vec4(_779 / vec3(float(_298.Supersample * _298.Supersample)), 1.0));
        break;
    } while(false);
}

