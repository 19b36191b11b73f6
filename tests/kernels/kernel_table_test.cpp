// The kernel table is hlsl/shaders.json: every shader in it is a kernel with a role, the
// documents' transcriptions are the ones under hlsl/document/, and each compiles from the copy
// of hlsl/ inside the program.
#include "kernels/kernel_table.hpp"

#include "shader_manifest.hpp"

#include <gtest/gtest.h>

#include <set>

namespace iblkit::kernels {
namespace {

TEST(KernelTable, EveryManifestShaderIsAKernelAndCompiles) {
    const auto manifest = compiler::readShaderManifest("hlsl/shaders.json");
    ASSERT_EQ(kernelTable().size(), manifest.size()) << "the built-in manifest is the one on disk";
    std::set<KernelRole> roles;
    for (const auto& kernel : kernelTable()) {
        roles.insert(kernel.role);
        EXPECT_NO_THROW(compileKernel(kernel)) << kernel.name;
    }
    EXPECT_EQ(roles.size(), 20u) << "every role has a kernel";
}

TEST(KernelTable, TheDocumentsShadersAreTheFrozenOnes) {
    std::set<std::string> document;
    for (const auto& kernel : kernelTable())
        if (kernel.document) document.insert(kernel.name);
    EXPECT_EQ(document, (std::set<std::string>{"PrecomputedBrdfCS", "PrefilterSpecularCS"}));
    EXPECT_EQ(kernelFor(KernelRole::Prefilter, "document").name, "PrefilterSpecularCS");
    EXPECT_EQ(kernelFor(KernelRole::PrefilterChunk, "document").name, "PrefilterSpecularChunkCS");
    EXPECT_EQ(methodsOf(KernelRole::Prefilter), (std::vector<std::string>{"document", "filtered"}));
    EXPECT_EQ(methodsOf(KernelRole::PrefilterTable), std::vector<std::string>{"table"});
    EXPECT_EQ(methodsOf(KernelRole::PrefilterConvolution), std::vector<std::string>{"convolution"});
}

TEST(KernelTable, AKernelSharedByMethodsServesEach) {
    // The ring is the pyramid's for wide lobes and the mip chain's.
    EXPECT_EQ(methodsOf(KernelRole::PrefilterRing), (std::vector<std::string>{"pyramid", "mipchain"}));
    EXPECT_EQ(methodsOf(KernelRole::RenderReference), (std::vector<std::string>{"document", "split-sum-material"}));
    EXPECT_EQ(kernelFor(KernelRole::PrefilterRing, "pyramid").name, "PrefilterRingCS");
    EXPECT_EQ(kernelFor(KernelRole::PrefilterRing, "mipchain").name, "PrefilterRingCS");
    EXPECT_THROW(kernelFor(KernelRole::PrefilterPyramid, "mipchain"), std::out_of_range);
}

TEST(KernelTable, UnknownNamesAreRefusedByName) {
    EXPECT_THROW(kernelNamed("NoSuchCS"), std::out_of_range);
    EXPECT_THROW(kernelFor(KernelRole::Prefilter, "no-such-method"), std::out_of_range);
}

TEST(KernelTable, ReplacedShaderFilesAreWhatCompiles) {
    auto files = embeddedShaderFiles();
    files.at("hlsl/document/Common/PBR.fxh") = "this is not HLSL";
    EXPECT_ANY_THROW(compileKernel(kernelNamed("PrefilterSpecularCS"), {}, {}, files));
}

} // namespace
} // namespace iblkit::kernels
