#pragma once

#include <iblkit/bake.hpp>

#include "bake.hpp"

namespace iblkit::api {

// The bake's maps in the library's plain types.
BakedMaps bakedMapsOf(bake::ComputedMaps maps, const bake::BakePlan& plan);

// Nine RGB SH coefficients as plain arrays.
std::array<std::array<double, 3>, 9> shCoefficientsOf(const std::array<glm::dvec3, 9>& coefficients);

} // namespace iblkit::api
