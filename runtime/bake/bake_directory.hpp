#pragma once

#include <filesystem>

namespace iblkit::bake {

// Where a bake writes: a fresh folder beside the target, swapped into place only when every
// file is written, so a failed or killed bake never touches what the target holds. The target
// must be absent, an empty folder or an earlier bake (a manifest.json that iblkit wrote); any
// other folder is refused rather than replaced. Throws BakeError.
class BakeDirectory {
public:
    explicit BakeDirectory(std::filesystem::path target);
    BakeDirectory(const BakeDirectory&) = delete;
    BakeDirectory& operator=(const BakeDirectory&) = delete;
    ~BakeDirectory(); // removes the staging folder unless committed

    const std::filesystem::path& staging() const { return staging_; }
    // Exchanges the staging folder with the target atomically (renameat2 RENAME_EXCHANGE;
    // two renames on file systems without it), then removes the earlier bake.
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path staging_;
    bool committed_ = false;
};

// Throws BakeError unless `target` may receive a bake (see BakeDirectory).
void checkBakeTarget(const std::filesystem::path& target);

} // namespace iblkit::bake
