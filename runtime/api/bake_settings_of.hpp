#pragma once

#include <iblkit/bake.hpp>

#include "bake_settings.hpp"

namespace iblkit::api {

// The request as the bake's typed settings, converted once here; the output folder and the
// validation log are the caller's to add. `iblkit plan` takes its settings from here too, so that
// a plan is of the bake it describes.
bake::BakeSettings bakeSettingsOf(const BakeRequest& request);

} // namespace iblkit::api
