// The quadrature-grid LUT, first pass: the quadrature of Common/BrdfQuadrature.fxh at the nodes
// of a small grid (Common/LutGrid.fxh), which BrdfLutResampleCS interpolates to the LUT's texels.
// The LUT is smooth in the grid's coordinates, so a 64² grid stands for a 512² LUT within 1e-3:
// 64 times fewer quadratures.
#include "Common/BrdfQuadrature.fxh"
#include "Common/LutGrid.fxh"

cbuffer LutGridParameter : register( b0 )
{
    uint GridSize; // nodes per side, at least 4
};

RWStructuredBuffer<float2> Grid; // node (i, j) at j * GridSize + i

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    if ( any( DTid.xy >= GridSize ) )
        return;
    BuildGaussLegendre();
    float2 ndotv = NdotvGridNodeValue( (float)DTid.x / (float)( GridSize - 1 ) );
    float roughness = RoughnessGridNodeValue( (float)DTid.y / (float)( GridSize - 1 ) );
    Grid[DTid.y * GridSize + DTid.x] = IntegrateBrdfQuadrature( ndotv.x, ndotv.y, roughness );
}
