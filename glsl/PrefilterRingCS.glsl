#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterRingParameter
{
    vec4 Ring;
} _144;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _298 = uvec3(0u);
        uvec3 _299 = uvec3(imageSize(Prefiltered));
        _298.x = _299.x;
        _298.y = _299.y;
        _298.z = _299.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _298)))
        {
            break;
        }
        vec2 _347 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_298.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _508;
        if (param.z == 0u)
        {
            _508 = vec3(1.0, _347.y, -_347.x);
        }
        else
        {
            vec3 _509;
            if (param.z == 1u)
            {
                _509 = vec3(-1.0, _347.y, _347.x);
            }
            else
            {
                vec3 _510;
                if (param.z == 2u)
                {
                    _510 = vec3(_347.x, 1.0, -_347.y);
                }
                else
                {
                    vec3 _511;
                    if (param.z == 3u)
                    {
                        _511 = vec3(_347.x, -1.0, _347.y);
                    }
                    else
                    {
                        vec3 _512;
                        if (param.z == 4u)
                        {
                            _512 = vec3(_347.x, _347.y, 1.0);
                        }
                        else
                        {
                            _512 = vec3(-_347.x, _347.y, -1.0);
                        }
                        _511 = _512;
                    }
                    _510 = _511;
                }
                _509 = _510;
            }
            _508 = _509;
        }
        vec3 _353 = normalize(_508);
        vec3 _304 = _353;
        vec3 _438 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_304.y) < 0.999000012874603271484375)), _353));
        vec3 _442 = normalize(cross(_353, _438));
        float _450 = sqrt(clamp(fma(-_144.Ring.z, _144.Ring.z, 1.0), 0.0, 1.0));
        vec3 _660 = ((((textureLod(EnvMap_EnvMapSampler, (_353 * _144.Ring.z) + ((_438 * 1.0) * _450), _144.Ring.y).xyz + textureLod(EnvMap_EnvMapSampler, (_353 * _144.Ring.z) + (((_438 * 0.707106769084930419921875) + (_442 * 0.707106769084930419921875)) * _450), _144.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_353 * _144.Ring.z) + (((_438 * (-4.3711388286737928865477442741394e-08)) + (_442 * 1.0)) * _450), _144.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_353 * _144.Ring.z) + (((_438 * (-0.707106769084930419921875)) + (_442 * 0.707106769084930419921875)) * _450), _144.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_353 * _144.Ring.z) + (((_438 * (-1.0)) + (_442 * (-8.7422776573475857730954885482788e-08))) * _450), _144.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_353 * _144.Ring.z) + (((_438 * (-0.707106649875640869140625)) + (_442 * (-0.707106888294219970703125))) * _450), _144.Ring.y).xyz;
        vec3 _507 = (textureLod(EnvMap_EnvMapSampler, _353, _144.Ring.x).xyz * _144.Ring.w) + (((_660 + textureLod(EnvMap_EnvMapSampler, (_353 * _144.Ring.z) + (((_438 * 1.1924880638503054797183722257614e-08) + (_442 * (-1.0))) * _450), _144.Ring.y).xyz) + textureLod(EnvMap_EnvMapSampler, (_353 * _144.Ring.z) + (((_438 * 0.707107007503509521484375) + (_442 * (-0.707106530666351318359375))) * _450), _144.Ring.y).xyz) * ((1.0 - _144.Ring.w) * 0.125));
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_507, 0.0));
        break;
    } while(false);
}

