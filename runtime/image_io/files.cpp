#include "files.hpp"

#include "dds.hpp"
#include "file_names.hpp"
#include "image_error.hpp"
#include "ktx2.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace iblkit::image_io {
namespace {

class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

[[noreturn]] void fail(const char* verb, const std::filesystem::path& path, int error) {
    throw ImageError(std::string(verb) + " " + quoted(path) + ": " + std::strerror(error));
}

} // namespace

std::vector<std::byte> readFileBytes(const std::filesystem::path& path) {
    // O_NONBLOCK: opening a FIFO would wait for a writer. A device (/dev/zero) has no end.
    const FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
    if (file.get() < 0) fail("cannot open", path, errno);
    struct stat status {};
    if (::fstat(file.get(), &status) != 0) fail("cannot open", path, errno);
    if (S_ISDIR(status.st_mode)) fail("cannot open", path, EISDIR);
    if (!S_ISREG(status.st_mode))
        throw ImageError("cannot open " + quoted(path) + ": not a regular file (a device, a pipe or a socket)");
    std::vector<std::byte> bytes(size_t(status.st_size));
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(file.get(), bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail("cannot read", path, errno);
        if (n == 0) break; // the file shrank while being read
        done += size_t(n);
    }
    bytes.resize(done);
    return bytes;
}

Texture readTextureFile(const std::filesystem::path& path) {
    const auto extension = lowerExtension(path);
    if (extension == ".ktx2") return decodeKtx2(readFileBytes(path), path.string());
    if (extension == ".dds") return decodeDds(readFileBytes(path), path.string());
    throw ImageError("unsupported texture format " + describedExtension(path) + " for " + quoted(path) +
                     " (supported: .ktx2, .dds)");
}

} // namespace iblkit::image_io
