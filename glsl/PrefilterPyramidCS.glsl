#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterPyramidParameter
{
    vec4 ReadLods;
    vec4 ReadWeights;
} _165;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _257 = uvec3(0u);
        uvec3 _258 = uvec3(imageSize(Prefiltered));
        _257.x = _258.x;
        _257.y = _258.y;
        _257.z = _258.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _257)))
        {
            break;
        }
        vec2 _306 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_257.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _431;
        if (param.z == 0u)
        {
            _431 = vec3(1.0, _306.y, -_306.x);
        }
        else
        {
            vec3 _432;
            if (param.z == 1u)
            {
                _432 = vec3(-1.0, _306.y, _306.x);
            }
            else
            {
                vec3 _433;
                if (param.z == 2u)
                {
                    _433 = vec3(_306.x, 1.0, -_306.y);
                }
                else
                {
                    vec3 _434;
                    if (param.z == 3u)
                    {
                        _434 = vec3(_306.x, -1.0, _306.y);
                    }
                    else
                    {
                        vec3 _435;
                        if (param.z == 4u)
                        {
                            _435 = vec3(_306.x, _306.y, 1.0);
                        }
                        else
                        {
                            _435 = vec3(-_306.x, _306.y, -1.0);
                        }
                        _434 = _435;
                    }
                    _433 = _434;
                }
                _432 = _433;
            }
            _431 = _432;
        }
        vec3 _312 = normalize(_431);
        vec3 _379 = abs(_312);
        float _395 = max(_379.x, max(_379.y, _379.z));
        float _401 = log2((_395 * _395) * _395);
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4((textureLod(EnvMap_EnvMapSampler, _312, max(fma(-0.5, _401, _165.ReadLods.x), 0.0)).xyz * _165.ReadWeights.x) + (textureLod(EnvMap_EnvMapSampler, _312, max(fma(-0.5, _401, _165.ReadLods.y), 0.0)).xyz * _165.ReadWeights.y), 0.0));
        break;
    } while(false);
}

