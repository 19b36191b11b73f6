#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterTableParameter
{
    uint SampleCount;
} _152;

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
        uvec3 _307 = uvec3(0u);
        uvec3 _308 = uvec3(imageSize(Prefiltered));
        _307.x = _308.x;
        _307.y = _308.y;
        _307.z = _308.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _307)))
        {
            break;
        }
        vec2 _356 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_307.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _524;
        if (param.z == 0u)
        {
            _524 = vec3(1.0, _356.y, -_356.x);
        }
        else
        {
            vec3 _525;
            if (param.z == 1u)
            {
                _525 = vec3(-1.0, _356.y, _356.x);
            }
            else
            {
                vec3 _526;
                if (param.z == 2u)
                {
                    _526 = vec3(_356.x, 1.0, -_356.y);
                }
                else
                {
                    vec3 _527;
                    if (param.z == 3u)
                    {
                        _527 = vec3(_356.x, -1.0, _356.y);
                    }
                    else
                    {
                        vec3 _528;
                        if (param.z == 4u)
                        {
                            _528 = vec3(_356.x, _356.y, 1.0);
                        }
                        else
                        {
                            _528 = vec3(-_356.x, _356.y, -1.0);
                        }
                        _527 = _528;
                    }
                    _526 = _527;
                }
                _525 = _526;
            }
            _524 = _525;
        }
        vec3 _362 = normalize(_524);
        vec3 _313 = _362;
        vec3 _450 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_313.y) < 0.999000012874603271484375)), _362));
        vec3 _454 = normalize(cross(_362, _450));
        vec3 _530;
        float _531;
        _531 = 0.0;
        _530 = vec3(0.0);
        vec3 _511;
        float _515;
        for (uint _529 = 0u; _529 < _152.SampleCount; _531 = _515, _530 = _511, _529++)
        {
            vec4 _434 = SampleTable_1._data[_529];
            vec3 _478 = ((_450 * _434.x) + (_454 * _434.y)) + (_362 * _434.z);
            vec3 _436 = abs(_478);
            float _488 = max(_436.x, max(_436.y, _436.z));
            _511 = _530 + (textureLod(EnvMap_EnvMapSampler, _478, max(fma(-0.5, log2((_488 * _488) * _488), _434.w), 0.0)).xyz * _434.z);
            _515 = _531 + _434.z;
        }
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_530 / vec3(_531), 0.0));
        break;
    } while(false);
}

