#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, std140) uniform ClusterParameter
{
    uint Level;
} _213;

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
        uvec3 _637 = uvec3(0u);
        uvec3 _638 = uvec3(imageSize(Energy));
        _637.x = _638.x;
        _637.y = _638.y;
        _637.z = _638.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _637)))
        {
            break;
        }
        if (_213.Level == 0u)
        {
            vec3 _694 = texelFetch(Source, ivec4(ivec3(gl_GlobalInvocationID), 0).xyz, 0).xyz;
            uvec2 _641 = gl_GlobalInvocationID.xy;
            float _1054 = float(_637.x);
            float _1055 = 1.0 / _1054;
            float _1062 = fma(2.0 * float(_641.x), _1055, -1.0);
            float _1069 = fma(2.0 * float(_641.y), _1055, -1.0);
            float _1073 = _1062 + (2.0 / _1054);
            float _1077 = _1069 + (2.0 / _1054);
            float _1092 = ((atan(_1062 * _1069, sqrt(fma(_1062, _1062, _1069 * _1069) + 1.0)) - atan(_1062 * _1077, sqrt(fma(_1062, _1062, _1077 * _1077) + 1.0))) - atan(_1073 * _1069, sqrt(fma(_1073, _1073, _1069 * _1069) + 1.0))) + atan(_1073 * _1077, sqrt(fma(_1073, _1073, _1077 * _1077) + 1.0));
            vec2 _645 = (((vec2(gl_GlobalInvocationID.xy) + vec2(0.5)) / vec2(float(_637.x))) - vec2(0.5)) * vec2(2.0, -2.0);
            vec3 _1220;
            if (param.z == 0u)
            {
                _1220 = vec3(1.0, _645.y, -_645.x);
            }
            else
            {
                vec3 _1221;
                if (param.z == 1u)
                {
                    _1221 = vec3(-1.0, _645.y, _645.x);
                }
                else
                {
                    vec3 _1222;
                    if (param.z == 2u)
                    {
                        _1222 = vec3(_645.x, 1.0, -_645.y);
                    }
                    else
                    {
                        vec3 _1223;
                        if (param.z == 3u)
                        {
                            _1223 = vec3(_645.x, -1.0, _645.y);
                        }
                        else
                        {
                            vec3 _1224;
                            if (param.z == 4u)
                            {
                                _1224 = vec3(_645.x, _645.y, 1.0);
                            }
                            else
                            {
                                _1224 = vec3(-_645.x, _645.y, -1.0);
                            }
                            _1223 = _1224;
                        }
                        _1222 = _1223;
                    }
                    _1221 = _1222;
                }
                _1220 = _1221;
            }
            vec3 _1219 = normalize(_1220);
            float _717 = max(dot(_694, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875)), 0.0) * _1092;
            imageStore(Energy, ivec3(gl_GlobalInvocationID), vec4(_694 * _1092, _1092));
            imageStore(Centroid, ivec3(gl_GlobalInvocationID), vec4(_1219 * _717, _717));
            imageStore(Geometry, ivec3(gl_GlobalInvocationID), vec4(_1219 * _1092, _1092));
            break;
        }
        ivec2 _756 = ivec2(gl_GlobalInvocationID.xy) * ivec2(2);
        int _760 = int(_213.Level) - 1;
        imageStore(Energy, ivec3(gl_GlobalInvocationID), ((texelFetch(EnergyIn, ivec4(_756, int(param.z), _760).xyz, _760) + texelFetch(EnergyIn, ivec4(_756 + ivec2(1, 0), int(param.z), _760).xyz, _760)) + texelFetch(EnergyIn, ivec4(_756 + ivec2(0, 1), int(param.z), _760).xyz, _760)) + texelFetch(EnergyIn, ivec4(_756 + ivec2(1), int(param.z), _760).xyz, _760));
        imageStore(Centroid, ivec3(gl_GlobalInvocationID), ((texelFetch(CentroidIn, ivec4(_756, int(param.z), _760).xyz, _760) + texelFetch(CentroidIn, ivec4(_756 + ivec2(1, 0), int(param.z), _760).xyz, _760)) + texelFetch(CentroidIn, ivec4(_756 + ivec2(0, 1), int(param.z), _760).xyz, _760)) + texelFetch(CentroidIn, ivec4(_756 + ivec2(1), int(param.z), _760).xyz, _760));
        imageStore(Geometry, ivec3(gl_GlobalInvocationID), ((texelFetch(GeometryIn, ivec4(_756, int(param.z), _760).xyz, _760) + texelFetch(GeometryIn, ivec4(_756 + ivec2(1, 0), int(param.z), _760).xyz, _760)) + texelFetch(GeometryIn, ivec4(_756 + ivec2(0, 1), int(param.z), _760).xyz, _760)) + texelFetch(GeometryIn, ivec4(_756 + ivec2(1), int(param.z), _760).xyz, _760));
        break;
    } while(false);
}

