// The quadrature-grid LUT, second pass: each texel (N.V = (x + 0.5) / width, roughness =
// (y + 0.5) / height) by bicubic Catmull-Rom interpolation of BrdfLutGridCS's nodes, in the
// grid's coordinates (Common/LutGrid.fxh). Past the grid's first and last nodes, the missing
// neighbour is extrapolated by the quadratic through the three nearest nodes: a repeated edge
// node would make the end intervals first-order (1.8e-3 off at a 128² grid's N.V = 1 corner).
// The LUT lies in [0, 1]: saturate keeps the interpolation's undershoot of a bias near 0 from
// turning negative, which an RG16F LUT would store as a half of the other sign.
#include "Common/LutGrid.fxh"

cbuffer LutGridParameter : register( b0 )
{
    uint GridSize; // nodes per side, at least 4
};

StructuredBuffer<float2> Grid; // node (i, j) at j * GridSize + i
RWTexture2D<float2> Precomputed;

// Catmull-Rom through the four nodes around interval `cell` (0 to last - 1) of one axis. At the
// first and last intervals, the neighbour outside the grid (passed as any node) is replaced by the
// quadratic through the three nearest.
float2 CatmullRom( float2 before, float2 start, float2 end, float2 after, int cell, int last, float4 weights )
{
    if ( cell == 0 ) before = 3.f * start - 3.f * end + after;
    if ( cell == last - 1 ) after = 3.f * end - 3.f * start + before;
    return weights.x * before + weights.y * start + weights.z * end + weights.w * after;
}

// Along a row of the grid; loads stay inside the row.
float2 RowInterpolation( int row, int cell, int last, float4 weights )
{
    int first = row * ( last + 1 );
    return CatmullRom( Grid[first + max( cell - 1, 0 )], Grid[first + cell], Grid[first + cell + 1],
                       Grid[first + min( cell + 2, last )], cell, last, weights );
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint2 dims = (uint2)0;
    Precomputed.GetDimensions( dims.x, dims.y );
    if ( any( DTid.xy >= dims ) )
        return;
    int2 last = (int2)GridSize - 1;
    float2 position = float2( NdotvGridPosition( ( (float)DTid.x + 0.5f ) / dims.x, last.x ),
                              RoughnessGridPosition( ( (float)DTid.y + 0.5f ) / dims.y, last.y ) );
    int2 cell = min( (int2)position, last - 1 );
    float4 across = CatmullRomWeights( position.x - cell.x ), down = CatmullRomWeights( position.y - cell.y );
    float2 rows[4];
    [unroll] for ( int k = 0; k < 4; ++k )
        rows[k] = RowInterpolation( clamp( cell.y - 1 + k, 0, last.y ), cell.x, last.x, across );
    Precomputed[DTid.xy] = saturate( CatmullRom( rows[0], rows[1], rows[2], rows[3], cell.y, last.y, down ) );
}
