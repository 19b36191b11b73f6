#pragma once

#include "kernels/convolution_method.hpp"
#include "kernels/mip_chain_method.hpp"
#include "kernels/pyramid_method.hpp"
#include "kernels/sampled_methods.hpp"
#include "kernels/table_method.hpp"

#include "shading/lobe_table.hpp"

#include <optional>
#include <string>
#include <vector>

namespace iblkit::kernels {

// How a prefilter method's kernels compute a mip: a sampled estimator with its per-sample work
// on the GPU (Prefilter, PrefilterChunk), a host sample table (PrefilterTable), reads of the
// source's mip chain along the normal (PrefilterPyramid), the source's mips themselves with the
// ring where the lobe is wide (PrefilterRing alone), or the convolution (ClusterCube +
// PrefilterConvolution). Throws std::out_of_range for a method with none of them.
enum class SpecularKind { Sampled, Table, Pyramid, MipChain, Convolution };
SpecularKind specularKindOf(const std::string& method);
bool isConvolutionMethod(const std::string& method);

// Every method with a prefilter kernel: the sampled ones, the tables, the pyramids, then the
// convolutions, in table order.
std::vector<std::string> specularMethods();

// The largest sample count (budget, for the convolution; reads, for the pyramid; 1, for the mip
// chain, which takes none) `method`'s prefilter takes: a sampled method without a chunked twin,
// and a table, stop at the driver's loop limit. Throws
// std::out_of_range for a method with no prefilter kernel.
uint32_t maxSamplesOf(const std::string& method);

// A prefilter method by name, whichever kernels implement it. `samples` is the sample count of
// a sampled method, the reads per texel of the pyramid, and the budget of terms per output texel
// of the convolution. `expectedSourceSize`, where known, is the width of the sources it will run
// on (the convolution compiles the walk for their pyramid first).
class SpecularMethod {
public:
    SpecularMethod(const vulkan::VulkanContext& context, const std::string& method, uint32_t samples,
                   const ShaderFiles& files = embeddedShaderFiles(), uint32_t expectedSourceSize = 0);
    // Writes mip `mip` of `target` (RGBA32F, storage) from `source` at `roughness`; a sampled
    // method reads `source` through `sampler`.
    void run(vulkan::Image& source, const vulkan::Sampler& sampler, vulkan::Image& target, uint32_t mip, float roughness);
    // The lobe the next runs weigh: N·L (every method, the default) or G1 (the convolution alone;
    // std::invalid_argument for another method).
    void setWeighting(shading::LobeWeighting weighting);
    DispatchTotals takeTotals();
    uint32_t chunkSamples() const; // 0 for one dispatch per mip
    // Frees what the runs kept of their source (the convolution's pyramids) once a chain is done.
    void releaseSourceData();

private:
    std::optional<PrefilterMethod> sampled_;
    std::optional<TablePrefilter> table_;
    std::optional<PyramidPrefilter> pyramid_;
    std::optional<MipChainPrefilter> mipChain_;
    std::optional<ConvolutionPrefilter> convolution_;
};

} // namespace iblkit::kernels
