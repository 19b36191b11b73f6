#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterRingParameter
{
    vec4 Ring;
} _133;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _287 = uvec3(0u);
        uvec3 _288 = uvec3(imageSize(Prefiltered));
        _287.x = _288.x;
        _287.y = _288.y;
        _287.z = _288.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _287)))
        {
            break;
        }
        vec2 _291 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_287.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _490;
        if (param.z == 0u)
        {
            _490 = vec3(1.0, _291.y, -_291.x);
        }
        else
        {
            vec3 _491;
            if (param.z == 1u)
            {
                _491 = vec3(-1.0, _291.y, _291.x);
            }
            else
            {
                vec3 _492;
                if (param.z == 2u)
                {
                    _492 = vec3(_291.x, 1.0, -_291.y);
                }
                else
                {
                    vec3 _493;
                    if (param.z == 3u)
                    {
                        _493 = vec3(_291.x, -1.0, _291.y);
                    }
                    else
                    {
                        vec3 _494;
                        if (param.z == 4u)
                        {
                            _494 = vec3(_291.x, _291.y, 1.0);
                        }
                        else
                        {
                            _494 = vec3(-_291.x, _291.y, -1.0);
                        }
                        _493 = _494;
                    }
                    _492 = _493;
                }
                _491 = _492;
            }
            _490 = _491;
        }
        vec3 _401 = normalize(_490);
        vec3 _293 = _401;
        vec3 _420 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_293.y) < 0.999000012874603271484375)), _401));
        vec3 _424 = normalize(cross(_401, _420));
        float _432 = sqrt(clamp(fma(-_133.Ring.z, _133.Ring.z, 1.0), 0.0, 1.0));
        vec3 _642 = ((((textureLod(EnvMap_EnvMapSampler, (_401 * _133.Ring.z) + ((_420 * 1.0) * _432), _133.Ring.y).xyz + textureLod(EnvMap_EnvMapSampler, (_401 * _133.Ring.z) + (((_420 * 0.707106769084930419921875) + (_424 * 0.707106769084930419921875)) * _432), _133.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_401 * _133.Ring.z) + (((_420 * (-4.3711388286737928865477442741394e-08)) + (_424 * 1.0)) * _432), _133.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_401 * _133.Ring.z) + (((_420 * (-0.707106769084930419921875)) + (_424 * 0.707106769084930419921875)) * _432), _133.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_401 * _133.Ring.z) + (((_420 * (-1.0)) + (_424 * (-8.7422776573475857730954885482788e-08))) * _432), _133.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_401 * _133.Ring.z) + (((_420 * (-0.707106649875640869140625)) + (_424 * (-0.707106888294219970703125))) * _432), _133.Ring.y).xyz;
        vec3 _489 = (textureLod(EnvMap_EnvMapSampler, _401, _133.Ring.x).xyz * _133.Ring.w) + (((_642 + textureLod(EnvMap_EnvMapSampler, (_401 * _133.Ring.z) + (((_420 * 1.1924880638503054797183722257614e-08) + (_424 * (-1.0))) * _432), _133.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_401 * _133.Ring.z) + (((_420 * 0.707107007503509521484375) + (_424 * (-0.707106530666351318359375))) * _432), _133.Ring.y).xyz) * ((1.0 - _133.Ring.w) * 0.125));
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_489, 0.0));
        break;
    } while(false);
}

