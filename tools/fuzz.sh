#!/usr/bin/env bash
# Fuzzes every target of tests/fuzz (or the ones named) for a bounded time with iblkit_fuzz, the
# libFuzzer program of the fuzz preset (clang-14, ASan, UBSan), and prints what each run did.
#
#   tools/fuzz.sh [--seconds N] [--jobs N] [TARGET...]
#
# N seconds per target (600 by default), N targets at a time (2). Each target works in
# build-fuzz/fuzz/TARGET/: corpus/ (what the fuzzer added to the seeds of tests/fuzz/corpus/TARGET),
# findings/ (this run's crash, timeout and out-of-memory inputs) and log.txt. Exits 1 if any target found
# something: reproduce it with `build-fuzz/tests/fuzz/iblkit_fuzz --target=TARGET FILE`, fix it,
# and add FILE to tests/fuzz/corpus/TARGET/ so that the test suite replays it from then on.
set -euo pipefail

seconds=600
jobs=2
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=${2:?--seconds needs a number}; shift 2 ;;
    --jobs) jobs=${2:?--jobs needs a number}; shift 2 ;;
    -*) echo "fuzz.sh: unknown option '$1' (usage: tools/fuzz.sh [--seconds N] [--jobs N] [TARGET...])" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz.sh: --seconds '$seconds' is not a positive whole number" >&2; exit 2; }
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz.sh: --jobs '$jobs' is not a positive whole number" >&2; exit 2; }

IBLKIT_PRESET=fuzz
IBLKIT_EXTRA_PACKAGES=(clang-14 libclang-rt-14-dev libfuzzer-14-dev)
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"

readonly program=build-fuzz/tests/fuzz/iblkit_fuzz
if [ ${#targets[@]} -eq 0 ]; then
  mapfile -t targets < <(ls tests/fuzz/corpus)
fi
for target in "${targets[@]}"; do
  [ -d "tests/fuzz/corpus/$target" ] || { echo "fuzz.sh: unknown target '$target' (one of: $(ls tests/fuzz/corpus | xargs))" >&2; exit 2; }
done

# A hang is a finding once an input runs 30 s (the compile entry stops glslang after 5 s of CPU);
# 4 GiB leaves room for ASan's shadow beside a large image.
fuzz_one() {
  local target=$1 work=build-fuzz/fuzz/$1
  rm -rf "$work/findings"
  mkdir -p "$work/corpus" "$work/findings"
  local dictionary=()
  [ -f "tests/fuzz/dictionaries/$target.dict" ] && dictionary=(-dict="tests/fuzz/dictionaries/$target.dict")
  "$program" --target="$target" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 \
    -print_final_stats=1 -artifact_prefix="$work/findings/" ${dictionary[@]+"${dictionary[@]}"} \
    "$work/corpus" "tests/fuzz/corpus/$target" >"$work/log.txt" 2>&1
}

# target | seconds | inputs run | per second | coverage | corpus | findings, from the run's log
summarize() {
  local target=$1 work=build-fuzz/fuzz/$1
  local runs coverage corpus findings
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log.txt" | tail -1)
  coverage=$(grep -o 'cov: [0-9]*' "$work/log.txt" | tail -1 | cut -d' ' -f2)
  corpus=$(grep -o 'corp: [0-9]*' "$work/log.txt" | tail -1 | cut -d' ' -f2)
  findings=$(find "$work/findings" -type f | wc -l)
  echo "| $target | $seconds | ${runs:-?} | $(( ${runs:-0} / seconds )) | ${coverage:-?} | ${corpus:-?} | $findings |"
}

echo "fuzz.sh: ${#targets[@]} targets, $seconds s each, $jobs at a time; logs in build-fuzz/fuzz/" >&2
failed=()
running=0
declare -A pid_of
for target in "${targets[@]}"; do
  if [ "$running" -ge "$jobs" ]; then wait -n || true; running=$((running - 1)); fi
  fuzz_one "$target" & pid_of[$target]=$!
  running=$((running + 1))
done
for target in "${targets[@]}"; do
  status=0
  wait "${pid_of[$target]}" || status=$?
  # A finding may also come from a child process the target starts, which the fuzzer outlives.
  if [ "$status" -ne 0 ] || [ -n "$(ls -A "build-fuzz/fuzz/$target/findings")" ]; then failed+=("$target"); fi
done

echo "| target | seconds | inputs run | per second | coverage (edges) | corpus | findings |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for target in "${targets[@]}"; do summarize "$target"; done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: findings in ${failed[*]}: see build-fuzz/fuzz/TARGET/log.txt and findings/" >&2
  exit 1
fi
