#pragma once

#include "shading/lobe_table.hpp"

#include <span>

namespace iblkit::shading {

// shading::lobeTable(kLobeTableSize, weighting), computed once by lobe_tables_main.cpp and
// committed (built_lobe_tables.cpp): 1024 lobe fits per weighting, about 0.1 s of a core, that
// every bake would otherwise spend again beside the device.
std::span<const float> builtLobeTable(LobeWeighting weighting);

} // namespace iblkit::shading
