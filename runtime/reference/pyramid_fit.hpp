#pragma once

#include <cstdint>
#include <vector>

namespace iblkit::reference {

// One read of the pyramid prefilter: the source's mip chain sampled along the texel's normal at
// `lod` (at a face centre), weighted by `weight`.
struct PyramidRead {
    float lod = 0;
    float weight = 0;
};

inline constexpr uint32_t kMaxPyramidReads = 4;

// The reads whose weighted sum best matches the prefilter's lobe at `roughness` on a cube of
// sourceSize² faces (a power of two): least squares, in double, between the lobe's weights over
// the mip-0 texels of a face around its centre, D(N·H) N·L dω at N = V, and the kernels the reads
// apply there. A read at lod l is the mip chain's 2x2 means, read bilinearly at mips ⌊l⌋ and ⌈l⌉
// and blended, averaged over where the read falls among the texels. Lods are searched in
// quarters from 0 to the top of the chain; weights are non-negative and sum to 1. Returns at
// most `reads` reads (fewer where more do not fit better), ordered by lod; at roughness 0, a
// mirror, one read of mip 0. Throws
// std::invalid_argument for 0 or more than kMaxPyramidReads reads, or a size that is not a power
// of two.
std::vector<PyramidRead> fitPyramidReads(double roughness, uint32_t reads, uint32_t sourceSize);

} // namespace iblkit::reference
