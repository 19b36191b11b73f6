// Diffuse irradiance as a cube: for each texel's normal n, the exact sum over every texel of a
// source mip of radiance * max(0, n . l) * solid angle, divided by pi. A texel holds E(n) / pi,
// the radiance a white Lambertian surface reflects: multiply by albedo to shade.
#include "Common/Cube.fxh"

cbuffer IrradianceParameter : register( b0 )
{
    uint SourceMip;
};

Texture2DArray<float4> Source;
RWTexture2DArray<float4> Irradiance;

static const uint GROUP_SIZE = 64;

// One chunk of the source's texels at a time, shared by the group: each texel's direction and
// its radiance times its solid angle are computed once per group instead of once per output
// texel (CubeTexelSolidAngle's four atan2 cost more than the rest of the sum).
groupshared float3 ChunkDirection[GROUP_SIZE];
groupshared float3 ChunkEnergy[GROUP_SIZE];

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId, uint GroupIndex : SV_GroupIndex )
{
    uint3 dims = (uint3)0;
    Irradiance.GetDimensions( dims.x, dims.y, dims.z );
    bool inside = all( DTid < dims ); // every thread loads its share of each chunk

    uint width = 0, height = 0, layers = 0, levels = 0;
    Source.GetDimensions( SourceMip, width, height, layers, levels );
    uint faceTexels = width * width, texels = 6 * faceTexels;

    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    float3 sum = 0.f;
    for ( uint start = 0; start < texels; start += GROUP_SIZE )
    {
        uint index = start + GroupIndex;
        float3 direction = 0.f, energy = 0.f;
        if ( index < texels )
        {
            uint face = index / faceTexels, x = index % width, y = ( index % faceTexels ) / width;
            direction = CubeFaceDirection( face, ( float2( x, y ) + 0.5f ) / width );
            energy = Source.Load( int4( x, y, face, SourceMip ) ).rgb * CubeTexelSolidAngle( uint2( x, y ), width );
        }
        ChunkDirection[GroupIndex] = direction;
        ChunkEnergy[GroupIndex] = energy;
        GroupMemoryBarrierWithGroupSync();
        for ( uint i = 0; i < GROUP_SIZE; ++i )
        {
            float cosine = dot( normal, ChunkDirection[i] );
            if ( cosine > 0.f )
                sum += ChunkEnergy[i] * cosine;
        }
        GroupMemoryBarrierWithGroupSync();
    }
    if ( inside )
        Irradiance[DTid] = float4( sum / CUBE_PI, 1.f );
}
