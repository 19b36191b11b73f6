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
            vec4 _1831;
            vec4 _1832;
            vec4 _1833;
            if (_821.x == _826.x)
            {
                uvec3 _830 = gl_GlobalInvocationID;
                uvec2 _1192 = gl_GlobalInvocationID.xy;
                float _1259 = float(_826.x);
                float _1260 = 1.0 / _1259;
                float _1267 = fma(2.0 * float(_1192.x), _1260, -1.0);
                float _1274 = fma(2.0 * float(_1192.y), _1260, -1.0);
                float _1278 = _1267 + (2.0 / _1259);
                float _1282 = _1274 + (2.0 / _1259);
                float _1297 = ((atan(_1267 * _1274, sqrt(fma(_1267, _1267, _1274 * _1274) + 1.0)) - atan(_1267 * _1282, sqrt(fma(_1267, _1267, _1282 * _1282) + 1.0))) - atan(_1278 * _1274, sqrt(fma(_1278, _1278, _1274 * _1274) + 1.0))) + atan(_1278 * _1282, sqrt(fma(_1278, _1278, _1282 * _1282) + 1.0));
                if (_830.z == 0u)
                {
                    imageStore(TexelSolidAngle, ivec2(gl_GlobalInvocationID.xy), vec4(_1297));
                }
                vec3 _1232 = texelFetch(Source, ivec4(ivec3(gl_GlobalInvocationID), 0).xyz, 0).xyz;
                precise vec2 _1369 = vec2(gl_GlobalInvocationID.xy) + vec2(0.5);
                precise vec2 _1373 = _1369 / vec2(float(_826.x));
                vec2 _1360 = (_1373 - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _1826;
                if (_830.z == 0u)
                {
                    _1826 = vec3(1.0, _1360.y, -_1360.x);
                }
                else
                {
                    vec3 _1827;
                    if (_830.z == 1u)
                    {
                        _1827 = vec3(-1.0, _1360.y, _1360.x);
                    }
                    else
                    {
                        vec3 _1828;
                        if (_830.z == 2u)
                        {
                            _1828 = vec3(_1360.x, 1.0, -_1360.y);
                        }
                        else
                        {
                            vec3 _1829;
                            if (_830.z == 3u)
                            {
                                _1829 = vec3(_1360.x, -1.0, _1360.y);
                            }
                            else
                            {
                                vec3 _1830;
                                if (_830.z == 4u)
                                {
                                    _1830 = vec3(_1360.x, _1360.y, 1.0);
                                }
                                else
                                {
                                    _1830 = vec3(-_1360.x, _1360.y, -1.0);
                                }
                                _1829 = _1830;
                            }
                            _1828 = _1829;
                        }
                        _1827 = _1828;
                    }
                    _1826 = _1827;
                }
                vec3 _1474 = normalize(_1826);
                precise float _1380 = max(dot(_1232, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1297;
                precise vec3 _1383 = _1232 * _1297;
                precise vec3 _1386 = _1474 * _1380;
                precise vec3 _1389 = _1474 * _1297;
                _1833 = vec4(_1389, _1297);
                _1832 = vec4(_1386, _1380);
                _1831 = vec4(_1383, _1297);
            }
            else
            {
                uvec3 _835 = gl_GlobalInvocationID;
                vec4 _1794;
                vec4 _1795;
                vec4 _1796;
                _1796 = vec4(0.0);
                _1795 = vec4(0.0);
                _1794 = vec4(0.0);
                vec4 _1550;
                vec4 _1553;
                vec4 _1556;
                for (uint _1793 = 0u; _1793 < 4u; _1796 = _1556, _1795 = _1553, _1794 = _1550, _1793++)
                {
                    uvec2 _1506 = (gl_GlobalInvocationID.xy * uvec2(2u)) + uvec2(_1793 & 1u, _1793 >> uint(1));
                    uvec2 _1478 = _1506;
                    float _1577 = float(_826.x);
                    float _1578 = 1.0 / _1577;
                    float _1585 = fma(2.0 * float(_1478.x), _1578, -1.0);
                    float _1592 = fma(2.0 * float(_1478.y), _1578, -1.0);
                    float _1596 = _1585 + (2.0 / _1577);
                    float _1600 = _1592 + (2.0 / _1577);
                    float _1615 = ((atan(_1585 * _1592, sqrt(fma(_1585, _1585, _1592 * _1592) + 1.0)) - atan(_1585 * _1600, sqrt(fma(_1585, _1585, _1600 * _1600) + 1.0))) - atan(_1596 * _1592, sqrt(fma(_1596, _1596, _1592 * _1592) + 1.0))) + atan(_1596 * _1600, sqrt(fma(_1596, _1596, _1600 * _1600) + 1.0));
                    if (_835.z == 0u)
                    {
                        imageStore(TexelSolidAngle, ivec2(_1506), vec4(_1615));
                    }
                    vec3 _1538 = texelFetch(Source, ivec4(ivec2(_1506), int(_835.z), 0).xyz, 0).xyz;
                    precise vec2 _1687 = vec2(_1506) + vec2(0.5);
                    precise vec2 _1691 = _1687 / vec2(float(_826.x));
                    vec2 _1678 = (_1691 - vec2(0.5)) * vec2(2.0, -2.0);
                    vec3 _1797;
                    if (_835.z == 0u)
                    {
                        _1797 = vec3(1.0, _1678.y, -_1678.x);
                    }
                    else
                    {
                        vec3 _1798;
                        if (_835.z == 1u)
                        {
                            _1798 = vec3(-1.0, _1678.y, _1678.x);
                        }
                        else
                        {
                            vec3 _1799;
                            if (_835.z == 2u)
                            {
                                _1799 = vec3(_1678.x, 1.0, -_1678.y);
                            }
                            else
                            {
                                vec3 _1800;
                                if (_835.z == 3u)
                                {
                                    _1800 = vec3(_1678.x, -1.0, _1678.y);
                                }
                                else
                                {
                                    vec3 _1801;
                                    if (_835.z == 4u)
                                    {
                                        _1801 = vec3(_1678.x, _1678.y, 1.0);
                                    }
                                    else
                                    {
                                        _1801 = vec3(-_1678.x, _1678.y, -1.0);
                                    }
                                    _1800 = _1801;
                                }
                                _1799 = _1800;
                            }
                            _1798 = _1799;
                        }
                        _1797 = _1798;
                    }
                    vec3 _1792 = normalize(_1797);
                    precise float _1698 = max(dot(_1538, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1615;
                    precise vec3 _1701 = _1538 * _1615;
                    precise vec3 _1704 = _1792 * _1698;
                    precise vec3 _1707 = _1792 * _1615;
                    _1550 = _1794 + vec4(_1701, _1615);
                    _1553 = _1795 + vec4(_1704, _1698);
                    _1556 = _1796 + vec4(_1707, _1615);
                }
                _1833 = _1796;
                _1832 = _1795;
                _1831 = _1794;
            }
            imageStore(Energy, ivec3(gl_GlobalInvocationID), _1831);
            imageStore(Centroid, ivec3(gl_GlobalInvocationID), _1832);
            imageStore(Geometry, ivec3(gl_GlobalInvocationID), _1833);
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

