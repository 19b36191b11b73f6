#pragma once

// iblkit's library: compile HLSL to every form, run a run file, bake an environment's maps.
// See docs/api.md.
#include <iblkit/bake.hpp>
#include <iblkit/batch.hpp>
#include <iblkit/compile.hpp>
#include <iblkit/error.hpp>
#include <iblkit/run.hpp>
#include <iblkit/version.hpp>
