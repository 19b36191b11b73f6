// Common/Lights.fxh — the path tracer document's lights: each one's term of the rendering equation
// at a surface point X seen from V, with the visibility V(x' <-> x) given by the caller. Every
// change from the printed text is in docs/hlsl-transcription.md.
#ifndef COMMON_LIGHTS_FXH
#define COMMON_LIGHTS_FXH

#include "Common/Bsdf.fxh"
#include "Common/Random.fxh"

struct DirectionalLight
{
    float3 Direction; // omega_L: the direction the light travels, unit
    float3 Radiance;  // L_0
};

struct PointLight
{
    float3 Position;
    float3 Radiance;  // L_0, as the document names it: the intensity, radiant power per solid angle
};

// A parallelogram Corner + u EdgeU + v EdgeV, u and v in [0, 1], emitting L_0 on the side of
// cross(EdgeU, EdgeV).
struct AreaLight
{
    float3 Corner;
    float3 EdgeU;
    float3 EdgeV;
    float3 Radiance;
};

// f_s(x, -omega_L, omega_o) L_0 V (n . -omega_L).
float3 DirectionalLightTerm( SurfacePoint X, float3 V, DirectionalLight Light, float Visibility )
{
    float3 L = -Light.Direction;
    return BSDF( X, L, V ) * Light.Radiance * Visibility * abs( dot( GetSurfaceNormal( X ), L ) );
}

// f_s(x, omega_L, omega_o) L_0 V |n . omega_i| / |x_L - x|^2: the document's G without |n' . omega_i|,
// which a point has not.
float3 PointLightTerm( SurfacePoint X, float3 V, PointLight Light, float Visibility )
{
    float3 ToLight = Light.Position - X.Position;
    float Distance2 = dot( ToLight, ToLight );
    float3 L = ToLight * rsqrt( Distance2 );
    return BSDF( X, L, V ) * Light.Radiance * Visibility * abs( dot( GetSurfaceNormal( X ), L ) ) / Distance2;
}

// The point the area light is sampled at, uniformly: pdf 1 / Area.
float3 SampleAreaLight( AreaLight Light, inout RandomState rng )
{
    float u = Random( rng );
    float v = Random( rng );
    return Light.Corner + u * Light.EdgeU + v * Light.EdgeV;
}

// One sample of the area light's term: f_s L_0 V G(x_L <-> x) / pdf, pdf = 1 / Area, with
// G = |n . omega_i| |n' . omega_i| / |x_L - x|^2; nothing from the back of the light.
float3 AreaLightTerm( SurfacePoint X, float3 V, AreaLight Light, float3 LightPoint, float Visibility )
{
    float3 Across = cross( Light.EdgeU, Light.EdgeV );
    float Area = length( Across );
    float3 LightNormal = Across / Area;
    float3 ToLight = LightPoint - X.Position;
    float Distance2 = dot( ToLight, ToLight );
    float3 L = ToLight * rsqrt( Distance2 );
    float Emitting = dot( LightNormal, -L ) > 0.f ? 1.f : 0.f;
    float Geometry = abs( dot( GetSurfaceNormal( X ), L ) ) * abs( dot( LightNormal, L ) ) / Distance2;
    return BSDF( X, L, V ) * Light.Radiance * Emitting * Visibility * Geometry * Area;
}

#endif // COMMON_LIGHTS_FXH
