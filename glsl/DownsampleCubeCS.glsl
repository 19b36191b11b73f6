#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

int _340;

layout(binding = 0, std140) uniform DownsampleParameter
{
    uint SourceMip;
} _68;

layout(binding = 0, rgba32f) uniform writeonly image2DArray Destination;
layout(binding = 0) uniform sampler2DArray Source;

void main()
{
    uvec3 param = gl_GlobalInvocationID;
    do
    {
        uvec3 _199 = uvec3(0u);
        uvec3 _200 = uvec3(imageSize(Destination));
        _199.x = _200.x;
        _199.y = _200.y;
        _199.z = _200.z;
        if (any(greaterThanEqual(gl_GlobalInvocationID, _199)))
        {
            break;
        }
        ivec2 _227 = ivec2(gl_GlobalInvocationID.xy) * ivec2(2);
        imageStore(Destination, ivec3(gl_GlobalInvocationID), (((texelFetch(Source, ivec4(_227, int(param.z), _340).xyz, int(_68.SourceMip)) + texelFetch(Source, ivec4(_227 + ivec2(1, 0), int(param.z), _340).xyz, int(_68.SourceMip))) + texelFetch(Source, ivec4(_227 + ivec2(0, 1), int(param.z), _340).xyz, int(_68.SourceMip))) + texelFetch(Source, ivec4(_227 + ivec2(1), int(param.z), _340).xyz, int(_68.SourceMip))) * 0.25);
        break;
    } while(false);
}

