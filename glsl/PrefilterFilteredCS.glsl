#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterSpecularParameter
{
    float Roughness;
} _316;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 1) uniform samplerCube EnvMap;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _536 = uvec3(0u);
        uvec3 _537 = uvec3(imageSize(Prefiltered));
        _536.x = _537.x;
        _536.y = _537.y;
        _536.z = _537.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _536)))
        {
            break;
        }
        uvec2 _538 = uvec2(textureSize(EnvMap, 0));
        float _578 = 4.0 / (float(_538.x) * float(_538.x));
        vec2 _544 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_536.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _946;
        if (param.z == 0u)
        {
            _946 = vec3(1.0, _544.y, -_544.x);
        }
        else
        {
            vec3 _947;
            if (param.z == 1u)
            {
                _947 = vec3(-1.0, _544.y, _544.x);
            }
            else
            {
                vec3 _948;
                if (param.z == 2u)
                {
                    _948 = vec3(_544.x, 1.0, -_544.y);
                }
                else
                {
                    vec3 _949;
                    if (param.z == 3u)
                    {
                        _949 = vec3(_544.x, -1.0, _544.y);
                    }
                    else
                    {
                        vec3 _950;
                        if (param.z == 4u)
                        {
                            _950 = vec3(_544.x, _544.y, 1.0);
                        }
                        else
                        {
                            _950 = vec3(-_544.x, _544.y, -1.0);
                        }
                        _949 = _950;
                    }
                    _948 = _949;
                }
                _947 = _948;
            }
            _946 = _947;
        }
        vec3 _668 = normalize(_946);
        vec3 _952;
        float _953;
        _953 = 0.0;
        _952 = vec3(0.0);
        vec3 _955;
        float _956;
        for (uint _951 = 0u; _951 < 1024u; _953 = _956, _952 = _955, _951++)
        {
            uint _780 = (_951 << uint(16)) | (_951 >> uint(16));
            uint _787 = ((_780 & 1431655765u) << uint(1)) | ((_780 & 2863311530u) >> uint(1));
            uint _794 = ((_787 & 858993459u) << uint(2)) | ((_787 & 3435973836u) >> uint(2));
            uint _801 = ((_794 & 252645135u) << uint(4)) | ((_794 & 4042322160u) >> uint(4));
            vec2 _677 = vec2(float(_951) * 0.0009765625, float(((_801 & 16711935u) << uint(8)) | ((_801 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            vec3 _678 = _668;
            float _824 = _316.Roughness * _316.Roughness;
            float _827 = 6.283185482025146484375 * _677.x;
            float _840 = sqrt((1.0 - _677.y) / fma(fma(_824, _824, -1.0), _677.y, 1.0));
            float _845 = sqrt(fma(-_840, _840, 1.0));
            vec3 _865 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_678.y) < 0.999000012874603271484375)), _668));
            vec3 _889 = normalize(mat3(_865, normalize(cross(_668, _865)), _668) * vec3(cos(_827) * _845, sin(_827) * _845, _840));
            vec3 _710 = normalize((_889 * (2.0 * dot(_668, _889))) - _668);
            float _714 = clamp(dot(_668, _710), 0.0, 1.0);
            if (_714 > 0.0)
            {
                vec3 _682 = abs(_710);
                float _727 = max(_682.x, max(_682.y, _682.z));
                float _731 = clamp(dot(_668, _889), 0.0, 1.0);
                float _926 = _316.Roughness * _316.Roughness;
                float _938 = fma(_731 * _731, fma(_926, _926, -1.0), 1.0);
                float _945 = (_926 * _926) / ((3.1415927410125732421875 * _938) * _938);
                float _908 = 0.5 * log2(4.0 / ((1024.0 * _945) * (((_578 * _727) * _727) * _727)));
                _956 = _953 + _714;
                _955 = _952 + (textureLod(EnvMap_EnvMapSampler, _710, ((_945 > 0.0) && (_908 > 0.0)) ? _908 : 0.0).xyz * _714);
            }
            else
            {
                _956 = _953;
                _955 = _952;
            }
        }
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_952 / vec3(_953), 0.0));
        break;
    } while(false);
}

