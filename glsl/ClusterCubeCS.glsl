#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform ClusterParameter
{
    uint Level;
} _433;

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
        uvec3 _810 = uvec3(0u);
        uvec3 _811 = uvec3(imageSize(Energy));
        _810.x = _811.x;
        _810.y = _811.y;
        _810.z = _811.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _810)))
        {
            break;
        }
        if (_433.Level == 0u)
        {
            uvec3 _815 = uvec3(textureSize(Source, 0));
            vec4 _1809;
            vec4 _1810;
            vec4 _1811;
            if (_810.x == _815.x)
            {
                uvec3 _819 = gl_GlobalInvocationID;
                uvec2 _1180 = gl_GlobalInvocationID.xy;
                float _1237 = float(_815.x);
                float _1238 = 1.0 / _1237;
                float _1245 = fma(2.0 * float(_1180.x), _1238, -1.0);
                float _1252 = fma(2.0 * float(_1180.y), _1238, -1.0);
                float _1256 = _1245 + (2.0 / _1237);
                float _1260 = _1252 + (2.0 / _1237);
                float _1275 = ((atan(_1245 * _1252, sqrt(fma(_1245, _1245, _1252 * _1252) + 1.0)) - atan(_1245 * _1260, sqrt(fma(_1245, _1245, _1260 * _1260) + 1.0))) - atan(_1256 * _1252, sqrt(fma(_1256, _1256, _1252 * _1252) + 1.0))) + atan(_1256 * _1260, sqrt(fma(_1256, _1256, _1260 * _1260) + 1.0));
                vec3 _1211 = texelFetch(Source, ivec4(ivec3(gl_GlobalInvocationID), 0).xyz, 0).xyz;
                precise vec2 _1347 = vec2(gl_GlobalInvocationID.xy) + vec2(0.5);
                precise vec2 _1351 = _1347 / vec2(float(_815.x));
                vec2 _1338 = (_1351 - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _1804;
                if (_819.z == 0u)
                {
                    _1804 = vec3(1.0, _1338.y, -_1338.x);
                }
                else
                {
                    vec3 _1805;
                    if (_819.z == 1u)
                    {
                        _1805 = vec3(-1.0, _1338.y, _1338.x);
                    }
                    else
                    {
                        vec3 _1806;
                        if (_819.z == 2u)
                        {
                            _1806 = vec3(_1338.x, 1.0, -_1338.y);
                        }
                        else
                        {
                            vec3 _1807;
                            if (_819.z == 3u)
                            {
                                _1807 = vec3(_1338.x, -1.0, _1338.y);
                            }
                            else
                            {
                                vec3 _1808;
                                if (_819.z == 4u)
                                {
                                    _1808 = vec3(_1338.x, _1338.y, 1.0);
                                }
                                else
                                {
                                    _1808 = vec3(-_1338.x, _1338.y, -1.0);
                                }
                                _1807 = _1808;
                            }
                            _1806 = _1807;
                        }
                        _1805 = _1806;
                    }
                    _1804 = _1805;
                }
                vec3 _1452 = normalize(_1804);
                precise float _1358 = max(dot(_1211, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1275;
                precise vec3 _1361 = _1211 * _1275;
                precise vec3 _1364 = _1452 * _1358;
                precise vec3 _1367 = _1452 * _1275;
                _1811 = vec4(_1367, _1275);
                _1810 = vec4(_1364, _1358);
                _1809 = vec4(_1361, _1275);
            }
            else
            {
                uvec3 _824 = gl_GlobalInvocationID;
                vec4 _1772;
                vec4 _1773;
                vec4 _1774;
                _1774 = vec4(0.0);
                _1773 = vec4(0.0);
                _1772 = vec4(0.0);
                vec4 _1528;
                vec4 _1531;
                vec4 _1534;
                for (uint _1771 = 0u; _1771 < 4u; _1774 = _1534, _1773 = _1531, _1772 = _1528, _1771++)
                {
                    uvec2 _1484 = (gl_GlobalInvocationID.xy * uvec2(2u)) + uvec2(_1771 & 1u, _1771 >> uint(1));
                    uvec2 _1456 = _1484;
                    float _1555 = float(_815.x);
                    float _1556 = 1.0 / _1555;
                    float _1563 = fma(2.0 * float(_1456.x), _1556, -1.0);
                    float _1570 = fma(2.0 * float(_1456.y), _1556, -1.0);
                    float _1574 = _1563 + (2.0 / _1555);
                    float _1578 = _1570 + (2.0 / _1555);
                    float _1593 = ((atan(_1563 * _1570, sqrt(fma(_1563, _1563, _1570 * _1570) + 1.0)) - atan(_1563 * _1578, sqrt(fma(_1563, _1563, _1578 * _1578) + 1.0))) - atan(_1574 * _1570, sqrt(fma(_1574, _1574, _1570 * _1570) + 1.0))) + atan(_1574 * _1578, sqrt(fma(_1574, _1574, _1578 * _1578) + 1.0));
                    if (_824.z == 0u)
                    {
                        imageStore(TexelSolidAngle, ivec2(_1484), vec4(_1593));
                    }
                    vec3 _1516 = texelFetch(Source, ivec4(ivec2(_1484), int(_824.z), 0).xyz, 0).xyz;
                    precise vec2 _1665 = vec2(_1484) + vec2(0.5);
                    precise vec2 _1669 = _1665 / vec2(float(_815.x));
                    vec2 _1656 = (_1669 - vec2(0.5)) * vec2(2.0, -2.0);
                    vec3 _1775;
                    if (_824.z == 0u)
                    {
                        _1775 = vec3(1.0, _1656.y, -_1656.x);
                    }
                    else
                    {
                        vec3 _1776;
                        if (_824.z == 1u)
                        {
                            _1776 = vec3(-1.0, _1656.y, _1656.x);
                        }
                        else
                        {
                            vec3 _1777;
                            if (_824.z == 2u)
                            {
                                _1777 = vec3(_1656.x, 1.0, -_1656.y);
                            }
                            else
                            {
                                vec3 _1778;
                                if (_824.z == 3u)
                                {
                                    _1778 = vec3(_1656.x, -1.0, _1656.y);
                                }
                                else
                                {
                                    vec3 _1779;
                                    if (_824.z == 4u)
                                    {
                                        _1779 = vec3(_1656.x, _1656.y, 1.0);
                                    }
                                    else
                                    {
                                        _1779 = vec3(-_1656.x, _1656.y, -1.0);
                                    }
                                    _1778 = _1779;
                                }
                                _1777 = _1778;
                            }
                            _1776 = _1777;
                        }
                        _1775 = _1776;
                    }
                    vec3 _1770 = normalize(_1775);
                    precise float _1676 = max(dot(_1516, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1593;
                    precise vec3 _1679 = _1516 * _1593;
                    precise vec3 _1682 = _1770 * _1676;
                    precise vec3 _1685 = _1770 * _1593;
                    _1528 = _1772 + vec4(_1679, _1593);
                    _1531 = _1773 + vec4(_1682, _1676);
                    _1534 = _1774 + vec4(_1685, _1593);
                }
                _1811 = _1774;
                _1810 = _1773;
                _1809 = _1772;
            }
            imageStore(Energy, ivec3(gl_GlobalInvocationID), _1809);
            imageStore(Centroid, ivec3(gl_GlobalInvocationID), _1810);
            imageStore(Geometry, ivec3(gl_GlobalInvocationID), _1811);
            break;
        }
        ivec2 _898 = ivec2(gl_GlobalInvocationID.xy) * ivec2(2);
        int _902 = int(_433.Level) - 1;
        imageStore(Energy, ivec3(gl_GlobalInvocationID), ((texelFetch(EnergyIn, ivec4(_898, int(param.z), _902).xyz, _902) + texelFetch(EnergyIn, ivec4(_898 + ivec2(1, 0), int(param.z), _902).xyz, _902)) + texelFetch(EnergyIn, ivec4(_898 + ivec2(0, 1), int(param.z), _902).xyz, _902)) + texelFetch(EnergyIn, ivec4(_898 + ivec2(1), int(param.z), _902).xyz, _902));
        imageStore(Centroid, ivec3(gl_GlobalInvocationID), ((texelFetch(CentroidIn, ivec4(_898, int(param.z), _902).xyz, _902) + texelFetch(CentroidIn, ivec4(_898 + ivec2(1, 0), int(param.z), _902).xyz, _902)) + texelFetch(CentroidIn, ivec4(_898 + ivec2(0, 1), int(param.z), _902).xyz, _902)) + texelFetch(CentroidIn, ivec4(_898 + ivec2(1), int(param.z), _902).xyz, _902));
        imageStore(Geometry, ivec3(gl_GlobalInvocationID), ((texelFetch(GeometryIn, ivec4(_898, int(param.z), _902).xyz, _902) + texelFetch(GeometryIn, ivec4(_898 + ivec2(1, 0), int(param.z), _902).xyz, _902)) + texelFetch(GeometryIn, ivec4(_898 + ivec2(0, 1), int(param.z), _902).xyz, _902)) + texelFetch(GeometryIn, ivec4(_898 + ivec2(1), int(param.z), _902).xyz, _902));
        break;
    } while(false);
}

