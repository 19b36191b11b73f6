#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

int _1065;

layout(binding = 0, std140) uniform ShProjectParameter
{
    uint SourceMip;
} _279;

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
    uvec3 _515 = uvec3(textureSize(Source, int(_279.SourceMip)));
    uint _541 = _515.x;
    uint _543 = _515.y;
    vec3 _517 = vec3(0.0, 0.0, 1.0);
    float _516[9] = float[](0.2820948064327239990234375, 0.48860251903533935546875 * _517.y, 0.48860251903533935546875 * _517.z, 0.48860251903533935546875 * _517.x, (1.09254848957061767578125 * _517.x) * _517.y, (1.09254848957061767578125 * _517.y) * _517.z, 0.3153915703296661376953125 * fma(3.0 * _517.z, _517.z, -1.0), (1.09254848957061767578125 * _517.x) * _517.z, 0.546274244785308837890625 * fma(_517.x, _517.x, -(_517.y * _517.y)));
    vec3 _1053;
    float _1055;
    if ((param.x < _541) && (param.y < _543))
    {
        vec2 _523 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(float(_541))) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _1041;
        if (param.z == 0u)
        {
            _1041 = vec3(1.0, _523.y, -_523.x);
        }
        else
        {
            vec3 _1042;
            if (param.z == 1u)
            {
                _1042 = vec3(-1.0, _523.y, _523.x);
            }
            else
            {
                vec3 _1043;
                if (param.z == 2u)
                {
                    _1043 = vec3(_523.x, 1.0, -_523.y);
                }
                else
                {
                    vec3 _1044;
                    if (param.z == 3u)
                    {
                        _1044 = vec3(_523.x, -1.0, _523.y);
                    }
                    else
                    {
                        vec3 _1045;
                        if (param.z == 4u)
                        {
                            _1045 = vec3(_523.x, _523.y, 1.0);
                        }
                        else
                        {
                            _1045 = vec3(-_523.x, _523.y, -1.0);
                        }
                        _1044 = _1045;
                    }
                    _1043 = _1044;
                }
                _1042 = _1043;
            }
            _1041 = _1042;
        }
        vec3 _524 = normalize(_1041);
        _516 = float[](0.2820948064327239990234375, 0.48860251903533935546875 * _524.y, 0.48860251903533935546875 * _524.z, 0.48860251903533935546875 * _524.x, (1.09254848957061767578125 * _524.x) * _524.y, (1.09254848957061767578125 * _524.y) * _524.z, 0.3153915703296661376953125 * fma(3.0 * _524.z, _524.z, -1.0), (1.09254848957061767578125 * _524.x) * _524.z, 0.546274244785308837890625 * fma(_524.x, _524.x, -(_524.y * _524.y)));
        uvec2 _526 = gl_GlobalInvocationID.xy;
        float _904 = float(_541);
        float _905 = 1.0 / _904;
        float _912 = fma(2.0 * float(_526.x), _905, -1.0);
        float _919 = fma(2.0 * float(_526.y), _905, -1.0);
        float _923 = _912 + (2.0 / _904);
        float _927 = _919 + (2.0 / _904);
        _1055 = ((atan(_912 * _919, sqrt(fma(_912, _912, _919 * _919) + 1.0)) - atan(_912 * _927, sqrt(fma(_912, _912, _927 * _927) + 1.0))) - atan(_923 * _919, sqrt(fma(_923, _923, _919 * _919) + 1.0))) + atan(_923 * _927, sqrt(fma(_923, _923, _927 * _927) + 1.0));
        _1053 = texelFetch(Source, ivec4(ivec2(gl_GlobalInvocationID.xy), int(param.z), _1065).xyz, int(_279.SourceMip)).xyz;
    }
    else
    {
        _1055 = 0.0;
        _1053 = vec3(0.0);
    }
    for (uint _1046 = 0u; _1046 < 9u; _1046++)
    {
        Shared[gl_LocalInvocationIndex][_1046] = vec4((_1053 * _516[_1046]) * _1055, _1055);
    }
    barrier();
    for (uint _1047 = 32u; _1047 > 0u; _1047 /= 2u)
    {
        if (gl_LocalInvocationIndex < _1047)
        {
            for (uint _1049 = 0u; _1049 < 9u; _1049++)
            {
                Shared[gl_LocalInvocationIndex][_1049] += Shared[gl_LocalInvocationIndex + _1047][_1049];
            }
        }
        barrier();
    }
    if (gl_LocalInvocationIndex == 0u)
    {
        uint _688 = (((param_1.z * ((_543 + 7u) / 8u)) + param_1.y) * ((_541 + 7u) / 8u)) + param_1.x;
        for (uint _1048 = 0u; _1048 < 9u; _1048++)
        {
            Partials_1._data[(_688 * 9u) + _1048] = Shared[0][_1048];
        }
    }
}

