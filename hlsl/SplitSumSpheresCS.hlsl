// iblkit render's split-sum image: the spheres of Common/SphereGrid.fxh shaded with the baked maps,
// in linear radiance, for the host to hold against RenderReferenceCS's Monte Carlo reference.
// Opaque spheres take the recipe's shading (Common/ImageBasedLighting.fxh's IblShadeOpaque; the
// documents' combine is the recipe of linear lods, R and one lookup at the surface's roughness,
// no lights); glass the transmission GlassTransmission names (IblGlassReadOf), each with the
// lights the bake took out added as the fxh's functions say.
#include "Common/ImageBasedLighting.fxh"
#include "Common/SphereGrid.fxh"

cbuffer SplitSumParameter : register( b0 )
{
    uint Columns;
    uint CellSize;
    uint SpecularMips;
    uint SpecularSize;
    uint LodMapping;
    float LodParameter;
    uint Direction;
    uint Lookup;
    uint LightCount;
    uint LightLevel;
    uint GlassTransmission;
    float GlassRoughnessScale;
};

TextureCube Specular;
TextureCube IrradianceMap;
Texture2D<float2> BrdfLut;
Texture2D<float4> LobeTable;
Texture2D<float2> TransmissionTable;
Texture2D<float4> SphereTransmissionTable;
// Two float4 per light: (direction towards it, angular radius), (radiance, solid angle).
StructuredBuffer<float4> Lights;
SamplerState LinearClamp;
RWTexture2D<float4> SplitSum;

IblRecipe Recipe()
{
    return IblRecipeOf( LodMapping, LodParameter, SpecularMips, SpecularSize, Direction, Lookup, LightCount, LightLevel );
}

float3 GlassSplitSum( float3 normal, float3 viewDirection, float roughness, float eta )
{
    IblGlassRead read = IblGlassReadOf( GlassTransmission, normal, viewDirection, roughness, eta, GlassRoughnessScale,
                                        TransmissionTable, SphereTransmissionTable, LinearClamp );
    float residualShare;
    float3 radiance = IblGlassRadiance( read, Recipe(), Specular, LinearClamp, residualShare );
    for ( uint i = 0u; i < LightCount; ++i )
        radiance += IblGlassLight( read, residualShare, Lights[2u * i], Lights[2u * i + 1u] );
    return radiance * read.Weight;
}

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint2 dims = ( uint2 )0;
    SplitSum.GetDimensions( dims.x, dims.y );
    if ( any( DTid.xy >= dims ) )
        return;
    SphereHit hit = SphereAt( DTid.xy, Columns, CellSize );
    float3 color = ( float3 )0.f;
    float3 viewDirection = float3( 0.f, 0.f, 1.f );
    SphereMaterial material = hit.Material;
    if ( hit.Covered && material.Transmittance > 0.f )
        color = GlassSplitSum( hit.Normal, viewDirection, material.Roughness, material.Eta );
    else if ( hit.Covered )
    {
        float residualShare;
        color = IblShadeOpaque( hit.Normal, viewDirection, material.Albedo, material.Roughness, material.Metalness, Recipe(),
                                Specular, IrradianceMap, BrdfLut, LobeTable, LinearClamp, residualShare );
        float3 f0 = lerp( ( float3 )0.04f, material.Albedo, material.Metalness );
        float3 albedo = IblDirectionalAlbedo( hit.Normal, viewDirection, material.Roughness, f0, BrdfLut, LinearClamp );
        for ( uint i = 0u; i < LightCount; ++i )
            color += IblDiskLight( hit.Normal, viewDirection, material.Roughness, f0, albedo,
                                   material.Albedo * ( 1.f - material.Metalness ), residualShare, Lights[2u * i], Lights[2u * i + 1u] );
    }
    SplitSum[DTid.xy] = float4( color, hit.Covered ? 1.f : 0.f );
}
