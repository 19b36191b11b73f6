#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterChunkParameter
{
    float Roughness;
    uint FirstSample;
    uint ChunkSamples;
    uint Resolve;
} _282;

layout(binding = 1, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 0, rgba32f) uniform image2DArray Accumulated;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _454 = uvec3(0u);
        uvec3 _455 = uvec3(imageSize(Prefiltered));
        _454.x = _455.x;
        _454.y = _455.y;
        _454.z = _455.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _454)))
        {
            break;
        }
        vec2 _458 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_454.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _792;
        if (param.z == 0u)
        {
            _792 = vec3(1.0, _458.y, -_458.x);
        }
        else
        {
            vec3 _793;
            if (param.z == 1u)
            {
                _793 = vec3(-1.0, _458.y, _458.x);
            }
            else
            {
                vec3 _794;
                if (param.z == 2u)
                {
                    _794 = vec3(_458.x, 1.0, -_458.y);
                }
                else
                {
                    vec3 _795;
                    if (param.z == 3u)
                    {
                        _795 = vec3(_458.x, -1.0, _458.y);
                    }
                    else
                    {
                        vec3 _796;
                        if (param.z == 4u)
                        {
                            _796 = vec3(_458.x, _458.y, 1.0);
                        }
                        else
                        {
                            _796 = vec3(-_458.x, _458.y, -1.0);
                        }
                        _795 = _796;
                    }
                    _794 = _795;
                }
                _793 = _794;
            }
            _792 = _793;
        }
        vec3 _593 = normalize(_792);
        vec4 _798;
        _798 = vec4(0.0);
        vec4 _800;
        for (uint _797 = _282.FirstSample; _797 < (_282.FirstSample + _282.ChunkSamples); _798 = _800, _797++)
        {
            uint _682 = (_797 << uint(16)) | (_797 >> uint(16));
            uint _689 = ((_682 & 1431655765u) << uint(1)) | ((_682 & 2863311530u) >> uint(1));
            uint _696 = ((_689 & 858993459u) << uint(2)) | ((_689 & 3435973836u) >> uint(2));
            uint _703 = ((_696 & 252645135u) << uint(4)) | ((_696 & 4042322160u) >> uint(4));
            vec2 _601 = vec2(float(_797) * 0.0009765625, float(((_703 & 16711935u) << uint(8)) | ((_703 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            vec3 _602 = _593;
            float _726 = _282.Roughness * _282.Roughness;
            float _729 = 6.283185482025146484375 * _601.x;
            float _742 = sqrt((1.0 - _601.y) / fma(fma(_726, _726, -1.0), _601.y, 1.0));
            float _747 = sqrt(fma(-_742, _742, 1.0));
            vec3 _767 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_602.y) < 0.999000012874603271484375)), _593));
            vec3 _791 = normalize(mat3(_767, normalize(cross(_593, _767)), _593) * vec3(cos(_729) * _747, sin(_729) * _747, _742));
            vec3 _636 = normalize((_791 * (2.0 * dot(_593, _791))) - _593);
            float _640 = clamp(dot(_593, _636), 0.0, 1.0);
            if (_640 > 0.0)
            {
                _800 = _798 + vec4(textureLod(EnvMap_EnvMapSampler, _636, 0.0).xyz * _640, _640);
            }
            else
            {
                _800 = _798;
            }
        }
        vec4 _459 = _798;
        if (_282.FirstSample > 0u)
        {
            _459 += imageLoad(Accumulated, ivec3(gl_GlobalInvocationID));
        }
        imageStore(Accumulated, ivec3(gl_GlobalInvocationID), _459);
        if (_282.Resolve != 0u)
        {
            imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_459.xyz / vec3(_459.w), 0.0));
        }
        break;
    } while(false);
}

