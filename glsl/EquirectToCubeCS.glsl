#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform EquirectToCubeParameter
{
    uint Supersample;
} _312;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Cube;
layout(binding = 0) uniform sampler2D Equirect;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _399 = uvec3(0u);
        uvec3 _400 = uvec3(imageSize(Cube));
        _399.x = _400.x;
        _399.y = _400.y;
        _399.z = _400.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _399)))
        {
            break;
        }
        uvec2 _401 = uvec2(0u);
        uvec2 _402 = uvec2(textureSize(Equirect, 0));
        _401.x = _402.x;
        _401.y = _402.y;
        vec3 _849;
        _849 = vec3(0.0);
        vec3 _858;
        for (uint _848 = 0u; _848 < _312.Supersample; _849 = _858, _848++)
        {
            _858 = _849;
            vec3 _483;
            for (uint _850 = 0u; _850 < _312.Supersample; _858 = _483, _850++)
            {
                vec2 _409 = (((vec2(gl_GlobalInvocationID.xy) + ((vec2(float(_850), float(_848)) + vec2(0.5)) / vec2(float(_312.Supersample)))) / vec2(_399.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _852;
                if (param.z == 0u)
                {
                    _852 = vec3(1.0, _409.y, -_409.x);
                }
                else
                {
                    vec3 _853;
                    if (param.z == 1u)
                    {
                        _853 = vec3(-1.0, _409.y, _409.x);
                    }
                    else
                    {
                        vec3 _854;
                        if (param.z == 2u)
                        {
                            _854 = vec3(_409.x, 1.0, -_409.y);
                        }
                        else
                        {
                            vec3 _855;
                            if (param.z == 3u)
                            {
                                _855 = vec3(_409.x, -1.0, _409.y);
                            }
                            else
                            {
                                vec3 _856;
                                if (param.z == 4u)
                                {
                                    _856 = vec3(_409.x, _409.y, 1.0);
                                }
                                else
                                {
                                    _856 = vec3(-_409.x, _409.y, -1.0);
                                }
                                _855 = _856;
                            }
                            _854 = _855;
                        }
                        _853 = _854;
                    }
                    _852 = _853;
                }
                ivec2 _479 = ivec2(_401);
                vec3 _577 = normalize(_852);
                vec2 _599 = fma(vec2(fma(atan(_577.x, -_577.z), 0.15915493667125701904296875, 0.5), acos(clamp(_577.y, -1.0, 1.0)) * 0.3183098733425140380859375), vec2(_479), vec2(-0.5));
                vec2 _601 = floor(_599);
                vec2 _579 = _599 - _601;
                ivec2 _606 = ivec2(_601);
                ivec2 _582 = _606;
                ivec2 _583 = _479;
                _582.x += ((_582.x < 0) ? _583.x : ((_582.x >= _583.x) ? (-_583.x) : 0));
                _582.x = clamp(_582.x, 0, _583.x - 1);
                _582.y = clamp(_582.y, 0, _583.y - 1);
                ivec2 _584 = _606 + ivec2(1, 0);
                ivec2 _585 = _479;
                _584.x += ((_584.x < 0) ? _585.x : ((_584.x >= _585.x) ? (-_585.x) : 0));
                _584.x = clamp(_584.x, 0, _585.x - 1);
                _584.y = clamp(_584.y, 0, _585.y - 1);
                ivec2 _587 = _606 + ivec2(0, 1);
                ivec2 _588 = _479;
                _587.x += ((_587.x < 0) ? _588.x : ((_587.x >= _588.x) ? (-_588.x) : 0));
                _587.x = clamp(_587.x, 0, _588.x - 1);
                _587.y = clamp(_587.y, 0, _588.y - 1);
                ivec2 _589 = _606 + ivec2(1);
                ivec2 _590 = _479;
                _589.x += ((_589.x < 0) ? _590.x : ((_589.x >= _590.x) ? (-_590.x) : 0));
                _589.x = clamp(_589.x, 0, _590.x - 1);
                _589.y = clamp(_589.y, 0, _590.y - 1);
                _483 = _858 + mix(mix(texelFetch(Equirect, ivec3(_582, 0).xy, 0).xyz, texelFetch(Equirect, ivec3(_584, 0).xy, 0).xyz, vec3(_579.x)), mix(texelFetch(Equirect, ivec3(_587, 0).xy, 0).xyz, texelFetch(Equirect, ivec3(_589, 0).xy, 0).xyz, vec3(_579.x)), vec3(_579.y));
            }
        }
        imageStore(Cube, ivec3(gl_GlobalInvocationID), vec4(_849 / vec3(float(_312.Supersample * _312.Supersample)), 1.0));
        break;
    } while(false);
}

