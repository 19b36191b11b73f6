// The spheres of iblkit render drawn as an engine's forward pass draws meshes: one unit-sphere mesh
// (vertex buffer, index buffer), one instance per cell of Common/SphereGrid.fxh's grid, seen by
// the same orthographic camera looking down -Z, each pixel shaded from the baked maps and lights
// as Common/SplitSumShading.fxh shades it, from the mesh's interpolated normal. The image is
// SplitSumSpheresCS's but for what a mesh changes: the normal between the vertices' and the
// silhouette's polygon. Every lookup is the fxh's SampleLevel: the prefiltered cube at the lod
// of the surface's roughness, as engines read it (textureLod); the irradiance cube and the LUT at
// mip 0, which is all they have, so an engine's Sample would read the same texels.
#include "Common/SplitSumShading.fxh"

struct SphereVertex
{
    float3 Position : POSITION; // on the unit sphere: also the outward normal
    uint Instance : SV_InstanceID;
};

struct SphereFragment
{
    float4 Position : SV_Position;
    float3 Normal : NORMAL;
    nointerpolation uint2 Cell : CELL;
};

// The grid's size in pixels: Columns cells across, as many rows as Spheres holds cells.
float2 GridSize()
{
    uint values, stride;
    Spheres.GetDimensions( values, stride );
    uint rows = ( values / 2u + Columns - 1u ) / Columns;
    return float2( Columns, rows ) * CellSize;
}

SphereFragment VSMain( SphereVertex input )
{
    SphereFragment output;
    uint2 cell = uint2( input.Instance % Columns, input.Instance / Columns );
    // SphereAt's mapping backwards: the point over which normal n lies is SPHERE_RADIUS n.xy
    // half cells from the cell's centre, y down the image.
    float2 pixel = ( float2( cell ) + 0.5f + 0.5f * SPHERE_RADIUS * float2( input.Position.x, -input.Position.y ) ) * CellSize;
    output.Position = float4( pixel / GridSize() * float2( 2.f, -2.f ) + float2( -1.f, 1.f ), 0.5f - 0.5f * input.Position.z, 1.f );
    output.Normal = input.Position;
    output.Cell = cell;
    return output;
}

float4 PSMain( SphereFragment input ) : SV_Target0
{
    float3 color = SplitSumShade( SphereMaterialOf( input.Cell, Columns ), normalize( input.Normal ), float3( 0.f, 0.f, 1.f ) );
    return float4( color, 1.f );
}
