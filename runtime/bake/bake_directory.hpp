#pragma once

#include "signal_cleanup.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace iblkit::bake {

// Where a bake writes: a fresh folder beside the target, swapped into place only when every
// file is written, so a failed or killed bake never touches what the target holds. The target
// (a link to a folder is followed) must be absent, an empty folder, or an earlier output of the
// same command (`command`, as the manifest's "command" says): a folder holding only manifest.json
// and the files its "files" list names, each still with its SHA-256. Anything else is refused before any work, as is a target that holds the input, or
// one the bake could not replace (read-only). The staging folder follows the umask, and is
// removed when the bake fails or SIGINT, SIGTERM or SIGHUP stop it (files::cleanUpOnSignals).
// Throws BakeError.
// An earlier bake's file as its check found it whole: its status (device, inode, size, change
// and modification times), so that the check before the commit hashes again only what changed.
struct CheckedFile {
    uint64_t device = 0, inode = 0, size = 0;
    int64_t changed = 0, modified = 0; // ns
    bool operator==(const CheckedFile&) const = default;
};
using CheckedFiles = std::map<std::string, CheckedFile>;

class BakeDirectory {
public:
    BakeDirectory(std::filesystem::path target, const std::optional<std::filesystem::path>& input,
                  std::string_view command = "bake");
    BakeDirectory(const BakeDirectory&) = delete;
    BakeDirectory& operator=(const BakeDirectory&) = delete;
    ~BakeDirectory(); // removes the staging folder unless committed

    const std::filesystem::path& staging() const { return staging_; }
    void clearStaging(); // every file written into the staging folder removed, for a bake begun again
    // Exchanges the staging folder with the target atomically (renameat2 RENAME_EXCHANGE;
    // two renames on file systems without it), then removes the earlier bake.
    void commit();

private:
    std::filesystem::path target_;
    std::optional<std::filesystem::path> input_;
    std::string command_;
    std::filesystem::path staging_;
    std::unique_ptr<files::RemovedOnSignal> cleanup_;
    bool committed_ = false;
    CheckedFiles checked_; // by the first check
};

// Throws BakeError unless `target` may receive a bake that reads `input` (see BakeDirectory).
// With `checked`, the earlier bake's files whose status is as `checked` holds are taken as whole
// without hashing them again, and each file found whole is recorded there.
void checkBakeTarget(const std::filesystem::path& target, const std::optional<std::filesystem::path>& input,
                     std::string_view command = "bake", CheckedFiles* checked = nullptr);

// Throws BakeError when the cache folder is the target or inside it: the command replaces the
// target as a whole, so the cache would be deleted by it or, created there during the work, make
// the target a folder that no later run may replace.
void requireCacheOutsideTarget(const std::filesystem::path& cache, const std::filesystem::path& target);

} // namespace iblkit::bake
