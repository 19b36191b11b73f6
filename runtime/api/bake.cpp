#include <iblkit/bake.hpp>
#include <iblkit/version.hpp>

#include "api/bake_settings_of.hpp"
#include "api/bake_summary.hpp"
#include "api/baked_maps.hpp"
#include "api/error_translation.hpp"
#include "api/folder_bake_job.hpp"

#include "bake.hpp"

#include <memory>

namespace iblkit {
namespace {

// The settings with a log that outlives the bake's Vulkan context, which reports into it while
// it is destroyed (leaked objects).
struct LoggedSettings {
    bake::BakeSettings settings;
    std::shared_ptr<vulkan::ValidationLog> log = std::make_shared<vulkan::ValidationLog>();
};

LoggedSettings loggedSettingsOf(const BakeRequest& request) {
    LoggedSettings logged{api::bakeSettingsOf(request)};
    logged.settings.context.validationLog = logged.log;
    return logged;
}

} // namespace

std::filesystem::path defaultCacheFolder() { return cache::ContentStore::defaultFolder(); }

BakedMaps bakeToMemory(const BakeRequest& request) {
    const auto logged = loggedSettingsOf(request);
    const auto& settings = logged.settings;
    bake::BakeProgress progress(request.quiet);
    auto prepared = api::translated(ErrorKind::BadInput, [&] {
        return bake::prepareBake(settings, bake::BakeDestination::Memory, progress);
    });
    auto maps = api::translated(ErrorKind::BakeFailed, [&] {
        return api::bakedMapsOf(bake::computeMaps(prepared, version(), progress), prepared.plan);
    });
    maps.validationMessages = logged.log->messages();
    return maps;
}

BakeSummary bakeToFolder(const BakeRequest& request, const std::filesystem::path& folder) {
    api::FolderBakeJob job(request, folder); // a batch of one, without a session: nothing outlives the bake
    job.prepare();
    job.compute();
    auto summary = job.write();
    summary.validationMessages = job.settings().context.validationLog->messages();
    return summary;
}

} // namespace iblkit
