// Common/SplitSumMaterial.fxh — the path tracer document's BSDF (document/Common/Bsdf.fxh) with
// the two choices the split sum makes differently, so that iblkit render can tell the split sum's
// approximation from the difference between the two materials:
//   - G takes Smith-Schlick's k for image-based light, roughness² / 2 (PBR.fxh's
//     GeometrySmithForIBL, which the LUT integrates), where the document has the direct-light
//     (roughness + 1)² / 8, which darkens even a mirror at grazing angles;
//   - the diffuse term is weighted by (1 - Metalness) alone, as the irradiance map's is, where the
//     document's k_d is (1 - F)(1 - Metalness).
// Everything else is the document's: D, F, F0, Walter's BTDF, the choice between BRDF and BTDF.
#ifndef COMMON_SPLIT_SUM_MATERIAL_FXH
#define COMMON_SPLIT_SUM_MATERIAL_FXH

#include "Common/Bsdf.fxh"

float GForIBL( float3 N, float3 V, float3 L, float Roughness )
{
    return GeometrySmithForIBL( abs( dot( N, L ) ), abs( dot( N, V ) ), Roughness );
}

float3 BrdfAsSplitSum( SurfacePoint X, float3 L, float3 V )
{
    float3 N = GetSurfaceNormal( X );
    float3 H = normalize( L + V );
    float3 Fresnel = F( L, H, BaseReflectance( X ) );
    float3 Diffuse = X.Albedo / PI * ( 1.f - X.Metalness );
    float3 Specular = Fresnel * GForIBL( N, V, L, X.Roughness ) * D( N, H, X.Roughness ) /
                      ( 4.f * abs( dot( N, V ) ) * abs( dot( N, L ) ) );
    return Diffuse + Specular;
}

// Bsdf.fxh's BTDF with GForIBL for G.
float3 BtdfAsSplitSum( SurfacePoint X, float3 L, float3 V )
{
    float3 N = GetSurfaceNormal( X );
    bool LightOutside = dot( L, N ) > 0.f;
    float EtaI = LightOutside ? 1.f : X.Eta;
    float EtaO = LightOutside ? X.Eta : 1.f;
    float3 H = -normalize( EtaI * L + EtaO * V );
    float3 Rarer = EtaI <= EtaO ? L : V;
    float3 Fresnel = F( Rarer, H, BaseReflectance( X ) );
    float LdotH = dot( L, H );
    float VdotH = dot( V, H );
    float Sum = EtaI * LdotH + EtaO * VdotH;
    return abs( LdotH ) * abs( VdotH ) * EtaO * EtaO * ( 1.f - Fresnel ) / ( Sum * Sum ) *
           GForIBL( N, V, L, X.Roughness ) / ( abs( dot( N, V ) ) * abs( dot( N, L ) ) ) * D( N, H, X.Roughness );
}

float3 BsdfAsSplitSum( SurfacePoint X, float3 L, float3 V )
{
    float T = GetTransmittance( X );
    float3 N = GetSurfaceNormal( X );
    if ( dot( L, N ) * dot( V, N ) > 0.f ) { return ( 1.f - T ) * BrdfAsSplitSum( X, L, V ); }
    return T * BtdfAsSplitSum( X, L, V );
}

#endif // COMMON_SPLIT_SUM_MATERIAL_FXH
