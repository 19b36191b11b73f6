#include "include_resolver.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <utility>

namespace iblkit::compiler {
namespace {

bool sameLetters(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](unsigned char x, unsigned char y) {
               return std::tolower(x) == std::tolower(y);
           });
}

// The file as Windows finds it: a name that differs only in case from the one on disk (the
// compilers of Direct3D code bases run on a file system that ignores case).
std::filesystem::path onDisk(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::exists(path, error)) return path;
    std::filesystem::path found;
    for (const auto& part : path.lexically_normal()) {
        const auto candidate = found / part;
        if (found.empty() || std::filesystem::exists(candidate, error) || part == "..") {
            found = candidate;
            continue;
        }
        bool matched = false;
        for (const auto& entry : std::filesystem::directory_iterator(found, error))
            if (sameLetters(entry.path().filename().string(), part.string())) {
                found = entry.path();
                matched = true;
                break;
            }
        if (!matched) return path;
    }
    return found;
}

bool readFile(const std::filesystem::path& path, std::string& text) {
    std::error_code error;
    const auto file = onDisk(path);
    if (!std::filesystem::is_regular_file(file, error)) return false;
    std::ifstream stream(file, std::ios::binary);
    if (!stream) return false;
    std::ostringstream buffer;
    buffer << stream.rdbuf();
    text = asGlslangReadsIt(buffer.str());
    return true;
}

// "util\\HlslCompat.h" as Windows reads it.
std::string forwardSlashes(std::string name) {
    std::replace(name.begin(), name.end(), '\\', '/');
    return name;
}

int lineOfInclude(const std::string& includerText, const std::string& headerName) {
    std::istringstream lines(includerText);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number)
        if (line.find("#include") != std::string::npos && line.find(headerName) != std::string::npos) return number;
    return 1;
}

bool isContinuation(const std::string& text, size_t at) {
    return text[at] == '\\' && (text.compare(at + 1, 1, "\n") == 0 || text.compare(at + 1, 2, "\r\n") == 0);
}

// Lines ended by a backslash joined before glslang reads them, as a C preprocessor's second phase
// does: glslang's own splicing loses a macro whose name is followed by one ("#define RS\" then
// "[RootSignature(...)]" on the next lines). Outside a string literal the join keeps the tokens
// apart with a space, except before "(", where "#define F\" + "(x)" is a function-like macro.
// The joined lines' newlines follow the logical line, so every later line keeps its number.
std::string withContinuationsJoined(const std::string& text) {
    if (text.find("\\\n") == std::string::npos && text.find("\\\r\n") == std::string::npos) return text;
    std::string joined;
    joined.reserve(text.size());
    size_t pendingNewlines = 0;
    bool inString = false;
    for (size_t at = 0; at < text.size(); ++at) {
        if (isContinuation(text, at)) {
            at += text[at + 1] == '\r' ? 2 : 1;
            ++pendingNewlines;
            const bool beforeParenthesis = at + 1 < text.size() && text[at + 1] == '(';
            if (!inString && !beforeParenthesis) joined += ' ';
            continue;
        }
        const char c = text[at];
        if (c == '"' && (at == 0 || text[at - 1] != '\\')) inString = !inString;
        if (c == '\n') inString = false;
        joined += c;
        if (c == '\n') joined.append(std::exchange(pendingNewlines, 0), '\n');
    }
    return joined;
}

} // namespace

std::string asGlslangReadsIt(std::string text) {
    constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
    if (text.rfind(kByteOrderMark, 0) == 0) text.erase(0, kByteOrderMark.size());
    if (!text.empty() && text.back() != '\n') text += '\n';
    return withContinuationsJoined(text);
}

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
    if (auto* result = load(includerDir / forwardSlashes(headerName), headerName, includerName)) return result;
    return includeSystem(headerName, includerName, depth);
}

IncludeResolver::IncludeResult* IncludeResolver::includeSystem(const char* headerName, const char* includerName,
                                                               size_t) {
    for (const auto& dir : includeDirs_)
        if (auto* result = load(dir / forwardSlashes(headerName), headerName, includerName)) return result;
    // A header an engine's build makes as it compiles, served by the name it is included by.
    if (virtualFiles_ && virtualFiles_->count(headerName)) return load(headerName, headerName, includerName);
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
