#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

int _1083;

layout(binding = 0, std140) uniform ShProjectParameter
{
    uint SourceMip;
} _290;

layout(binding = 0, std430) buffer Partials
{
    vec4 _data[];
} Partials_1;

layout(binding = 0) uniform sampler2DArray Source;

shared vec4 Shared[64][9];

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    uvec3 param_1 = gl_WorkGroupID;
    uvec3 _526 = uvec3(textureSize(Source, int(_290.SourceMip)));
    uint _552 = _526.x;
    uint _554 = _526.y;
    vec3 _528 = vec3(0.0, 0.0, 1.0);
    float _527[9] = float[](0.2820948064327239990234375, 0.48860251903533935546875 * _528.y, 0.48860251903533935546875 * _528.z, 0.48860251903533935546875 * _528.x, (1.09254848957061767578125 * _528.x) * _528.y, (1.09254848957061767578125 * _528.y) * _528.z, 0.3153915703296661376953125 * fma(3.0 * _528.z, _528.z, -1.0), (1.09254848957061767578125 * _528.x) * _528.z, 0.546274244785308837890625 * fma(_528.x, _528.x, -(_528.y * _528.y)));
    vec3 _1071;
    float _1073;
    if ((param.x < _552) && (param.y < _554))
    {
        vec2 _776 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(float(_552))) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _1059;
        if (param.z == 0u)
        {
            _1059 = vec3(1.0, _776.y, -_776.x);
        }
        else
        {
            vec3 _1060;
            if (param.z == 1u)
            {
                _1060 = vec3(-1.0, _776.y, _776.x);
            }
            else
            {
                vec3 _1061;
                if (param.z == 2u)
                {
                    _1061 = vec3(_776.x, 1.0, -_776.y);
                }
                else
                {
                    vec3 _1062;
                    if (param.z == 3u)
                    {
                        _1062 = vec3(_776.x, -1.0, _776.y);
                    }
                    else
                    {
                        vec3 _1063;
                        if (param.z == 4u)
                        {
                            _1063 = vec3(_776.x, _776.y, 1.0);
                        }
                        else
                        {
                            _1063 = vec3(-_776.x, _776.y, -1.0);
                        }
                        _1062 = _1063;
                    }
                    _1061 = _1062;
                }
                _1060 = _1061;
            }
            _1059 = _1060;
        }
        vec3 _535 = normalize(_1059);
        _527 = float[](0.2820948064327239990234375, 0.48860251903533935546875 * _535.y, 0.48860251903533935546875 * _535.z, 0.48860251903533935546875 * _535.x, (1.09254848957061767578125 * _535.x) * _535.y, (1.09254848957061767578125 * _535.y) * _535.z, 0.3153915703296661376953125 * fma(3.0 * _535.z, _535.z, -1.0), (1.09254848957061767578125 * _535.x) * _535.z, 0.546274244785308837890625 * fma(_535.x, _535.x, -(_535.y * _535.y)));
        uvec2 _537 = gl_GlobalInvocationID.xy;
        float _922 = float(_552);
        float _923 = 1.0 / _922;
        float _930 = fma(2.0 * float(_537.x), _923, -1.0);
        float _937 = fma(2.0 * float(_537.y), _923, -1.0);
        float _941 = _930 + (2.0 / _922);
        float _945 = _937 + (2.0 / _922);
        _1073 = ((atan(_930 * _937, sqrt(fma(_930, _930, _937 * _937) + 1.0)) - atan(_930 * _945, sqrt(fma(_930, _930, _945 * _945) + 1.0))) - atan(_941 * _937, sqrt(fma(_941, _941, _937 * _937) + 1.0))) + atan(_941 * _945, sqrt(fma(_941, _941, _945 * _945) + 1.0));
        _1071 = texelFetch(Source, ivec4(ivec2(gl_GlobalInvocationID.xy), int(param.z), _1083).xyz, int(_290.SourceMip)).xyz;
    }
    else
    {
        _1073 = 0.0;
        _1071 = vec3(0.0);
    }
    for (uint _1064 = 0u; _1064 < 9u; _1064++)
    {
        Shared[gl_LocalInvocationIndex][_1064] = vec4((_1071 * _527[_1064]) * _1073, _1073);
    }
    barrier();
    for (uint _1065 = 32u; _1065 > 0u; _1065 /= 2u)
    {
        if (gl_LocalInvocationIndex < _1065)
        {
            for (uint _1067 = 0u; _1067 < 9u; _1067++)
            {
                Shared[gl_LocalInvocationIndex][_1067] += Shared[gl_LocalInvocationIndex + _1065][_1067];
            }
        }
        barrier();
    }
    if (gl_LocalInvocationIndex == 0u)
    {
        uint _699 = (((param_1.z * ((_554 + 7u) / 8u)) + param_1.y) * ((_552 + 7u) / 8u)) + param_1.x;
        for (uint _1066 = 0u; _1066 < 9u; _1066++)
        {
            Partials_1._data[(_699 * 9u) + _1066] = Shared[0][_1066];
        }
    }
}

