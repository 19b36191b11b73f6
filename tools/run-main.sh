#!/usr/bin/env bash
# The main job on its built-in default: bake the built-in environment (a sky with a bright sun
# and a checkered ground) into build/out/bake: specular.ktx2, brdf_lut.ktx2, irradiance.ktx2,
# manifest.json and preview.png.
set -euo pipefail
# Builds the iblkit program alone: the tests are built by tools/run-tests.sh.
IBLKIT_BUILD_PRESET=main
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
build/tools/iblkit/iblkit bake -o build/out/bake "$@"
