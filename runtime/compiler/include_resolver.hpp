#pragma once

#include <glslang/Public/ShaderLang.h>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace iblkit::compiler {

// Source text as DXC and fxc take it, for glslang: a UTF-8 byte-order mark (Visual Studio's
// default) dropped, and a last line given its newline (glslang refuses an #include without one).
std::string asGlslangReadsIt(std::string text);

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
    // "b.hlsl:3: error: #include cycle: a.hlsl → b.hlsl → a.hlsl" once a file was included while
    // already open twice (an include guard stops a cycle at its second entry; without one it never ends).
    const std::optional<std::string>& cycle() const { return cycle_; }

private:
    bool readVirtualFile(const std::string& name, std::string& text) const;
    IncludeResult* load(const std::filesystem::path& path, const std::string& headerName, const char* includerName);
    std::string cycleMessage(const std::string& name, const char* includerName, const std::string& headerName) const;

    std::vector<std::filesystem::path> includeDirs_;
    const std::map<std::string, std::string>* virtualFiles_;
    std::map<std::string, std::string> texts_;
    std::map<std::string, IncludeSite> sites_;
    std::vector<std::string> includedFiles_;
    std::vector<std::string> open_; // the files being read, outermost first
    std::optional<std::string> cycle_;
};

} // namespace iblkit::compiler
