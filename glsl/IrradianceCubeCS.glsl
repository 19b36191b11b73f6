#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform IrradianceParameter
{
    uint MomentSize;
} _133;

layout(binding = 0, std430) readonly buffer Moments
{
    vec4 _data[];
} Moments_1;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Irradiance;

shared vec3 ChunkEnergy[64];
shared vec3 ChunkDirection[64];

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    uvec3 _266 = uvec3(0u);
    uvec3 _267 = uvec3(imageSize(Irradiance));
    _266.x = _267.x;
    _266.y = _267.y;
    _266.z = _267.z;
    uvec3 _293 = _266;
    uint _301 = (6u * _133.MomentSize) * _133.MomentSize;
    vec2 _272 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_293.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
    vec3 _450;
    if (param.z == 0u)
    {
        _450 = vec3(1.0, _272.y, -_272.x);
    }
    else
    {
        vec3 _451;
        if (param.z == 1u)
        {
            _451 = vec3(-1.0, _272.y, _272.x);
        }
        else
        {
            vec3 _452;
            if (param.z == 2u)
            {
                _452 = vec3(_272.x, 1.0, -_272.y);
            }
            else
            {
                vec3 _453;
                if (param.z == 3u)
                {
                    _453 = vec3(_272.x, -1.0, _272.y);
                }
                else
                {
                    vec3 _454;
                    if (param.z == 4u)
                    {
                        _454 = vec3(_272.x, _272.y, 1.0);
                    }
                    else
                    {
                        _454 = vec3(-_272.x, _272.y, -1.0);
                    }
                    _453 = _454;
                }
                _452 = _453;
            }
            _451 = _452;
        }
        _450 = _451;
    }
    vec3 _449 = normalize(_450);
    vec3 _456;
    _456 = vec3(0.0);
    vec3 _462;
    for (uint _455 = 0u; _455 < _301; _456 = _462, _455 += 64u)
    {
        uint _322 = _455 + gl_LocalInvocationIndex;
        vec3 _457;
        vec3 _458;
        if (_322 < _301)
        {
            _458 = Moments_1._data[(2u * _322) + 1u].xyz;
            _457 = Moments_1._data[2u * _322].xyz;
        }
        else
        {
            _458 = vec3(0.0);
            _457 = vec3(0.0);
        }
        ChunkEnergy[gl_LocalInvocationIndex] = _457;
        ChunkDirection[gl_LocalInvocationIndex] = _458;
        barrier();
        _462 = _456;
        vec3 _361;
        for (uint _459 = 0u; _459 < 64u; _462 = _361, _459++)
        {
            _361 = _462 + (ChunkEnergy[_459] * max(dot(_449, ChunkDirection[_459]), 0.0));
        }
        barrier();
    }
    if (all(lessThan(gl_GlobalInvocationID, _293)))
    {
        imageStore(Irradiance, ivec3(gl_GlobalInvocationID), vec4(_456 * vec3(0.3183098733425140380859375), 1.0));
    }
}

