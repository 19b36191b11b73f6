#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform PrefilterSpecularParameter
{
    float Roughness;
} _384;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Prefiltered;
layout(binding = 0) uniform samplerCube EnvMap_EnvMapSampler;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    uvec3 _419 = uvec3(0u);
    uvec3 _420 = uvec3(imageSize(Prefiltered));
    _419.x = _420.x;
    _419.y = _420.y;
    _419.z = _420.z;
    if (all(lessThan(gl_GlobalInvocationID, _419)))
    {
        vec2 _421 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_419.xy)) - vec2(0.5)) * vec2(2.0, -2.0);
        vec3 _731;
        if (param.z == 0u)
        {
            _731 = vec3(1.0, _421.y, -_421.x);
        }
        else
        {
            vec3 _732;
            if (param.z == 1u)
            {
                _732 = vec3(-1.0, _421.y, _421.x);
            }
            else
            {
                vec3 _733;
                if (param.z == 2u)
                {
                    _733 = vec3(_421.x, 1.0, -_421.y);
                }
                else
                {
                    vec3 _734;
                    if (param.z == 3u)
                    {
                        _734 = vec3(_421.x, -1.0, _421.y);
                    }
                    else
                    {
                        vec3 _735;
                        if (param.z == 4u)
                        {
                            _735 = vec3(_421.x, _421.y, 1.0);
                        }
                        else
                        {
                            _735 = vec3(-_421.x, _421.y, -1.0);
                        }
                        _734 = _735;
                    }
                    _733 = _734;
                }
                _732 = _733;
            }
            _731 = _732;
        }
        vec3 _523 = normalize(_731);
        vec3 _737;
        float _738;
        _738 = 0.0;
        _737 = vec3(0.0);
        vec3 _740;
        float _741;
        for (uint _736 = 0u; _736 < 1024u; _738 = _741, _737 = _740, _736++)
        {
            uint _621 = (_736 << uint(16)) | (_736 >> uint(16));
            uint _628 = ((_621 & 1431655765u) << uint(1)) | ((_621 & 2863311530u) >> uint(1));
            uint _635 = ((_628 & 858993459u) << uint(2)) | ((_628 & 3435973836u) >> uint(2));
            uint _642 = ((_635 & 252645135u) << uint(4)) | ((_635 & 4042322160u) >> uint(4));
            vec2 _547 = vec2(float(_736) * 0.0009765625, float(((_642 & 16711935u) << uint(8)) | ((_642 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            vec3 _548 = _523;
            float _665 = _384.Roughness * _384.Roughness;
            float _668 = 6.283185482025146484375 * _547.x;
            float _681 = sqrt((1.0 - _547.y) / fma(fma(_665, _665, -1.0), _547.y, 1.0));
            float _686 = sqrt(fma(-_681, _681, 1.0));
            vec3 _706 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_548.y) < 0.999000012874603271484375)), _523));
            vec3 _730 = normalize(mat3(_706, normalize(cross(_523, _706)), _523) * vec3(cos(_668) * _686, sin(_668) * _686, _681));
            vec3 _574 = normalize((_730 * (2.0 * dot(_523, _730))) - _523);
            float _578 = clamp(dot(_523, _574), 0.0, 1.0);
            if (_578 > 0.0)
            {
                _741 = _738 + _578;
                _740 = _737 + (textureLod(EnvMap_EnvMapSampler, _574, 0.0).xyz * _578);
            }
            else
            {
                _741 = _738;
                _740 = _737;
            }
        }
        imageStore(Prefiltered, ivec3(gl_GlobalInvocationID), vec4(_737 / vec3(_738), 0.0));
    }
}

