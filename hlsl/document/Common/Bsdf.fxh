// Common/Bsdf.fxh — the path tracer document's material model, transcribed from its formulas and
// WGSL: a BSDF that picks the BRDF (Lambert diffuse weighted by k_d = (1 - F)(1 - Metalness), plus
// Cook-Torrance) or Walter's BTDF from the sign of (N.L)(N.V), weighted by the transmittance.
// L points from the surface towards the light, V towards the viewer; N is the surface's outward
// normal, on the side of the medium of index 1. Every change from the printed text is in
// docs/hlsl-transcription.md.
#ifndef COMMON_BSDF_FXH
#define COMMON_BSDF_FXH

#include "Common/PBR.fxh" // PI

// The surface point X of the document's functions.
struct SurfacePoint
{
    float3 Position;
    float3 Normal;       // unit, outward
    float3 Albedo;
    float Roughness;
    float Metalness;
    float Transmittance;
    float Eta;           // the material's index of refraction; the outside's is 1
};

float GetTransmittance( SurfacePoint X ) { return X.Transmittance; }
float3 GetSurfaceNormal( SurfacePoint X ) { return X.Normal; }

// D(N, H): GGX, Roughness^4 being alpha^2.
float D( float3 N, float3 H, float Roughness )
{
    float Roughness4 = Roughness * Roughness * Roughness * Roughness;
    float NdotH = dot( N, H );
    float Denominator = NdotH * NdotH * ( Roughness4 - 1.f ) + 1.f;
    return Roughness4 / ( PI * Denominator * Denominator );
}

// G(N, V, L): Smith-Schlick with the direct-light k = (Roughness + 1)^2 / 8, on |N.L| and |N.V|.
float G( float3 N, float3 V, float3 L, float Roughness )
{
    float k = ( Roughness + 1.f ) * ( Roughness + 1.f ) / 8.f;
    float NdotL = abs( dot( N, L ) );
    float NdotV = abs( dot( N, V ) );
    return NdotL / ( NdotL * ( 1.f - k ) + k ) * ( NdotV / ( NdotV * ( 1.f - k ) + k ) );
}

// F(L, H) as Schlick's: F0 + (1 - F0)(1 - saturate(L.H))^5.
float3 F( float3 L, float3 H, float3 F0 )
{
    return F0 + ( 1.f - F0 ) * pow( 1.f - saturate( dot( L, H ) ), 5.f );
}

float3 BaseReflectance( SurfacePoint X )
{
    float Dielectric = ( 1.f - X.Eta ) / ( 1.f + X.Eta );
    return lerp( ( float3 )( Dielectric * Dielectric ), X.Albedo, X.Metalness );
}

float3 BRDF( SurfacePoint X, float3 L, float3 V )
{
    float3 N = GetSurfaceNormal( X );
    float3 H = normalize( L + V );
    float3 Fresnel = F( L, H, BaseReflectance( X ) );
    float3 kd = ( 1.f - Fresnel ) * ( 1.f - X.Metalness );
    float3 Diffuse = X.Albedo / PI;
    float3 Specular = Fresnel * G( N, V, L, X.Roughness ) * D( N, H, X.Roughness ) /
                      ( 4.f * abs( dot( N, V ) ) * abs( dot( N, L ) ) );
    return kd * Diffuse + Specular;
}

// Walter et al. 2007: L and V on opposite sides; eta_i is the index on L's side, eta_o on V's.
// H is Walter's generalized half vector -(eta_i L + eta_o V), which points into the medium of the
// lower index; Schlick's F takes the cosine on that side, where the light's is the same whichever
// way it crosses.
float3 BTDF( SurfacePoint X, float3 L, float3 V )
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
           G( N, V, L, X.Roughness ) / ( abs( dot( N, V ) ) * abs( dot( N, L ) ) ) * D( N, H, X.Roughness );
}

float3 BSDF( SurfacePoint X, float3 L, float3 V )
{
    float T = GetTransmittance( X );
    float3 N = GetSurfaceNormal( X );

    if ( dot( L, N ) * dot( V, N ) > 0.f ) { return ( 1.f - T ) * BRDF( X, L, V ); }
    return T * BTDF( X, L, V );
}

#endif // COMMON_BSDF_FXH
