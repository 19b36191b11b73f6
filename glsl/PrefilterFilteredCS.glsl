#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterSpecularParameter
{
    float Roughness;
} _327;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 1) uniform samplerCube EnvMap;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _547 = uvec3(0u);
        uvec3 _548 = uvec3(imageSize(Prefiltered));
        _547.x = _548.x;
        _547.y = _548.y;
        _547.z = _548.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _547)))
        {
            break;
        }
        uvec2 _549 = uvec2(textureSize(EnvMap, 0));
        float _589 = 4.0 / (float(_549.x) * float(_549.x));
        vec2 _614 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_547.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _964;
        if (param.z == 0u)
        {
            _964 = vec3(1.0, _614.y, -_614.x);
        }
        else
        {
            vec3 _965;
            if (param.z == 1u)
            {
                _965 = vec3(-1.0, _614.y, _614.x);
            }
            else
            {
                vec3 _966;
                if (param.z == 2u)
                {
                    _966 = vec3(_614.x, 1.0, -_614.y);
                }
                else
                {
                    vec3 _967;
                    if (param.z == 3u)
                    {
                        _967 = vec3(_614.x, -1.0, _614.y);
                    }
                    else
                    {
                        vec3 _968;
                        if (param.z == 4u)
                        {
                            _968 = vec3(_614.x, _614.y, 1.0);
                        }
                        else
                        {
                            _968 = vec3(-_614.x, _614.y, -1.0);
                        }
                        _967 = _968;
                    }
                    _966 = _967;
                }
                _965 = _966;
            }
            _964 = _965;
        }
        vec3 _620 = normalize(_964);
        vec3 _970;
        float _971;
        _971 = 0.0;
        _970 = vec3(0.0);
        vec3 _973;
        float _974;
        for (uint _969 = 0u; _969 < 1024u; _971 = _974, _970 = _973, _969++)
        {
            uint _798 = (_969 << uint(16)) | (_969 >> uint(16));
            uint _805 = ((_798 & 1431655765u) << uint(1)) | ((_798 & 2863311530u) >> uint(1));
            uint _812 = ((_805 & 858993459u) << uint(2)) | ((_805 & 3435973836u) >> uint(2));
            uint _819 = ((_812 & 252645135u) << uint(4)) | ((_812 & 4042322160u) >> uint(4));
            vec2 _695 = vec2(float(_969) * 0.0009765625, float(((_819 & 16711935u) << uint(8)) | ((_819 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            vec3 _696 = _620;
            float _842 = _327.Roughness * _327.Roughness;
            float _845 = 6.283185482025146484375 * _695.x;
            float _858 = sqrt((1.0 - _695.y) / fma(fma(_842, _842, -1.0), _695.y, 1.0));
            float _863 = sqrt(fma(-_858, _858, 1.0));
            vec3 _883 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_696.y) < 0.999000012874603271484375)), _620));
            vec3 _907 = normalize(mat3(_883, normalize(cross(_620, _883)), _620) * vec3(cos(_845) * _863, sin(_845) * _863, _858));
            vec3 _728 = normalize((_907 * (2.0 * dot(_620, _907))) - _620);
            float _732 = clamp(dot(_620, _728), 0.0, 1.0);
            if (_732 > 0.0)
            {
                vec3 _700 = abs(_728);
                float _745 = max(_700.x, max(_700.y, _700.z));
                float _749 = clamp(dot(_620, _907), 0.0, 1.0);
                float _944 = _327.Roughness * _327.Roughness;
                float _956 = fma(_749 * _749, fma(_944, _944, -1.0), 1.0);
                float _963 = (_944 * _944) / ((3.1415927410125732421875 * _956) * _956);
                float _926 = 0.5 * log2(4.0 / ((1024.0 * _963) * (((_589 * _745) * _745) * _745)));
                _974 = _971 + _732;
                _973 = _970 + (textureLod(EnvMap_EnvMapSampler, _728, ((_963 > 0.0) && (_926 > 0.0)) ? _926 : 0.0).xyz * _732);
            }
            else
            {
                _974 = _971;
                _973 = _970;
            }
        }
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_970 / vec3(_971), 0.0));
        break;
    } while(false);
}

