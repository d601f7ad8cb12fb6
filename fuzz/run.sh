#!/usr/bin/env bash
# Fuzzes locally with the `fuzz` preset: merges new coverage into corpus/fuzz/, minimises crashes into corpus/regressions/.
#
#   fuzz/run.sh [TARGET|all] [SECONDS]   fuzz one target (or every one, the default) for SECONDS each (default 60),
#                                        then merge the inputs that add coverage into corpus/fuzz/TARGET (-merge=1).
#                                        A crash, hang (over 1 s) or OOM (over 2 GiB) is minimised
#                                        (-minimize_crash=1) into corpus/regressions/TARGET/, which ctest replays.
#   fuzz/run.sh --ci [SECONDS] [JOBS]    CI: every target for SECONDS (default 60), JOBS at a time (default 2), the
#                                        corpus left untouched; exits 1 if any target failed, naming the reproducer
#                                        and printing it in base64 (the CI machine's files do not outlive it).
#
# RASTER_FUZZ_SEED sets libFuzzer's -seed. CI mode defaults it to 1, so that a CI run can be repeated here input
# for input (up to the run count the machine reached in the time); local runs default to a random seed.
#
# Each target's flags come from fuzz/TARGET.options (the same file OSS-Fuzz reads). Set RASTER_FUZZ_BUILD to use
# another build directory; it must be configured like the preset (libFuzzer engine).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${RASTER_FUZZ_BUILD:-$root/build-fuzz}

ci=0
if [[ ${1:-} == --ci ]]; then
  ci=1
  target=all
  seconds=${2:-60}
  jobs=${3:-2}
  RASTER_FUZZ_SEED=${RASTER_FUZZ_SEED:-1}
else
  target=${1:-all}
  seconds=${2:-60}
  jobs=1
fi

if [[ -z ${RASTER_FUZZ_BUILD:-} ]]; then
  (cd "$root" && cmake --preset fuzz >/dev/null && cmake --build --preset fuzz)
fi
# Absolute, because the cli target changes directory while an input runs (libFuzzer may write artifacts then).
build=$(cd "$build" && pwd)

# The libFuzzer flags of a target's .options file, one per line ([libfuzzer] key = value; the dict made absolute).
options_of() {
  local file=$root/fuzz/$1.options
  [[ -f $file ]] || return 0
  awk -v fuzz="$root/fuzz" '
    /^\[/ { section = $0; next }
    section == "[libfuzzer]" && /=/ {
      key = $1; value = $0; sub(/^[^=]*=[ \t]*/, "", value); sub(/[ \t]*$/, "", value)
      if (key == "dict") value = fuzz "/" value
      print "-" key "=" value
    }' "$file"
}

# fuzz_target NAME: fuzzes NAME for $seconds; prints one summary line; returns 1 on a crash, hang or OOM.
fuzz_target() {
  local name=$1
  local binary=$build/fuzz/${name}_fuzzer
  local work artifacts log status=0
  work=$(mktemp -d "${TMPDIR:-/tmp}/raster-fuzz-run-$name-XXXXXX")
  artifacts=$build/artifacts/$name
  log=$build/artifacts/$name.log
  rm -rf "$artifacts" && mkdir -p "$artifacts" "$work/new"
  local corpora=("$work/new" "$root/corpus/fuzz/$name")
  [[ -d $root/corpus/regressions/$name ]] && corpora+=("$root/corpus/regressions/$name")
  mapfile -t flags < <(options_of "$name")
  [[ -n ${RASTER_FUZZ_SEED:-} ]] && flags+=("-seed=$RASTER_FUZZ_SEED")
  "$binary" "${flags[@]}" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$artifacts/" \
    "${corpora[@]}" >"$log" 2>&1 || status=$?

  local runs rate cov
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1 || true)
  if ((status == 0)); then
    echo "fuzz: $name: ${runs:-?} runs in $seconds s (${rate:-?}/s), $cov${RASTER_FUZZ_SEED:+, seed $RASTER_FUZZ_SEED}"
    if ((!ci)); then
      local before after
      before=$(find "$root/corpus/fuzz/$name" -type f | wc -l)
      "$binary" "${flags[@]}" -merge=1 "$root/corpus/fuzz/$name" "$work/new" >>"$log" 2>&1
      after=$(find "$root/corpus/fuzz/$name" -type f | wc -l)
      echo "fuzz: $name: merged $((after - before)) new inputs into corpus/fuzz/$name"
    fi
    rm -rf "$work"
    return 0
  fi

  local found
  found=$(find "$artifacts" -type f | head -1)
  echo "fuzz: $name: FAILED (exit $status) after ${runs:-?} runs${RASTER_FUZZ_SEED:+ (seed $RASTER_FUZZ_SEED)}; log: $log" >&2
  grep -E 'ERROR|SUMMARY|check failed|^ {2,}[^ #]' "$log" | head -60 >&2 || true
  if [[ -z $found ]]; then
    echo "fuzz: $name: no reproducer was written" >&2
  elif ((ci)); then
    echo "fuzz: $name: reproducer: $found" >&2
    echo "fuzz: $name: replay it with: $binary $found" >&2
    echo "fuzz: $name: the reproducer in base64 (recreate it with: base64 -d > FILE):" >&2
    base64 "$found" >&2
  else
    local kept=$root/corpus/regressions/$name/$(basename "$found")
    mkdir -p "$(dirname "$kept")"
    "$binary" "${flags[@]}" -minimize_crash=1 -max_total_time=60 -exact_artifact_path="$kept" "$found" \
      >>"$log" 2>&1 || true
    [[ -f $kept ]] || cp "$found" "$kept"
    echo "fuzz: $name: minimised reproducer: $kept (fix the bug, then commit it: ctest -L fuzz replays it)" >&2
  fi
  rm -rf "$work"
  return 1
}

names=()
if [[ $target == all ]]; then
  for binary in "$build"/fuzz/*_fuzzer; do
    name=$(basename "$binary")
    name=${name%_fuzzer}
    # RASTER_FUZZ_SKIP: space-separated targets left out of an `all` run (CI skips targets with open findings).
    if [[ " ${RASTER_FUZZ_SKIP:-} " == *" $name "* ]]; then
      echo "fuzz: $name skipped (RASTER_FUZZ_SKIP)" >&2
      continue
    fi
    names+=("$name")
  done
else
  [[ -x $build/fuzz/${target}_fuzzer ]] || { echo "fuzz: no target '$target' in $build/fuzz" >&2; exit 2; }
  names=("$target")
fi

start=$(date +%s)
failed=()
running=0
declare -A job_of_pid=()
for name in "${names[@]}"; do
  if ((running >= jobs)); then
    finished_pid=""
    wait -n -p finished_pid || failed+=("${job_of_pid[$finished_pid]}")
    running=$((running - 1))
  fi
  fuzz_target "$name" &
  job_of_pid[$!]=$name
  running=$((running + 1))
done
while ((running > 0)); do
  finished_pid=""
  wait -n -p finished_pid || failed+=("${job_of_pid[$finished_pid]}")
  running=$((running - 1))
done

echo "fuzz: ${#names[@]} targets in $(($(date +%s) - start)) s"
if ((${#failed[@]})); then
  echo "fuzz: FAILED: ${failed[*]}" >&2
  exit 1
fi
