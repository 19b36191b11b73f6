#include "vulkan_test_support.hpp"

#include "temp_folder.hpp"

namespace iblkit::testing {

compiler::CompiledShader compileTestShader(const std::string& name, const std::string& source,
                                           std::map<std::string, std::string> imageFormats) {
    const TempFolder folder;
    compiler::CompileOptions options;
    options.source = folder.write(name + ".hlsl", source);
    options.imageFormats = std::move(imageFormats);
    return compiler::compileShader(options);
}

} // namespace iblkit::testing
