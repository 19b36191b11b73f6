#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform ClusterParameter
{
    uint Level;
} _456;

layout(binding = 3, r32f) uniform writeonly image2D TexelSolidAngle;
layout(binding = 0, rgba32f) uniform writeonly image2DArray Energy;
layout(binding = 1, rgba32f) uniform writeonly image2DArray Centroid;
layout(binding = 2, rgba32f) uniform writeonly image2DArray Geometry;
layout(binding = 0) uniform sampler2DArray Source;
layout(binding = 1) uniform sampler2DArray EnergyIn;
layout(binding = 2) uniform sampler2DArray CentroidIn;
layout(binding = 3) uniform sampler2DArray GeometryIn;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _831 = uvec3(0u);
        uvec3 _832 = uvec3(imageSize(Energy));
        _831.x = _832.x;
        _831.y = _832.y;
        _831.z = _832.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _831)))
        {
            break;
        }
        if (_456.Level == 0u)
        {
            uvec3 _836 = uvec3(textureSize(Source, 0));
            vec4 _1851;
            vec4 _1852;
            vec4 _1853;
            if (_831.x == _836.x)
            {
                uvec3 _840 = gl_GlobalInvocationID;
                uvec2 _1200 = gl_GlobalInvocationID.xy;
                float _1267 = float(_836.x);
                float _1268 = 1.0 / _1267;
                float _1275 = fma(2.0 * float(_1200.x), _1268, -1.0);
                float _1282 = fma(2.0 * float(_1200.y), _1268, -1.0);
                float _1286 = _1275 + (2.0 / _1267);
                float _1290 = _1282 + (2.0 / _1267);
                float _1305 = ((atan(_1275 * _1282, sqrt(fma(_1275, _1275, _1282 * _1282) + 1.0)) - atan(_1275 * _1290, sqrt(fma(_1275, _1275, _1290 * _1290) + 1.0))) - atan(_1286 * _1282, sqrt(fma(_1286, _1286, _1282 * _1282) + 1.0))) + atan(_1286 * _1290, sqrt(fma(_1286, _1286, _1290 * _1290) + 1.0));
                if (_840.z == 0u)
                {
                    imageStore(TexelSolidAngle, ivec2(gl_GlobalInvocationID.xy), vec4(_1305));
                }
                vec3 _1240 = texelFetch(Source, ivec4(ivec3(gl_GlobalInvocationID), 0).xyz, 0).xyz;
                precise vec2 _1377 = vec2(gl_GlobalInvocationID.xy) + vec2(0.5);
                precise vec2 _1381 = _1377 / vec2(float(_836.x));
                vec2 _1368 = (_1381 - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _1846;
                if (_840.z == 0u)
                {
                    _1846 = vec3(1.0, _1368.y, -_1368.x);
                }
                else
                {
                    vec3 _1847;
                    if (_840.z == 1u)
                    {
                        _1847 = vec3(-1.0, _1368.y, _1368.x);
                    }
                    else
                    {
                        vec3 _1848;
                        if (_840.z == 2u)
                        {
                            _1848 = vec3(_1368.x, 1.0, -_1368.y);
                        }
                        else
                        {
                            vec3 _1849;
                            if (_840.z == 3u)
                            {
                                _1849 = vec3(_1368.x, -1.0, _1368.y);
                            }
                            else
                            {
                                vec3 _1850;
                                if (_840.z == 4u)
                                {
                                    _1850 = vec3(_1368.x, _1368.y, 1.0);
                                }
                                else
                                {
                                    _1850 = vec3(-_1368.x, _1368.y, -1.0);
                                }
                                _1849 = _1850;
                            }
                            _1848 = _1849;
                        }
                        _1847 = _1848;
                    }
                    _1846 = _1847;
                }
                vec3 _1482 = normalize(_1846);
                precise float _1388 = max(dot(_1240, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1305;
                precise vec3 _1391 = _1240 * _1305;
                precise vec3 _1394 = _1482 * _1388;
                precise vec3 _1397 = _1482 * _1305;
                _1853 = vec4(_1397, _1305);
                _1852 = vec4(_1394, _1388);
                _1851 = vec4(_1391, _1305);
            }
            else
            {
                uvec3 _845 = gl_GlobalInvocationID;
                uvec3 _1486 = uvec3(textureSize(Source, 0));
                vec4 _1814;
                vec4 _1815;
                vec4 _1816;
                _1816 = vec4(0.0);
                _1815 = vec4(0.0);
                _1814 = vec4(0.0);
                vec4 _1570;
                vec4 _1573;
                vec4 _1576;
                for (uint _1813 = 0u; _1813 < 4u; _1816 = _1576, _1815 = _1573, _1814 = _1570, _1813++)
                {
                    uvec2 _1526 = (gl_GlobalInvocationID.xy * uvec2(2u)) + uvec2(_1813 & 1u, _1813 >> uint(1));
                    uvec2 _1490 = _1526;
                    float _1597 = float(_1486.x);
                    float _1598 = 1.0 / _1597;
                    float _1605 = fma(2.0 * float(_1490.x), _1598, -1.0);
                    float _1612 = fma(2.0 * float(_1490.y), _1598, -1.0);
                    float _1616 = _1605 + (2.0 / _1597);
                    float _1620 = _1612 + (2.0 / _1597);
                    float _1635 = ((atan(_1605 * _1612, sqrt(fma(_1605, _1605, _1612 * _1612) + 1.0)) - atan(_1605 * _1620, sqrt(fma(_1605, _1605, _1620 * _1620) + 1.0))) - atan(_1616 * _1612, sqrt(fma(_1616, _1616, _1612 * _1612) + 1.0))) + atan(_1616 * _1620, sqrt(fma(_1616, _1616, _1620 * _1620) + 1.0));
                    if (_845.z == 0u)
                    {
                        imageStore(TexelSolidAngle, ivec2(_1526), vec4(_1635));
                    }
                    vec3 _1558 = texelFetch(Source, ivec4(ivec2(_1526), int(_845.z), 0).xyz, 0).xyz;
                    precise vec2 _1707 = vec2(_1526) + vec2(0.5);
                    precise vec2 _1711 = _1707 / vec2(float(_1486.x));
                    vec2 _1698 = (_1711 - vec2(0.5)) * vec2(2.0, -2.0);
                    vec3 _1817;
                    if (_845.z == 0u)
                    {
                        _1817 = vec3(1.0, _1698.y, -_1698.x);
                    }
                    else
                    {
                        vec3 _1818;
                        if (_845.z == 1u)
                        {
                            _1818 = vec3(-1.0, _1698.y, _1698.x);
                        }
                        else
                        {
                            vec3 _1819;
                            if (_845.z == 2u)
                            {
                                _1819 = vec3(_1698.x, 1.0, -_1698.y);
                            }
                            else
                            {
                                vec3 _1820;
                                if (_845.z == 3u)
                                {
                                    _1820 = vec3(_1698.x, -1.0, _1698.y);
                                }
                                else
                                {
                                    vec3 _1821;
                                    if (_845.z == 4u)
                                    {
                                        _1821 = vec3(_1698.x, _1698.y, 1.0);
                                    }
                                    else
                                    {
                                        _1821 = vec3(-_1698.x, _1698.y, -1.0);
                                    }
                                    _1820 = _1821;
                                }
                                _1819 = _1820;
                            }
                            _1818 = _1819;
                        }
                        _1817 = _1818;
                    }
                    vec3 _1812 = normalize(_1817);
                    precise float _1718 = max(dot(_1558, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1635;
                    precise vec3 _1721 = _1558 * _1635;
                    precise vec3 _1724 = _1812 * _1718;
                    precise vec3 _1727 = _1812 * _1635;
                    _1570 = _1814 + vec4(_1721, _1635);
                    _1573 = _1815 + vec4(_1724, _1718);
                    _1576 = _1816 + vec4(_1727, _1635);
                }
                _1853 = _1816;
                _1852 = _1815;
                _1851 = _1814;
            }
            imageStore(Energy, ivec3(gl_GlobalInvocationID), _1851);
            imageStore(Centroid, ivec3(gl_GlobalInvocationID), _1852);
            imageStore(Geometry, ivec3(gl_GlobalInvocationID), _1853);
            break;
        }
        ivec2 _917 = ivec2(gl_GlobalInvocationID.xy) * ivec2(2);
        int _921 = int(_456.Level) - 1;
        imageStore(Energy, ivec3(gl_GlobalInvocationID), ((texelFetch(EnergyIn, ivec4(_917, int(param.z), _921).xyz, _921) + texelFetch(EnergyIn, ivec4(_917 + ivec2(1, 0), int(param.z), _921).xyz, _921)) + texelFetch(EnergyIn, ivec4(_917 + ivec2(0, 1), int(param.z), _921).xyz, _921)) + texelFetch(EnergyIn, ivec4(_917 + ivec2(1), int(param.z), _921).xyz, _921));
        imageStore(Centroid, ivec3(gl_GlobalInvocationID), ((texelFetch(CentroidIn, ivec4(_917, int(param.z), _921).xyz, _921) + texelFetch(CentroidIn, ivec4(_917 + ivec2(1, 0), int(param.z), _921).xyz, _921)) + texelFetch(CentroidIn, ivec4(_917 + ivec2(0, 1), int(param.z), _921).xyz, _921)) + texelFetch(CentroidIn, ivec4(_917 + ivec2(1), int(param.z), _921).xyz, _921));
        imageStore(Geometry, ivec3(gl_GlobalInvocationID), ((texelFetch(GeometryIn, ivec4(_917, int(param.z), _921).xyz, _921) + texelFetch(GeometryIn, ivec4(_917 + ivec2(1, 0), int(param.z), _921).xyz, _921)) + texelFetch(GeometryIn, ivec4(_917 + ivec2(0, 1), int(param.z), _921).xyz, _921)) + texelFetch(GeometryIn, ivec4(_917 + ivec2(1), int(param.z), _921).xyz, _921));
        break;
    } while(false);
}

