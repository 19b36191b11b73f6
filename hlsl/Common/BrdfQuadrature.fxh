// The split-sum LUT, the integrals IntegrateBRDF estimates, by a deterministic quadrature:
//   scale = ∫ (1 - Fc) G V.H / (N.H N.V) D N.H dω_h,  bias the same with Fc = (1 - V.H)^5,
// G = GemoetrySmithForIBL (Schlick-GGX, k = roughness² / 2), D = GGX (α = roughness²).
//
// With N = z, V = (sin θv, 0, N.V) and H at polar angle θ, azimuth φ, both V.H = p cos φ + q and
// N.L = 2 (V.H)(N.H) - N.V = A cos φ + B are linear in c = cos φ on a ring of fixed θ. So the
// integrand is a polynomial of degree 6 in c, V.H (1 - V.H)^5 or V.H, times Schlick-GGX's
// G1(N.L) = u / (u (1 - k) + k) = (1 - κ / (u + κ)) / (1 - k), κ = k / (1 - k): a simple pole in c.
// RingIntegral integrates a ring over φ in closed form from the polynomial's Chebyshev
// coefficients. Only θ is integrated numerically: Gauss–Legendre with SAMPLE_COUNT nodes per
// panel, the panels graded geometrically towards the points where the ring integral is not
// smooth, as in runtime/reference/converged_lut.cpp: the edge of the cap where every ring is
// visible (θ1 = asin(N.V) / 2) and the band's far edge (θ2 = π/2 - θ1), at the distance of G1's
// pole. No sampling noise; no NaN at N.V = 0 or roughness = 0 (the mirror limit).
#ifndef BRDF_QUADRATURE_FXH
#define BRDF_QUADRATURE_FXH
#include "Common/PBR.fxh"

#if SAMPLE_COUNT > 16
#error the quadrature takes at most 16 nodes per panel (SAMPLE_COUNT)
#endif
// Gauss–Legendre nodes per panel. A compile-time count, so that the node loops unroll and the
// rule stays in registers: llvmpipe reads an array at a varying index from memory (unrolled, the
// 512² LUT went from 0.19 to 0.14 s).
static const uint NODES = SAMPLE_COUNT;
static const uint SERIES_TERMS = 24; // |r| <= 1/2 on the far branch: r^24 < 1e-7
static const float FAR_POLE = 1.25f; // x < -FAR_POLE: the far branch (RingPoleFar)
static const float PANEL_RATIO = 4.f;
// A panel whose whole contribution is bounded below this is left out (PanelIsNegligible).
static const float NEGLIGIBLE = 1e-6f;

// llvmpipe's atan is 2e-5 off (relative) and its asin 2e-4 (absolute), and the arcs below need
// their angles to float precision: Cephes' atanf instead (relative error ~1e-7), for x >= 0.
float PreciseAtan( float x )
{
    float offset = 0.f;
    if ( x > 2.414213562f ) { offset = PI / 2.f; x = -1.f / x; }
    else if ( x > 0.414213562f ) { offset = PI / 4.f; x = ( x - 1.f ) / ( x + 1.f ); }
    float z = x * x;
    return offset + ( ( ( ( 8.05374449538e-2f * z - 1.38776856032e-1f ) * z + 1.99777106478e-1f ) * z - 3.33329491539e-1f ) * z * x + x );
}

// asin(x) for x in [0, 1], through PreciseAtan.
float PreciseAsin( float x )
{
    float complement = sqrt( ( 1.f - x ) * ( 1.f + x ) );
    return x > complement ? PI / 2.f - PreciseAtan( complement / x ) : PreciseAtan( x / complement );
}

static float GaussNodes[NODES];
static float GaussWeights[NODES];

// Gauss–Legendre on [0, 1] by Newton's method on the Legendre polynomial (weights sum to 1).
void BuildGaussLegendre()
{
    [unroll] for ( uint i = 0; i < NODES; ++i )
    {
        float x = cos( PI * ( (float)i + 0.75f ) / ( (float)NODES + 0.5f ) );
        float derivative = 1.f;
        for ( uint iteration = 0; iteration < 6; ++iteration )
        {
            float previous = 1.f, current = x;
            [unroll] for ( uint j = 2; j <= NODES; ++j )
            {
                float next = ( ( 2.f * j - 1.f ) * x * current - ( j - 1.f ) * previous ) / (float)j;
                previous = current;
                current = next;
            }
            derivative = (float)NODES * ( x * current - previous ) / ( x * x - 1.f );
            x -= current / derivative;
        }
        GaussNodes[i] = 0.5f - 0.5f * x;
        GaussWeights[i] = 1.f / ( ( 1.f - x * x ) * derivative * derivative );
    }
}

struct LutSetting
{
    float ndotv, ndotvComplement, sinV; // N.V, 1 - N.V, sin θv
    float alpha2, k, kappa; // GGX α², Schlick-GGX k, κ = k / (1 - k)
    float theta1;           // the edge of the fully visible cap
    float visibilityV;      // G1(N.V) / N.V = 1 / (N.V (1 - k) + k), finite at N.V = 0
};

// GGX D with its denominator written as sin²θ + α² cos²θ, which DistributionGGX's
// 1 + cos²θ (α² - 1) loses to rounding near θ = 0.
float GgxAt( float cosH, float sinH, float alpha2 )
{
    float spread = sinH * sinH + alpha2 * cosH * cosH;
    return alpha2 / ( PI * spread * spread );
}

// The Chebyshev series in c of the bias term's polynomial, V.H (1 - V.H)^5 with V.H = p c + q:
// its power series by the binomial theorem, then c^k in T_j (c² = (T_0 + T_2) / 2, ...). Both
// stay within a small factor of the polynomial's size on [-1, 1]. 1 - V.H is (1 - q) - p c with
// 1 - q given apart, so that (1 - V.H)^5 keeps its precision where V.H is near 1.
void BiasSeries( float p, float q, float qComplement, out float a[7] )
{
    float m2 = qComplement * qComplement, p2 = p * p;
    float binomial[6]; // (1 - q - p c)^5 = Σ_k binomial[k] c^k
    binomial[0] = m2 * m2 * qComplement;
    binomial[1] = -5.f * m2 * m2 * p;
    binomial[2] = 10.f * m2 * qComplement * p2;
    binomial[3] = -10.f * m2 * p2 * p;
    binomial[4] = 5.f * qComplement * p2 * p2;
    binomial[5] = -p2 * p2 * p;
    float d[7]; // times (q + p c)
    d[0] = q * binomial[0];
    [unroll] for ( uint k = 1; k < 6; ++k ) d[k] = q * binomial[k] + p * binomial[k - 1];
    d[6] = p * binomial[5];
    a[0] = d[0] + d[2] / 2.f + 3.f * d[4] / 8.f + 10.f * d[6] / 32.f;
    a[1] = d[1] + 3.f * d[3] / 4.f + 10.f * d[5] / 16.f;
    a[2] = d[2] / 2.f + d[4] / 2.f + 15.f * d[6] / 32.f;
    a[3] = d[3] / 4.f + 5.f * d[5] / 16.f;
    a[4] = d[4] / 8.f + 6.f * d[6] / 32.f;
    a[5] = d[5] / 16.f;
    a[6] = d[6] / 32.f;
}

// The pole's integrals J_j = ∫_0^φm cos(jφ) / (cos φ - x) dφ summed against the bias series
// (Σ_j a_j J_j) and against V.H's (q J_0 + p J_1), for x >= -FAR_POLE, by J's three-term
// recurrence (J_{j+1} = 2x J_j - J_{j-1} + 2 S_j; it grows errors at most ρ^6 = 64 times here).
// J_0 in closed form: with t = tan(φm / 2), 2 atanh(t s) / ((1 - x) s), s = sqrt((1 + x) / (1 - x)),
// for x > -1, and its continuation with atan beyond. t s is below 1 by the pole's distance past the
// arc's edge, gap = κ / A, which can be below float's resolution of 1: atanh is taken with
// 1 - (t s)² = gap (1 + t²) / (1 - x), exact since t² = (1 - c) / (1 + c) at the edge c = x + gap.
float2 RingPoleNear( float a[7], float p, float q, float S[7], float x, float gap, float tanHalfArc )
{
    float s = sqrt( abs( 1.f + x ) / ( 1.f - x ) ), y = tanHalfArc * s;
    float ratio; // atanh(y) / s or atan(y) / s; by their series where log(1 + 2y) would lose y
    if ( y < 0.125f )
    {
        float z = ( x > -1.f ? 1.f : -1.f ) * y * y;
        ratio = tanHalfArc * ( 1.f + z * ( 1.f / 3.f + z * ( 1.f / 5.f + z * ( 1.f / 7.f + z / 9.f ) ) ) );
    }
    else if ( x > -1.f )
        ratio = 0.5f * log( ( 1.f + y ) * ( 1.f + y ) * ( 1.f - x ) / ( gap * ( 1.f + tanHalfArc * tanHalfArc ) ) ) / s;
    else
        ratio = PreciseAtan( y ) / s;
    float previous = 2.f * ratio / ( 1.f - x );
    float current = x * previous + S[0];
    float2 sums = float2( a[0] * previous + a[1] * current, q * previous + p * current );
    [unroll] for ( uint j = 1; j < 6; ++j )
    {
        float next = 2.f * x * current - previous + 2.f * S[j];
        previous = current;
        current = next;
        sums.x += a[j + 1] * current;
    }
    return sums;
}

// The same sums for x < -FAR_POLE by the Poisson kernel, 1 / (cos φ - x) =
// -2r / (1 - r²) (1 + 2 Σ_m r^m cos mφ), r = x + sqrt(x² - 1): Σ_j a_j J_j = -2r / (1 - r²) Σ_n S_n c_n
// with c_0 = Σ_j a_j r^j and c_n = Σ_j a_j (r^|n-j| + r^(n+j)), so c_n = r^(n-6) c_6 from n = 6 on
// (for V.H's series, c_0 = q + p r and c_n = r^(n-1) (2 q r + p (1 + r²)) from n = 1 on).
// The convolutions by r^|n-j| run as two first-order recurrences. Returned without the factor
// -2r / (1 - r²).
float2 RingPoleFar( float a[7], float p, float q, float S[7], float r, float cosArc )
{
    float right[7]; // Σ_{j>n} a_j r^(j-n)
    right[6] = 0.f;
    [unroll] for ( int n = 5; n >= 0; --n ) right[n] = ( right[n + 1] + a[n + 1] ) * r;
    float left = a[0];           // Σ_{j<=n} a_j r^(n-j)
    float atZero = left + right[0]; // c_0 = Σ_j a_j r^j
    float bias = S[0] * atZero, head = 0.f, power = 1.f, c6 = 0.f, fifthPower = 0.f;
    [unroll] for ( uint n = 1; n < 7; ++n )
    {
        left = left * r + a[n];
        float below = power; // r^(n-1)
        power *= r;
        float cn = left + right[n] + power * atZero;
        if ( n < 6 )
        {
            bias += S[n] * cn;
            head += S[n] * below;
        }
        else
        {
            c6 = cn;
            fifthPower = below;
        }
    }
    // The tail Σ_{n>=6} S_n r^(n-6), S_n = sin(nφm) / n by sin's recurrence, until r^(n-6) < 1e-7.
    float sinPrevious = S[5] * 5.f, sinCurrent = S[6] * 6.f;
    float tail = 0.f, weight = 1.f;
    for ( uint m = 6; m < 6 + SERIES_TERMS && abs( weight ) > 1e-7f; ++m )
    {
        tail += weight * sinCurrent / (float)m;
        float sinNext = 2.f * cosArc * sinCurrent - sinPrevious;
        sinPrevious = sinCurrent;
        sinCurrent = sinNext;
        weight *= r;
    }
    float vdoth = S[0] * ( q + p * r ) + ( 2.f * q * r + p * ( 1.f + r * r ) ) * ( head + fifthPower * tail );
    return float2( bias + c6 * tail, vdoth );
}

// ∫_0^φm G1(N.L) V.H (1 - Fc, Fc) dφ over one ring of half-vectors: the whole half ring (φm = π)
// when fullRing, else the visible arc with tan(φm / 2) = tanHalfArc.
float2 RingIntegral( LutSetting s, float cosH, float sinH, float tanHalfArc, bool fullRing )
{
    float p = s.sinV * sinH, q = s.ndotv * cosH;
    float qComplement = s.ndotvComplement + s.ndotv * sinH * sinH / ( 1.f + cosH ); // 1 - N.V cos θ
    float A = 2.f * p * cosH, B = s.ndotv * ( cosH - sinH ) * ( cosH + sinH );
    float a[7];
    BiasSeries( p, q, qComplement, a );
    float beta = B + s.kappa; // u + κ = A (c - x), x = -β / A
    float2 polynomial, pole; // (bias, V.H)
    if ( fullRing )
    {
        // x < -1 on a full ring (N.L >= 0 at c = -1); J_j = π (-2r / (1 - r²)) r^j.
        float rOverA = -1.f / ( beta + sqrt( ( beta - A ) * ( beta + A ) ) ), r = rOverA * A;
        float sum = a[6];
        [unroll] for ( int j = 5; j >= 0; --j ) sum = sum * r + a[j];
        polynomial = PI * float2( a[0], q );
        pole = ( -2.f * s.kappa * rOverA / ( 1.f - r * r ) ) * PI * float2( sum, q + p * r );
    }
    else
    {
        float t2 = tanHalfArc * tanHalfArc;
        float cosArc = ( 1.f - t2 ) / ( 1.f + t2 ), sinArc = 2.f * tanHalfArc / ( 1.f + t2 );
        float S[7]; // ∫_0^φm cos(nφ) dφ
        S[0] = 2.f * PreciseAtan( tanHalfArc );
        float sinPrevious = 0.f, sinCurrent = sinArc;
        [unroll] for ( uint n = 1; n < 7; ++n )
        {
            S[n] = sinCurrent / (float)n;
            float sinNext = 2.f * cosArc * sinCurrent - sinPrevious;
            sinPrevious = sinCurrent;
            sinCurrent = sinNext;
        }
        polynomial = float2( 0.f, q * S[0] + p * S[1] );
        [unroll] for ( uint j = 0; j < 7; ++j ) polynomial.x += a[j] * S[j];
        if ( beta > FAR_POLE * A )
        {
            float rOverA = -1.f / ( beta + sqrt( ( beta - A ) * ( beta + A ) ) ), r = rOverA * A;
            pole = ( -2.f * s.kappa * rOverA / ( 1.f - r * r ) ) * RingPoleFar( a, p, q, S, r, cosArc );
        }
        else
            pole = ( s.kappa / A ) * RingPoleNear( a, p, q, S, -beta / A, s.kappa / A, tanHalfArc );
    }
    float2 biasAndTotal = ( polynomial - pole ) / ( 1.f - s.k );
    return float2( biasAndTotal.y - biasAndTotal.x, biasAndTotal.x );
}

// A panel's contribution is at most G1(N.V)/N.V times its share of the GGX lobe (its span in
// η, the lobe's cumulative distribution) over its least N.H, as G1(N.L) V.H <= 1.
bool PanelIsNegligible( LutSetting s, float lobeShare, float leastCosH )
{
    return s.visibilityV * lobeShare < NEGLIGIBLE * leastCosH;
}

// η = α² / (tan²θ + α²), the document's inverse-CDF variable, so that D N.H dω_h = dη dφ / 2π.
float EtaAt( float theta, float alpha2 )
{
    float t = tan( theta );
    return alpha2 / ( t * t + alpha2 );
}

// θ in [0, θ1], every ring fully visible, integrated in η over [η1, 1] (the integrand is then
// bounded), graded towards η1 at the distance of the pole's pinch at θ1 + asin(κ) / 2.
float2 FullCapIntegral( LutSetting s )
{
    float t1 = tan( s.theta1 ), tan2 = t1 * t1;
    float eta1 = s.alpha2 / ( tan2 + s.alpha2 ), length = tan2 / ( tan2 + s.alpha2 );
    float2 sum = (float2)0.f;
    if ( !( length > 0.f ) ) return sum;
    float halfPinch = min( PreciseAsin( min( s.kappa, 1.f ) ), s.theta1 ) / 2.f;
    // At least 1e-15, as in the band: a scale rounded to 0 would never grow past the cap.
    float scale = max( eta1 - EtaAt( s.theta1 + halfPinch, s.alpha2 ), 1e-15f );
    if ( !( scale < length / PANEL_RATIO ) ) scale = length;
    for ( float near = 0.f, far = scale; near < length; near = far, far *= PANEL_RATIO )
    {
        float end = min( far, length ), width = end - near;
        float leastEta = eta1 + near;
        float leastCosH = sqrt( leastEta / ( leastEta + s.alpha2 * ( length - near ) ) );
        if ( PanelIsNegligible( s, width, leastCosH ) ) continue;
        [unroll] for ( uint i = 0; i < NODES; ++i )
        {
            float u = near + width * GaussNodes[i];
            float eta = eta1 + u, etaComplement = length - u, denominator = eta + s.alpha2 * etaComplement;
            float cosH = sqrt( eta / denominator ), sinH = sqrt( s.alpha2 * etaComplement / denominator );
            sum += GaussWeights[i] * width / cosH * RingIntegral( s, cosH, sinH, 0.f, true );
        }
    }
    return sum / PI; // 2 (φ in [π, 2π]) / 2π
}

// η at θ = π/2 - ψ, from ψ: tan θ = 1 / tan ψ, without π/2's rounding.
float EtaBesideHorizon( float psi, float alpha2 )
{
    float t = tan( psi ), scaled = alpha2 * t * t;
    return scaled / ( 1.f + scaled );
}

// θ in [θ1, θ2], where only the arc |φ| < φm of a ring has N.L > 0, tan²(φm / 2) =
// sin 2(θ2 - θ) / sin 2(θ - θ1). Each half is graded towards its end; the end panel is smoothed
// by u = far t² against the arc's square-root opening. A node is placed by its distance d from
// its end, and every angle is taken from d and θ1 alone (θ2 = π/2 - θ1, sin 2(θ2 - θ) =
// sin 2(2θ1 + d) on the θ1 side, cos θ = sin(θ1 + d) on the θ2 side): an angle near π/2 formed
// in float would carry π/2's rounding, 4e-8, larger than the arc's whole opening near N.V = 0.
float2 PartialBandIntegral( LutSetting s )
{
    float width = PI / 2.f - 2.f * s.theta1;
    float2 sum = (float2)0.f;
    if ( !( width > 0.f ) ) return sum;
    float halfPinch = PreciseAsin( min( s.kappa, 1.f ) ) / 2.f;
    float scale = max( s.theta1 > 0.f ? min( s.theta1, halfPinch ) : halfPinch, 1e-15f );
    float half = width / 2.f;
    if ( !( scale < half / PANEL_RATIO ) ) scale = half;
    for ( uint side = 0; side < 2; ++side ) // 0: from θ1, 1: from θ2
        for ( float near = 0.f, far = scale; near < half; near = far, far *= PANEL_RATIO )
        {
            float end = min( far, half );
            float lobeShare = side == 0 ? EtaAt( s.theta1 + near, s.alpha2 ) - EtaAt( s.theta1 + end, s.alpha2 )
                                        : EtaBesideHorizon( s.theta1 + end, s.alpha2 ) - EtaBesideHorizon( s.theta1 + near, s.alpha2 );
            float leastCosH = side == 0 ? cos( s.theta1 + end ) : sin( s.theta1 + near );
            if ( PanelIsNegligible( s, lobeShare, leastCosH ) ) continue;
            [unroll] for ( uint i = 0; i < NODES; ++i )
            {
                float t = GaussNodes[i];
                bool endPanel = near == 0.f;
                float fromEnd = endPanel ? end * t * t : near + ( end - near ) * t;
                float jacobian = endPanel ? end * 2.f * t : end - near;
                float angle = s.theta1 + fromEnd, cosAngle = cos( angle ), sinAngle = sin( angle );
                float cosH = side == 0 ? cosAngle : sinAngle, sinH = side == 0 ? sinAngle : cosAngle;
                float nearSin = sin( 2.f * fromEnd ), farSin = sin( 2.f * ( 2.f * s.theta1 + fromEnd ) );
                float tanHalfArc = side == 0 ? sqrt( farSin ) / sqrt( nearSin ) : sqrt( nearSin ) / sqrt( farSin );
                float density = 2.f * GgxAt( cosH, sinH, s.alpha2 ) * sinH; // 2: φ < 0
                sum += GaussWeights[i] * jacobian * density * RingIntegral( s, cosH, sinH, tanHalfArc, false );
            }
        }
    return sum;
}

// 1 - N.V is passed apart: the LUT's texel centres give it exactly, 1 - N.V would not near N.V = 1.
float2 IntegrateBrdfQuadrature( float ndotv, float ndotvComplement, float roughness )
{
    float alpha = roughness * roughness, alpha2 = alpha * alpha, k = alpha / 2.f;
    float fc = pow( ndotvComplement, 5.f );
    if ( alpha2 < 1e-30f ) return float2( 1.f - fc, fc ); // the mirror limit: G -> 1, a lobe at H = N
    LutSetting s;
    s.ndotv = ndotv;
    s.ndotvComplement = ndotvComplement;
    s.sinV = sqrt( ndotvComplement * ( 1.f + ndotv ) );
    s.alpha2 = alpha2;
    s.k = k;
    s.kappa = k / ( 1.f - k );
    s.theta1 = PreciseAsin( ndotv ) / 2.f;
    s.visibilityV = 1.f / ( ndotv * ( 1.f - k ) + k );
    return s.visibilityV * ( FullCapIntegral( s ) + PartialBandIntegral( s ) );
}

#endif
