#include "bake_directory.hpp"

#include "bake_error.hpp"
#include "file_names.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <string>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;

using image_io::quoted;

bool isEarlierBake(const fs::path& folder) {
    std::ifstream stream(folder / "manifest.json");
    if (!stream) return false;
    const auto manifest = nlohmann::json::parse(stream, nullptr, false);
    return manifest.is_object() && manifest.value("generator", "") == "iblkit";
}

fs::path makeStagingFolder(const fs::path& target) {
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code error;
    fs::create_directories(parent, error);
    if (error) throw BakeError("cannot create " + quoted(parent) + ": " + error.message());
    std::string pattern = (parent / ("." + target.filename().string() + ".iblkit-partial-XXXXXX")).string();
    if (!mkdtemp(pattern.data())) throw BakeError("cannot create a folder in " + quoted(parent) + ": " + std::strerror(errno));
    return pattern;
}

} // namespace

void checkBakeTarget(const fs::path& target) {
    std::error_code error;
    if (!fs::exists(target, error)) return;
    if (!fs::is_directory(target, error)) throw BakeError(quoted(target) + " exists and is not a folder");
    if (fs::is_empty(target, error) || isEarlierBake(target)) return;
    throw BakeError(quoted(target) + " is a folder with other files (no manifest.json written by iblkit); "
                    "refusing to replace it");
}

BakeDirectory::BakeDirectory(fs::path target) : target_(std::move(target)) {
    if (target_.filename().empty()) target_ = target_.parent_path(); // "out/" names "out"
    checkBakeTarget(target_);
    staging_ = makeStagingFolder(target_);
}

BakeDirectory::~BakeDirectory() {
    std::error_code ignored;
    if (!committed_) fs::remove_all(staging_, ignored);
}

void BakeDirectory::commit() {
    checkBakeTarget(target_);
    std::error_code error;
    if (!fs::exists(target_, error)) {
        fs::rename(staging_, target_, error);
        if (error) throw BakeError("cannot move the bake into " + quoted(target_) + ": " + error.message());
        committed_ = true;
        return;
    }
    if (renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
        // No atomic exchange here: move the earlier bake aside first, then the new one in.
        const fs::path aside = staging_.string() + ".old";
        fs::rename(target_, aside, error);
        if (error) throw BakeError("cannot move the earlier bake out of " + quoted(target_) + ": " + error.message());
        fs::rename(staging_, target_, error);
        if (error) {
            std::error_code ignored;
            fs::rename(aside, target_, ignored);
            throw BakeError("cannot move the bake into " + quoted(target_) + ": " + error.message());
        }
        staging_ = aside;
    }
    committed_ = true;
    fs::remove_all(staging_, error); // the earlier bake, now in the staging folder's place
}

} // namespace iblkit::bake
