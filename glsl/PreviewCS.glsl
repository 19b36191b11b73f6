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
        uvec2 _500 = uvec2(0u);
        uvec2 _501 = uvec2(imageSize(Preview));
        _500.x = _501.x;
        _500.y = _501.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _500)))
        {
            break;
        }
        uint _529 = _175.Rows * _175.CellSize;
        vec3 _871;
        if (param.x >= (_175.Columns * _175.CellSize))
        {
            _871 = vec3(0.0199999995529651641845703125);
        }
        else
        {
            vec3 _872;
            if (param.y < _529)
            {
                vec3 _870;
                do
                {
                    uvec2 _572 = gl_GlobalInvocationID.xy / uvec2(_175.CellSize);
                    vec2 _573 = (((vec2(gl_GlobalInvocationID.xy % uvec2(_175.CellSize)) + vec2(0.5)) / vec2(float(_175.CellSize))) * 2.0) - vec2(1.0);
                    _573.y = -_573.y;
                    float _627 = dot(_573, _573);
                    if ((_627 * 1.2345678806304931640625) >= 1.0)
                    {
                        _870 = vec3(0.0199999995529651641845703125);
                        break;
                    }
                    float _683 = (_175.Columns > 1u) ? (float(_572.x) / float(_175.Columns - 1u)) : 0.0;
                    float _694 = (_175.Rows > 1u) ? (float(_572.y) / float(_175.Rows - 1u)) : 0.0;
                    float _648 = sqrt(fma(-_627, 1.2345678806304931640625, 1.0));
                    vec3 _651 = vec3(_573 * vec2(1.111111164093017578125), _648);
                    vec2 _698 = vec2(textureLod(BrdfLut_LinearClamp, vec2(clamp(_648, 0.0, 1.0), _683), 0.0).xy);
                    _870 = fma(textureLod(Specular_LinearClamp, reflect(vec3(-0.0, -0.0, -1.0), _651), _683 * float(_175.SpecularMips - 1u)).xyz, (mix(vec3(0.039999999105930328369140625), vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125), vec3(_694)) * _698.x) + vec3(_698.y), (textureLod(IrradianceMap_LinearClamp, _651, 0.0).xyz * vec3(1.0, 0.765999972820281982421875, 0.3359999954700469970703125)) * (1.0 - _694));
                    break;
                } while(false);
                _872 = _870;
            }
            else
            {
                uvec2 _505 = uvec2(param.x, param.y - _529);
                vec3 _869;
                do
                {
                    uint _765 = _505.x / _175.StripPanelWidth;
                    if (_765 >= _175.SpecularMips)
                    {
                        _869 = vec3(0.0199999995529651641845703125);
                        break;
                    }
                    vec2 _757 = (vec2(float(_505.x % _175.StripPanelWidth), float(_505.y)) + vec2(0.5)) / vec2(float(_175.StripPanelWidth), float(_175.StripPanelWidth / 2u));
                    float _812 = (_757.x - 0.5) * 6.283185482025146484375;
                    float _815 = _757.y * 3.1415927410125732421875;
                    _869 = textureLod(Specular_LinearClamp, vec3(sin(_815) * sin(_812), cos(_815), (-sin(_815)) * cos(_812)), float(_765)).xyz;
                    break;
                } while(false);
                _872 = _869;
            }
            _871 = _872;
        }
        vec3 _838 = _871 * _175.Exposure;
        vec3 _856 = clamp((_838 * ((_838 * 2.5099999904632568359375) + vec3(0.02999999932944774627685546875))) / fma(_838, (_838 * 2.4300000667572021484375) + vec3(0.589999973773956298828125), vec3(0.14000000059604644775390625)), vec3(0.0), vec3(1.0));
        imageStore(Preview, ivec2(gl_GlobalInvocationID.xy), vec4(mix((pow(_856, vec3(0.4166666567325592041015625)) * 1.05499994754791259765625) - vec3(0.054999999701976776123046875), _856 * 12.9200000762939453125, step(_856, vec3(0.003130800090730190277099609375))), 1.0));
        break;
    } while(false);
}

