#include "api/folder_bake_job.hpp"

#include <iblkit/version.hpp>

#include "api/bake_settings_of.hpp"
#include "api/bake_summary.hpp"
#include "api/error_translation.hpp"

namespace iblkit::api {

FolderBakeJob::FolderBakeJob(const BakeRequest& request, const std::filesystem::path& folder,
                             std::shared_ptr<vulkan::ValidationLog> log)
    : settings_(bakeSettingsOf(request)), log_(std::move(log)), progress_(std::make_unique<bake::BakeProgress>(request.quiet)) {
    // The log outlives the bake's Vulkan context, which reports into it while it is destroyed (leaked objects).
    settings_.context.validationLog = log_;
    settings_.outputDir = folder;
}

FolderBakeJob::~FolderBakeJob() = default;
FolderBakeJob::FolderBakeJob(FolderBakeJob&&) noexcept = default;

void FolderBakeJob::prepare(bake::BakeSession* session) {
    prepared_ = translated(ErrorKind::BadInput, [&] {
        return bake::prepareBake(settings_, bake::BakeDestination::Folder, *progress_, session);
    });
}

void FolderBakeJob::compute() {
    maps_ = translated(ErrorKind::BakeFailed, [&] { return bake::computeMaps(*prepared_, version(), *progress_); });
}

BakeSummary FolderBakeJob::write() {
    auto summary = translated(ErrorKind::BakeFailed, [&] {
        return bakeSummaryOf(bake::writeBake(*prepared_, std::move(*maps_), version(), *progress_));
    });
    maps_.reset();
    prepared_.reset(); // the input's memory goes with it
    return summary;
}

} // namespace iblkit::api
