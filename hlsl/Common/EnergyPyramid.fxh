// Common/EnergyPyramid.fxh — one source texel as a block of ClusterCubeCS's energy pyramid.
#ifndef COMMON_ENERGY_PYRAMID_FXH
#define COMMON_ENERGY_PYRAMID_FXH

#include "Cube.fxh"

static const float3 PYRAMID_LUMINANCE = float3( 0.2126f, 0.7152f, 0.0722f );

// Texel xy of face `face` of a size x size source, holding `radiance` over `solidAngle`
// (CubeTexelSolidAngle's), as the pyramid's three sums: Energy (radiance times solid angle; solid
// angle), Centroid (w times direction; w, with w = max(luminance, 0) times solid angle) and
// Geometry (solid angle times direction; solid angle). A pyramid as wide as the source (sources up
// to 512²) keeps these as its level 0. A half-width one keeps no level of single texels:
// ClusterCubeCS sums four of these for its first level, and PrefilterConvolutionCS makes one
// wherever its walk reaches a source texel, with the solid angle ClusterCubeCS tabled (at 1024²,
// three RGBA32F cubes of 96 MiB each are never made). Either way the same products, so the sums
// are the same bit for bit. `precise`: each product is rounded as a stored value would be, never
// fused into the sum that follows.
void SourceTexelBlock( float3 radiance, uint face, uint2 xy, uint size, float solidAngle, out float4 energy,
                       out float4 weighted, out float4 geometry )
{
    float3 direction = CubeFaceDirection( face, ( float2( xy ) + 0.5f ) / float( size ) );
    precise float weight = max( dot( radiance, PYRAMID_LUMINANCE ), 0.f ) * solidAngle;
    precise float3 lightSum = radiance * solidAngle;
    precise float3 weightedSum = direction * weight;
    precise float3 geometrySum = direction * solidAngle;
    energy = float4( lightSum, solidAngle );
    weighted = float4( weightedSum, weight );
    geometry = float4( geometrySum, solidAngle );
}

#endif // COMMON_ENERGY_PYRAMID_FXH
