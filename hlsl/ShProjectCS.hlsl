// Projects one mip of a cube onto the 9 spherical harmonics of bands 0-2: the integral of
// radiance times Y_lm over the sphere, each texel weighted by its exact solid angle. Every
// 8x8 group reduces its texels in shared memory and writes 9 partial sums (rgb, and the solid
// angle it covered in w); the host adds the groups' partial sums in double.
#include "Common/Cube.fxh"
#include "Common/SphericalHarmonics.fxh"

cbuffer ShProjectParameter : register( b0 )
{
    uint SourceMip;
};

Texture2DArray<float4> Source;
RWStructuredBuffer<float4> Partials;

static const uint GROUP_SIZE = 64;
groupshared float4 Shared[GROUP_SIZE][SH_COEFFICIENT_COUNT];

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId, uint3 Gid : SV_GroupID, uint GI : SV_GroupIndex )
{
    uint width = 0, height = 0, layers = 0, levels = 0;
    Source.GetDimensions( SourceMip, width, height, layers, levels );

    float basis[SH_COEFFICIENT_COUNT];
    ShBasis( float3( 0.f, 0.f, 1.f ), basis );
    float3 radiance = 0.f;
    float solidAngle = 0.f;
    if ( DTid.x < width && DTid.y < height )
    {
        float3 direction = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / width );
        ShBasis( direction, basis );
        solidAngle = CubeTexelSolidAngle( DTid.xy, width );
        radiance = Source.Load( int4( DTid.xy, DTid.z, SourceMip ) ).rgb;
    }
    for ( uint k = 0; k < SH_COEFFICIENT_COUNT; ++k )
        Shared[GI][k] = float4( radiance * basis[k] * solidAngle, solidAngle );
    GroupMemoryBarrierWithGroupSync();

    for ( uint stride = GROUP_SIZE / 2; stride > 0; stride /= 2 )
    {
        if ( GI < stride )
        {
            for ( uint k = 0; k < SH_COEFFICIENT_COUNT; ++k )
                Shared[GI][k] += Shared[GI + stride][k];
        }
        GroupMemoryBarrierWithGroupSync();
    }

    if ( GI == 0 )
    {
        uint groupsX = ( width + 7 ) / 8;
        uint groupsY = ( height + 7 ) / 8;
        uint group = ( Gid.z * groupsY + Gid.y ) * groupsX + Gid.x;
        for ( uint k = 0; k < SH_COEFFICIENT_COUNT; ++k )
            Partials[group * SH_COEFFICIENT_COUNT + k] = Shared[0][k];
    }
}
