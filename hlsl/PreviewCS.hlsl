// The bake's preview: a grid of spheres, roughness 0 to 1 across and metalness 0 to 1 down,
// shaded with the baked maps and lights as the bake's shading recipe reads them
// (Common/ImageBasedLighting.fxh's IblShadeOpaque and IblDiskLight; the documents' recipe is
// their split-sum combine plus the diffuse term), above a strip of the prefiltered mips as
// panoramas; tone mapped and sRGB encoded for an 8-bit image.
#include "Common/Cube.fxh"
#include "Common/ImageBasedLighting.fxh"

cbuffer PreviewParameter : register( b0 )
{
    uint Columns;
    uint Rows;
    uint CellSize;
    uint SpecularMips;
    uint StripPanelWidth;
    float Exposure;
    uint SpecularSize;
    uint LodMapping;
    float LodParameter;
    uint Direction;
    uint Lookup;
    uint LightCount;
    uint LightLevel;
};

TextureCube Specular;
TextureCube IrradianceMap;
Texture2D<float2> BrdfLut;
Texture2D<float4> LobeTable;
// Two float4 per light: (direction towards it, angular radius), (radiance, solid angle).
StructuredBuffer<float4> Lights;
SamplerState LinearClamp;
RWTexture2D<float4> Preview;

// Gold's reflectance at normal incidence: orange plastic at metalness 0, gold at 1.
static const float3 BASE_COLOR = float3( 1.f, 0.766f, 0.336f );
static const float3 BACKGROUND = float3( 0.02f, 0.02f, 0.02f );

IblRecipe Recipe()
{
    return IblRecipeOf( LodMapping, LodParameter, SpecularMips, SpecularSize, Direction, Lookup, LightCount, LightLevel );
}

float Fraction( uint index, uint count )
{
    return count > 1 ? float( index ) / float( count - 1 ) : 0.f;
}

// Krzysztof Narkowicz's fit of the ACES filmic curve, then the sRGB transfer function.
float3 ToneMap( float3 color )
{
    color *= Exposure;
    color = saturate( ( color * ( 2.51f * color + 0.03f ) ) / ( color * ( 2.43f * color + 0.59f ) + 0.14f ) );
    float3 linearPart = 12.92f * color;
    float3 curvedPart = 1.055f * pow( color, 1.f / 2.4f ) - 0.055f;
    return lerp( curvedPart, linearPart, step( color, (float3)0.0031308f ) );
}

float3 ShadeSphere( uint2 pixel )
{
    uint2 cell = pixel / CellSize;
    float2 p = ( float2( pixel % CellSize ) + 0.5f ) / CellSize * 2.f - 1.f;
    p.y = -p.y;
    const float radius = 0.9f;
    float r2 = dot( p, p ) / ( radius * radius );
    if ( r2 >= 1.f )
        return BACKGROUND;

    float roughness = Fraction( cell.x, Columns );
    float metalness = Fraction( cell.y, Rows );
    float3 normal = float3( p / radius, sqrt( 1.f - r2 ) );
    float3 viewDirection = float3( 0.f, 0.f, 1.f );
    float residualShare;
    float3 color = IblShadeOpaque( normal, viewDirection, BASE_COLOR, roughness, metalness, Recipe(), Specular,
                                   IrradianceMap, BrdfLut, LobeTable, LinearClamp, residualShare );
    float3 f0 = lerp( (float3)0.04f, BASE_COLOR, metalness );
    float3 albedo = IblDirectionalAlbedo( normal, viewDirection, roughness, f0, BrdfLut, LinearClamp );
    for ( uint i = 0u; i < LightCount; ++i )
        color += IblDiskLight( normal, viewDirection, roughness, f0, albedo, BASE_COLOR * ( 1.f - metalness ), residualShare,
                               Lights[2u * i], Lights[2u * i + 1u] );
    return color;
}

float3 ShadeStrip( uint2 pixel )
{
    uint panel = pixel.x / StripPanelWidth;
    if ( panel >= SpecularMips )
        return BACKGROUND;
    float2 uv = ( float2( pixel.x % StripPanelWidth, pixel.y ) + 0.5f ) / float2( StripPanelWidth, StripPanelWidth / 2 );
    return Specular.SampleLevel( LinearClamp, EquirectToDirection( uv ), panel ).rgb;
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint2 dims = (uint2)0;
    Preview.GetDimensions( dims.x, dims.y );
    if ( any( DTid.xy >= dims ) )
        return;

    uint gridHeight = Rows * CellSize;
    float3 color;
    if ( DTid.x >= Columns * CellSize )
        color = BACKGROUND;
    else if ( DTid.y < gridHeight )
        color = ShadeSphere( DTid.xy );
    else
        color = ShadeStrip( uint2( DTid.x, DTid.y - gridHeight ) );
    Preview[DTid.xy] = float4( ToneMap( color ), 1.f );
}
