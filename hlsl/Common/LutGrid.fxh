// The node grid of the quadrature-grid LUT (BrdfLutGridCS writes it, BrdfLutResampleCS reads
// it): node (i, j) of a g x g grid sits at u = i / (g - 1), w = j / (g - 1), both ends included.
// Roughness = w³. N.V = s (2 - s) with s = u³, so that 1 - N.V = (1 - s)².
// The LUT turns fastest near N.V = 0 at low roughness (Schlick-GGX's G1(V) = N.V / (N.V (1 - k) + k)
// switches on over N.V ~ k = roughness² / 2), and the cube roots crowd the nodes there: at g = 64,
// a cube-root grid is 9e-4 off at worst where square roots are 2.4e-3 and a uniform grid 0.21
// (Catmull-Rom, against the converged LUT at 512²). Near N.V = 1 the bias is small (2e-5) and an
// RG16F LUT needs it to 1e-3 of itself: s (2 - s) crowds the nodes there too, which took a 128²
// grid's furthest half from 5 steps to 2 (the C++ twin, runtime/reference/lut_grid.cpp).
#ifndef LUT_GRID_FXH
#define LUT_GRID_FXH

// Roughness in [0, 1] in grid units of a grid whose last node is `last`.
float RoughnessGridPosition( float roughness, uint last )
{
    return pow( roughness, 1.f / 3.f ) * (float)last;
}

// N.V in [0, 1] in grid units: u = cbrt(1 - sqrt(1 - N.V)), written without the cancellation.
float NdotvGridPosition( float ndotv, uint last )
{
    return pow( ndotv / ( 1.f + sqrt( 1.f - ndotv ) ), 1.f / 3.f ) * (float)last;
}

// The roughness of the node at w.
float RoughnessGridNodeValue( float w )
{
    return w * w * w;
}

// N.V and 1 - N.V of the node at u; 1 - s = (1 - u)(1 + u + u²) keeps its precision near u = 1.
float2 NdotvGridNodeValue( float u )
{
    float s = u * u * u, rest = ( 1.f - u ) * ( 1.f + u + u * u );
    return float2( s * ( 2.f - s ), rest * rest );
}

// Catmull-Rom's weights of four nodes around a point t in [0, 1] of the middle interval.
float4 CatmullRomWeights( float t )
{
    float t2 = t * t, t3 = t2 * t;
    return 0.5f * float4( -t + 2.f * t2 - t3, 2.f - 5.f * t2 + 3.f * t3, t + 4.f * t2 - 3.f * t3, t3 - t2 );
}

#endif
