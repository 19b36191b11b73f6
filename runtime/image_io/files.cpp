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

#include <utility>

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
    FileDescriptor(FileDescriptor&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    int get() const { return fd_; }

private:
    int fd_;
};

[[noreturn]] void fail(const char* verb, const std::filesystem::path& path, int error) {
    throw ImageError(std::string(verb) + " " + quoted(path) + ": " + std::strerror(error));
}

// A regular file opened for reading, and its size. O_NONBLOCK: opening a FIFO would wait for a
// writer. A device (/dev/zero) has no end.
FileDescriptor openRegularFile(const std::filesystem::path& path, size_t& size) {
    FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
    if (file.get() < 0) fail("cannot open", path, errno);
    struct stat status {};
    if (::fstat(file.get(), &status) != 0) fail("cannot open", path, errno);
    if (S_ISDIR(status.st_mode)) fail("cannot open", path, EISDIR);
    if (!S_ISREG(status.st_mode))
        throw ImageError("cannot open " + quoted(path) + ": not a regular file (a device, a pipe or a socket)");
    size = size_t(status.st_size);
    return file;
}

// Reads into `buffer` until it is full or the file ends; the bytes read.
size_t readInto(const FileDescriptor& file, const std::filesystem::path& path, std::span<std::byte> buffer) {
    size_t done = 0;
    while (done < buffer.size()) {
        const ssize_t n = ::read(file.get(), buffer.data() + done, buffer.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail("cannot read", path, errno);
        if (n == 0) break; // the end, or the file shrank while being read
        done += size_t(n);
    }
    return done;
}

} // namespace

std::vector<std::byte> readFileBytes(const std::filesystem::path& path, uint64_t maxBytes) {
    size_t size = 0;
    const FileDescriptor file = openRegularFile(path, size);
    if (size > maxBytes)
        throw ImageError("cannot open " + quoted(path) + ": " + std::to_string(size) + " bytes, past the limit of " +
                         std::to_string(maxBytes));
    std::vector<std::byte> bytes(size);
    bytes.resize(readInto(file, path, bytes));
    return bytes;
}

void readFileInChunks(const std::filesystem::path& path, const std::function<void(std::span<const std::byte>)>& chunk) {
    size_t size = 0;
    const FileDescriptor file = openRegularFile(path, size);
    std::vector<std::byte> buffer(size_t(1) << 20);
    for (size_t got; (got = readInto(file, path, buffer)) > 0;) chunk(std::span(buffer).first(got));
}

namespace {

// Checked before the file is opened, so that an unsupported name is named as such.
void requireTextureName(const std::filesystem::path& path) {
    const auto extension = lowerExtension(path);
    if (extension != ".ktx2" && extension != ".dds")
        throw ImageError("unsupported texture format " + describedExtension(path) + " for " + quoted(path) +
                         " (supported: .ktx2, .dds)");
}

} // namespace

Texture readTextureFile(const std::filesystem::path& path) {
    requireTextureName(path);
    return decodeTextureFile(readFileBytes(path), path);
}

Texture decodeTextureFile(std::span<const std::byte> bytes, const std::filesystem::path& path) {
    requireTextureName(path);
    return lowerExtension(path) == ".ktx2" ? decodeKtx2(bytes, path.string()) : decodeDds(bytes, path.string());
}

} // namespace iblkit::image_io
