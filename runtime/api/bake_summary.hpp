#pragma once

#include <iblkit/bake.hpp>

#include "bake.hpp"

namespace iblkit::api {

// The folder bake's summary in the library's plain types, with its JSON.
BakeSummary bakeSummaryOf(const bake::BakeSummary& summary);

} // namespace iblkit::api
