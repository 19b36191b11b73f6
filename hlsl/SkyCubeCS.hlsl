// The built-in environment, rendered straight into mip 0 of a cube: a blue sky brightening to a
// hazy horizon, a sun disc of 2.5° radius and radiance 4000 with a glow (about six times the
// sky's irradiance, like a clear day), and a checkered ground. Each texel is the mean of
// Supersample² evaluations spread over its footprint, so the sun's disc and the checker's edges
// keep their energy. reference/sky_environment.hpp is the same function in C++.
#include "Common/Cube.fxh"

cbuffer SkyCubeParameter : register( b0 )
{
    uint Supersample;
};

RWTexture2DArray<float4> Cube;

static const float3 SUN_COLOR = float3( 1.f, 0.92f, 0.8f );
static const float SUN_RADIUS = 2.5f * CUBE_PI / 180.f;
static const float SUN_EDGE = 0.1f * CUBE_PI / 180.f;

float3 SkyRadiance( float3 d )
{
    float3 zenith = float3( 0.18f, 0.36f, 0.95f ), horizon = float3( 1.05f, 1.1f, 1.2f );
    return lerp( horizon, zenith, pow( saturate( d.y ), 0.4f ) );
}

float3 GroundRadiance( float3 d )
{
    float longitude = atan2( d.x, -d.z ), latitude = asin( clamp( d.y, -1.f, 1.f ) );
    int cell = int( floor( longitude / ( CUBE_PI / 12.f ) ) ) + int( floor( latitude / ( CUBE_PI / 24.f ) ) );
    float3 ground = ( cell & 1 ) != 0 ? float3( 0.42f, 0.36f, 0.28f ) : float3( 0.16f, 0.14f, 0.12f );
    // A hazy band just below the horizon joins the ground to the sky.
    return lerp( ground, float3( 0.9f, 0.92f, 0.95f ), exp( d.y * 40.f ) );
}

float3 SunRadiance( float3 d )
{
    // The angle by atan2 of sine and cosine: acos loses it near the sun's centre, in float.
    float3 sun = normalize( float3( 0.3f, 0.45f, 0.84f ) );
    float angle = atan2( length( cross( d, sun ) ), dot( d, sun ) );
    float disc = saturate( ( SUN_RADIUS + SUN_EDGE - angle ) / ( 2.f * SUN_EDGE ) );
    return SUN_COLOR * ( 4000.f * disc + 40.f * exp( -angle * 25.f ) );
}

float3 EnvironmentRadiance( float3 d )
{
    return ( d.y >= 0.f ? SkyRadiance( d ) : GroundRadiance( d ) ) + SunRadiance( d );
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Cube.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    float3 sum = 0.f;
    for ( uint j = 0; j < Supersample; ++j )
    {
        for ( uint i = 0; i < Supersample; ++i )
        {
            float2 at = float2( DTid.xy ) + ( float2( i, j ) + 0.5f ) / float( Supersample );
            sum += EnvironmentRadiance( CubeFaceDirection( DTid.z, at / float( dims.x ) ) );
        }
    }
    Cube[DTid] = float4( sum / float( Supersample * Supersample ), 1.f );
}
