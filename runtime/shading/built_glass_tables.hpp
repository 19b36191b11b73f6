#pragma once

#include <span>

namespace iblkit::shading {

// shading::transmissionTable and shading::sphereTransmissionTable at kTransmissionTableSize,
// computed once by glass_tables_main.cpp and committed (built_glass_tables.cpp): about 12 s of CPU
// that every render with glass would otherwise spend again.
std::span<const float> builtTransmissionTable();
std::span<const float> builtSphereTransmissionTable();

} // namespace iblkit::shading
