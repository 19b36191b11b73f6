#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform BrdfChunkParameter
{
    uint FirstSample;
    uint ChunkSamples;
    uint Resolve;
} _258;

layout(binding = 1, rg16f) uniform writeonly image2D Precomputed;
layout(binding = 0, rg32f) uniform image2D Accumulated;

void main()
{
    do
    {
        uvec2 _445 = uvec2(0u);
        uvec2 _446 = uvec2(imageSize(Precomputed));
        _445.x = _446.x;
        _445.y = _446.y;
        if (any(greaterThanEqual(gl_GlobalInvocationID.xy, _445)))
        {
            break;
        }
        vec2 _447 = (vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(_445);
        vec3 _542 = vec3(sqrt(fma(-_447.x, _447.x, 1.0)), 0.0, _447.x);
        vec2 _800;
        _800 = vec2(0.0);
        vec2 _803;
        for (uint _799 = _258.FirstSample; _799 < (_258.FirstSample + _258.ChunkSamples); _800 = _803, _799++)
        {
            uint _630 = (_799 << uint(16)) | (_799 >> uint(16));
            uint _637 = ((_630 & 1431655765u) << uint(1)) | ((_630 & 2863311530u) >> uint(1));
            uint _644 = ((_637 & 858993459u) << uint(2)) | ((_637 & 3435973836u) >> uint(2));
            uint _651 = ((_644 & 252645135u) << uint(4)) | ((_644 & 4042322160u) >> uint(4));
            vec2 _521 = vec2(float(_799) * 0.0009765625, float(((_651 & 16711935u) << uint(8)) | ((_651 & 4278255360u) >> uint(8))) * 2.3283064365386962890625e-10);
            vec3 _522 = vec3(0.0, 0.0, 1.0);
            float _674 = _447.y * _447.y;
            float _677 = 6.283185482025146484375 * _521.x;
            float _690 = sqrt((1.0 - _521.y) / fma(fma(_674, _674, -1.0), _521.y, 1.0));
            float _695 = sqrt(fma(-_690, _690, 1.0));
            vec3 _715 = normalize(cross(mix(vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 0.0), bvec3(abs(_522.y) < 0.999000012874603271484375)), vec3(0.0, 0.0, 1.0)));
            vec3 _739 = normalize(mat3(_715, normalize(cross(vec3(0.0, 0.0, 1.0), _715)), vec3(0.0, 0.0, 1.0)) * vec3(cos(_677) * _695, sin(_677) * _695, _690));
            vec3 _520 = _739;
            vec3 _524 = normalize((_739 * (2.0 * dot(_542, _739))) - _542);
            float _572 = clamp(_524.z, 0.0, 1.0);
            float _579 = clamp(dot(_542, _739), 0.0, 1.0);
            if (_572 > 0.0)
            {
                float _766 = _447.y * _447.y;
                float _787 = _447.y * _447.y;
                float _593 = (((_572 / fma(_572, fma(-_766, 0.5, 1.0), _766 * 0.5)) * (_447.x / fma(_447.x, fma(-_787, 0.5, 1.0), _787 * 0.5))) * _579) / (clamp(_520.z, 0.0, 1.0) * _447.x);
                float _596 = pow(1.0 - _579, 5.0);
                _803 = _800 + vec2((1.0 - _596) * _593, _596 * _593);
            }
            else
            {
                _803 = _800;
            }
        }
        vec2 _801;
        if (_258.FirstSample > 0u)
        {
            _801 = _800 + vec2(imageLoad(Accumulated, ivec2(gl_GlobalInvocationID.xy)).xy);
        }
        else
        {
            _801 = _800;
        }
        imageStore(Accumulated, ivec2(gl_GlobalInvocationID.xy), _801.xyyy);
        if (_258.Resolve != 0u)
        {
            imageStore(Precomputed, ivec2(gl_GlobalInvocationID.xy), (_801 * vec2(0.0009765625)).xyyy);
        }
        break;
    } while(false);
}

