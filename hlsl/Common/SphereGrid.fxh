// Common/SphereGrid.fxh — the spheres iblkit render draws, one per cell of a grid: roughness
// across, metalness down, then a row of glass. Each sphere is alone in the environment (no sphere
// sees another), seen by an orthographic camera looking down -Z, one ray through each pixel's
// centre, so the Monte Carlo reference and the split sum shade exactly the same points.
#ifndef COMMON_SPHERE_GRID_FXH
#define COMMON_SPHERE_GRID_FXH

// Gold's reflectance at normal incidence, as in the preview: orange plastic at metalness 0.
static const float3 SPHERE_BASE_COLOR = float3( 1.f, 0.766f, 0.336f );
static const float3 GLASS_ALBEDO = float3( 1.f, 1.f, 1.f );
static const float GLASS_ETA = 1.5f;
// The sphere's radius in half cells.
static const float SPHERE_RADIUS = 0.9f;
// GGX of roughness 0 is a delta the ported BSDF cannot evaluate (D is 0/0 at N.H = 1): the first
// column is this rough instead, a mirror to the eye, where float still resolves D's peak to 2 %.
static const float MIN_ROUGHNESS = 0.05f;

struct SphereMaterial
{
    float3 Albedo;
    float Roughness;
    float Metalness;
    float Transmittance;
};

struct SphereHit
{
    bool Covered;        // whether the pixel's ray meets the sphere
    float3 Normal;       // outward, unit: also the hit point on a sphere of radius 1 at the origin
    SphereMaterial Material;
};

float GridFraction( uint index, uint count )
{
    return count > 1 ? float( index ) / float( count - 1 ) : 0.f;
}

// Columns of roughness; metalRows rows of opaque metalness 0 to 1, then one row of glass.
SphereMaterial SphereMaterialOf( uint2 cell, uint columns, uint metalRows )
{
    SphereMaterial material;
    material.Roughness = max( GridFraction( cell.x, columns ), MIN_ROUGHNESS );
    bool glass = cell.y >= metalRows;
    material.Albedo = glass ? GLASS_ALBEDO : SPHERE_BASE_COLOR;
    material.Metalness = glass ? 0.f : GridFraction( cell.y, metalRows );
    material.Transmittance = glass ? 1.f : 0.f;
    return material;
}

SphereHit SphereAt( uint2 pixel, uint columns, uint metalRows, uint cellSize )
{
    SphereHit hit;
    uint2 cell = pixel / cellSize;
    float2 p = ( float2( pixel % cellSize ) + 0.5f ) / cellSize * 2.f - 1.f;
    p.y = -p.y;
    float r2 = dot( p, p ) / ( SPHERE_RADIUS * SPHERE_RADIUS );
    hit.Covered = r2 < 1.f;
    hit.Normal = float3( p / SPHERE_RADIUS, sqrt( max( 1.f - r2, 0.f ) ) );
    hit.Material = SphereMaterialOf( cell, columns, metalRows );
    return hit;
}

#endif // COMMON_SPHERE_GRID_FXH
