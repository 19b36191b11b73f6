// iblkit render's split-sum image: the spheres of Common/SphereGrid.fxh shaded with the baked maps,
// in linear radiance, for the host to hold against RenderReferenceCS's Monte Carlo reference, each
// pixel as Common/SplitSumShading.fxh shades it.
#include "Common/SplitSumShading.fxh"

RWTexture2D<float4> SplitSum;

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint2 dims = ( uint2 )0;
    SplitSum.GetDimensions( dims.x, dims.y );
    if ( any( DTid.xy >= dims ) )
        return;
    SphereHit hit = SphereAt( DTid.xy, Columns, CellSize );
    float3 color = hit.Covered ? SplitSumShade( hit.Material, hit.Normal, float3( 0.f, 0.f, 1.f ) ) : ( float3 )0.f;
    SplitSum[DTid.xy] = float4( color, hit.Covered ? 1.f : 0.f );
}
