#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PreviewParameter
{
    uint Columns;
    uint Rows;
    uint CellSize;
    uint SpecularMips;
    uint StripPanelWidth;
    float Exposure;
} _175;

layout(binding = 0, rgba32f) uniform writeonly image2D Preview;
layout(binding = 0) uniform samplerCube Specular_LinearClamp;
layout(binding = 2) uniform sampler2D BrdfLut_LinearClamp;
layout(binding = 1) uniform samplerCube IrradianceMap_LinearClamp;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec2 _497 = uvec2(0u);
        uvec2 _498 = uvec2(imageSize(Preview));
        _497.x = _498.x;
        _497.y = _498.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _497)))
        {
            break;
        }
        uint _526 = _175.Rows * _175.CellSize;
        vec3 _868;
        if (param.x >= (_175.Columns * _175.CellSize))
        {
            _868 = vec3(0.0199999995529651641845703125);
        }
        else
        {
            vec3 _869;
            if (param.y < _526)
            {
                vec3 _867;
                do
                {
                    uvec2 _569 = gl_GlobalInvocationID.xy / uvec2(_175.CellSize);
                    vec2 _570 = (((vec2(gl_GlobalInvocationID.xy % uvec2(_175.CellSize)) + vec2(0.5)) / vec2(float(_175.CellSize))) * 2.0) - vec2(1.0);
                    _570.y = -_570.y;
                    float _624 = dot(_570, _570);
                    if ((_624 * 1.2345678806304931640625) >= 1.0)
                    {
                        _867 = vec3(0.0199999995529651641845703125);
                        break;
                    }
                    float _680 = (_175.Columns > 1u) ? (float(_569.x) / float(_175.Columns - 1u)) : 0.0;
                    float _691 = (_175.Rows > 1u) ? (float(_569.y) / float(_175.Rows - 1u)) : 0.0;
                    float _645 = sqrt(fma(-_624, 1.2345678806304931640625, 1.0));
                    vec3 _648 = vec3(_570 * vec2(1.111111164093017578125), _645);
                    vec2 _695 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_645, 0.0, 1.0), _680), 0.0).xy);
                    _867 = fma(textureLod(Specular_LinearClamp, reflect(vec3(-0.0, -0.0, -1.0), _648), _680 * float(_175.SpecularMips - 1u)).xyz, (mix(vec3(0.039999999105930328369140625), vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), vec3(_691)) * _695.x) + vec3(_695.y), (textureLod(IrradianceMap_LinearClamp, _648, 0.0).xyz * vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125)) * (1.0 - _691));
                    break;
                } while(false);
                _869 = _867;
            }
            else
            {
                uvec2 _502 = uvec2(param.x, param.y - _526);
                vec3 _866;
                do
                {
                    uint _762 = _502.x / _175.StripPanelWidth;
                    if (_762 >= _175.SpecularMips)
                    {
                        _866 = vec3(0.0199999995529651641845703125);
                        break;
                    }
                    vec2 _754 = (vec2(float(_502.x % _175.StripPanelWidth), float(_502.y)) + vec2(0.5)) / vec2(float(_175.StripPanelWidth), float(_175.StripPanelWidth / 2u));
                    float _809 = (_754.x - 0.5) * 6.283185482025146484375;
                    float _812 = _754.y * 3.1415927410125732421875;
                    _866 = textureLod(Specular_LinearClamp, vec3(sin(_812) * sin(_809), cos(_812), (-sin(_812)) * cos(_809)), float(_762)).xyz;
                    break;
                } while(false);
                _869 = _866;
            }
            _868 = _869;
        }
        vec3 _835 = _868 * _175.Exposure;
        vec3 _853 = clamp((_835 * ((_835 * 2.5099999904632568359375) + vec3(0.02999999932944774627685546875))) / fma(_835, (_835 * 2.4300000667572021484375) + vec3(0.589999973773956298828125), vec3(0.14000000059604644775390625)), vec3(0.0), vec3(1.0));
        imageStore(Preview, ivec2(gl_GlobalInvocationID.xy), vec4(mix((pow(_853, vec3(0.4166666567325592041015625)) * 1.05499994754791259765625) - vec3(0.054999999701976776123046875), _853 * 12.9200000762939453125, step(_853, vec3(0.003130800090730190277099609375))), 1.0));
        break;
    } while(false);
}

