#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterPyramidParameter
{
    vec4 ReadLods;
    vec4 ReadWeights;
} _154;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _246 = uvec3(0u);
        uvec3 _247 = uvec3(imageSize(Prefiltered));
        _246.x = _247.x;
        _246.y = _247.y;
        _246.z = _247.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _246)))
        {
            break;
        }
        vec2 _250 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_246.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _413;
        if (param.z == 0u)
        {
            _413 = vec3(1.0, _250.y, -_250.x);
        }
        else
        {
            vec3 _414;
            if (param.z == 1u)
            {
                _414 = vec3(-1.0, _250.y, _250.x);
            }
            else
            {
                vec3 _415;
                if (param.z == 2u)
                {
                    _415 = vec3(_250.x, 1.0, -_250.y);
                }
                else
                {
                    vec3 _416;
                    if (param.z == 3u)
                    {
                        _416 = vec3(_250.x, -1.0, _250.y);
                    }
                    else
                    {
                        vec3 _417;
                        if (param.z == 4u)
                        {
                            _417 = vec3(_250.x, _250.y, 1.0);
                        }
                        else
                        {
                            _417 = vec3(-_250.x, _250.y, -1.0);
                        }
                        _416 = _417;
                    }
                    _415 = _416;
                }
                _414 = _415;
            }
            _413 = _414;
        }
        vec3 _360 = normalize(_413);
        vec3 _361 = abs(_360);
        float _377 = max(_361.x, max(_361.y, _361.z));
        float _383 = log2((_377 * _377) * _377);
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4((textureLod(EnvMap_EnvMapSampler, _360, max(fma(-0.5, _383, _154.ReadLods.x), 0.0)).xyz * _154.ReadWeights.x) + (textureLod(EnvMap_EnvMapSampler, _360, max(fma(-0.5, _383, _154.ReadLods.y), 0.0)).xyz * _154.ReadWeights.y), 0.0));
        break;
    } while(false);
}

