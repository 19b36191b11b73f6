#!/usr/bin/env bash
# The main job on its built-in default: every shader of hlsl/ compiled into every form
# (SPIR-V, GLSL 450, ESSL 310, MSL, HLSL, reflection JSON) in build/out/shaders.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
build/tools/iblkit/iblkit compile-all hlsl/shaders.json -o build/out/shaders
echo "iblkit: outputs in build/out/shaders" >&2
