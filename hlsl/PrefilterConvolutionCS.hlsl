// The prefilter integral of PrefilterSpecular (N = V = R), summed over the source's texels
// instead of estimated from samples:
//   P(N) = sum_t L_t W_t / sum_t W_t,  W_t = D(N.H) N.L over texel t,  N.H = sqrt((1 + N.L) / 2),
// or, with Weighting 1, W_t = D(N.H) G1(N.L), Smith-Schlick's G1 with k = roughness² / 2: the
// split sum's own reflected lobe at N = V (runtime/shading/lobe_table.hpp).
// Texels are visited as a tree over ClusterCubeCS's energy pyramid (Barnes & Hut's), whose level
// 0 is the source's texels themselves (LoadBlock) and level n > 0 blocks of 2^n x 2^n: a block
// far from N (its centre more than Refine of its own widths away) is one term, its light taken
// by its mean direction and spread (the luminance-weighted first moment of its directions), so
// a sun keeps its exact position at every level; the lobe is averaged over that spread to
// second order. Blocks near N open into their four children down to FineLevel, and blocks
// across N's horizon, where N.L > 0 clips the lobe, down to HorizonLevel. "Near" grows with a
// block's brightness: a light far brighter than its surroundings outweighs the lobe's fall-off,
// so its block must be resolved from farther away (Opens). The denominator sums
// the same blocks by their solid angles, so a constant environment is returned exactly. No
// sampling noise; the error falls with Refine, as the number of terms per texel grows.
#include "Common/PBR.fxh"
#include "Common/EnergyPyramid.fxh"

#ifndef SOURCE_TEXELS_IN_PYRAMID
#define SOURCE_TEXELS_IN_PYRAMID 0
#endif

cbuffer PrefilterConvolutionParameter : register( b0 )
{
    float Roughness; // > 0
    uint TopLevel;   // the pyramid level the tree starts from: every block of it is visited
    uint FineLevel;  // the finest level it opens blocks into
    float Refine;    // a block opens when its centre is within Refine of its widths of N
    uint HorizonLevel; // the finest level a block across N's horizon opens into
    uint Weighting;    // 0: N.L, as the documents; 1: G1(N.L)
};

#if !SOURCE_TEXELS_IN_PYRAMID
Texture2DArray<float4> Source; // the radiance cube the pyramid was made from
Texture2D<float> TexelSolidAngle; // ClusterCubeCS's table of its texels' solid angles
#endif
Texture2DArray<float4> Energy;
Texture2DArray<float4> Centroid;
Texture2DArray<float4> Geometry;
RWTexture2DArray<float4> Prefiltered;

// Block (face, xy) of tree level `level` of a source of baseSize² texels per face. With
// SOURCE_TEXELS_IN_PYRAMID, the pyramid is as wide as the source and its mip `level` is the level.
// Without, the pyramid is half as wide: a source texel is made here at level 0, and the pyramid's
// mip level - 1 read above it. (CPU drivers run both sides of a branch for their whole vector of
// texels, so the first form spares every step of the walk the second's two loads and a direction;
// the second spares a large source three RGBA32F cubes of its size.)
void LoadBlock( uint face, uint2 xy, uint level, uint baseSize, out float4 energy, out float4 weighted, out float4 geometry )
{
#if SOURCE_TEXELS_IN_PYRAMID
    int4 at = int4( xy, face, level );
#else
    if ( level == 0u )
    {
        SourceTexelBlock( Source.Load( int4( xy, face, 0 ) ).rgb, face, xy, baseSize, TexelSolidAngle.Load( int3( xy, 0 ) ),
                          energy, weighted, geometry );
        return;
    }
    int4 at = int4( xy, face, level - 1u );
#endif
    energy = Energy.Load( at );
    weighted = Centroid.Load( at );
    geometry = Geometry.Load( at );
}

// The integrand of PrefilterSpecular's ratio at N = V, per unit solid angle of L, is the pdf
// of L (D N.H / (4 V.H), with N.H = V.H) times the N.L weight: D(sqrt((1 + N.L) / 2)) N.L,
// without the constant 1/4, which cancels (ExpectedLobeWeight).

// Phi(z), the standard normal distribution, by Abramowitz & Stegun 7.1.26 (|error| < 1.5e-7 in
// erf), given its density's exponential exp(-z²/2), which ClippedMean needs too: one exp, not two.
float NormalCdf( float z, float gaussian )
{
    float t = 1.f / ( 1.f + 0.3275911f * 0.70710678f * abs( z ) );
    float polynomial = 0.254829592f + t * ( -0.284496736f + t * ( 1.421413741f + t * ( -1.453152027f + t * 1.061405429f ) ) );
    float tail = 0.5f * t * polynomial * gaussian;
    return z >= 0.f ? 1.f - tail : tail;
}

// E[max(x, 0)] for x ~ Normal(mean, spread^2).
float ClippedMean( float mean, float spread )
{
    float clipped = max( mean, 0.f );
    if ( spread > 0.f && abs( mean ) <= 5.f * spread )
    {
        float z = mean / spread;
        float gaussian = exp( -0.5f * z * z );
        clipped = spread * gaussian * 0.39894228f + mean * NormalCdf( z, gaussian );
    }
    return clipped;
}

// Smith-Schlick's G1 of the split sum's k = r² / 2 (PBR.fxh's GeometrySchlickGGXForIBL), written
// as u / (c u + k) with c = 1 - k.
float WeightingG1( float u, float k )
{
    return u / ( ( 1.f - k ) * u + k );
}

// The lobe's expected weight over light whose N.L has mean `ndotl` and variance `variance`.
// As a function of N.L = u the lobe is g(u) = D(u) w(u), D(u) = a2 / (PI (A + B u)^2) with
// A = (1 + a2) / 2, B = (a2 - 1) / 2, and w(u) = u or G1(u): away from the horizon
// E[g] = g + g'' variance / 2, g'' / D = w (6 B² / s² ) - 4 B w' / s + w'' with s = A + B u
// (for w = u: (-B) (4A - 2B u) / s²; for G1: w' = k / (c u + k)², w'' = -2 c k / (c u + k)³);
// across it, the clip max(u, 0) is taken in expectation over a normal spread, and w and D at the
// mean.
float ExpectedLobeWeight( float ndotl, float variance, float roughness )
{
    float spread = sqrt( max( variance, 0.f ) );
    float D = DistributionGGX( sqrt( 0.5f + 0.5f * max( ndotl, 0.f ) ), roughness );
    float k = 0.5f * roughness * roughness;
    float expected;
    if ( ndotl > 3.f * spread )
    {
        // Each denominator inverted once: CPU drivers run every division of both weightings and
        // both sides of the horizon for every term.
        float a2 = roughness * roughness * roughness * roughness;
        float A = 0.5f + 0.5f * a2, B = 0.5f * a2 - 0.5f;
        float inverseS = 1.f / ( A + B * ndotl );
        if ( Weighting == 0u )
            expected = ndotl + 0.5f * variance * ( -B ) * ( 4.f * A - 2.f * B * ndotl ) * inverseS * inverseS;
        else
        {
            float inverseQ = 1.f / ( ( 1.f - k ) * ndotl + k );
            float w = ndotl * inverseQ, w1 = k * inverseQ * inverseQ, w2 = -2.f * ( 1.f - k ) * w1 * inverseQ;
            expected = w + 0.5f * variance * ( w * 6.f * B * B * inverseS * inverseS - 4.f * B * w1 * inverseS + w2 );
        }
    }
    else
    {
        float clipped = max( ClippedMean( ndotl, spread ), 0.f );
        expected = Weighting == 0u ? clipped : WeightingG1( clipped, k );
    }
    return D * expected;
}

// ExpectedLobeWeight over directions whose first moment is `mean`: N.L has the mean N.mean and,
// the spread 1 - |mean|^2 taken as the same along every tangent axis, the variance of its part
// across N's direction.
float BlockLobeWeight( float3 normal, float3 mean, float roughness )
{
    float length2 = dot( mean, mean );
    float meanCosine = dot( normal, mean );
    float variance = 0.5f * max( 1.f - length2, 0.f ) * max( 1.f - meanCosine * meanCosine / length2, 0.f );
    return ExpectedLobeWeight( meanCosine, variance, roughness );
}

// A block of size texels per face spans at most 2 / size radians from its centre to a corner
// along a great circle (the face's centre has the widest texels, 2 / size across).
static const float HORIZON_OPEN = 2.f;

// The block after (face, xy, level) and its subtree in depth-first order, or face 6 when the walk
// is over. No stack: a block's four children are (2x, 2y), (2x + 1, 2y), (2x, 2y + 1),
// (2x + 1, 2y + 1), so where the walk goes next follows from the block's own coordinates. (An
// indexed local array would be lowered to a chain of selects by the compilers of CPU drivers,
// which costs more than the whole sum.) A last child climbs to its first ancestor that is not one,
// as far as the top level: as many levels as xy's trailing bits set in both coordinates, counted
// at once (a loop of one level a step took the walk 1.03 times as long).
void NextBlock( inout uint face, inout uint2 xy, inout uint level, uint topSize )
{
    uint climb = min( firstbitlow( ~( xy.x & xy.y ) ), TopLevel - level );
    xy >>= climb;
    level += climb;
    if ( level == TopLevel )
    {
        // topSize is a power of two: shifts and masks, where a division would be one per lane
        // (CPU drivers' vectors have no integer division), 15 % of the walk on llvmpipe.
        uint topShift = firstbitlow( topSize );
        uint top = ( ( ( face << topShift ) + xy.y ) << topShift ) + xy.x + 1;
        face = top >> ( 2u * topShift );
        xy = uint2( top & ( topSize - 1u ), ( top >> topShift ) & ( topSize - 1u ) );
    }
    else if ( ( xy.x & 1u ) == 0u )
        xy.x += 1;
    else
        xy += uint2( 0xFFFFFFFFu, 1u );
}

// How many times the environment's mean luminance a block's light is: the mean over the whole
// sphere is the pyramid's top, six texels of one direction each.
float MeanLuminance( uint topLevel, uint baseSize )
{
    float light = 0.f, solidAngle = 0.f;
    for ( uint face = 0; face < 6; ++face )
    {
        float4 energy, weighted, geometry;
        LoadBlock( face, uint2( 0, 0 ), topLevel, baseSize, energy, weighted, geometry );
        light += weighted.w;
        solidAngle += geometry.w;
    }
    return light / solidAngle;
}

// 1 / 2^n exactly, from its exponent bits, where a division would be a vector division a term on
// CPU drivers.
float InversePowerOfTwo( uint n )
{
    return asfloat( ( 127u - n ) << 23 );
}

// Whether the block (face, xy) of `level` > 0 of a source 2^baseLog2 texels wide (size x size
// blocks per face, size = 2^(baseLog2 - level)), with its Centroid `weighted`
// and Geometry `geometry`, opens for N = normal: when N
// is within Refine of its widths (2 / size each) of its centre, as a chord (|N - centre|^2 =
// 2 - 2 cos), or, down to HorizonLevel, when it lies across N's horizon, where N.L > 0 clips
// the lobe. The reach grows as the cube root of the block's brightness against the mean: the
// lobe's tail falls as the fourth power of the angle, and a block's error against its
// distance as a power of its width over that angle, so a block `brightness` times the mean is
// resolved as finely as its share of the result needs (measured over the built-in sky and
// Blender's HDRIs: the cube root holds the error of small bright lights to that of the rest
// for about 15 % more terms; the square root costs twice that for no gain).
bool Opens( float3 normal, uint face, uint2 xy, uint level, uint baseLog2, float meanLuminance, float halfOverRefine,
            float4 weighted, float4 geometry )
{
    uint sizeLog2 = baseLog2 - level; // the level's blocks per face: 2^sizeLog2
    float size = float( 1u << sizeLog2 ), inverseSize = InversePowerOfTwo( sizeLog2 );
    float3 centre = CubeFacePoint( face, ( float2( xy ) + 0.5f ) * inverseSize );
    float cosine = dot( normal, centre ) * ( 1.f / sqrt( dot( centre, centre ) ) );
    float brightness = max( weighted.w / max( geometry.w * meanLuminance, 1e-30f ), 1.f );
    // chord < reach x cbrt(brightness), reach = Refine x 2 / size, cubed: CPU drivers make a pow of
    // a log and an exp.
    float widthsOut = size * halfOverRefine;
    float widths = ( 2.f - 2.f * cosine ) * widthsOut * widthsOut;
    bool nearN = widths * widths * widths < brightness * brightness;
    bool acrossHorizon = level > HorizonLevel && abs( cosine ) < HORIZON_OPEN * inverseSize;
    return nearN || acrossHorizon;
}

// llvmpipe counts every iteration of all of an invocation's loops against one budget of 65535
// (Mesa's gallivm loop limiter: one counter per shader, for the SIMD vector of texels it runs
// together) and past it ends them all without a word. Every iteration of the walk is a term or a
// descent, and a descent opens a block into four, so there are at most 4/3 of an iteration per
// term, each of them one iteration. The cost per term counted below, 3 + 2 x depth, bounded that
// when NextBlock climbed in a loop of its own ((4/3) (2 + depth) <= 3 + 2 x depth): kept, so that
// where the budget binds the walk sums what it did, and now conservative. Bright blocks open from farther away, so no budget
// bounds the walk of every environment: a texel stops opening blocks once its terms at that cost
// leave only what the rest of its walk needs (the top level's blocks and at most three siblings
// per level, taken whole).
static const uint LOOP_BUDGET = 65535u;

[numthreads(8, 8, 1)]
void main( uint3 DTid : SV_DispatchThreadId )
{
    uint3 dims = (uint3)0;
    Prefiltered.GetDimensions( dims.x, dims.y, dims.z );
    if ( any( DTid >= dims ) )
        return;

    float3 normal = CubeFaceDirection( DTid.z, ( float2( DTid.xy ) + 0.5f ) / float( dims.x ) );

    uint baseSize = 0, baseHeight = 0, layers = 0;
#if SOURCE_TEXELS_IN_PYRAMID
    uint mips = 0;
    Energy.GetDimensions( 0, baseSize, baseHeight, layers, mips );
#else
    Source.GetDimensions( baseSize, baseHeight, layers );
#endif

    float3 radiance = 0.f;
    float weight = 0.f;
    uint topSize = max( baseSize >> TopLevel, 1u );
    uint baseLog2 = firstbithigh( baseSize );
    float meanLuminance = MeanLuminance( baseLog2, baseSize ); // the 1x1 level of the full chain
    uint termCost = 3u + 2u * ( TopLevel - FineLevel );
    uint openLimit = LOOP_BUDGET / termCost - min( 6u * topSize * topSize + 3u * TopLevel + 1u, LOOP_BUDGET / termCost );
    float halfOverRefine = 0.5f / Refine;
    uint terms = 0;
    uint face = 0, level = TopLevel;
    uint2 xy = 0;
    // Each block is read once: what decides whether it opens is what its term sums.
    while ( face < 6 )
    {
        float4 energy, weighted, geometry;
        LoadBlock( face, xy, level, baseSize, energy, weighted, geometry );
        if ( level > FineLevel && terms < openLimit
             && Opens( normal, face, xy, level, baseLog2, meanLuminance, halfOverRefine, weighted, geometry ) )
        {
            xy *= 2;
            level -= 1;
            continue;
        }
        // The first moments of the block's directions, by solid angle and by light: their
        // length falls short of 1 by their spread.
        float3 extent = geometry.xyz * ( 1.f / geometry.w );
        float3 light = weighted.w > 0.f ? weighted.xyz * ( 1.f / weighted.w ) : extent;
        radiance += energy.rgb * BlockLobeWeight( normal, light, Roughness );
        weight += energy.a * BlockLobeWeight( normal, extent, Roughness );
        terms += 1;
        NextBlock( face, xy, level, topSize );
    }
    Prefiltered[DTid] = float4( radiance / weight, 0.f );
}
