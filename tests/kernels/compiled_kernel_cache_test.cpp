// The compiled-kernel cache: a second compile of a kernel is a hit with the same program, an
// #included file that changed makes its entry stale, defines are part of the key, a damaged entry
// is compiled again, a cache that cannot be written still compiles, and the cache is per thread.
#include "kernels/compiled_kernel_cache.hpp"

#include "content_store.hpp"
#include "temp_folder.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

namespace iblkit::kernels {
namespace {

namespace fs = std::filesystem;

const KernelEntry& skyCube() { return kernelFor(KernelRole::SkyCube); } // includes Common/Cube.fxh

std::vector<fs::path> entries(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) files.push_back(entry.path());
    return files;
}

void expectSameProgram(const KernelProgram& a, const KernelProgram& b) {
    EXPECT_EQ(a.spirv, b.spirv);
    EXPECT_EQ(compiler::toJson(a.reflection), compiler::toJson(b.reflection));
}

TEST(CompiledKernelCache, ASecondCompileIsAHitWithTheSameProgram) {
    iblkit::testing::TempFolder folder;
    CompiledKernelCache cache(folder.path());
    const auto uncached = compileKernel(skyCube());
    const UseCompiledKernelCache use(&cache);
    const auto first = compileKernel(skyCube());
    const auto second = compileKernel(skyCube());
    EXPECT_EQ(cache.counts().misses, 1u);
    EXPECT_EQ(cache.counts().hits, 1u);
    expectSameProgram(first, uncached);
    expectSameProgram(second, uncached);
}

TEST(CompiledKernelCache, AChangedIncludeMakesTheEntryStale) {
    iblkit::testing::TempFolder folder;
    CompiledKernelCache cache(folder.path());
    const UseCompiledKernelCache use(&cache);
    const auto original = compileKernel(skyCube());
    auto files = embeddedShaderFiles();
    auto& header = files.at("hlsl/Common/Cube.fxh");
    const std::string scale = "float2( 2.f, -2.f )";
    ASSERT_NE(header.find(scale), std::string::npos);
    header.replace(header.find(scale), scale.size(), "float2( 2.f, -2.5f )");
    const auto changed = compileKernel(skyCube(), {}, {}, files);
    EXPECT_EQ(cache.counts().stale, 1u);
    EXPECT_EQ(cache.counts().hits, 0u);
    EXPECT_NE(changed.spirv, original.spirv) << "the stale entry's program was served";
    const auto again = compileKernel(skyCube(), {}, {}, files);
    EXPECT_EQ(cache.counts().hits, 1u) << "the new compile replaced the stale entry";
    expectSameProgram(again, changed);
}

TEST(CompiledKernelCache, DefinesArePartOfTheKey) {
    iblkit::testing::TempFolder folder;
    CompiledKernelCache cache(folder.path());
    const UseCompiledKernelCache use(&cache);
    const auto& kernel = kernelFor(KernelRole::Prefilter, "document");
    const auto few = compileKernel(kernel, {{"SAMPLE_COUNT", "16"}});
    const auto many = compileKernel(kernel, {{"SAMPLE_COUNT", "64"}});
    EXPECT_EQ(cache.counts().misses, 2u);
    EXPECT_NE(few.spirv, many.spirv);
    expectSameProgram(compileKernel(kernel, {{"SAMPLE_COUNT", "64"}}), many);
    EXPECT_EQ(cache.counts().hits, 1u);
}

TEST(CompiledKernelCache, ADamagedEntryIsCompiledAgain) {
    iblkit::testing::TempFolder folder;
    const auto original = compileKernel(skyCube());
    {
        CompiledKernelCache cache(folder.path());
        const UseCompiledKernelCache use(&cache);
        compileKernel(skyCube());
    }
    const auto files = entries(folder.path());
    ASSERT_EQ(files.size(), 1u);
    {
        std::fstream file(files[0], std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(-9, std::ios::end);
        file.put('!');
    }
    CompiledKernelCache cache(folder.path());
    const UseCompiledKernelCache use(&cache);
    expectSameProgram(compileKernel(skyCube()), original);
    EXPECT_EQ(cache.counts().damaged, 1u);
    EXPECT_EQ(cache.counts().hits, 0u);
    expectSameProgram(compileKernel(skyCube()), original);
    EXPECT_EQ(cache.counts().hits, 1u) << "written anew";
}

TEST(CompiledKernelCache, AWholeEntryThatIsNoKernelIsDamaged) {
    iblkit::testing::TempFolder folder;
    {
        CompiledKernelCache cache(folder.path());
        const UseCompiledKernelCache use(&cache);
        compileKernel(skyCube());
    }
    const auto key = entries(folder.path()).at(0).filename().string();
    cache::ContentStore(folder.path()).put(key, "not CBOR"); // its checksum holds
    CompiledKernelCache cache(folder.path());
    const UseCompiledKernelCache use(&cache);
    expectSameProgram(compileKernel(skyCube()), compileKernel(skyCube()));
    EXPECT_EQ(cache.counts().damaged, 1u);
    EXPECT_EQ(cache.counts().hits, 1u);
}

TEST(CompiledKernelCache, ACacheThatCannotBeWrittenStillCompiles) {
    iblkit::testing::TempFolder folder;
    const auto notAFolder = folder.write("file", "a file where the cache's folder would be");
    CompiledKernelCache cache(notAFolder);
    const UseCompiledKernelCache use(&cache);
    expectSameProgram(compileKernel(skyCube()), [] {
        const UseCompiledKernelCache none(nullptr);
        return compileKernel(skyCube());
    }());
    EXPECT_EQ(cache.counts().unwritable, 1u);
}

TEST(CompiledKernelCache, TheCacheInUseIsPerThreadAndScopesRestoreIt) {
    iblkit::testing::TempFolder folder;
    CompiledKernelCache outer(folder.path() / "outer"), inner(folder.path() / "inner");
    EXPECT_EQ(compiledKernelCacheInUse(), nullptr);
    {
        const UseCompiledKernelCache useOuter(&outer);
        {
            const UseCompiledKernelCache useInner(&inner);
            EXPECT_EQ(compiledKernelCacheInUse(), &inner);
            CompiledKernelCache* seenByAnotherThread = &outer;
            std::thread([&] { seenByAnotherThread = compiledKernelCacheInUse(); }).join();
            EXPECT_EQ(seenByAnotherThread, nullptr);
        }
        EXPECT_EQ(compiledKernelCacheInUse(), &outer);
    }
    EXPECT_EQ(compiledKernelCacheInUse(), nullptr);
}

TEST(CompiledKernelCache, ThreadsSharingOneCacheCountEveryCompile) {
    iblkit::testing::TempFolder folder;
    CompiledKernelCache cache(folder.path());
    const auto compileTwice = [&cache](KernelRole role) {
        const UseCompiledKernelCache use(&cache);
        compileKernel(kernelFor(role));
        compileKernel(kernelFor(role));
    };
    std::thread a(compileTwice, KernelRole::SkyCube), b(compileTwice, KernelRole::DownsampleCube);
    a.join();
    b.join();
    EXPECT_EQ(cache.counts().misses, 2u);
    EXPECT_EQ(cache.counts().hits, 2u);
}

} // namespace
} // namespace iblkit::kernels
