#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterTableParameter
{
    uint SampleCount;
} _141;

layout(binding = 0, std430) readonly buffer SampleTable
{
    vec4 _data[];
} SampleTable_1;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _296 = uvec3(0u);
        uvec3 _297 = uvec3(imageSize(Prefiltered));
        _296.x = _297.x;
        _296.y = _297.y;
        _296.z = _297.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _296)))
        {
            break;
        }
        vec2 _300 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_296.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _506;
        if (param.z == 0u)
        {
            _506 = vec3(1.0, _300.y, -_300.x);
        }
        else
        {
            vec3 _507;
            if (param.z == 1u)
            {
                _507 = vec3(-1.0, _300.y, _300.x);
            }
            else
            {
                vec3 _508;
                if (param.z == 2u)
                {
                    _508 = vec3(_300.x, 1.0, -_300.y);
                }
                else
                {
                    vec3 _509;
                    if (param.z == 3u)
                    {
                        _509 = vec3(_300.x, -1.0, _300.y);
                    }
                    else
                    {
                        vec3 _510;
                        if (param.z == 4u)
                        {
                            _510 = vec3(_300.x, _300.y, 1.0);
                        }
                        else
                        {
                            _510 = vec3(-_300.x, _300.y, -1.0);
                        }
                        _509 = _510;
                    }
                    _508 = _509;
                }
                _507 = _508;
            }
            _506 = _507;
        }
        vec3 _410 = normalize(_506);
        vec3 _302 = _410;
        vec3 _432 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_302.y) < 0.999000012874603271484375)), _410));
        vec3 _436 = normalize(cross(_410, _432));
        vec3 _512;
        float _513;
        _513 = 0.0;
        _512 = vec3(0.0);
        vec3 _493;
        float _497;
        for (uint _511 = 0u; _511 < _141.SampleCount; _513 = _497, _512 = _493, _511++)
        {
            vec4 _416 = SampleTable_1._data[_511];
            vec3 _460 = ((_432 * _416.x) + (_436 * _416.y)) + (_410 * _416.z);
            vec3 _418 = abs(_460);
            float _470 = max(_418.x, max(_418.y, _418.z));
            _493 = _512 + (textureLod(EnvMap_EnvMapSampler, _460, max(fma(-0.5, log2((_470 * _470) * _470), _416.w), 0.0)).xyz * _416.z);
            _497 = _513 + _416.z;
        }
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_512 / vec3(_513), 0.0));
        break;
    } while(false);
}

