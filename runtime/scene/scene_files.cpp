#include "scene_files.hpp"

#include "scene_error.hpp"

#include <tiny_gltf.h>

#include <fmt/core.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace iblkit::scene {
namespace {

class OpenFile {
public:
    explicit OpenFile(const std::filesystem::path& path) : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)) {}
    ~OpenFile() {
        if (fd_ >= 0) ::close(fd_);
    }
    OpenFile(const OpenFile&) = delete;
    OpenFile& operator=(const OpenFile&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

// Why a file cannot be read by the policy.
struct Refused {
    std::string why;
};

[[noreturn]] void refuse(const std::string& why) { throw Refused{why}; }

std::vector<unsigned char> readByThePolicy(const std::filesystem::path& path) {
    const OpenFile file(path);
    if (file.get() < 0) refuse(std::strerror(errno));
    struct stat status {};
    if (::fstat(file.get(), &status) != 0) refuse(std::strerror(errno));
    if (!S_ISREG(status.st_mode)) refuse("not a regular file (a folder, a device or a pipe)");
    if (uint64_t(status.st_size) > kMaxSceneFileBytes)
        refuse(fmt::format("{} bytes, past the {} a scene's file may hold", status.st_size, kMaxSceneFileBytes));
    std::vector<unsigned char> bytes(size_t(status.st_size));
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(file.get(), bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) refuse(std::strerror(errno));
        if (n == 0) break;
        done += size_t(n);
    }
    bytes.resize(done);
    return bytes;
}

bool fileExists(const std::string& path, void*) {
    std::error_code error;
    return std::filesystem::exists(path, error);
}

std::string pathAsIs(const std::string& path, void*) { return path; }

bool readWhole(std::vector<unsigned char>* out, std::string*, const std::string& path, void*) {
    try {
        *out = readByThePolicy(path);
    } catch (const Refused& refused) {
        throw ReferencedFileRefused(path + ": " + refused.why);
    }
    return true;
}

bool writeNothing(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    *error = "a scene is only read";
    return false;
}

} // namespace

std::vector<unsigned char> readSceneFile(const std::filesystem::path& path) {
    try {
        return readByThePolicy(path);
    } catch (const Refused& refused) {
        throw SceneError(fmt::format("{}: error: {}", path.string(), refused.why));
    }
}

void requireJsonNestingWithin(std::string_view json, const std::filesystem::path& path) {
    size_t depth = 0;
    bool inString = false, escaped = false;
    for (const char c : json) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonNesting)
                throw SceneError(fmt::format("{}: error: its JSON nests arrays and objects more than {} deep", path.string(),
                                             kMaxJsonNesting));
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

void readReferencedFilesByThePolicy(tinygltf::TinyGLTF& loader) {
    loader.SetFsCallbacks({fileExists, pathAsIs, readWhole, writeNothing, nullptr});
}

} // namespace iblkit::scene
