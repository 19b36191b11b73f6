#!/usr/bin/env bash
# docs/porting-real-code.md from the code bases of docs/porting-real-code/*.json, once they are on
# disk: CODE_BASES holds each in a folder of its name, at the commit its manifest gives (and each
# code base a manifest "requires", beside it); tools/fetch-real-code.sh puts them there.
#   tools/porting-real-code.sh CODE_BASES [--json FILE]
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: tools/porting-real-code.sh CODE_BASES [--json FILE]" >&2; exit 2; }
sources=$1
shift
cd "$(dirname "${BASH_SOURCE[0]}")/.."
manifests=()
for manifest in docs/porting-real-code/*.json; do manifests+=(--manifest "$manifest"); done
build/tools/iblkit/iblkit porting "${manifests[@]}" --sources "$sources" --out docs/porting-real-code.md "$@"
