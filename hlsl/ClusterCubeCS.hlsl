// One level of the energy pyramid that PrefilterConvolutionCS sums: for every texel of the
// level, the radiance integrated over its exact solid angle, where that light sits (the
// luminance-weighted sum of its directions) and where the texel itself sits (the solid-angle
// weighted sum of its directions). Each level is exact, not a mean of means weighted alike. A
// pyramid half the source's width keeps no single texels (Common/EnergyPyramid.fxh): its mip n
// covers 2^(n+1) x 2^(n+1) source texels. One as wide as the source keeps them as its mip 0,
// and its mip n covers 2^n x 2^n.
#include "Common/EnergyPyramid.fxh"

cbuffer ClusterParameter : register( b0 )
{
    uint Level; // 0: from Source's mip 0 (its texels, or 2x2 of them); above it: the 2x2 blocks of level Level - 1
};

Texture2DArray<float4> Source;     // the radiance cube
Texture2DArray<float4> EnergyIn;   // Energy, Centroid and Geometry themselves, read at level Level - 1
Texture2DArray<float4> CentroidIn;
Texture2DArray<float4> GeometryIn;
RWTexture2DArray<float4> Energy;   // rgb: radiance times solid angle; a: solid angle
RWTexture2DArray<float4> Centroid; // xyz: the sum of w times direction; a: the sum of w; w = max(luminance, 0) times solid angle
RWTexture2DArray<float4> Geometry; // xyz: the sum of solid angle times direction; a: solid angle
RWTexture2D<float> TexelSolidAngle; // each source texel's (the same on every face), written with a half-width level 0

// The four texels of the source below pyramid texel DTid, summed in the order of the levels above.
void SourceQuad( uint3 DTid, uint sourceSize, out float4 energy, out float4 weighted, out float4 geometry )
{
    energy = 0.f;
    weighted = 0.f;
    geometry = 0.f;
    for ( uint corner = 0; corner < 4; ++corner )
    {
        uint2 xy = DTid.xy * 2u + uint2( corner & 1u, corner >> 1 );
        float solidAngle = CubeTexelSolidAngle( xy, sourceSize );
        if ( DTid.z == 0 )
            TexelSolidAngle[xy] = solidAngle;
        float4 e, w, g;
        SourceTexelBlock( Source.Load( int4( xy, DTid.z, 0 ) ).rgb, DTid.z, xy, sourceSize, solidAngle, e, w, g );
        energy += e;
        weighted += w;
        geometry += g;
    }
}

// Source texel DTid itself, where the pyramid is as wide as the source and keeps single texels as
// its level 0 (PrefilterConvolutionCS's SOURCE_TEXELS_IN_PYRAMID, which reads no TexelSolidAngle).
void SourceTexel( uint3 DTid, uint sourceSize, out float4 energy, out float4 weighted, out float4 geometry )
{
    SourceTexelBlock( Source.Load( int4( DTid, 0 ) ).rgb, DTid.z, DTid.xy, sourceSize, CubeTexelSolidAngle( DTid.xy, sourceSize ),
                      energy, weighted, geometry );
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Energy.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    if ( Level == 0 )
    {
        uint sourceSize = 0, sourceHeight = 0, layers = 0;
        Source.GetDimensions( sourceSize, sourceHeight, layers );
        float4 energy, weighted, geometry;
        if ( dims.x == sourceSize )
            SourceTexel( DTid, sourceSize, energy, weighted, geometry );
        else
            SourceQuad( DTid, sourceSize, energy, weighted, geometry );
        Energy[DTid] = energy;
        Centroid[DTid] = weighted;
        Geometry[DTid] = geometry;
        return;
    }

    int2 corner = int2( DTid.xy ) * 2;
    int below = int( Level ) - 1;
    float4 energy = EnergyIn.Load( int4( corner, DTid.z, below ) )
                  + EnergyIn.Load( int4( corner + int2( 1, 0 ), DTid.z, below ) )
                  + EnergyIn.Load( int4( corner + int2( 0, 1 ), DTid.z, below ) )
                  + EnergyIn.Load( int4( corner + int2( 1, 1 ), DTid.z, below ) );
    float4 weighted = CentroidIn.Load( int4( corner, DTid.z, below ) )
                    + CentroidIn.Load( int4( corner + int2( 1, 0 ), DTid.z, below ) )
                    + CentroidIn.Load( int4( corner + int2( 0, 1 ), DTid.z, below ) )
                    + CentroidIn.Load( int4( corner + int2( 1, 1 ), DTid.z, below ) );
    float4 geometry = GeometryIn.Load( int4( corner, DTid.z, below ) )
                    + GeometryIn.Load( int4( corner + int2( 1, 0 ), DTid.z, below ) )
                    + GeometryIn.Load( int4( corner + int2( 0, 1 ), DTid.z, below ) )
                    + GeometryIn.Load( int4( corner + int2( 1, 1 ), DTid.z, below ) );
    Energy[DTid] = energy;
    Centroid[DTid] = weighted;
    Geometry[DTid] = geometry;
}
