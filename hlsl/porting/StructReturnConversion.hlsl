// A vertex shader that passes its input through as its output, a struct of the same member types
// under another name (Direct3D's samples write it): HLSL converts it member by member.
struct Vertex
{
    float4 position : SV_Position;
    float4 colour : COLOR0;
};

struct Interpolants
{
    float4 position : SV_Position;
    float4 colour : COLOR0;
};

Interpolants main(Vertex input)
{
    return input;
}
