// Common/Random.fxh — the generator behind the path tracer document's Random(), which the document
// uses without defining (docs/hlsl-transcription.md).
//
// State: one uint. Each draw advances it by the LCG  s' = 747796405 s + 2891336453  (mod 2^32) and
// returns PCG's RXS-M-XS permutation of s' (O'Neill 2014; the "pcg_hash" of Jarzynski and Olano
// 2020, Hash Functions for GPU Rendering), its high 24 bits scaled into [0, 1): every value a float
// holds exactly, never 1. The same seed and stream give the same numbers in HLSL, in every form
// the kit writes and in the C++ reference (runtime/reference/path_tracer.hpp).
#ifndef COMMON_RANDOM_FXH
#define COMMON_RANDOM_FXH

struct RandomState
{
    uint State;
};

uint PcgPermute( uint state )
{
    uint word = ( ( state >> ( ( state >> 28u ) + 4u ) ) ^ state ) * 277803737u;
    return ( word >> 22u ) ^ word;
}

// A generator for one stream (a pixel, a thread) of a seeded run: streams of one seed, and seeds
// of one stream, start at unrelated states.
RandomState SeedRandom( uint seed, uint stream )
{
    RandomState rng;
    rng.State = PcgPermute( PcgPermute( seed ) + stream );
    return rng;
}

float Random( inout RandomState rng )
{
    rng.State = rng.State * 747796405u + 2891336453u;
    return float( PcgPermute( rng.State ) >> 8 ) * ( 1.f / 16777216.f );
}

#endif // COMMON_RANDOM_FXH
