#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform SkyCubeParameter
{
    uint Supersample;
} _293;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Cube;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _381 = uvec3(0u);
        uvec3 _382 = uvec3(imageSize(Cube));
        _381.x = _382.x;
        _381.y = _382.y;
        _381.z = _382.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _381)))
        {
            break;
        }
        vec3 _644;
        _644 = vec3(0.0);
        vec3 _653;
        for (uint _643 = 0u; _643 < _293.Supersample; _644 = _653, _643++)
        {
            _653 = _644;
            vec3 _451;
            for (uint _645 = 0u; _645 < _293.Supersample; _653 = _451, _645++)
            {
                vec2 _478 = (((vec2(gl_GlobalInvocationID.xy) + ((vec2(float(_645), float(_643)) + vec2(0.5)) / vec2(float(_293.Supersample)))) / vec2(float(_381.x))) - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _647;
                if (param.z == 0u)
                {
                    _647 = vec3(1.0, _478.y, -_478.x);
                }
                else
                {
                    vec3 _648;
                    if (param.z == 1u)
                    {
                        _648 = vec3(-1.0, _478.y, _478.x);
                    }
                    else
                    {
                        vec3 _649;
                        if (param.z == 2u)
                        {
                            _649 = vec3(_478.x, 1.0, -_478.y);
                        }
                        else
                        {
                            vec3 _650;
                            if (param.z == 3u)
                            {
                                _650 = vec3(_478.x, -1.0, _478.y);
                            }
                            else
                            {
                                vec3 _651;
                                if (param.z == 4u)
                                {
                                    _651 = vec3(_478.x, _478.y, 1.0);
                                }
                                else
                                {
                                    _651 = vec3(-_478.x, _478.y, -1.0);
                                }
                                _650 = _651;
                            }
                            _649 = _650;
                        }
                        _648 = _649;
                    }
                    _647 = _648;
                }
                vec3 _484 = normalize(_647);
                vec3 _389 = _484;
                vec3 _551 = _484;
                vec3 _552 = _484;
                float _629 = atan(length(cross(_484, vec3(0.300285398960113525390625, 0.4504280984401702880859375, 0.840799152851104736328125))), dot(_484, vec3(0.300285398960113525390625, 0.4504280984401702880859375, 0.840799152851104736328125)));
                _451 = _653 + (mix(mix(mix(vec3(0.1599999964237213134765625, 0.14000000059604644775390625, 0.119999997317790985107421875), vec3(0.4199999868869781494140625, 0.36000001430511474609375, 0.2800000011920928955078125), bvec3(((int(floor(atan(_552.x, -_552.z) * 3.8197185993194580078125)) + int(floor(asin(clamp(_552.y, -1.0, 1.0)) * 7.639437198638916015625))) & 1) != 0)), vec3(0.89999997615814208984375, 0.920000016689300537109375, 0.949999988079071044921875), vec3(exp(_552.y * 40.0))), mix(vec3(1.0499999523162841796875, 1.10000002384185791015625, 1.2000000476837158203125), vec3(0.180000007152557373046875, 0.36000001430511474609375, 0.949999988079071044921875), vec3(pow(clamp(_551.y, 0.0, 1.0), 0.4000000059604644775390625))), bvec3(_389.y >= 0.0)) + (vec3(1.0, 0.920000016689300537109375, 0.800000011920928955078125) * fma(4000.0, clamp((0.0453785620629787445068359375 - _629) * 286.478912353515625, 0.0, 1.0), 40.0 * exp(_629 * (-25.0)))));
            }
        }
        imageStore(Cube, ivec3(gl_GlobalInvocationID), vec4(_644 / vec3(float(_293.Supersample * _293.Supersample)), 1.0));
        break;
    } while(false);
}

