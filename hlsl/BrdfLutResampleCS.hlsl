// The quadrature-grid LUT, second pass: each texel (N.V = (x + 0.5) / width, roughness =
// (y + 0.5) / height) by bicubic Catmull-Rom interpolation of BrdfLutGridCS's nodes, in the
// grid's coordinates (Common/LutGrid.fxh). Past the grid's first and last nodes, the missing
// neighbour is extrapolated by the quadratic through the three nearest nodes: a repeated edge
// node would make the end intervals first-order (1e-3 off at a 128² grid's N.V = 1 corner).
#include "Common/LutGrid.fxh"

cbuffer LutGridParameter : register( b0 )
{
    uint GridSize; // nodes per side, at least 4
};

// A buffer, not a texture: llvmpipe loads a buffer as plain memory, and a texel fetch through
// its sampling path (16 a texel here) cost as much as the rest of the kernel.
StructuredBuffer<float2> Grid; // node (i, j) at j * GridSize + i
RWTexture2D<float2> Precomputed;

// Along a row of the grid: the four nodes around interval `cell` (0 to last - 1), weighted.
float2 RowInterpolation( int row, int cell, int last, float4 weights )
{
    // Loads stay inside the grid's row.
    int first = row * ( last + 1 );
    float2 before = Grid[first + max( cell - 1, 0 )];
    float2 start = Grid[first + cell];
    float2 end = Grid[first + cell + 1];
    float2 after = Grid[first + min( cell + 2, last )];
    if ( cell == 0 ) before = 3.f * start - 3.f * end + after;
    if ( cell == last - 1 ) after = 3.f * end - 3.f * start + before;
    return weights.x * before + weights.y * start + weights.z * end + weights.w * after;
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint2 dims = (uint2)0;
    Precomputed.GetDimensions( dims.x, dims.y );
    if ( any( DTid.xy >= dims ) )
        return;
    int2 last = (int2)GridSize - 1;
    float2 position = float2( GridPosition( ( (float)DTid.x + 0.5f ) / dims.x, last.x ),
                              GridPosition( ( (float)DTid.y + 0.5f ) / dims.y, last.y ) );
    int2 cell = min( (int2)position, last - 1 );
    float4 across = CatmullRomWeights( position.x - cell.x ), down = CatmullRomWeights( position.y - cell.y );
    float2 rows[4];
    [unroll] for ( int k = 0; k < 4; ++k )
        rows[k] = RowInterpolation( clamp( cell.y - 1 + k, 0, last.y ), cell.x, last.x, across );
    if ( cell.y == 0 ) rows[0] = 3.f * rows[1] - 3.f * rows[2] + rows[3];
    if ( cell.y == last.y - 1 ) rows[3] = 3.f * rows[2] - 3.f * rows[1] + rows[0];
    Precomputed[DTid.xy] = down.x * rows[0] + down.y * rows[1] + down.z * rows[2] + down.w * rows[3];
}
