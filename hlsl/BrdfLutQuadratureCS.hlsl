// The split-sum LUT by the deterministic quadrature of Common/BrdfQuadrature.fxh, at every
// texel: N.V = (x + 0.5) / width, roughness = (y + 0.5) / height.
#include "Common/BrdfQuadrature.fxh"

RWTexture2D<float2> Precomputed;

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint2 dims = (uint2)0;
    Precomputed.GetDimensions( dims.x, dims.y );
    if ( any( DTid.xy >= dims ) )
        return;
    BuildGaussLegendre();
    float2 uv = ( (float2)DTid.xy + 0.5f ) / dims;
    float ndotvComplement = ( (float)( dims.x - DTid.x ) - 0.5f ) / dims.x;
    Precomputed[DTid.xy] = IntegrateBrdfQuadrature( uv.x, ndotvComplement, uv.y );
}
