#!/usr/bin/env bash
# Soaks fuzz targets: each for RUNS executions with a random seed, from its seed corpus, and prints what each reached.
#
#   tools/soak_fuzz.sh OUT RUNS TARGET...    OUT is an engine build ($OUT of tools/check_fuzz_build.sh, which keeps
#                                            it when given OUT=DIR); TARGET is a name such as ply or differential
#
# Each target runs from a scratch copy of its seed corpus (OUT/NAME_fuzzer_seed_corpus.zip) with the flags of its
# .options file, a fresh random seed (libFuzzer's -seed=0, printed), -timeout=10 (a soak shares the machine, so the
# 1 s hang limit would flag load) and at low priority. Logs, corpora and artifacts stay in $SOAK_DIR (default a new
# temporary folder, printed). One line per target: runs, seconds, the cov: reached, and a finding's reproducer.
# Exits 1 if any target found something (crash, timeout, OOM), 2 on a usage error.
set -uo pipefail

if [[ ${1:-} == -h || ${1:-} == --help || $# -lt 3 ]]; then
  sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
  [[ $# -lt 3 && ${1:-} != -h && ${1:-} != --help ]] && exit 2
  exit 0
fi
out=$(cd "$1" && pwd) || { echo "soak_fuzz: no folder $1" >&2; exit 2; }
runs=$2
shift 2
[[ $runs =~ ^[0-9]+$ ]] || { echo "soak_fuzz: RUNS must be a number, not '$runs'" >&2; exit 2; }
soak=${SOAK_DIR:-$(mktemp -d /tmp/raster-soak.XXXXXX)}
mkdir -p "$soak"
echo "soak_fuzz: logs, corpora and artifacts in $soak" >&2

# The libFuzzer flags of a target's .options file ([libfuzzer] key = value; the dict made absolute).
options() {
  awk -v out="$out" '/^\[/ { section = $0; next }
    section == "[libfuzzer]" && /=/ {
      key = $1; value = $0; sub(/^[^=]*=[ \t]*/, "", value)
      if (key == "dict") value = out "/" value
      printf "-%s=%s\n", key, value }' "$out/$1_fuzzer.options"
}

status=0
for target in "$@"; do
  binary=$out/${target}_fuzzer
  [[ -x $binary ]] || { echo "soak_fuzz: no $binary" >&2; exit 2; }
  corpus=$soak/corpus/$target artifacts=$soak/artifacts/$target/ log=$soak/$target.log
  mkdir -p "$corpus" "$artifacts"
  [[ -f $out/${target}_fuzzer_seed_corpus.zip ]] && unzip -oq "$out/${target}_fuzzer_seed_corpus.zip" -d "$corpus"
  mapfile -t flags < <(options "$target")
  start=$(date +%s)
  nice -n 10 "$binary" "${flags[@]}" -seed=0 -timeout=10 -runs="$runs" -print_final_stats=1 \
    -artifact_prefix="$artifacts" "$corpus" > "$log" 2>&1
  code=$?
  seconds=$(( $(date +%s) - start ))
  done_runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1)
  seed=$(sed -n 's/^INFO: Seed: //p' "$log" | head -n 1)
  finding=$(ls "$artifacts" 2>/dev/null | head -n 1)
  line="$target: ${done_runs:-?} runs in $seconds s, ${cov:-cov: ?}, seed $seed"
  if [[ $code -ne 0 || -n $finding ]]; then
    echo "$line: FINDING (exit $code) $artifacts$finding"
    status=1
  else
    echo "$line: no finding"
  fi
done
exit $status
