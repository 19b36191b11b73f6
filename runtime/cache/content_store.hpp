#pragma once

#include "mapped_file.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace iblkit::cache {

// Entries by key (CacheKey::hex()) under FOLDER/objects/ab/abcd...: each holds its key and its
// payload's SHA-256 beside the payload, so an entry damaged on disk, or copied or renamed to
// another key's place, is found when it is read, removed, and counted a miss. An entry is written
// to a temporary file beside its place (KEY.tmp-HOST-PID-XXXXXX, unique by mkstemp) and renamed
// into place, so bakes that share the folder, on one machine or many, never read half an entry;
// two that make the same entry write the same bytes, and the last rename wins. A put removes the
// temporaries of its folder that killed writers left: this host's whose process is gone, and any
// older than a day.
class ContentStore {
public:
    // A read-only store leaves damaged entries where they are, and refuses put.
    enum class Access { ReadWrite, ReadOnly };
    explicit ContentStore(std::filesystem::path folder, Access access = Access::ReadWrite);

    std::optional<std::string> get(const std::string& key);
    // An entry's payload read in place, for payloads of megabytes that are parsed, not kept.
    class Payload {
    public:
        Payload(MappedFile file, size_t offset) : file_(std::move(file)), offset_(offset) {}
        std::string_view payload() const { return file_.bytes().substr(offset_); }

    private:
        MappedFile file_;
        size_t offset_;
    };
    std::optional<Payload> getInPlace(const std::string& key);
    // get, not counted: for the small entries that only save a bake time (bake/remembered_facts.hpp).
    std::optional<std::string> peek(const std::string& key);
    void put(const std::string& key, std::string_view payload); // throws CacheError when it cannot write
    void put(const std::string& key, std::span<const std::string_view> payload); // the payload in parts, written in order

    struct Counts {
        size_t hits = 0, misses = 0, corrupt = 0;
    };
    const Counts& counts() const { return counts_; }
    void restoreCounts(const Counts& earlier) { counts_ = earlier; } // after reading entries a bake then set aside
    const std::filesystem::path& folder() const { return folder_; }

    // $XDG_CACHE_HOME/iblkit, else ~/.cache/iblkit, else build/cache.
    static std::filesystem::path defaultFolder();

private:
    std::filesystem::path pathOf(const std::string& key) const;
    std::optional<Payload> read(const std::string& key, Counts& counts);

    std::filesystem::path folder_;
    Access access_;
    Counts counts_;
};

} // namespace iblkit::cache
