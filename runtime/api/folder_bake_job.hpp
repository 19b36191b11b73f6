#pragma once

#include <iblkit/bake.hpp>

#include "bake.hpp"

#include <filesystem>
#include <memory>
#include <optional>

namespace iblkit::api {

// One bake into a folder in its three steps, each with its errors as the library's: prepare
// (BadInput: the request and its input refused), compute (the device's work, on the session's
// device where one is given) and write (the files committed, all or nothing). bakeToFolder runs
// the three in turn; bakeBatch runs them overlapped across its bakes.
class FolderBakeJob {
public:
    FolderBakeJob(const BakeRequest& request, const std::filesystem::path& folder,
                  std::shared_ptr<vulkan::ValidationLog> log = std::make_shared<vulkan::ValidationLog>());
    ~FolderBakeJob();
    FolderBakeJob(FolderBakeJob&&) noexcept;

    void prepare(bake::BakeSession* session = nullptr);
    void compute();
    BakeSummary write();
    const bake::BakeSettings& settings() const { return settings_; }

private:
    bake::BakeSettings settings_;
    std::shared_ptr<vulkan::ValidationLog> log_;
    std::unique_ptr<bake::BakeProgress> progress_;
    std::optional<bake::PreparedBake> prepared_;
    std::optional<bake::ComputedMaps> maps_;
};

} // namespace iblkit::api
