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

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _228 = uvec3(0u);
        uvec3 _229 = uvec3(imageSize(Irradiance));
        _228.x = _229.x;
        _228.y = _229.y;
        _228.z = _229.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _228)))
        {
            break;
        }
        uint _263 = (6u * _133.MomentSize) * _133.MomentSize;
        vec2 _233 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_228.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _383;
        if (param.z == 0u)
        {
            _383 = vec3(1.0, _233.y, -_233.x);
        }
        else
        {
            vec3 _384;
            if (param.z == 1u)
            {
                _384 = vec3(-1.0, _233.y, _233.x);
            }
            else
            {
                vec3 _385;
                if (param.z == 2u)
                {
                    _385 = vec3(_233.x, 1.0, -_233.y);
                }
                else
                {
                    vec3 _386;
                    if (param.z == 3u)
                    {
                        _386 = vec3(_233.x, -1.0, _233.y);
                    }
                    else
                    {
                        vec3 _387;
                        if (param.z == 4u)
                        {
                            _387 = vec3(_233.x, _233.y, 1.0);
                        }
                        else
                        {
                            _387 = vec3(-_233.x, _233.y, -1.0);
                        }
                        _386 = _387;
                    }
                    _385 = _386;
                }
                _384 = _385;
            }
            _383 = _384;
        }
        vec3 _382 = normalize(_383);
        vec3 _389;
        _389 = vec3(0.0);
        vec3 _300;
        for (uint _388 = 0u; _388 < _263; _389 = _300, _388++)
        {
            _300 = _389 + (Moments_1._data[2u * _388].xyz * max(dot(_382, Moments_1._data[(2u * _388) + 1u].xyz), 0.0));
        }
        imageStore(Irradiance, ivec3(gl_GlobalInvocationID), vec4(_389 * vec3(0.3183098733425140380859375), 1.0));
        break;
    } while(false);
}

