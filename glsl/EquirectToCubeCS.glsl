#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform EquirectToCubeParameter
{
    uint Supersample;
} _323;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Cube;
layout(binding = 0) uniform sampler2D Equirect;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _410 = uvec3(0u);
        uvec3 _411 = uvec3(imageSize(Cube));
        _410.x = _411.x;
        _410.y = _411.y;
        _410.z = _411.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _410)))
        {
            break;
        }
        uvec2 _412 = uvec2(0u);
        uvec2 _413 = uvec2(textureSize(Equirect, 0));
        _412.x = _413.x;
        _412.y = _413.y;
        vec3 _867;
        _867 = vec3(0.0);
        vec3 _876;
        for (uint _866 = 0u; _866 < _323.Supersample; _867 = _876, _866++)
        {
            _876 = _867;
            vec3 _494;
            for (uint _868 = 0u; _868 < _323.Supersample; _876 = _494, _868++)
            {
                vec2 _521 = (((vec2(gl_GlobalInvocationID.xy) + ((vec2(float(_868), float(_866)) + vec2(0.5)) / vec2(float(_323.Supersample)))) / vec2(_410.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _870;
                if (param.z == 0u)
                {
                    _870 = vec3(1.0, _521.y, -_521.x);
                }
                else
                {
                    vec3 _871;
                    if (param.z == 1u)
                    {
                        _871 = vec3(-1.0, _521.y, _521.x);
                    }
                    else
                    {
                        vec3 _872;
                        if (param.z == 2u)
                        {
                            _872 = vec3(_521.x, 1.0, -_521.y);
                        }
                        else
                        {
                            vec3 _873;
                            if (param.z == 3u)
                            {
                                _873 = vec3(_521.x, -1.0, _521.y);
                            }
                            else
                            {
                                vec3 _874;
                                if (param.z == 4u)
                                {
                                    _874 = vec3(_521.x, _521.y, 1.0);
                                }
                                else
                                {
                                    _874 = vec3(-_521.x, _521.y, -1.0);
                                }
                                _873 = _874;
                            }
                            _872 = _873;
                        }
                        _871 = _872;
                    }
                    _870 = _871;
                }
                ivec2 _490 = ivec2(_412);
                vec3 _595 = normalize(_870);
                vec2 _617 = fma(vec2(fma(atan(_595.x, -_595.z), 0.15915493667125701904296875, 0.5), acos(clamp(_595.y, -1.0, 1.0)) * 0.3183098733425140380859375), vec2(_490), vec2(-0.5));
                vec2 _619 = floor(_617);
                vec2 _597 = _617 - _619;
                ivec2 _624 = ivec2(_619);
                ivec2 _600 = _624;
                ivec2 _601 = _490;
                _600.x += ((_600.x < 0) ? _601.x : ((_600.x >= _601.x) ? (-_601.x) : 0));
                _600.x = clamp(_600.x, 0, _601.x - 1);
                _600.y = clamp(_600.y, 0, _601.y - 1);
                ivec2 _602 = _624 + ivec2(1, 0);
                ivec2 _603 = _490;
                _602.x += ((_602.x < 0) ? _603.x : ((_602.x >= _603.x) ? (-_603.x) : 0));
                _602.x = clamp(_602.x, 0, _603.x - 1);
                _602.y = clamp(_602.y, 0, _603.y - 1);
                ivec2 _605 = _624 + ivec2(0, 1);
                ivec2 _606 = _490;
                _605.x += ((_605.x < 0) ? _606.x : ((_605.x >= _606.x) ? (-_606.x) : 0));
                _605.x = clamp(_605.x, 0, _606.x - 1);
                _605.y = clamp(_605.y, 0, _606.y - 1);
                ivec2 _607 = _624 + ivec2(1);
                ivec2 _608 = _490;
                _607.x += ((_607.x < 0) ? _608.x : ((_607.x >= _608.x) ? (-_608.x) : 0));
                _607.x = clamp(_607.x, 0, _608.x - 1);
                _607.y = clamp(_607.y, 0, _608.y - 1);
                _494 = _876 + mix(mix(texelFetch(Equirect, ivec3(_600, 0).xy, 0).xyz, texelFetch(Equirect, ivec3(_602, 0).xy, 0).xyz, vec3(_597.x)), mix(texelFetch(Equirect, ivec3(_605, 0).xy, 0).xyz, texelFetch(Equirect, ivec3(_607, 0).xy, 0).xyz, vec3(_597.x)), vec3(_597.y));
            }
        }
        imageStore(Cube, ivec3(gl_GlobalInvocationID), vec4(_867 / vec3(float(_323.Supersample * _323.Supersample)), 1.0));
        break;
    } while(false);
}

