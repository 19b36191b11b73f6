#!/usr/bin/env bash
# iblkit batch on a real Slurm: a private single-node cluster (slurm_cluster.sh) runs the script
# `iblkit batch --slurm-script` prints as a job array over a shared folder and cache. Checked on
# the outputs, never on sbatch's status: every folder is byte for byte a local `iblkit bake` of its
# line, a second submission bakes nothing, and a line made to fail is in the merged status.
# Usage: slurm_batch_test.sh IBLKIT
set -euo pipefail
iblkit=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
fail() { echo "slurm batch test: $*" >&2; exit 1; }

for tool in slurmctld slurmd munged sbatch squeue scontrol; do
    command -v "$tool" >/dev/null ||
        fail "$tool is missing: Slurm is not installed (apt-get install slurmctld slurmd slurm-client munge), so this test cannot run"
done
[[ $(id -u) == 0 ]] || fail "slurmd must run as root to start jobs; run the test as root"

work=$(mktemp -d /tmp/iblkit-slurm.XXXXXX)
# shellcheck source=slurm_cluster.sh
source "$here/slurm_cluster.sh"
trap 'slurm_cluster_stop "$work/cluster"; rm -rf "$work"' EXIT
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
slurm_cluster_start "$work/cluster" || fail "the cluster did not start"

# A small HDR panorama (flat texels: stb reads rows narrower than 8 as such), and one that is not an image.
{ printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n'; for _ in $(seq 32); do printf '\x80\x60\x40\x81'; done; } >"$work/warm.hdr"
printf 'not an image' >"$work/broken.hdr"
small="--size 16 --samples 16 --lut-size 8 --lut-samples 16 --irradiance-size 4"
cat >"$work/list.txt" <<LIST
# name  environment  flags of iblkit bake
sky     $small
three   $small --profile threejs
warm    $work/warm.hdr $small --dds
pyramid --size 16 --lut-size 8 --lut-samples 16 --irradiance-size 4 --method pyramid --samples 2
broken  $work/broken.hdr $small
LIST

submit() { # the printed script, submitted; prints the job id once it has ended
    "$iblkit" batch "$work/list.txt" -o "$work/out" --cache "$work/cache" --shards 3 --cpus-per-task 1 --slurm-script \
        >"$work/job.sh"
    local job
    job=$(cd "$work" && sbatch --parsable "$work/job.sh") || fail "sbatch refused the script"
    slurm_cluster_wait "${job%%;*}" 300 >/dev/null 2>&1 || true # a task fails (the broken line): the outputs tell
}

submit
grep -q '^#SBATCH --array=0-2$' "$work/job.sh" || fail "the script is not an array of three tasks"
[[ $(ls "$work/out/batch-shards"/*.json | wc -l) == 3 ]] || fail "not every task wrote its record: $(ls "$work/out/batch-shards")"

# Every folder is what a local bake of its line writes.
while read -r name rest; do
    [[ -z $name || $name == \#* || $name == broken ]] && continue
    # shellcheck disable=SC2086 # the line's words, as the batch splits them
    "$iblkit" bake $rest -o "$work/local/$name" --no-cache --quiet
    diff -r "$work/local/$name" "$work/out/$name" >/dev/null || fail "$name differs from a local iblkit bake of its line"
done <"$work/list.txt"

# The merged status names the failed line, and exits 1 for it.
if "$iblkit" batch --merge "$work/out" --quiet 2>"$work/merge.err"; then fail "the merge exited 0 with a failed line"; fi
python3 - "$work/out/batch.json" <<'PY' || fail "the merged status is wrong: $(cat "$work/out/batch.json")"
import json, sys
record = json.load(open(sys.argv[1]))
status = {bake["name"]: bake["status"] for bake in record["bakes"]}
assert status == {"sky": "baked", "three": "baked", "warm": "baked", "pyramid": "baked", "broken": "failed"}, status
assert "not a Radiance HDR image" in next(b["error"] for b in record["bakes"] if b["name"] == "broken")
PY

# A second submission bakes nothing: every good line is done, its folder untouched.
stat -c '%n %i %Y' "$work"/out/{sky,three,warm,pyramid}/* >"$work/before.txt"
submit
"$iblkit" batch --merge "$work/out" --quiet 2>/dev/null || true
python3 - "$work/out/batch.json" <<'PY' || fail "the second submission baked again: $(cat "$work/out/batch.json")"
import json, sys
record = json.load(open(sys.argv[1]))
status = {bake["name"]: bake["status"] for bake in record["bakes"]}
assert status == {"sky": "done", "three": "done", "warm": "done", "pyramid": "done", "broken": "failed"}, status
PY
stat -c '%n %i %Y' "$work"/out/{sky,three,warm,pyramid}/* | diff - "$work/before.txt" >/dev/null ||
    fail "a done folder was written again"
echo "slurm batch test: passed"
