#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace iblkit::files {

// The files and folders a writer makes beside what it writes (a cache entry's temporary, a bake's
// staging folder) carry its host and process in their names, PREFIX + "HOST-PID-" + a unique
// suffix, so that what a killed writer left can be told from what a live one is still filling.
std::string writerTag(); // "HOST-PID" of this process

// Whether the entry, named PREFIX + "HOST-PID-XXXXXX" (PREFIX anywhere in the name), was left by a
// writer that is gone: one of this host whose process no longer exists. Another host's processes
// cannot be asked: what they made (and what carries no tag) counts as left once a day old.
bool leftByAGoneWriter(const std::filesystem::directory_entry& entry, std::string_view prefix);

// Removes, whole, every entry of `folder` whose name holds `prefix` and that a gone writer left.
// What cannot be removed is left as it is.
void removeLeftBehind(const std::filesystem::path& folder, std::string_view prefix);

} // namespace iblkit::files
