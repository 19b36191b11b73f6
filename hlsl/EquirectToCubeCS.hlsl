// An equirectangular panorama resampled onto a cube's faces. Each cube texel averages
// Supersample² bilinear reads spread over its footprint, so a panorama finer than the cube is
// filtered rather than point-sampled and a small bright sun keeps its energy.
#include "Common/Cube.fxh"

cbuffer EquirectToCubeParameter : register( b0 )
{
    uint Supersample;
};

Texture2D<float4> Equirect;
RWTexture2DArray<float4> Cube;

// Longitude wraps around; latitude stops at the poles. A bilinear read's column is -1 to
// dims.x, so one step either way wraps it (where a remainder would be an integer division per
// lane on CPU drivers, most of this kernel's time there); the clamp keeps any other in the image.
float3 EquirectTexel( int2 texel, int2 dims )
{
    texel.x += texel.x < 0 ? dims.x : ( texel.x >= dims.x ? -dims.x : 0 );
    texel.x = clamp( texel.x, 0, dims.x - 1 );
    texel.y = clamp( texel.y, 0, dims.y - 1 );
    return Equirect.Load( int3( texel, 0 ) ).rgb;
}

// Bilinear filtering in float on the shader's side: exact, and free of the texture unit's
// reduced sub-texel precision.
float3 SampleEquirect( float3 direction, int2 dims )
{
    float2 position = DirectionToEquirect( direction ) * dims - 0.5f;
    float2 cell = floor( position );
    float2 f = position - cell;
    int2 i = (int2)cell;
    float3 top = lerp( EquirectTexel( i, dims ), EquirectTexel( i + int2( 1, 0 ), dims ), f.x );
    float3 bottom = lerp( EquirectTexel( i + int2( 0, 1 ), dims ), EquirectTexel( i + int2( 1, 1 ), dims ), f.x );
    return lerp( top, bottom, f.y );
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Cube.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    uint2 sourceDims = (uint2)0;
    Equirect.GetDimensions( sourceDims.x, sourceDims.y );

    float3 sum = 0.f;
    for ( uint j = 0; j < Supersample; ++j )
    {
        for ( uint i = 0; i < Supersample; ++i )
        {
            float2 offset = ( float2( i, j ) + 0.5f ) / Supersample;
            float3 direction = CubeFaceDirection( DTid.z, ( DTid.xy + offset ) / dims.xy );
            sum += SampleEquirect( direction, (int2)sourceDims );
        }
    }
    Cube[DTid] = float4( sum / ( Supersample * Supersample ), 1.f );
}
