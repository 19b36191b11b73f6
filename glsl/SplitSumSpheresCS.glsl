#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform SplitSumParameter
{
    uint Columns;
    uint MetalRows;
    uint CellSize;
    uint SpecularMips;
} _337;

layout(binding = 0, rgba32f) uniform writeonly image2D SplitSum;
layout(binding = 0) uniform samplerCube Specular_LinearClamp;
layout(binding = 2) uniform sampler2D BrdfLut_LinearClamp;
layout(binding = 1) uniform samplerCube IrradianceMap_LinearClamp;

void main()
{
    do
    {
        uvec2 _495 = uvec2(0u);
        uvec2 _496 = uvec2(imageSize(SplitSum));
        _495.x = _496.x;
        _495.y = _496.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _495)))
        {
            break;
        }
        vec2 _612 = (((vec2(gl_GlobalInvocationID.xy % uvec2(_337.CellSize)) + vec2(0.5)) / vec2(float(_337.CellSize))) * 2.0) - vec2(1.0);
        _612.y = -_612.y;
        float _644 = dot(_612, _612);
        bool _647 = (_644 * 1.2345678806304931640625) < 1.0;
        float _655 = sqrt(max(fma(-_644, 1.2345678806304931640625, 1.0), 0.0));
        vec3 _658 = vec3(_612 * vec2(1.111111164093017578125), _655);
        uvec2 _615 = gl_GlobalInvocationID.xy / uvec2(_337.CellSize);
        float _678 = max((_337.Columns > 1u) ? (float(_615.x) / float(_337.Columns - 1u)) : 0.0, 0.0500000007450580596923828125);
        bool _683 = _615.y >= _337.MetalRows;
        vec3 _686 = mix(vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), vec3(1.0), bvec3(_683));
        float _693 = _683 ? 0.0 : ((_337.MetalRows > 1u) ? (float(_615.y) / float(_337.MetalRows - 1u)) : 0.0);
        vec3 _928;
        if (_647 && (float(_683) > 0.0))
        {
            vec3 _927;
            do
            {
                vec3 _742 = refract(vec3(-0.0, -0.0, -1.0), _658, 0.666666686534881591796875);
                vec3 _751 = normalize(_658 - (_742 * (2.0 * dot(_658, _742))));
                vec3 _755 = refract(_742, -_751, 1.5);
                if (dot(_755, _755) == 0.0)
                {
                    _927 = vec3(0.0);
                    break;
                }
                _927 = textureLod(Specular_LinearClamp, _755, _678 * float(_337.SpecularMips - 1u)).xyz * ((1.0 - fma(0.959999978542327880859375, pow(1.0 - clamp(_655, 0.0, 1.0), 5.0), 0.0400000028312206268310546875)) * (1.0 - fma(0.959999978542327880859375, pow(1.0 - clamp(dot(_751, _755), 0.0, 1.0), 5.0), 0.0400000028312206268310546875)));
                break;
            } while(false);
            _928 = _927;
        }
        else
        {
            vec3 _929;
            if (_647)
            {
                vec2 _816 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_655, 0.0, 1.0), _678), 0.0).xy);
                _929 = fma(textureLod(Specular_LinearClamp, reflect(vec3(-0.0, -0.0, -1.0), _658), _678 * float(_337.SpecularMips - 1u)).xyz, (mix(vec3(0.039999999105930328369140625), _686, vec3(_693)) * _816.x) + vec3(_816.y), (textureLod(IrradianceMap_LinearClamp, _658, 0.0).xyz * _686) * (1.0 - _693));
            }
            else
            {
                _929 = vec3(0.0);
            }
            _928 = _929;
        }
        imageStore(SplitSum, ivec2(gl_GlobalInvocationID.xy), vec4(_928, float(_647)));
        break;
    } while(false);
}

