// One mip of a cube from the mip above it: the mean of each 2x2 block (faces are powers of
// two), which keeps the environment's total energy exact.
cbuffer DownsampleParameter : register( b0 )
{
    uint SourceMip;
};

Texture2DArray<float4> Source;
RWTexture2DArray<float4> Destination;

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Destination.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    int2 corner = int2( DTid.xy ) * 2;
    float4 sum = Source.Load( int4( corner, DTid.z, SourceMip ) )
               + Source.Load( int4( corner + int2( 1, 0 ), DTid.z, SourceMip ) )
               + Source.Load( int4( corner + int2( 0, 1 ), DTid.z, SourceMip ) )
               + Source.Load( int4( corner + int2( 1, 1 ), DTid.z, SourceMip ) );
    Destination[DTid] = sum * 0.25f;
}
