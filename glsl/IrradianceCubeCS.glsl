#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform IrradianceParameter
{
    uint MomentSize;
} _144;

layout(binding = 0, std430) readonly buffer Moments
{
    vec4 _data[];
} Moments_1;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Irradiance;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _239 = uvec3(0u);
        uvec3 _240 = uvec3(imageSize(Irradiance));
        _239.x = _240.x;
        _239.y = _240.y;
        _239.z = _240.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _239)))
        {
            break;
        }
        uint _274 = (6u * _144.MomentSize) * _144.MomentSize;
        vec2 _328 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_239.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _401;
        if (param.z == 0u)
        {
            _401 = vec3(1.0, _328.y, -_328.x);
        }
        else
        {
            vec3 _402;
            if (param.z == 1u)
            {
                _402 = vec3(-1.0, _328.y, _328.x);
            }
            else
            {
                vec3 _403;
                if (param.z == 2u)
                {
                    _403 = vec3(_328.x, 1.0, -_328.y);
                }
                else
                {
                    vec3 _404;
                    if (param.z == 3u)
                    {
                        _404 = vec3(_328.x, -1.0, _328.y);
                    }
                    else
                    {
                        vec3 _405;
                        if (param.z == 4u)
                        {
                            _405 = vec3(_328.x, _328.y, 1.0);
                        }
                        else
                        {
                            _405 = vec3(-_328.x, _328.y, -1.0);
                        }
                        _404 = _405;
                    }
                    _403 = _404;
                }
                _402 = _403;
            }
            _401 = _402;
        }
        vec3 _334 = normalize(_401);
        vec3 _407;
        _407 = vec3(0.0);
        vec3 _311;
        for (uint _406 = 0u; _406 < _274; _407 = _311, _406++)
        {
            _311 = _407 + (Moments_1._data[2u * _406].xyz * max(dot(_334, Moments_1._data[(2u * _406) + 1u].xyz), 0.0));
        }
        imageStore(Irradiance, ivec3(gl_GlobalInvocationID), vec4(_407 * vec3(0.3183098733425140380859375), 1.0));
        break;
    } while(false);
}

