#include "include_resolver.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace iblkit::compiler {
namespace {

bool readFile(const std::filesystem::path& path, std::string& text) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return false;
    std::ifstream stream(path, std::ios::binary);
    if (!stream) return false;
    std::ostringstream buffer;
    buffer << stream.rdbuf();
    text = buffer.str();
    return true;
}

int lineOfInclude(const std::string& includerText, const std::string& headerName) {
    std::istringstream lines(includerText);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number)
        if (line.find("#include") != std::string::npos && line.find(headerName) != std::string::npos) return number;
    return 1;
}

} // namespace

IncludeResolver::IncludeResolver(std::vector<std::filesystem::path> includeDirs,
                                 const std::map<std::string, std::string>* virtualFiles)
    : includeDirs_(std::move(includeDirs)), virtualFiles_(virtualFiles) {}

void IncludeResolver::addSource(const std::string& name, std::string text) {
    texts_[name] = std::move(text);
    open_.push_back(name);
}

const std::string* IncludeResolver::sourceText(const std::string& name) const {
    auto it = texts_.find(name);
    return it == texts_.end() ? nullptr : &it->second;
}

const IncludeSite* IncludeResolver::includeSite(const std::string& name) const {
    auto it = sites_.find(name);
    return it == sites_.end() ? nullptr : &it->second;
}

IncludeResolver::IncludeResult* IncludeResolver::includeLocal(const char* headerName, const char* includerName,
                                                              size_t depth) {
    const auto includerDir = std::filesystem::path(includerName).parent_path();
    if (auto* result = load(includerDir / headerName, headerName, includerName)) return result;
    return includeSystem(headerName, includerName, depth);
}

IncludeResolver::IncludeResult* IncludeResolver::includeSystem(const char* headerName, const char* includerName,
                                                               size_t) {
    for (const auto& dir : includeDirs_)
        if (auto* result = load(dir / headerName, headerName, includerName)) return result;
    return nullptr;
}

bool IncludeResolver::readVirtualFile(const std::string& name, std::string& text) const {
    if (!virtualFiles_) return false;
    const auto found = virtualFiles_->find(name);
    if (found == virtualFiles_->end()) return false;
    text = found->second;
    return true;
}

IncludeResolver::IncludeResult* IncludeResolver::load(const std::filesystem::path& path, const std::string& headerName,
                                                      const char* includerName) {
    const std::string name = path.lexically_normal().string();
    if (std::count(open_.begin(), open_.end(), name) >= 2) {
        if (!cycle_) cycle_ = cycleMessage(name, includerName, headerName);
        return nullptr;
    }
    std::string text;
    if (!texts_.count(name)) {
        if (!readVirtualFile(name, text) && !readFile(path, text)) return nullptr;
        texts_[name] = std::move(text);
        includedFiles_.push_back(name);
    }
    if (!sites_.count(name)) {
        const std::string* includerText = sourceText(includerName);
        sites_[name] = IncludeSite{includerName, includerText ? lineOfInclude(*includerText, headerName) : 1};
    }
    const std::string& stored = texts_[name];
    open_.push_back(name);
    return new IncludeResult(name, stored.data(), stored.size(), nullptr);
}

std::string IncludeResolver::cycleMessage(const std::string& name, const char* includerName,
                                          const std::string& headerName) const {
    const auto last = std::find(open_.rbegin(), open_.rend(), name).base() - 1;
    std::string chain;
    for (auto it = last; it != open_.end(); ++it) chain += *it + " → ";
    const std::string* includerText = sourceText(includerName);
    const int line = includerText ? lineOfInclude(*includerText, headerName) : 1;
    return std::string(includerName) + ":" + std::to_string(line) + ": error: #include cycle: " + chain + name +
           " (a file that includes itself, directly or through others, with no include guard)";
}

void IncludeResolver::releaseInclude(IncludeResult* result) {
    if (result) {
        const auto open = std::find(open_.rbegin(), open_.rend(), result->headerName);
        if (open != open_.rend()) open_.erase(std::next(open).base());
    }
    delete result;
}

} // namespace iblkit::compiler
