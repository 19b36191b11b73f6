// Common/PBR.fxh — the shading functions of the specular IBL document, transcribed.
// Every change from the printed text is listed, with its reason, in docs/hlsl-transcription.md.
#ifndef COMMON_PBR_FXH
#define COMMON_PBR_FXH

static const float PI = 3.14159265358979323846f;

// Sample count of the Monte Carlo loops; the documents use 1024.
#ifndef SAMPLE_COUNT
#define SAMPLE_COUNT 1024
#endif

float DistributionGGX( float ndoth, float roughness )
{
    float a = roughness * roughness;
    float a2 = a * a;
    float ndoth2 = ndoth * ndoth;

    float num = a2;
    float denom = ( ndoth2 * ( a2 - 1.f ) + 1.f );
    denom = PI * denom * denom;

    return num / denom;
}

float3 FresnelSchlick( float cosTheta, float3 f0 )
{
    return f0 + ( 1.f - f0 ) * pow( saturate( 1.f - cosTheta ), 5.f );
}

float GeometrySchlickGGXForIBL( float ndotv, float roughness )
{
    float a = roughness;
    float k = ( a * a ) / 2.f;

    float num = ndotv;
    float denom = ndotv * ( 1.f - k ) + k;

    return num / denom;
}

float GemoetrySmithForIBL( float ndotl, float ndotv, float roughness )
{
    float ggx1 = GeometrySchlickGGXForIBL( ndotl, roughness );
    float ggx2 = GeometrySchlickGGXForIBL( ndotv, roughness );

    return ggx1 * ggx2;
}

// The document's name is misspelled; this is the same function under the correct name.
float GeometrySmithForIBL( float ndotl, float ndotv, float roughness )
{
    return GemoetrySmithForIBL( ndotl, ndotv, roughness );
}

// VanDerCorput을 다차원으로 확장하면 Halton 수열
float VanDerCorput( uint bits )
{
    bits = ( bits << 16 ) | ( bits >> 16 );
    bits = ( ( bits & 0x55555555 ) << 1 ) | ( ( bits & 0xAAAAAAAA ) >> 1 );
    bits = ( ( bits & 0x33333333 ) << 2 ) | ( ( bits & 0xCCCCCCCC ) >> 2 );
    bits = ( ( bits & 0x0F0F0F0F ) << 4 ) | ( ( bits & 0xF0F0F0F0 ) >> 4 );
    bits = ( ( bits & 0x00FF00FF ) << 8 ) | ( ( bits & 0xFF00FF00 ) >> 8 );
    return float( bits ) * 2.3283064365386963e-10; // 0x100000000
}

float2 Hammersley( uint i, uint n )
{
    return float2( float( i ) / float( n ), VanDerCorput( i ) );
}

float3 ImportanceSampleGGX( float2 xi, float3 normal, float roughness )
{
    float a = roughness * roughness;

    float phi = 2.f * PI * xi.x;
    float cosTheta = sqrt( ( 1.f - xi.y ) / ( 1.f + ( a * a - 1.f ) * xi.y ) ); // InverseCDF
    float sinTheta = sqrt( 1.f - cosTheta * cosTheta );

    float3 h = { cos( phi ) * sinTheta, sin( phi ) * sinTheta, cosTheta };

    float3 up = ( abs( normal.y ) < 0.999f ) ? float3( 0.f, 1.f, 0.f ) : float3( 0.f, 0.f, 1.f );
    float3 right = normalize( cross( up, normal ) );
    up = normalize( cross( normal, right ) );

    float3x3 toWorld = float3x3( right, up, normal );

    return normalize( mul( h, toWorld ) );
}

float3 PrefilterSpecular( float3 normal, float roughness, TextureCube envMap, SamplerState envMapSampler )
{
    float3 viewDirection = normal;

    const uint SampleCount = SAMPLE_COUNT;
    float totalWeight = 0.f;
    float3 prefilteredColor = (float3)0.f;

    for ( uint i = 0; i < SampleCount; ++i )
    {
        float2 xi = Hammersley( i, SampleCount );
        float3 halfWay = ImportanceSampleGGX( xi, normal, roughness );
        float3 toLight = normalize( 2.f * dot( viewDirection, halfWay ) * halfWay - viewDirection );

        float ndotl = saturate( dot( normal, toLight ) );

        if (ndotl > 0.f)
        {
            prefilteredColor += envMap.SampleLevel( envMapSampler, toLight, 0 ).rgb * ndotl;
            totalWeight += ndotl;
        }
    }

    return prefilteredColor / totalWeight;
}

float2 IntegrateBRDF( float ndotv, float roughness )
{
    float3 viewDirection = { sqrt( 1.f - ndotv * ndotv ), 0.f, ndotv };

    float a = 0.f;
    float b = 0.f;

    float3 normal = { 0.f, 0.f, 1.f };

    const uint SampleCount = SAMPLE_COUNT;
    for ( uint i = 0; i < SampleCount; ++i )
    {
        float2 xi = Hammersley( i, SampleCount );
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

            a += ( 1.f - fc ) * gVis;
            b += fc * gVis;
        }
    }

    a /= (float)SampleCount;
    b /= (float)SampleCount;

    return float2( a, b );
}

// The "full approximation": the Monte Carlo estimate of the specular integral without the
// split sum. Repaired to compile (see docs/hlsl-transcription.md): the environment is passed in
// like PrefilterSpecular's, ImportanceSampleGGX takes (xi, normal, roughness), and G_Smith is the
// document's GemoetrySmithForIBL.
float3 SpecularIBL( float3 SpecularColor , float Roughness , float3 N, float3 V, TextureCube EnvMap, SamplerState EnvMapSampler )
{
    float3 SpecularLighting = 0;
    const uint NumSamples = SAMPLE_COUNT;
    for( uint i = 0; i < NumSamples; i++ )
    {
        float2 Xi = Hammersley( i, NumSamples );
        float3 H = ImportanceSampleGGX( Xi, N, Roughness );
        float3 L = 2 * dot( V, H ) * H - V;
        float NoV = saturate( dot( N, V ) );
        float NoL = saturate( dot( N, L ) );
        float NoH = saturate( dot( N, H ) );
        float VoH = saturate( dot( V, H ) );
        if( NoL > 0 )
        {
            float3 SampleColor = EnvMap.SampleLevel( EnvMapSampler , L, 0 ).rgb;
            float G = GemoetrySmithForIBL( NoL, NoV, Roughness );
            float Fc = pow( 1 - VoH, 5 );
            float3 F = (1 - Fc) * SpecularColor + Fc;
            // Incident light = SampleColor * NoL
            // Microfacet specular = D * G * F / (4 * NoL * NoV)
            // pdf = D * NoH / (4 * VoH)
            SpecularLighting += SampleColor * F * G * VoH / (NoH * NoV);
        }
    }
    return SpecularLighting / NumSamples;
}

#endif // COMMON_PBR_FXH
