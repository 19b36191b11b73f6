#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform ClusterParameter
{
    uint Level;
} _397;

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
        uvec3 _742 = uvec3(0u);
        uvec3 _743 = uvec3(imageSize(Energy));
        _742.x = _743.x;
        _742.y = _743.y;
        _742.z = _743.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _742)))
        {
            break;
        }
        if (_397.Level == 0u)
        {
            uvec3 _747 = gl_GlobalInvocationID;
            uvec3 _1083 = uvec3(textureSize(Source, 0));
            vec4 _1411;
            vec4 _1412;
            vec4 _1413;
            _1413 = vec4(0.0);
            _1412 = vec4(0.0);
            _1411 = vec4(0.0);
            vec4 _1167;
            vec4 _1170;
            vec4 _1173;
            for (uint _1410 = 0u; _1410 < 4u; _1413 = _1173, _1412 = _1170, _1411 = _1167, _1410++)
            {
                uvec2 _1123 = (gl_GlobalInvocationID.xy * uvec2(2u)) + uvec2(_1410 & 1u, _1410 >> uint(1));
                uvec2 _1087 = _1123;
                float _1194 = float(_1083.x);
                float _1195 = 1.0 / _1194;
                float _1202 = fma(2.0 * float(_1087.x), _1195, -1.0);
                float _1209 = fma(2.0 * float(_1087.y), _1195, -1.0);
                float _1213 = _1202 + (2.0 / _1194);
                float _1217 = _1209 + (2.0 / _1194);
                float _1232 = ((atan(_1202 * _1209, sqrt(fma(_1202, _1202, _1209 * _1209) + 1.0)) - atan(_1202 * _1217, sqrt(fma(_1202, _1202, _1217 * _1217) + 1.0))) - atan(_1213 * _1209, sqrt(fma(_1213, _1213, _1209 * _1209) + 1.0))) + atan(_1213 * _1217, sqrt(fma(_1213, _1213, _1217 * _1217) + 1.0));
                if (_747.z == 0u)
                {
                    imageStore(TexelSolidAngle, ivec2(_1123), vec4(_1232));
                }
                vec3 _1155 = texelFetch(Source, ivec4(ivec2(_1123), int(_747.z), 0).xyz, 0).xyz;
                precise vec2 _1304 = vec2(_1123) + vec2(0.5);
                precise vec2 _1308 = _1304 / vec2(float(_1083.x));
                vec2 _1295 = (_1308 - vec2(0.5)) * vec2(2.0, -2.0);
                vec3 _1414;
                if (_747.z == 0u)
                {
                    _1414 = vec3(1.0, _1295.y, -_1295.x);
                }
                else
                {
                    vec3 _1415;
                    if (_747.z == 1u)
                    {
                        _1415 = vec3(-1.0, _1295.y, _1295.x);
                    }
                    else
                    {
                        vec3 _1416;
                        if (_747.z == 2u)
                        {
                            _1416 = vec3(_1295.x, 1.0, -_1295.y);
                        }
                        else
                        {
                            vec3 _1417;
                            if (_747.z == 3u)
                            {
                                _1417 = vec3(_1295.x, -1.0, _1295.y);
                            }
                            else
                            {
                                vec3 _1418;
                                if (_747.z == 4u)
                                {
                                    _1418 = vec3(_1295.x, _1295.y, 1.0);
                                }
                                else
                                {
                                    _1418 = vec3(-_1295.x, _1295.y, -1.0);
                                }
                                _1417 = _1418;
                            }
                            _1416 = _1417;
                        }
                        _1415 = _1416;
                    }
                    _1414 = _1415;
                }
                vec3 _1409 = normalize(_1414);
                precise float _1315 = max(dot(_1155, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1232;
                precise vec3 _1318 = _1155 * _1232;
                precise vec3 _1321 = _1409 * _1315;
                precise vec3 _1324 = _1409 * _1232;
                _1167 = _1411 + vec4(_1318, _1232);
                _1170 = _1412 + vec4(_1321, _1315);
                _1173 = _1413 + vec4(_1324, _1232);
            }
            imageStore(Energy, ivec3(gl_GlobalInvocationID), _1411);
            imageStore(Centroid, ivec3(gl_GlobalInvocationID), _1412);
            imageStore(Geometry, ivec3(gl_GlobalInvocationID), _1413);
            break;
        }
        ivec2 _798 = ivec2(gl_GlobalInvocationID.xy) * ivec2(2);
        int _802 = int(_397.Level) - 1;
        imageStore(Energy, ivec3(gl_GlobalInvocationID), ((texelFetch(EnergyIn, ivec4(_798, int(param.z), _802).xyz, _802) + texelFetch(EnergyIn, ivec4(_798 + ivec2(1, 0), int(param.z), _802).xyz, _802)) + texelFetch(EnergyIn, ivec4(_798 + ivec2(0, 1), int(param.z), _802).xyz, _802)) + texelFetch(EnergyIn, ivec4(_798 + ivec2(1), int(param.z), _802).xyz, _802));
        imageStore(Centroid, ivec3(gl_GlobalInvocationID), ((texelFetch(CentroidIn, ivec4(_798, int(param.z), _802).xyz, _802) + texelFetch(CentroidIn, ivec4(_798 + ivec2(1, 0), int(param.z), _802).xyz, _802)) + texelFetch(CentroidIn, ivec4(_798 + ivec2(0, 1), int(param.z), _802).xyz, _802)) + texelFetch(CentroidIn, ivec4(_798 + ivec2(1), int(param.z), _802).xyz, _802));
        imageStore(Geometry, ivec3(gl_GlobalInvocationID), ((texelFetch(GeometryIn, ivec4(_798, int(param.z), _802).xyz, _802) + texelFetch(GeometryIn, ivec4(_798 + ivec2(1, 0), int(param.z), _802).xyz, _802)) + texelFetch(GeometryIn, ivec4(_798 + ivec2(0, 1), int(param.z), _802).xyz, _802)) + texelFetch(GeometryIn, ivec4(_798 + ivec2(1), int(param.z), _802).xyz, _802));
        break;
    } while(false);
}

