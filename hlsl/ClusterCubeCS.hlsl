// One level of the energy pyramid that PrefilterConvolutionCS sums: for every texel of the
// level, the radiance integrated over its exact solid angle, where that light sits (the
// luminance-weighted sum of its directions) and where the texel itself sits (the solid-angle
// weighted sum of its directions). A texel of level n covers 2^n x 2^n texels of the
// source's mip 0, so each level is exact, not a mean of means weighted alike.
#include "Common/Cube.fxh"

cbuffer ClusterParameter : register( b0 )
{
    uint Level; // 0: from Source's mip 0; above it: the 2x2 blocks of level Level - 1
};

Texture2DArray<float4> Source;     // the radiance cube
Texture2DArray<float4> EnergyIn;   // Energy and Centroid themselves, read at level Level - 1
Texture2DArray<float4> CentroidIn;
Texture2DArray<float4> GeometryIn;
RWTexture2DArray<float4> Energy;   // rgb: radiance times solid angle; a: solid angle
RWTexture2DArray<float4> Centroid; // xyz: the sum of w times direction; a: the sum of w; w = max(luminance, 0) times solid angle
RWTexture2DArray<float4> Geometry; // xyz: the sum of solid angle times direction; a: solid angle

static const float3 LUMINANCE = float3( 0.2126f, 0.7152f, 0.0722f );

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Energy.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    if ( Level == 0 )
    {
        float3 radiance = Source.Load( int4( DTid, 0 ) ).rgb;
        float solidAngle = CubeTexelSolidAngle( DTid.xy, dims.x );
        float3 direction = CubeFaceDirection( DTid.z, ( float2( DTid.xy ) + 0.5f ) / float( dims.x ) );
        float weight = max( dot( radiance, LUMINANCE ), 0.f ) * solidAngle;
        Energy[DTid] = float4( radiance * solidAngle, solidAngle );
        Centroid[DTid] = float4( direction * weight, weight );
        Geometry[DTid] = float4( direction * solidAngle, solidAngle );
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
