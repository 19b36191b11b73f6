#include "pyramid_fit.hpp"

#include "pbr.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace iblkit::reference {
namespace {

constexpr double kLodStep = 0.25;

// The lobe's weight at the mip-0 texels around the one a read falls in, by their offsets (x, y)
// from it, 0 to radius each (the lobe is symmetric in both): D(N·H) N·L dω with L through the
// texel's centre, normalised to sum 1 over all four quadrants.
std::vector<double> lobeQuadrant(double roughness, int radius, uint32_t sourceSize) {
    const int width = radius + 1;
    const double texel = 2.0 / sourceSize; // texel width on the face plane z = 1
    std::vector<double> weights(size_t(width) * width);
    double total = 0;
    for (int y = 0; y < width; ++y)
        for (int x = 0; x < width; ++x) {
            const double px = x * texel, py = y * texel;
            const double ndotl = 1 / std::sqrt(1 + px * px + py * py);
            const double solidAngle = texel * texel * ndotl * ndotl * ndotl;
            const double ndoth = std::sqrt((1 + ndotl) / 2); // H halfway between N = V and L
            const double weight = DistributionGGX(ndoth, roughness) * ndotl * solidAngle;
            weights[size_t(y) * width + x] = weight;
            total += weight * (x > 0 ? 2 : 1) * (y > 0 ? 2 : 1);
        }
    for (double& weight : weights) weight /= total;
    return weights;
}

// What a bilinear read at `mip` gives each mip-0 texel along one axis, by the texel's offset
// from the one the read falls in (-radius to radius), averaged over where in the mip's texel the
// read falls: mip-0 texel i is 1 / s of mip texel ⌊i / s⌋, whose bilinear weight at the read's
// position p is 1 - |p - its centre| / s.
std::vector<double> mipReadProfile(uint32_t mip, int radius) {
    const int span = 1 << mip;
    std::vector<double> profile(size_t(2 * radius + 1), 0.0);
    for (int q = 0; q < span; ++q) { // the read at mip-0 texel q's centre within its mip texel
        const double position = q + 0.5;
        for (int offset = -radius; offset <= radius; ++offset) {
            const int texel = q + offset;
            const double centre = (std::floor(double(texel) / span) + 0.5) * span;
            const double bilinear = std::max(0.0, 1 - std::abs(position - centre) / span);
            profile[size_t(offset + radius)] += bilinear / span / span;
        }
    }
    return profile;
}

std::vector<double> readProfile(double lod, const std::vector<std::vector<double>>& mipProfiles) {
    const auto below = size_t(std::floor(lod));
    const double fraction = lod - double(below);
    if (fraction == 0) return mipProfiles[below];
    std::vector<double> profile(mipProfiles[below].size());
    for (size_t i = 0; i < profile.size(); ++i)
        profile[i] = (1 - fraction) * mipProfiles[below][i] + fraction * mipProfiles[below + 1][i];
    return profile;
}

// The least-squares system of up to kMaxPyramidReads weights and their Lagrange multiplier, each
// row followed by its right-hand side.
using ReadSystem = std::array<std::array<double, kMaxPyramidReads + 2>, kMaxPyramidReads + 1>;

// Solves the first n rows in place by Gaussian elimination with partial pivoting, leaving the
// solution in column n; false when they are singular.
bool solve(ReadSystem& system, size_t n) {
    for (size_t column = 0; column < n; ++column) {
        size_t pivot = column;
        for (size_t row = column + 1; row < n; ++row)
            if (std::abs(system[row][column]) > std::abs(system[pivot][column])) pivot = row;
        if (std::abs(system[pivot][column]) < 1e-300) return false;
        std::swap(system[pivot], system[column]);
        for (size_t row = 0; row < n; ++row) {
            if (row == column) continue;
            const double factor = system[row][column] / system[column][column];
            for (size_t k = column; k <= n; ++k) system[row][k] -= factor * system[column][k];
        }
    }
    for (size_t row = 0; row < n; ++row) system[row][n] /= system[row][row];
    return true;
}

struct Candidates {
    std::vector<double> lods;
    std::vector<std::vector<double>> gram; // <kernel a, kernel b>
    std::vector<double> against;           // <kernel a, lobe>
};

struct Fit {
    double residual = std::numeric_limits<double>::infinity(); // ‖Σ w kernel‖² - 2 <Σ w kernel, lobe>
    std::vector<PyramidRead> reads;
};

// The least-squares weights of the candidates `chosen`, summing to 1 (a Lagrange multiplier),
// kept only if all are non-negative and the fit is better than `best`.
void tryChoice(const Candidates& candidates, const std::vector<size_t>& chosen, Fit& best) {
    const size_t n = chosen.size();
    ReadSystem system{};
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = 0; j < n; ++j) system[i][j] = candidates.gram[chosen[i]][chosen[j]];
        system[i][n] = 1;
        system[n][i] = 1;
        system[i][n + 1] = candidates.against[chosen[i]];
    }
    system[n][n + 1] = 1;
    if (!solve(system, n + 1)) return;
    const auto weight = [&](size_t i) { return system[i][n + 1]; };
    double residual = 0;
    for (size_t i = 0; i < n; ++i) {
        if (weight(i) < 0) return;
        residual -= 2 * weight(i) * candidates.against[chosen[i]];
        for (size_t j = 0; j < n; ++j) residual += weight(i) * weight(j) * candidates.gram[chosen[i]][chosen[j]];
    }
    if (residual >= best.residual) return;
    best.residual = residual;
    best.reads.clear();
    for (size_t i = 0; i < n; ++i)
        if (weight(i) > 0) best.reads.push_back({float(candidates.lods[chosen[i]]), float(weight(i))});
}

// Every choice of `count` candidates in increasing order.
void forEachChoice(size_t candidates, size_t count, std::vector<size_t>& chosen, const auto& visit) {
    if (chosen.size() == count) return visit(chosen);
    for (size_t next = chosen.empty() ? 0 : chosen.back() + 1; next < candidates; ++next) {
        chosen.push_back(next);
        forEachChoice(candidates, count, chosen, visit);
        chosen.pop_back();
    }
}

// The candidates on a cube of sourceSize² faces, lods counted from its mip 0.
Candidates candidatesFor(double roughness, uint32_t sourceSize) {
    const auto topMip = uint32_t(std::countr_zero(sourceSize));
    // The window holds the lobe to where D has fallen a thousandfold, within the face.
    const double alpha = std::max(roughness * roughness, 1.0 / sourceSize);
    const int radius = std::clamp(int(std::ceil(16 * alpha * sourceSize / 2)), 8, int(sourceSize / 2));
    const auto lobe = lobeQuadrant(roughness, radius, sourceSize);
    std::vector<std::vector<double>> mipProfiles;
    for (uint32_t mip = 0; mip <= topMip; ++mip) mipProfiles.push_back(mipReadProfile(mip, radius));

    Candidates candidates;
    std::vector<std::vector<double>> profiles;
    for (double lod = 0; lod <= topMip; lod += kLodStep) {
        candidates.lods.push_back(lod);
        profiles.push_back(readProfile(lod, mipProfiles));
    }
    const size_t width = size_t(2 * radius + 1), centre = size_t(radius), quadrant = size_t(radius + 1);
    for (const auto& a : profiles) {
        std::vector<double> row;
        for (const auto& b : profiles) {
            double dot = 0;
            for (size_t i = 0; i < width; ++i) dot += a[i] * b[i];
            row.push_back(dot * dot); // the kernels are separable
        }
        candidates.gram.push_back(row);
        // The lobe's quadrant holds offsets 0 to radius; each other quadrant mirrors it.
        const auto folded = [&](size_t offset) {
            return offset == 0 ? a[centre] : a[centre + offset] + a[centre - offset];
        };
        double against = 0;
        for (size_t y = 0; y < quadrant; ++y) {
            double rowSum = 0;
            for (size_t x = 0; x < quadrant; ++x) rowSum += folded(x) * lobe[y * quadrant + x];
            against += folded(y) * rowSum;
        }
        candidates.against.push_back(against);
    }
    return candidates;
}

// The same fit on a coarser cube with the lobe still 8 texels wide or more (mip c of this cube
// is mip 0 of that one, and a read at lod l there is a read at l + c here): the window and the
// profiles shrink fourfold per mip of coarsening, and no lod the coarser cube cannot read, below
// c, fits a lobe that wide.
uint32_t coarsening(double roughness, uint32_t sourceSize) {
    const double halfWidth = roughness * roughness * sourceSize / 2; // the lobe's, in texels
    uint32_t coarser = 0;
    while (sourceSize >> (coarser + 1) >= 8 && halfWidth / double(1u << (coarser + 1)) >= 8) ++coarser;
    return coarser;
}

} // namespace

std::vector<PyramidRead> fitPyramidReads(double roughness, uint32_t reads, uint32_t sourceSize) {
    if (reads == 0 || reads > kMaxPyramidReads)
        throw std::invalid_argument("the pyramid prefilter takes 1 to " + std::to_string(kMaxPyramidReads) +
                                    " reads, not " + std::to_string(reads));
    if (sourceSize == 0 || !std::has_single_bit(sourceSize))
        throw std::invalid_argument("the pyramid prefilter needs faces a power of two wide, not " +
                                    std::to_string(sourceSize));
    if (!(roughness > 0)) return {{0, 1}}; // D is 0/0 at roughness 0: a mirror reads mip 0
    const uint32_t coarser = coarsening(roughness, sourceSize);
    const auto candidates = candidatesFor(roughness, sourceSize >> coarser);
    Fit best;
    std::vector<size_t> chosen;
    for (uint32_t count = 1; count <= reads; ++count)
        forEachChoice(candidates.lods.size(), count, chosen, [&](const std::vector<size_t>& choice) {
            tryChoice(candidates, choice, best);
        });
    for (auto& read : best.reads) read.lod += float(coarser);
    return best.reads;
}

} // namespace iblkit::reference
