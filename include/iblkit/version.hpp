#pragma once

#include <string>

namespace iblkit {

// The library's version, "MAJOR.MINOR.PATCH": what `iblkit --version` prints and a bake's manifest
// records as its tool. The cache keys of a bake include it.
std::string version();

} // namespace iblkit
