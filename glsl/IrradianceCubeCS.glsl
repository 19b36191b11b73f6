#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

int _899;

layout(binding = 0, std140) uniform IrradianceParameter
{
    uint SourceMip;
} _222;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Irradiance;
layout(binding = 0) uniform sampler2DArray Source;

shared vec3 ChunkDirection[64];
shared vec3 ChunkEnergy[64];

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    uvec3 _420 = uvec3(0u);
    uvec3 _421 = uvec3(imageSize(Irradiance));
    _420.x = _421.x;
    _420.y = _421.y;
    _420.z = _421.z;
    uvec3 _461 = _420;
    uvec3 _427 = uvec3(textureSize(Source, int(_222.SourceMip)));
    uint _478 = _427.x * _427.x;
    uint _480 = 6u * _478;
    vec2 _432 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_461.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
    vec3 _859;
    if (param.z == 0u)
    {
        _859 = vec3(1.0, _432.y, -_432.x);
    }
    else
    {
        vec3 _860;
        if (param.z == 1u)
        {
            _860 = vec3(-1.0, _432.y, _432.x);
        }
        else
        {
            vec3 _861;
            if (param.z == 2u)
            {
                _861 = vec3(_432.x, 1.0, -_432.y);
            }
            else
            {
                vec3 _862;
                if (param.z == 3u)
                {
                    _862 = vec3(_432.x, -1.0, _432.y);
                }
                else
                {
                    vec3 _863;
                    if (param.z == 4u)
                    {
                        _863 = vec3(_432.x, _432.y, 1.0);
                    }
                    else
                    {
                        _863 = vec3(-_432.x, _432.y, -1.0);
                    }
                    _862 = _863;
                }
                _861 = _862;
            }
            _860 = _861;
        }
        _859 = _860;
    }
    vec3 _676 = normalize(_859);
    vec3 _865;
    _865 = vec3(0.0);
    vec3 _881;
    for (uint _864 = 0u; _864 < _480; _865 = _881, _864 += 64u)
    {
        uint _501 = _864 + gl_LocalInvocationIndex;
        vec3 _871;
        vec3 _872;
        if (_501 < _480)
        {
            uint _508 = _501 / _478;
            uint _511 = _501 % _427.x;
            uint _516 = (_501 % _478) / _427.x;
            vec2 _442 = (((vec2(float(_511), float(_516)) + vec2(0.5)) / vec2(float(_427.x))) - vec2(0.5)) * vec2(2.0, -2.0);
            vec3 _866;
            if (_508 == 0u)
            {
                _866 = vec3(1.0, _442.y, -_442.x);
            }
            else
            {
                vec3 _867;
                if (_508 == 1u)
                {
                    _867 = vec3(-1.0, _442.y, _442.x);
                }
                else
                {
                    vec3 _868;
                    if (_508 == 2u)
                    {
                        _868 = vec3(_442.x, 1.0, -_442.y);
                    }
                    else
                    {
                        vec3 _869;
                        if (_508 == 3u)
                        {
                            _869 = vec3(_442.x, -1.0, _442.y);
                        }
                        else
                        {
                            vec3 _870;
                            if (_508 == 4u)
                            {
                                _870 = vec3(_442.x, _442.y, 1.0);
                            }
                            else
                            {
                                _870 = vec3(-_442.x, _442.y, -1.0);
                            }
                            _869 = _870;
                        }
                        _868 = _869;
                    }
                    _867 = _868;
                }
                _866 = _867;
            }
            uvec2 _443 = uvec2(_511, _516);
            float _760 = float(_427.x);
            float _761 = 1.0 / _760;
            float _768 = fma(2.0 * float(_443.x), _761, -1.0);
            float _775 = fma(2.0 * float(_443.y), _761, -1.0);
            float _779 = _768 + (2.0 / _760);
            float _783 = _775 + (2.0 / _760);
            _872 = texelFetch(Source, ivec4(int(_511), int(_516), int(_508), _899).xyz, int(_222.SourceMip)).xyz * (((atan(_768 * _775, sqrt(fma(_768, _768, _775 * _775) + 1.0)) - atan(_768 * _783, sqrt(fma(_768, _768, _783 * _783) + 1.0))) - atan(_779 * _775, sqrt(fma(_779, _779, _775 * _775) + 1.0))) + atan(_779 * _783, sqrt(fma(_779, _779, _783 * _783) + 1.0)));
            _871 = normalize(_866);
        }
        else
        {
            _872 = vec3(0.0);
            _871 = vec3(0.0);
        }
        ChunkDirection[gl_LocalInvocationIndex] = _871;
        ChunkEnergy[gl_LocalInvocationIndex] = _872;
        barrier();
        _881 = _865;
        vec3 _890;
        for (uint _873 = 0u; _873 < 64u; _881 = _890, _873++)
        {
            float _577 = dot(_676, ChunkDirection[_873]);
            if (_577 > 0.0)
            {
                _890 = _881 + (ChunkEnergy[_873] * _577);
            }
            else
            {
                _890 = _881;
            }
        }
        barrier();
    }
    if (all(lessThan(gl_GlobalInvocationID, _461)))
    {
        imageStore(Irradiance, ivec3(gl_GlobalInvocationID), vec4(_865 * vec3(0.3183098733425140380859375), 1.0));
    }
}

