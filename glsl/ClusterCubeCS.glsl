#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform ClusterParameter
{
    uint Level;
} _444;

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
        uvec3 _821 = uvec3(0u);
        uvec3 _822 = uvec3(imageSize(Energy));
        _821.x = _822.x;
        _821.y = _822.y;
        _821.z = _822.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _821)))
        {
            break;
        }
        if (_444.Level == 0u)
        {
            uvec3 _826 = uvec3(textureSize(Source, 0));
            vec4 _1834;
            vec4 _1835;
            vec4 _1836;
            if (_821.x == _826.x)
            {
                uvec3 _830 = gl_GlobalInvocationID;
                uvec2 _1191 = gl_GlobalInvocationID.xy;
                float _1248 = float(_826.x);
                float _1249 = 1.0 / _1248;
                float _1256 = fma(2.0 * float(_1191.x), _1249, -1.0);
                float _1263 = fma(2.0 * float(_1191.y), _1249, -1.0);
                float _1267 = _1256 + (2.0 / _1248);
                float _1271 = _1263 + (2.0 / _1248);
                float _1286 = ((atan(_1256 * _1263, sqrt(fma(_1256, _1256, _1263 * _1263) + 1.0)) - atan(_1256 * _1271, sqrt(fma(_1256, _1256, _1271 * _1271) + 1.0))) - atan(_1267 * _1263, sqrt(fma(_1267, _1267, _1263 * _1263) + 1.0))) + atan(_1267 * _1271, sqrt(fma(_1267, _1267, _1271 * _1271) + 1.0));
                vec3 _1222 = texelFetch(Source, ivec4(ivec3(gl_GlobalInvocationID), 0).xyz, 0).xyz;
                precise vec2 _1358 = vec2(gl_GlobalInvocationID.xy) + vec2(0.5);
                precise vec2 _1362 = _1358 / vec2(float(_826.x));
                vec2 _1398 = (_1362 - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _1829;
                if (_830.z == 0u)
                {
                    _1829 = vec3(1.0, _1398.y, -_1398.x);
                }
                else
                {
                    vec3 _1830;
                    if (_830.z == 1u)
                    {
                        _1830 = vec3(-1.0, _1398.y, _1398.x);
                    }
                    else
                    {
                        vec3 _1831;
                        if (_830.z == 2u)
                        {
                            _1831 = vec3(_1398.x, 1.0, -_1398.y);
                        }
                        else
                        {
                            vec3 _1832;
                            if (_830.z == 3u)
                            {
                                _1832 = vec3(_1398.x, -1.0, _1398.y);
                            }
                            else
                            {
                                vec3 _1833;
                                if (_830.z == 4u)
                                {
                                    _1833 = vec3(_1398.x, _1398.y, 1.0);
                                }
                                else
                                {
                                    _1833 = vec3(-_1398.x, _1398.y, -1.0);
                                }
                                _1832 = _1833;
                            }
                            _1831 = _1832;
                        }
                        _1830 = _1831;
                    }
                    _1829 = _1830;
                }
                vec3 _1404 = normalize(_1829);
                precise float _1369 = max(dot(_1222, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1286;
                precise vec3 _1372 = _1222 * _1286;
                precise vec3 _1375 = _1404 * _1369;
                precise vec3 _1378 = _1404 * _1286;
                _1836 = vec4(_1378, _1286);
                _1835 = vec4(_1375, _1369);
                _1834 = vec4(_1372, _1286);
            }
            else
            {
                uvec3 _835 = gl_GlobalInvocationID;
                vec4 _1797;
                vec4 _1798;
                vec4 _1799;
                _1799 = vec4(0.0);
                _1798 = vec4(0.0);
                _1797 = vec4(0.0);
                vec4 _1546;
                vec4 _1549;
                vec4 _1552;
                for (uint _1796 = 0u; _1796 < 4u; _1799 = _1552, _1798 = _1549, _1797 = _1546, _1796++)
                {
                    uvec2 _1502 = (gl_GlobalInvocationID.xy * uvec2(2u)) + uvec2(_1796 & 1u, _1796 >> uint(1));
                    uvec2 _1474 = _1502;
                    float _1573 = float(_826.x);
                    float _1574 = 1.0 / _1573;
                    float _1581 = fma(2.0 * float(_1474.x), _1574, -1.0);
                    float _1588 = fma(2.0 * float(_1474.y), _1574, -1.0);
                    float _1592 = _1581 + (2.0 / _1573);
                    float _1596 = _1588 + (2.0 / _1573);
                    float _1611 = ((atan(_1581 * _1588, sqrt(fma(_1581, _1581, _1588 * _1588) + 1.0)) - atan(_1581 * _1596, sqrt(fma(_1581, _1581, _1596 * _1596) + 1.0))) - atan(_1592 * _1588, sqrt(fma(_1592, _1592, _1588 * _1588) + 1.0))) + atan(_1592 * _1596, sqrt(fma(_1592, _1592, _1596 * _1596) + 1.0));
                    if (_835.z == 0u)
                    {
                        imageStore(TexelSolidAngle, ivec2(_1502), vec4(_1611));
                    }
                    vec3 _1534 = texelFetch(Source, ivec4(ivec2(_1502), int(_835.z), 0).xyz, 0).xyz;
                    precise vec2 _1683 = vec2(_1502) + vec2(0.5);
                    precise vec2 _1687 = _1683 / vec2(float(_826.x));
                    vec2 _1723 = (_1687 - vec2(0.5)) * vec2(2.0, -2.0);
                    vec3 _1800;
                    if (_835.z == 0u)
                    {
                        _1800 = vec3(1.0, _1723.y, -_1723.x);
                    }
                    else
                    {
                        vec3 _1801;
                        if (_835.z == 1u)
                        {
                            _1801 = vec3(-1.0, _1723.y, _1723.x);
                        }
                        else
                        {
                            vec3 _1802;
                            if (_835.z == 2u)
                            {
                                _1802 = vec3(_1723.x, 1.0, -_1723.y);
                            }
                            else
                            {
                                vec3 _1803;
                                if (_835.z == 3u)
                                {
                                    _1803 = vec3(_1723.x, -1.0, _1723.y);
                                }
                                else
                                {
                                    vec3 _1804;
                                    if (_835.z == 4u)
                                    {
                                        _1804 = vec3(_1723.x, _1723.y, 1.0);
                                    }
                                    else
                                    {
                                        _1804 = vec3(-_1723.x, _1723.y, -1.0);
                                    }
                                    _1803 = _1804;
                                }
                                _1802 = _1803;
                            }
                            _1801 = _1802;
                        }
                        _1800 = _1801;
                    }
                    vec3 _1729 = normalize(_1800);
                    precise float _1694 = max(dot(_1534, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1611;
                    precise vec3 _1697 = _1534 * _1611;
                    precise vec3 _1700 = _1729 * _1694;
                    precise vec3 _1703 = _1729 * _1611;
                    _1546 = _1797 + vec4(_1697, _1611);
                    _1549 = _1798 + vec4(_1700, _1694);
                    _1552 = _1799 + vec4(_1703, _1611);
                }
                _1836 = _1799;
                _1835 = _1798;
                _1834 = _1797;
            }
            imageStore(Energy, ivec3(gl_GlobalInvocationID), _1834);
            imageStore(Centroid, ivec3(gl_GlobalInvocationID), _1835);
            imageStore(Geometry, ivec3(gl_GlobalInvocationID), _1836);
            break;
        }
        ivec2 _909 = ivec2(gl_GlobalInvocationID.xy) * ivec2(2);
        int _913 = int(_444.Level) - 1;
        imageStore(Energy, ivec3(gl_GlobalInvocationID), ((texelFetch(EnergyIn, ivec4(_909, int(param.z), _913).xyz, _913) + texelFetch(EnergyIn, ivec4(_909 + ivec2(1, 0), int(param.z), _913).xyz, _913)) + texelFetch(EnergyIn, ivec4(_909 + ivec2(0, 1), int(param.z), _913).xyz, _913)) + texelFetch(EnergyIn, ivec4(_909 + ivec2(1), int(param.z), _913).xyz, _913));
        imageStore(Centroid, ivec3(gl_GlobalInvocationID), ((texelFetch(CentroidIn, ivec4(_909, int(param.z), _913).xyz, _913) + texelFetch(CentroidIn, ivec4(_909 + ivec2(1, 0), int(param.z), _913).xyz, _913)) + texelFetch(CentroidIn, ivec4(_909 + ivec2(0, 1), int(param.z), _913).xyz, _913)) + texelFetch(CentroidIn, ivec4(_909 + ivec2(1), int(param.z), _913).xyz, _913));
        imageStore(Geometry, ivec3(gl_GlobalInvocationID), ((texelFetch(GeometryIn, ivec4(_909, int(param.z), _913).xyz, _913) + texelFetch(GeometryIn, ivec4(_909 + ivec2(1, 0), int(param.z), _913).xyz, _913)) + texelFetch(GeometryIn, ivec4(_909 + ivec2(0, 1), int(param.z), _913).xyz, _913)) + texelFetch(GeometryIn, ivec4(_909 + ivec2(1), int(param.z), _913).xyz, _913));
        break;
    } while(false);
}

