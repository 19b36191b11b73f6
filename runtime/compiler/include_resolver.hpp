#pragma once

#include <glslang/Public/ShaderLang.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace iblkit::compiler {

// Where a file was included from, for the include chain of a diagnostic.
struct IncludeSite {
    std::string includer;
    int line;
};

// Resolves #include "x" against the including file's folder, then the -I folders in order
// (#include <x> against the -I folders only), and remembers every file it read.
class IncludeResolver : public glslang::TShader::Includer {
public:
    explicit IncludeResolver(std::vector<std::filesystem::path> includeDirs,
                             const std::map<std::string, std::string>* virtualFiles = nullptr);

    void addSource(const std::string& name, std::string text); // the top-level file
    IncludeResult* includeLocal(const char* headerName, const char* includerName, size_t depth) override;
    IncludeResult* includeSystem(const char* headerName, const char* includerName, size_t depth) override;
    void releaseInclude(IncludeResult* result) override;

    const std::vector<std::string>& includedFiles() const { return includedFiles_; }
    const std::string* sourceText(const std::string& name) const;
    const IncludeSite* includeSite(const std::string& name) const;

private:
    bool readVirtualFile(const std::string& name, std::string& text) const;
    IncludeResult* load(const std::filesystem::path& path, const std::string& headerName, const char* includerName);

    std::vector<std::filesystem::path> includeDirs_;
    const std::map<std::string, std::string>* virtualFiles_;
    std::map<std::string, std::string> texts_;
    std::map<std::string, IncludeSite> sites_;
    std::vector<std::string> includedFiles_;
};

} // namespace iblkit::compiler
