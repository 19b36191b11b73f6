#!/usr/bin/env bash
# Clones each code base of docs/porting-real-code/*.json, and each one a manifest "requires", into
# CODE_BASES/NAME at the commit the manifest gives (git and the network needed; nothing of them
# enters this repository). Then tools/porting-real-code.sh CODE_BASES regenerates the page.
#   tools/fetch-real-code.sh CODE_BASES
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: tools/fetch-real-code.sh CODE_BASES" >&2; exit 2; }
target=$1
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mkdir -p "$target"
# name repository commit, one a line, for every code base and requirement.
python3 - docs/porting-real-code/*.json <<'PY' | sort -u | while read -r name repository commit; do
import json, sys
for path in sys.argv[1:]:
    manifest = json.load(open(path))
    for entry in [manifest] + manifest.get("requires", []):
        print(entry["name"], entry["repository"], entry["commit"])
PY
  folder="$target/$name"
  if [ "$(git -C "$folder" rev-parse HEAD 2>/dev/null)" = "$commit" ]; then continue; fi
  rm -rf "$folder"
  git init -q "$folder"
  git -C "$folder" fetch -q --depth 1 "$repository" "$commit"
  git -C "$folder" checkout -q FETCH_HEAD
  echo "$name at $commit"
done
