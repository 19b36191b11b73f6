#include "vulkan_test_support.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace iblkit::testing {

compiler::CompiledShader compileTestShader(const std::string& name, const std::string& source,
                                           std::map<std::string, std::string> imageFormats) {
    const auto folder = std::filesystem::temp_directory_path() / ("iblkit-vk-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const auto path = folder / (name + ".hlsl");
    std::ofstream(path) << source;
    compiler::CompileOptions options;
    options.source = path;
    options.imageFormats = std::move(imageFormats);
    auto shader = compiler::compileShader(options);
    std::filesystem::remove_all(folder);
    return shader;
}

} // namespace iblkit::testing
