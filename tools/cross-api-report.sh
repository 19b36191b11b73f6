#!/usr/bin/env bash
# Every run file of docs/examples/ and hlsl/porting/ on Vulkan and on OpenGL (iblkit run --api all):
# one line per value compared between the APIs, its largest difference and where, or why OpenGL
# did not run it. Exits non-zero when any run file fails.
#   tools/cross-api-report.sh [IBLKIT]
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
iblkit=${1:-build/tools/iblkit/iblkit}
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
status=0
for run in docs/examples/*.run.json hlsl/porting/*.run.json; do
    output=$("$iblkit" run "$run" --api all 2>&1) || status=1
    grep -E "cross-API|not run|: error:" <<<"$output" | sed "s|^|$run: |"
done
exit $status
