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

// Every texel reads every moment straight from the buffer, all at the same index, which a CPU
// driver's vector of texels reads as one. (Sharing chunks of them through
// groupshared memory, with a barrier per chunk, took the default bake's cube 1.4 times as long,
// and twice as long to compile.) One iteration per moment: at most 6 x 64² (gpu_steps.hpp's kMaxMomentSize),
// within llvmpipe's 65535 for the invocation.
[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Irradiance.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;
    uint texels = 6 * MomentSize * MomentSize;

    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    float3 sum = 0.f;
    for ( uint index = 0; index < texels; ++index )
    {
        float3 energy = Moments[2 * index].rgb;
        float3 direction = Moments[2 * index + 1].xyz;
        sum += energy * max( dot( normal, direction ), 0.f );
    }
    Irradiance[DTid] = float4( sum / CUBE_PI, 1.f );
}
