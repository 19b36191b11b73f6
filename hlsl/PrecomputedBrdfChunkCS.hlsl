// The document's LUT estimator (IntegrateBRDF in Common/PBR.fxh) over a range of its
// SAMPLE_COUNT samples, so that counts past a driver's loop limit (llvmpipe stops a loop after
// 65535 iterations) run as several dispatches. Each dispatch adds its samples' sums of the
// scale and bias terms to Accumulated; the last one also writes them divided by SAMPLE_COUNT.
// The per-sample math is the document's, from PBR.fxh's own functions, in the document's order.
#include "Common/PBR.fxh"

cbuffer BrdfChunkParameter : register( b0 )
{
    uint FirstSample;
    uint ChunkSamples;
    uint Resolve;
};

RWTexture2D<float2> Accumulated;
RWTexture2D<float2> Precomputed;

float2 IntegrateBrdfChunk( float ndotv, float roughness )
{
    float3 viewDirection = { sqrt( 1.f - ndotv * ndotv ), 0.f, ndotv };
    float3 normal = { 0.f, 0.f, 1.f };
    float2 sums = 0.f;
    for ( uint i = FirstSample; i < FirstSample + ChunkSamples; ++i )
    {
        float2 xi = Hammersley( i, SAMPLE_COUNT );
        float3 halfWay = ImportanceSampleGGX( xi, normal, roughness );
        float3 toLight = normalize( 2.f * dot( viewDirection, halfWay ) * halfWay - viewDirection );

        float ndotl = saturate( toLight.z );
        float ndoth = saturate( halfWay.z );
        float vdoth = saturate( dot( viewDirection, halfWay ) );

        if ( ndotl > 0.f )
        {
            float g = GemoetrySmithForIBL( ndotl, ndotv, roughness );
            float gVis = ( g * vdoth ) / ( ndoth * ndotv );
            float fc = pow( 1.f - vdoth, 5.f );
            sums += float2( ( 1.f - fc ) * gVis, fc * gVis );
        }
    }
    return sums;
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint2 dims = (uint2)0;
    Precomputed.GetDimensions( dims.x, dims.y );
    if ( any( DTid.xy >= dims ) )
        return;

    float2 uv = ( (float2)DTid.xy + 0.5f ) / dims;
    float2 sums = IntegrateBrdfChunk( uv.x, uv.y );
    if ( FirstSample > 0 )
        sums += Accumulated[DTid.xy];
    Accumulated[DTid.xy] = sums;
    if ( Resolve != 0 )
        Precomputed[DTid.xy] = sums / (float)SAMPLE_COUNT;
}
