#pragma once

#include "environment_input.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit::render {

// Synthetic environments of a small, bright sun over the built-in sky's sky and ground (its own
// 2.5-degree sun left out): a disk kSunRadius wide of radiance kSunRadiance, which carries about
// three quarters of the light, in front of the spheres (behind the camera), beside them, or
// behind them, where the split sum reads R at the rim and finds a sun the true lobe barely sees.
inline constexpr double kSunRadiusDegrees = 0.3;
inline constexpr double kSunRadiance = 1e5;
inline const std::vector<std::string> kSunEnvironments = {"sun-front", "sun-side", "sun-behind"};

// The cube (kDefaultSize faces, each texel the mean of 8 x 8 points where the disk's edge
// crosses it) of a name of kSunEnvironments; none for another name.
std::optional<bake::EnvironmentInput> sunEnvironment(std::string_view name);

} // namespace iblkit::render
