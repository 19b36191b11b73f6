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

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Irradiance.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    uint width = 0, height = 0, layers = 0, levels = 0;
    Source.GetDimensions( SourceMip, width, height, layers, levels );

    float3 normal = CubeFaceDirection( DTid.z, ( DTid.xy + 0.5f ) / dims.xy );
    float3 sum = 0.f;
    for ( uint face = 0; face < 6; ++face )
    {
        for ( uint y = 0; y < height; ++y )
        {
            for ( uint x = 0; x < width; ++x )
            {
                float3 direction = CubeFaceDirection( face, ( float2( x, y ) + 0.5f ) / width );
                float cosine = dot( normal, direction );
                if ( cosine > 0.f )
                {
                    float3 radiance = Source.Load( int4( x, y, face, SourceMip ) ).rgb;
                    sum += radiance * ( cosine * CubeTexelSolidAngle( uint2( x, y ), width ) );
                }
            }
        }
    }
    Irradiance[DTid] = float4( sum / CUBE_PI, 1.f );
}
