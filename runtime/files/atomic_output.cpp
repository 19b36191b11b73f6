#include "atomic_output.hpp"

#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace iblkit::files {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
    throw FileError(path.string() + ": error: cannot write the file: " + what);
}

std::filesystem::path writeTemporary(const std::filesystem::path& path, const std::string& contents) {
    const auto folder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) fail(path, "no such directory " + folder.string());
    if (std::filesystem::is_directory(path, error)) fail(path, "it is a directory");
    // Short, whatever the output's name: one near the 255-byte limit must still get a temporary.
    std::string pattern = (folder / ".iblkit-tmp-XXXXXX").string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) fail(path, "no new file can be made in " + folder.string() + ", where it is written first (" + std::strerror(errno) + ")");
    size_t written = 0;
    while (written < contents.size()) {
        const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string reason = std::strerror(errno);
            ::close(fd);
            ::unlink(pattern.c_str());
            fail(path, reason);
        }
        written += static_cast<size_t>(n);
    }
    // Temporaries are made 0600; outputs get the usual permissions.
    if (::fchmod(fd, 0644) != 0 || ::close(fd) != 0) {
        const std::string reason = std::strerror(errno);
        ::unlink(pattern.c_str());
        fail(path, reason);
    }
    return pattern;
}

void refuseClash(const std::filesystem::path& output, const std::vector<std::filesystem::path>& earlierOutputs,
                 const std::vector<std::filesystem::path>& inputs) {
    for (const auto& input : inputs)
        if (sameFile(output, input))
            throw FileError(output.string() + ": error: this output is also an input of the command" +
                            (output == input ? std::string() : " ('" + input.string() + "')") +
                            ": writing it would destroy it");
    for (const auto& earlier : earlierOutputs)
        if (sameFile(output, earlier))
            throw FileError(output.string() + ": error: two outputs of the command are this one file" +
                            (output == earlier ? std::string() : " (also named '" + earlier.string() + "')"));
}

} // namespace

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
    struct stat first {}, second {};
    if (::stat(a.c_str(), &first) == 0 && ::stat(b.c_str(), &second) == 0)
        return first.st_dev == second.st_dev && first.st_ino == second.st_ino;
    std::error_code error;
    const auto normal = [&](const std::filesystem::path& path) {
        const auto absolute = std::filesystem::weakly_canonical(path, error);
        return error ? std::filesystem::absolute(path).lexically_normal() : absolute;
    };
    return normal(a) == normal(b);
}

void requireDistinctOutputs(const std::vector<std::filesystem::path>& outputs,
                            const std::vector<std::filesystem::path>& inputs) {
    for (size_t i = 0; i < outputs.size(); ++i)
        refuseClash(outputs[i], std::vector<std::filesystem::path>(outputs.begin(), outputs.begin() + i), inputs);
}

void AtomicOutput::protect(std::vector<std::filesystem::path> inputs) {
    inputs_.insert(inputs_.end(), inputs.begin(), inputs.end());
}

AtomicOutput::~AtomicOutput() {
    if (!committed_) discard();
}

void AtomicOutput::add(const std::filesystem::path& path, std::string contents) {
    try {
        std::vector<std::filesystem::path> earlier;
        for (const auto& file : pending_) earlier.push_back(file.path);
        refuseClash(path, earlier, inputs_);
        pending_.push_back({path, writeTemporary(path, contents)});
    } catch (...) {
        discard();
        throw;
    }
}

void AtomicOutput::commit() {
    for (const auto& file : pending_) {
        std::error_code error;
        std::filesystem::rename(file.temporary, file.path, error);
        if (error) {
            discard();
            fail(file.path, error.message());
        }
    }
    committed_ = true;
}

void AtomicOutput::discard() {
    for (const auto& file : pending_) {
        std::error_code ignored;
        std::filesystem::remove(file.temporary, ignored);
    }
    pending_.clear();
}

void requireWritableFile(const std::filesystem::path& path, const std::string& option) {
    namespace fs = std::filesystem;
    const auto name = option + " " + path.string();
    if (path.empty()) throw FileError(option + " names no file");
    std::error_code error;
    const auto status = fs::status(path, error);
    if (fs::is_directory(status)) throw FileError(name + ": is a folder, not a file");
    if (fs::exists(status) && !fs::is_regular_file(status)) throw FileError(name + ": is not a regular file");
    const auto folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, error)) throw FileError(name + ": the folder " + folder.string() + " does not exist");
    if (::access(folder.c_str(), W_OK) != 0)
        throw FileError(name + ": the folder " + folder.string() + " is not writable (" + std::strerror(errno) + ")");
    // What the write will do: make a file beside it (a system folder such as /proc passes the
    // check above, and takes none).
    std::string probe = (folder / ".iblkit-tmp-XXXXXX").string();
    const int fd = mkstemp(probe.data());
    if (fd < 0)
        throw FileError(name + ": no new file can be made in the folder " + folder.string() + " (" + std::strerror(errno) + ")");
    ::close(fd);
    ::unlink(probe.c_str());
}

void requireNotAnInputIn(const std::filesystem::path& output, const std::filesystem::path& folder) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(output, error) || !std::filesystem::is_directory(folder, error)) return;
    std::vector<std::filesystem::path> inputs;
    for (auto it = std::filesystem::recursive_directory_iterator(folder, error);
         !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error))
        if (it->is_regular_file(error)) inputs.push_back(it->path());
    requireDistinctOutputs({output}, inputs);
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& contents) {
    AtomicOutput output;
    output.add(path, contents);
    output.commit();
}

} // namespace iblkit::files
