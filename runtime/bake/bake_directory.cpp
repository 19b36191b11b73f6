#include "bake_directory.hpp"

#include "left_behind.hpp"

#include "bake_error.hpp"
#include "file_names.hpp"
#include "sha256.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace iblkit::bake {
namespace {

namespace fs = std::filesystem;

using image_io::quoted;

// What an earlier folder's manifest.json says: the command that wrote it, and the files it wrote
// by name within the folder, with their SHA-256.
struct EarlierOutput {
    std::string command;
    std::map<std::string, std::string> files;
};

// Its "command"; a manifest from before that field: "render" for a render's, "bake" for any other.
std::string commandOf(const nlohmann::json& manifest) {
    if (manifest.contains("command") && manifest["command"].is_string()) return manifest["command"];
    return manifest.value("kind", "") == "render" ? "render" : "bake";
}

// Nothing when the folder holds no manifest.json that iblkit wrote with its list of files.
std::optional<EarlierOutput> earlierOutput(const fs::path& folder) {
    std::ifstream stream(folder / "manifest.json");
    if (!stream) return std::nullopt;
    const auto manifest = nlohmann::json::parse(stream, nullptr, false);
    if (!manifest.is_object() || manifest.value("generator", "") != "iblkit" || !manifest.contains("files") ||
        !manifest["files"].is_array())
        return std::nullopt;
    EarlierOutput earlier{commandOf(manifest), {}};
    for (const auto& file : manifest["files"])
        if (file.is_object() && file.value("name", "") != "") earlier.files[file.value("name", "")] = file.value("sha256", "");
    return earlier;
}

// The path with links resolved as far as it exists, absolute, with no trailing separator.
fs::path resolved(const fs::path& path) {
    std::error_code error;
    auto result = fs::weakly_canonical(fs::absolute(path, error), error);
    if (!result.has_filename() && result.has_parent_path()) result = result.parent_path();
    return result;
}

bool isInside(const fs::path& path, const fs::path& folder) {
    const auto inner = resolved(path), outer = resolved(folder);
    const auto [end, rest] = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
    return end == outer.end();
}

void requireWritable(const fs::path& folder, const fs::path& target) {
    if (::access(folder.c_str(), W_OK) != 0)
        throw BakeError("cannot replace " + quoted(target) + ": " + quoted(folder) + " is not writable (" +
                        std::strerror(errno) + ")");
}

// Every entry of the folder must be manifest.json, a file the earlier bake listed (still with
// its hash), or a folder of such files.
std::optional<CheckedFile> statusOf(const fs::path& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return std::nullopt;
    return CheckedFile{uint64_t(status.st_dev), uint64_t(status.st_ino), uint64_t(status.st_size),
                       int64_t(status.st_ctim.tv_sec) * 1000000000 + status.st_ctim.tv_nsec,
                       int64_t(status.st_mtim.tv_sec) * 1000000000 + status.st_mtim.tv_nsec};
}

// Whether `path` still holds the bytes whose SHA-256 is `sha256`: hashed, unless `checked` found
// it so with the same status (a write changes its change time, which no one can set back). A file
// changed within the last second is not recorded: a file system's clock may tick coarsely enough
// for a second write to keep the time of the first.
bool unchanged(const fs::path& path, const std::string& name, const std::string& sha256, CheckedFiles* checked) {
    const auto status = statusOf(path);
    if (checked && status) {
        const auto found = checked->find(name);
        if (found != checked->end() && found->second == *status) return true;
    }
    if (cache::sha256OfFile(path) != sha256) return false;
    timespec now{};
    clock_gettime(CLOCK_REALTIME, &now);
    if (checked && status && status->changed + 1000000000 < int64_t(now.tv_sec) * 1000000000 + now.tv_nsec)
        (*checked)[name] = *status;
    return true;
}

void requireOnlyBakeFiles(const fs::path& target, const std::map<std::string, std::string>& files, const std::string& command,
                          CheckedFiles* checked) {
    requireWritable(target, target);
    for (auto it = fs::recursive_directory_iterator(target); it != fs::recursive_directory_iterator(); ++it) {
        const auto name = fs::relative(it->path(), target).generic_string();
        if (it->is_symlink() || (!it->is_regular_file() && !it->is_directory()))
            throw BakeError("refusing to replace " + quoted(target) + ": it holds " + quoted(fs::path(name)) +
                            ", which is not a file the earlier " + command + " wrote");
        if (it->is_directory()) {
            requireWritable(it->path(), target);
            continue;
        }
        if (name == "manifest.json") continue;
        const auto listed = files.find(name);
        if (listed == files.end())
            throw BakeError("refusing to replace " + quoted(target) + ": it holds " + quoted(fs::path(name)) +
                            ", which no earlier " + command + " wrote (its manifest.json does not list it)");
        if (!unchanged(it->path(), name, listed->second, checked))
            throw BakeError("refusing to replace " + quoted(target) + ": " + quoted(fs::path(name)) +
                            " changed since the earlier " + command + " wrote it");
    }
}

fs::path nearestExisting(fs::path path) {
    std::error_code error;
    path = fs::absolute(path, error);
    while (!path.empty() && !fs::exists(path, error) && path.has_parent_path() && path.parent_path() != path)
        path = path.parent_path();
    return path;
}

// A link names its target: the bake replaces the folder the link points at, as the checks read it.
fs::path followed(fs::path target) {
    std::error_code error;
    target = fs::absolute(target, error).lexically_normal(); // "-o ." names the folder, beside which the bake stages
    if (target.filename().empty()) target = target.parent_path(); // "out/" names "out"
    if (!fs::is_symlink(target, error)) return target;
    const auto resolved = fs::canonical(target, error);
    if (error)
        throw BakeError(quoted(target) + " is a link to " + quoted(fs::read_symlink(target, error)) +
                        ", which does not exist");
    return resolved;
}

fs::path makeStagingFolder(const fs::path& target) {
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code error;
    fs::create_directories(parent, error);
    if (error) throw BakeError("cannot create " + quoted(parent) + ": " + error.message());
    // A short name of its own, not the target's plus a suffix: a target named near the file
    // system's 255-byte limit must still get one.
    // Its name holds this host and process: a later bake removes what a killed one left.
    files::removeLeftBehind(parent, ".iblkit-partial-");
    std::string pattern = (parent / (".iblkit-partial-" + files::writerTag() + "-XXXXXX")).string();
    if (!mkdtemp(pattern.data())) throw BakeError("cannot create a folder in " + quoted(parent) + ": " + std::strerror(errno));
    // mkdtemp makes it 0700; the bake's folder gets what the umask gives any new folder.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::chmod(pattern.c_str(), 0777 & ~mask);
    return pattern;
}

} // namespace

void checkBakeTarget(const fs::path& requested, const std::optional<fs::path>& input, std::string_view command,
                     CheckedFiles* checked) {
    const auto target = followed(requested);
    std::error_code error;
    if (input && (isInside(*input, target) || isInside(target, *input)))
        throw BakeError("the input " + quoted(*input) + " and the output folder " + quoted(target) +
                        " overlap: the " + std::string(command) + " would delete its own input");
    if (!fs::exists(target, error)) {
        const auto parent = nearestExisting(target.parent_path().empty() ? fs::path(".") : target.parent_path());
        if (::access(parent.c_str(), W_OK) != 0)
            throw BakeError("cannot write into " + quoted(target) + ": " + quoted(parent) + " is not writable");
        return;
    }
    if (!fs::is_directory(target, error)) throw BakeError(quoted(target) + " exists and is not a folder");
    requireWritable(target.parent_path().empty() ? fs::path(".") : target.parent_path(), target);
    if (fs::is_empty(target, error)) return requireWritable(target, target);
    const auto earlier = earlierOutput(target);
    if (!earlier)
        throw BakeError(quoted(target) + " is a folder with other files (no manifest.json written by iblkit); "
                        "refusing to replace it");
    if (earlier->command != command)
        throw BakeError(quoted(target) + " holds the output of iblkit " + earlier->command + " (its manifest.json says so), " +
                        "not of iblkit " + std::string(command) + "; refusing to replace it");
    requireOnlyBakeFiles(target, earlier->files, std::string(command), checked);
}

BakeDirectory::BakeDirectory(fs::path target, const std::optional<fs::path>& input, std::string_view command)
    : target_(followed(std::move(target))), input_(input), command_(command) {
    checkBakeTarget(target_, input_, command_, &checked_);
    staging_ = makeStagingFolder(target_);
    cleanup_ = std::make_unique<files::RemovedOnSignal>(staging_);
}

BakeDirectory::~BakeDirectory() {
    std::error_code ignored;
    if (!committed_) fs::remove_all(staging_, ignored);
}

void BakeDirectory::clearStaging() {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(staging_, error)) fs::remove_all(entry.path(), error);
    if (error) throw BakeError("cannot empty the staging folder " + quoted(staging_) + ": " + error.message());
}

void BakeDirectory::commit() {
    checkBakeTarget(target_, input_, command_, &checked_);
    std::error_code error;
    if (!fs::exists(target_, error)) {
        fs::rename(staging_, target_, error);
        if (error) throw BakeError("cannot move the " + command_ + " into " + quoted(target_) + ": " + error.message());
        committed_ = true;
        cleanup_.reset();
        return;
    }
    if (renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
        // No atomic exchange here: move the earlier bake aside first, then the new one in.
        const fs::path aside = staging_.string() + ".old";
        fs::rename(target_, aside, error);
        if (error) throw BakeError("cannot move the earlier " + command_ + " out of " + quoted(target_) + ": " + error.message());
        fs::rename(staging_, target_, error);
        if (error) {
            std::error_code ignored;
            fs::rename(aside, target_, ignored);
            throw BakeError("cannot move the " + command_ + " into " + quoted(target_) + ": " + error.message());
        }
        staging_ = aside;
    }
    committed_ = true;
    cleanup_.reset();
    fs::remove_all(staging_, error); // the earlier bake, now in the staging folder's place
}

void requireCacheOutsideTarget(const fs::path& cache, const fs::path& target) {
    if (isInside(cache, target))
        throw BakeError("--cache " + quoted(cache) + " is inside the output folder " + quoted(target) +
                        ", which the bake replaces as a whole: give a cache folder outside it");
}

} // namespace iblkit::bake
