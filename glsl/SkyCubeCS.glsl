#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform SkyCubeParameter
{
    uint Supersample;
} _282;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Cube;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _370 = uvec3(0u);
        uvec3 _371 = uvec3(imageSize(Cube));
        _370.x = _371.x;
        _370.y = _371.y;
        _370.z = _371.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _370)))
        {
            break;
        }
        vec3 _626;
        _626 = vec3(0.0);
        vec3 _635;
        for (uint _625 = 0u; _625 < _282.Supersample; _626 = _635, _625++)
        {
            _635 = _626;
            vec3 _440;
            for (uint _627 = 0u; _627 < _282.Supersample; _635 = _440, _627++)
            {
                vec2 _377 = (((vec2(gl_GlobalInvocationID.xy) + ((vec2(float(_627), float(_625)) + vec2(0.5)) / vec2(float(_282.Supersample)))) / vec2(float(_370.x))) - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _629;
                if (param.z == 0u)
                {
                    _629 = vec3(1.0, _377.y, -_377.x);
                }
                else
                {
                    vec3 _630;
                    if (param.z == 1u)
                    {
                        _630 = vec3(-1.0, _377.y, _377.x);
                    }
                    else
                    {
                        vec3 _631;
                        if (param.z == 2u)
                        {
                            _631 = vec3(_377.x, 1.0, -_377.y);
                        }
                        else
                        {
                            vec3 _632;
                            if (param.z == 3u)
                            {
                                _632 = vec3(_377.x, -1.0, _377.y);
                            }
                            else
                            {
                                vec3 _633;
                                if (param.z == 4u)
                                {
                                    _633 = vec3(_377.x, _377.y, 1.0);
                                }
                                else
                                {
                                    _633 = vec3(-_377.x, _377.y, -1.0);
                                }
                                _632 = _633;
                            }
                            _631 = _632;
                        }
                        _630 = _631;
                    }
                    _629 = _630;
                }
                vec3 _532 = normalize(_629);
                vec3 _378 = _532;
                vec3 _533 = _532;
                vec3 _534 = _532;
                float _611 = atan(length(cross(_532, vec3(0.300285398960113525390625, 0.4504280984401702880859375, 0.840799152851104736328125))), dot(_532, vec3(0.300285398960113525390625, 0.4504280984401702880859375, 0.840799152851104736328125)));
                _440 = _635 + (mix(mix(mix(vec3(0.1599999964237213134765625, 0.14000000059604644775390625, 0.119999997317790985107421875), vec3(0.4199999868869781494140625, 0.36000001430511474609375, 0.2800000011920928955078125), bvec3(((int(floor(atan(_534.x, -_534.z) * 3.8197185993194580078125)) + int(floor(asin(clamp(_534.y, -1.0, 1.0)) * 7.639437198638916015625))) & 1) != 0)), vec3(0.89999997615814208984375, 0.920000016689300537109375, 0.949999988079071044921875), vec3(exp(_534.y * 40.0))), mix(vec3(1.0499999523162841796875, 1.10000002384185791015625, 1.2000000476837158203125), vec3(0.180000007152557373046875, 0.36000001430511474609375, 0.949999988079071044921875), vec3(pow(clamp(_533.y, 0.0, 1.0), 0.4000000059604644775390625))), bvec3(_378.y >= 0.0)) + (vec3(1.0, 0.920000016689300537109375, 0.800000011920928955078125) * fma(4000.0, clamp((0.0453785620629787445068359375 - _611) * 286.478912353515625, 0.0, 1.0), 40.0 * exp(_611 * (-25.0)))));
            }
        }
        imageStore(Cube, ivec3(gl_GlobalInvocationID), vec4(_626 / vec3(float(_282.Supersample * _282.Supersample)), 1.0));
        break;
    } while(false);
}

