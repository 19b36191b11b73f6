#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace iblkit::files {

class FileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Writes a set of files all or nothing: every file goes to a temporary beside its final path,
// and only when all were written are they renamed into place, each rename atomic. A failure
// while writing removes the temporaries and leaves every existing file as it was; a rename can
// fail only if a folder changes under the run, and then the files renamed before it stay new.
// Throws FileError.
class AtomicOutput {
public:
    AtomicOutput() = default;
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;
    ~AtomicOutput();

    // Files this command reads: an output that is one of them (through any path or link) is
    // refused when it is added, as is an output added twice, before anything is written.
    void protect(std::vector<std::filesystem::path> inputs);
    void add(const std::filesystem::path& path, std::string contents);
    void commit();

private:
    struct Pending {
        std::filesystem::path path;
        std::filesystem::path temporary;
    };
    void discard();

    std::vector<Pending> pending_;
    std::vector<std::filesystem::path> inputs_;
    bool committed_ = false;
};

// Whether two paths name one file: the same device and inode when both exist (links followed),
// else the same path once made absolute and normal.
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b);

// Throws FileError when an output is one of the inputs, or two outputs are one file.
void requireDistinctOutputs(const std::vector<std::filesystem::path>& outputs,
                            const std::vector<std::filesystem::path>& inputs);

// Throws FileError "<option> <path>: <why>" unless `path` can be written: not a folder or a device,
// its folder there and writable. For the commands that write a report after minutes of work, before it.
void requireWritableFile(const std::filesystem::path& path, const std::string& option);

// Throws FileError when `output` is an existing file of `folder` (recursively): the inputs a
// command reads from a folder (a corpus, the kernels' HLSL), which writing it would destroy.
void requireNotAnInputIn(const std::filesystem::path& output, const std::filesystem::path& folder);

// One file, all or nothing.
void writeFileAtomically(const std::filesystem::path& path, const std::string& contents);

} // namespace iblkit::files
