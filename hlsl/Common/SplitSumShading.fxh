// Common/SplitSumShading.fxh — how iblkit render's split-sum image shades a sphere's point from
// the baked maps and the lights the bake took out, shared by the compute shader that writes the
// image (SplitSumSpheresCS) and the forward pass that draws the spheres as meshes (ForwardSpheres).
// Opaque spheres take the recipe's shading (Common/ImageBasedLighting.fxh's IblShadeOpaque; the
// documents' combine is the recipe of linear lods, R and one lookup at the surface's roughness,
// no lights); glass the transmission GlassTransmission names (IblGlassReadOf), each with the
// lights the bake took out added as the fxh's functions say.
#ifndef COMMON_SPLIT_SUM_SHADING_FXH
#define COMMON_SPLIT_SUM_SHADING_FXH

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

// The split-sum radiance leaving a sphere's point of unit `normal` towards `viewDirection`.
float3 SplitSumShade( SphereMaterial material, float3 normal, float3 viewDirection )
{
    if ( material.Transmittance > 0.f )
        return GlassSplitSum( normal, viewDirection, material.Roughness, material.Eta );
    float residualShare;
    float3 color = IblShadeOpaque( normal, viewDirection, material.Albedo, material.Roughness, material.Metalness, Recipe(),
                                   Specular, IrradianceMap, BrdfLut, LobeTable, LinearClamp, residualShare );
    float3 f0 = lerp( ( float3 )0.04f, material.Albedo, material.Metalness );
    float3 albedo = IblDirectionalAlbedo( normal, viewDirection, material.Roughness, f0, BrdfLut, LinearClamp );
    for ( uint i = 0u; i < LightCount; ++i )
        color += IblDiskLight( normal, viewDirection, material.Roughness, f0, albedo, material.Albedo * ( 1.f - material.Metalness ),
                               residualShare, Lights[2u * i], Lights[2u * i + 1u] );
    return color;
}

#endif // COMMON_SPLIT_SUM_SHADING_FXH
