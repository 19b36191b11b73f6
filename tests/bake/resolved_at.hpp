#pragma once

#include "bake_settings.hpp"

namespace iblkit::bake {

// `settings` resolved as a bake resolves them, at a face size of `size`.
inline ResolvedSettings resolvedAt(BakeSettings settings, uint32_t size = kDefaultSize) {
    settings.size = size;
    return resolveSettings(settings);
}

} // namespace iblkit::bake
