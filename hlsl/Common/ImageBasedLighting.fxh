// Common/ImageBasedLighting.fxh — shading with the baked maps: the documents' split-sum combine.
#ifndef COMMON_IMAGE_BASED_LIGHTING_FXH
#define COMMON_IMAGE_BASED_LIGHTING_FXH

#include "Common/PBR.fxh"

// The specular IBL document's final combine, as printed: the prefiltered radiance of the
// reflected direction at mip roughness * (mips - 1), times F0 * scale + bias from the LUT.
float3 SplitSumSpecular( float3 normal, float3 viewDirection, float roughness, float3 f0,
                         TextureCube prefilterMap, uint reflectionMipLevels,
                         Texture2D<float2> brdfLut, SamplerState linearSampler )
{
    float ndotv = saturate( dot( normal, viewDirection ) );
    float3 r = reflect( -viewDirection, normal );
    float3 prefilteredColor = prefilterMap.SampleLevel( linearSampler, r, roughness * ( reflectionMipLevels - 1 ) ).rgb;
    float2 brdf = brdfLut.SampleLevel( linearSampler, float2( ndotv, roughness ), 0 ).rg;
    return prefilteredColor * ( f0 * brdf.x + brdf.y );
}

// The diffuse term from an irradiance cube holding E(n) / pi: albedo times the texel, for the
// non-metallic part of the material.
float3 IrradianceDiffuse( float3 normal, float3 albedo, float metalness, TextureCube irradianceMap,
                          SamplerState linearSampler )
{
    return irradianceMap.SampleLevel( linearSampler, normal, 0 ).rgb * albedo * ( 1.f - metalness );
}

#endif // COMMON_IMAGE_BASED_LIGHTING_FXH
