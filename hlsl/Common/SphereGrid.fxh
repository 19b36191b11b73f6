// Common/SphereGrid.fxh — the spheres iblkit render draws, one per cell of a grid, each of the
// material the host gives for its cell (runtime/render/sphere_grid.hpp). Each sphere is alone in
// the environment (no sphere sees another), seen by an orthographic camera looking down -Z, one
// ray through each pixel's centre, so the Monte Carlo reference and the split sum shade exactly
// the same points.
#ifndef COMMON_SPHERE_GRID_FXH
#define COMMON_SPHERE_GRID_FXH

// The sphere's radius in half cells.
static const float SPHERE_RADIUS = 0.9f;

// Two float4 per cell, row after row: (albedo, roughness), (metalness, transmittance, eta, 0).
StructuredBuffer<float4> Spheres;

struct SphereMaterial
{
    float3 Albedo;
    float Roughness;
    float Metalness;
    float Transmittance;
    float Eta;
};

struct SphereHit
{
    bool Covered;        // whether the pixel's ray meets the sphere
    float3 Normal;       // outward, unit: also the hit point on a sphere of radius 1 at the origin
    SphereMaterial Material;
};

SphereMaterial SphereMaterialOf( uint2 cell, uint columns )
{
    uint index = 2u * ( cell.y * columns + cell.x );
    float4 first = Spheres[index];
    float4 second = Spheres[index + 1u];
    SphereMaterial material;
    material.Albedo = first.rgb;
    material.Roughness = first.a;
    material.Metalness = second.x;
    material.Transmittance = second.y;
    material.Eta = second.z;
    return material;
}

SphereHit SphereAt( uint2 pixel, uint columns, uint cellSize )
{
    SphereHit hit;
    uint2 cell = pixel / cellSize;
    float2 p = ( float2( pixel % cellSize ) + 0.5f ) / cellSize * 2.f - 1.f;
    p.y = -p.y;
    float r2 = dot( p, p ) / ( SPHERE_RADIUS * SPHERE_RADIUS );
    hit.Covered = r2 < 1.f;
    hit.Normal = float3( p / SPHERE_RADIUS, sqrt( max( 1.f - r2, 0.f ) ) );
    hit.Material = SphereMaterialOf( cell, columns );
    return hit;
}

#endif // COMMON_SPHERE_GRID_FXH
