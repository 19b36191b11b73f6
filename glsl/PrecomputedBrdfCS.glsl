#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, rg16f) uniform writeonly image2D Precomputed;

void main()
{
    uvec2 _405 = uvec2(0u);
    uvec2 _406 = uvec2(imageSize(Precomputed));
    _405.x = _406.x;
    _405.y = _406.y;
    if (all(lessThan(uvec2(gl_GlobalInvocationID.xy), _405)))
    {
        vec2 _407 = (vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_405);
        vec3 _476 = vec3(sqrt(fma(-_407.x, _407.x, 1.0)), 0.0, _407.x);
        float _734;
        float _735;
        _735 = 0.0;
        _734 = 0.0;
        float _737;
        float _738;
        for (uint _733 = 0u; _733 < 1024u; _735 = _738, _734 = _737, _733++)
        {
            uint _564 = (_733 << uint(16)) | (_733 >> uint(16));
            uint _571 = ((_564 & 1431655765u) << uint(1)) | ((_564 & 2863311530u) >> uint(1));
            uint _578 = ((_571 & 858993459u) << uint(2)) | ((_571 & 3435973836u) >> uint(2));
            uint _585 = ((_578 & 252645135u) << uint(4)) | ((_578 & 4042322160u) >> uint(4));
            vec2 _455 = vec2(float(_733) * 0.0009765625, float(((_585 & 16711935u) << uint(8)) | ((_585 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            vec3 _456 = vec3(0.0, 0.0, 1.0);
            float _608 = _407.y * _407.y;
            float _611 = 6.283185482025146484375 * _455.x;
            float _624 = sqrt((1.0 - _455.y) / fma(fma(_608, _608, -1.0), _455.y, 1.0));
            float _629 = sqrt(fma(-_624, _624, 1.0));
            vec3 _649 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_456.y) < 0.999000012874603271484375)), vec3(0.0, 0.0, 1.0)));
            vec3 _673 = normalize(mat3(_649, normalize(cross(vec3(0.0, 0.0, 1.0), _649)), vec3(0.0, 0.0, 1.0)) * vec3(cos(_611) * _629, sin(_611) * _629, _624));
            vec3 _454 = _673;
            vec3 _458 = normalize((_673 * (2.0 * dot(_476, _673))) - _476);
            float _499 = clamp(_458.z, 0.0, 1.0);
            float _506 = clamp(dot(_476, _673), 0.0, 1.0);
            if (_499 > 0.0)
            {
                float _700 = _407.y * _407.y;
                float _721 = _407.y * _407.y;
                float _520 = (((_499 / fma(_499, fma(-_700, 0.5, 1.0), _700 * 0.5)) * (_407.x / fma(_407.x, fma(-_721, 0.5, 1.0), _721 * 0.5))) * _506) / (clamp(_454.z, 0.0, 1.0) * _407.x);
                float _523 = pow(1.0 - _506, 5.0);
                _738 = fma(_523, _520, _735);
                _737 = fma(1.0 - _523, _520, _734);
            }
            else
            {
                _738 = _735;
                _737 = _734;
            }
        }
        imageStore(Precomputed, ivec2(gl_GlobalInvocationID.xy), vec2(_734 * 0.0009765625, _735 * 0.0009765625).xyyy);
    }
}

