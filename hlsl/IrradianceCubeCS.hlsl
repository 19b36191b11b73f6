// Diffuse irradiance as a cube: for each texel's normal n, E(n) / pi summed over the texels of a
// coarse cube of radiance moments, the radiance a white Lambertian surface reflects: multiply by
// albedo to shade.
//
// A moment texel holds the radiance times solid angle of the finer source texels it covers and
// their luminance-weighted mean direction (the host sums them: reference::irradianceMoments).
// Where the texel lies wholly above n's horizon, its luminance times max(0, n . direction) is its
// luminance's cosine integral exactly, wherever its light sits inside it; a texel's centre alone
// errs by the light's offset from it, which beside a small bright source near the horizon is
// percents of E. A texel the horizon cuts is approximated, and colour that varies inside a texel
// follows its luminance's direction.
#include "Common/Cube.fxh"

cbuffer IrradianceParameter : register( b0 )
{
    uint MomentSize; // the moment cube's face size; Moments holds 2 entries per texel, face, row, column
};

StructuredBuffer<float4> Moments; // per texel: radiance x solid angle (rgb), then the mean direction (xyz)
RWTexture2DArray<float4> Irradiance;

static const uint GROUP_SIZE = 64;

// One chunk of the moments at a time, shared by the group: each is read once per group instead
// of once per output texel.
groupshared float3 ChunkEnergy[GROUP_SIZE];
groupshared float3 ChunkDirection[GROUP_SIZE];

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId, uint GroupIndex : SV_GroupIndex )
{
    uint3 dims = (uint3)0;
    Irradiance.GetDimensions( dims.x, dims.y, dims.z );
    bool inside = all( DTid < dims ); // every thread loads its share of each chunk
    uint texels = 6 * MomentSize * MomentSize;

    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    float3 sum = 0.f;
    for ( uint start = 0; start < texels; start += GROUP_SIZE )
    {
        uint index = start + GroupIndex;
        float3 energy = 0.f, direction = 0.f;
        if ( index < texels )
        {
            energy = Moments[2 * index].rgb;
            direction = Moments[2 * index + 1].xyz;
        }
        ChunkEnergy[GroupIndex] = energy;
        ChunkDirection[GroupIndex] = direction;
        GroupMemoryBarrierWithGroupSync();
        for ( uint i = 0; i < GROUP_SIZE; ++i )
            sum += ChunkEnergy[i] * max( dot( normal, ChunkDirection[i] ), 0.f );
        GroupMemoryBarrierWithGroupSync();
    }
    if ( inside )
        Irradiance[DTid] = float4( sum / CUBE_PI, 1.f );
}
