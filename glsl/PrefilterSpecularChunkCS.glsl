#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterChunkParameter
{
    float Roughness;
    uint FirstSample;
    uint ChunkSamples;
    uint Resolve;
} _293;

layout(binding = 1, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 0, rgba32f) uniform image2DArray Accumulated;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _465 = uvec3(0u);
        uvec3 _466 = uvec3(imageSize(Prefiltered));
        _465.x = _466.x;
        _465.y = _466.y;
        _465.z = _466.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _465)))
        {
            break;
        }
        vec2 _539 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_465.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _810;
        if (param.z == 0u)
        {
            _810 = vec3(1.0, _539.y, -_539.x);
        }
        else
        {
            vec3 _811;
            if (param.z == 1u)
            {
                _811 = vec3(-1.0, _539.y, _539.x);
            }
            else
            {
                vec3 _812;
                if (param.z == 2u)
                {
                    _812 = vec3(_539.x, 1.0, -_539.y);
                }
                else
                {
                    vec3 _813;
                    if (param.z == 3u)
                    {
                        _813 = vec3(_539.x, -1.0, _539.y);
                    }
                    else
                    {
                        vec3 _814;
                        if (param.z == 4u)
                        {
                            _814 = vec3(_539.x, _539.y, 1.0);
                        }
                        else
                        {
                            _814 = vec3(-_539.x, _539.y, -1.0);
                        }
                        _813 = _814;
                    }
                    _812 = _813;
                }
                _811 = _812;
            }
            _810 = _811;
        }
        vec3 _545 = normalize(_810);
        vec4 _816;
        _816 = vec4(0.0);
        vec4 _818;
        for (uint _815 = _293.FirstSample; _815 < (_293.FirstSample + _293.ChunkSamples); _816 = _818, _815++)
        {
            uint _700 = (_815 << uint(16)) | (_815 >> uint(16));
            uint _707 = ((_700 & 1431655765u) << uint(1)) | ((_700 & 2863311530u) >> uint(1));
            uint _714 = ((_707 & 858993459u) << uint(2)) | ((_707 & 3435973836u) >> uint(2));
            uint _721 = ((_714 & 252645135u) << uint(4)) | ((_714 & 4042322160u) >> uint(4));
            vec2 _619 = vec2(float(_815) * 0.0009765625, float(((_721 & 16711935u) << uint(8)) | ((_721 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            vec3 _620 = _545;
            float _744 = _293.Roughness * _293.Roughness;
            float _747 = 6.283185482025146484375 * _619.x;
            float _760 = sqrt((1.0 - _619.y) / fma(fma(_744, _744, -1.0), _619.y, 1.0));
            float _765 = sqrt(fma(-_760, _760, 1.0));
            vec3 _785 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_620.y) < 0.999000012874603271484375)), _545));
            vec3 _809 = normalize(mat3(_785, normalize(cross(_545, _785)), _545) * vec3(cos(_747) * _765, sin(_747) * _765, _760));
            vec3 _654 = normalize((_809 * (2.0 * dot(_545, _809))) - _545);
            float _658 = clamp(dot(_545, _654), 0.0, 1.0);
            if (_658 > 0.0)
            {
                _818 = _816 + vec4(textureLod(EnvMap_EnvMapSampler, _654, 0.0).xyz * _658, _658);
            }
            else
            {
                _818 = _816;
            }
        }
        vec4 _470 = _816;
        if (_293.FirstSample > 0u)
        {
            _470 += imageLoad(Accumulated, ivec3(gl_GlobalInvocationID));
        }
        imageStore(Accumulated, ivec3(gl_GlobalInvocationID), _470);
        if (_293.Resolve != 0u)
        {
            imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_470.xyz / vec3(_470.w), 0.0));
        }
        break;
    } while(false);
}

