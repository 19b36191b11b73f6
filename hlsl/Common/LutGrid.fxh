// The node grid of the quadrature-grid LUT (BrdfLutGridCS writes it, BrdfLutResampleCS reads
// it): node (i, j) of a g x g grid sits at N.V = u³, roughness = w³ with u = i / (g - 1),
// w = j / (g - 1), both ends included. The LUT turns fastest near N.V = 0 at low roughness
// (Schlick-GGX's G1(V) = N.V / (N.V (1 - k) + k) switches on over N.V ~ k = roughness² / 2), and
// the cube roots crowd the nodes there: at g = 64, a cube-root grid is 9e-4 off at worst where
// square roots are 2.4e-3 and a uniform grid 0.21 (Catmull-Rom, against the converged LUT at 512²).
#ifndef LUT_GRID_FXH
#define LUT_GRID_FXH

// A LUT coordinate in [0, 1] (N.V or roughness) in grid units of a grid whose last node is `last`.
float GridPosition( float x, uint last )
{
    return pow( x, 1.f / 3.f ) * (float)last;
}

// u³, and 1 - u³ = (1 - u)(1 + u + u²), formed apart so that it keeps its precision near u = 1.
float2 GridNodeValue( float u )
{
    return float2( u * u * u, ( 1.f - u ) * ( 1.f + u + u * u ) );
}

// Catmull-Rom's weights of four nodes around a point t in [0, 1] of the middle interval.
float4 CatmullRomWeights( float t )
{
    float t2 = t * t, t3 = t2 * t;
    return 0.5f * float4( -t + 2.f * t2 - t3, 2.f - 5.f * t2 + 3.f * t3, t + 4.f * t2 - 3.f * t3, t3 - t2 );
}

#endif
