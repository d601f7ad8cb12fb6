#!/usr/bin/env bash
# plant_bugs.sh: the bug catalogue's run. Builds the mutant schemata build (every bug of mutants/bugs.txt compiled in
# behind RASTER_MUTANT=name), runs ctest on it once with no bug switched on, recording which tests reach which bug's
# code, then switches each bug on in turn and runs ctest's own tests that reach it. Prints the bug x test matrix.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: tools/plant_bugs.sh [--build-dir DIR [--reuse-build]] [--production RASTER] [--only NAME]... [--budget SECONDS] [--all-tests]
                           [--jobs N] [--list] [--check] [--help]

1. Builds the mutant schemata build in DIR (default build-mutants; -DRASTER_MUTANT_SCHEMATA=ON, Release, with
   Ninja and ccache where installed). Its sources are copies that raster_mutants writes into DIR/mutant_schemata/,
   each entry's find text a switch between the correct code and the bug; the source tree is never modified.
2. With --production RASTER (a normal build's raster), renders every corpus scene and every entry's scene and flags
   with both builds, no bug switched on: the PNG bytes must be identical.
3. Runs every ctest test of the schemata build with no bug switched on (all must pass: the correct build is clean),
   with RASTER_MUTANT_TRACE recording, for each test's processes, which bugs' code ran.
4. For each bug: RASTER_MUTANT=NAME ctest on the tests that reach its code, its own comparison case first (the
   ctest case that compares its scene and flags with the oracle), then the quickest others until their time in the
   correct run passes the budget (default 4 s; --all-tests: every test that reaches it); when none fails, the next
   quickest round within the budget, and so on until one fails or every test that reaches it has run. A test that
   never runs a bug's code cannot fail because of it (every check is seeded), so the tests left out could not have
   caught it.

stdout gets the matrix as Markdown: per bug, the tests that reach it, how many ran, which failed; then per test
suite, how many bugs it caught. Progress goes to stderr.

  --build-dir DIR      the schemata build's folder (reused: a second run rebuilds only what changed)
  --reuse-build        DIR is a normal build: reconfigure it in place as the schemata build. Every other file keeps
                       its command line, so only the copies and the files including a header copy compile again
                       (CI does this)
  --production RASTER  also check that the schemata build with no bug on gives RASTER's bytes
  --only NAME          run only this entry (repeatable)
  --budget SECONDS     expected test seconds of each round of a bug (default 4)
  --all-tests          run every test that reaches each bug (the full matrix; slow)
  --jobs N             build and test jobs (default 2)
  --list               print the catalogue's entries (name: bug) and exit
  --check              check the catalogue (well formed, fresh, switchable, judged by a ctest case) and exit
  --help               this text

Exit codes: 0 every bug made some ctest test fail, the correct build clean (and byte-identical with --production);
1 otherwise (each failure named); 2 bad usage, a malformed or stale catalogue, or a build that fails.
EOF
}

die_usage() { echo "plant_bugs: $*" >&2; echo "run tools/plant_bugs.sh --help for the options" >&2; exit 2; }
die() { echo "plant_bugs: $*" >&2; exit 2; }

root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-mutants
production="" budget=4 jobs=2 list=0 check=0 reuse=0
only=()
while (($#)); do
  case $1 in
    --help|-h) usage; exit 0 ;;
    --list) list=1 ;;
    --check) check=1 ;;
    --all-tests) budget=-1 ;;
    --reuse-build) reuse=1 ;;
    --build-dir) (($# >= 2)) || die_usage "--build-dir needs a folder"; build=$(realpath -m "$2"); shift ;;
    --production) [[ -x ${2:-} ]] || die_usage "--production needs an executable raster"; production=$(realpath "$2"); shift ;;
    --only) (($# >= 2)) || die_usage "--only needs a name"; only+=("$2"); shift ;;
    --budget) [[ ${2:-} =~ ^[0-9]+(\.[0-9]+)?$ ]] || die_usage "--budget needs a number of seconds"; budget=$2; shift ;;
    --jobs) [[ ${2:-} =~ ^[1-9][0-9]*$ ]] || die_usage "--jobs needs a positive number"; jobs=$2; shift ;;
    *) die_usage "unknown argument '$1'" ;;
  esac
  shift
done
start=$(date +%s)

# --- The schemata build ---

generator=() launcher=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
mkdir -p "$build"
logs=$build/plant_bugs
mkdir -p "$logs"
if [[ ! -f $build/CMakeCache.txt ]] || ((reuse)); then
  [[ -f $build/CMakeCache.txt ]] && generator=()  # an existing build keeps its generator
  cmake -S "$root" -B "$build" "${generator[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DRASTER_MUTANT_SCHEMATA=ON -DRASTER_BUILD_BENCH=OFF -DRASTER_BUILD_TESTS=ON -DRASTER_BUILD_FUZZERS=ON \
    >"$logs/configure.log" 2>&1 || { tail -n 30 "$logs/configure.log" >&2; die "configuring $build failed (log above)"; }
fi
grep -q '^RASTER_MUTANT_SCHEMATA:BOOL=ON' "$build/CMakeCache.txt" ||
  die "$build is not a mutant schemata build (configured without -DRASTER_MUTANT_SCHEMATA=ON)"
cmake --build "$build" -j "$jobs" --target raster_mutants >"$logs/build-tool.log" 2>&1 ||
  { tail -n 30 "$logs/build-tool.log" >&2; die "building raster_mutants failed (log above)"; }
tool=("$build/mutants/raster_mutants" --root "$root")
if ((list)); then "${tool[@]}" list; exit 0; fi
"${tool[@]}" check >&2 || exit 2
((check)) && exit 0

declare -A family=() file=() scene=() flags=() comparison=()
names=()
while IFS='|' read -r name entry_family entry_file entry_scene entry_flags entry_comparison; do
  names+=("$name")
  family[$name]=$entry_family file[$name]=$entry_file scene[$name]=$entry_scene flags[$name]=$entry_flags
  comparison[$name]=$entry_comparison
done < <("${tool[@]}" entries)
selected=("${names[@]}")
if ((${#only[@]})); then
  for name in "${only[@]}"; do [[ -n ${family[$name]+set} ]] || die_usage "no entry [$name] (see --list)"; done
  selected=("${only[@]}")
fi

echo "plant_bugs: building the schemata build in $build${generator[*]:+ (Ninja)}${launcher[*]:+ (ccache)}" >&2
build_start=$(date +%s)
# The copies first: the files that include a header copy see it through their module's include view, a link that
# ninja does not know the generator writes, so only a build that starts after the copies are written sees them new.
cmake --build "$build" -j "$jobs" --target raster_mutant_schemata_sources >"$logs/build.log" 2>&1 &&
cmake --build "$build" -j "$jobs" >>"$logs/build.log" 2>&1 ||
  { grep -m 10 -E 'error|FAILED' "$logs/build.log" >&2 || tail -n 30 "$logs/build.log" >&2; die "the schemata build fails"; }
echo "plant_bugs: schemata build done in $(($(date +%s) - build_start)) s" >&2
unclean=()

# --- The correct build: the production build's bytes ---

if [[ -n $production ]]; then
  renders=0
  while IFS=$'\t' read -r case_scene case_flags; do
    read -r -a flag_list <<<"$case_flags"
    for side in production schemata; do
      binary=$production
      [[ $side == schemata ]] && binary=$build/raster
      (cd "$root" && "$binary" render "$case_scene" "${flag_list[@]}" -o "$logs/bytes-$side.png" >/dev/null 2>&1) ||
        unclean+=("render failed: $binary render $case_scene $case_flags")
    done
    cmp -s "$logs/bytes-production.png" "$logs/bytes-schemata.png" ||
      unclean+=("bytes differ from the production build: $case_scene $case_flags")
    renders=$((renders + 1))
  done < <({ for s in "$root"/corpus/scenes/*.yaml; do printf '%s\t\n' "${s#"$root"/}"; done
             for name in "${selected[@]}"; do printf '%s\t%s\n' "${scene[$name]}" "${flags[$name]}"; done; } | sort -u)
  echo "plant_bugs: $renders scenes and flags rendered by both builds, ${#unclean[@]} differing" >&2
fi

# --- The correct build: every test passes, and which tests reach which bug ---

traces=$build/plant_bugs/traces
rm -rf "$traces"
mkdir -p "$traces"
correct_start=$(date +%s)
if ! RASTER_MUTANT_TRACE=$traces ctest --test-dir "$build" -j "$jobs" --timeout 600 >"$logs/correct.log" 2>&1; then
  unclean+=("ctest fails with no bug switched on: $(sed -n '/The following tests FAILED/,$p' "$logs/correct.log" |
    sed -n -E 's/^[[:space:]]+[0-9]+ - (.*) \(.*$/\1/p' | tr '\n' ' ')(see $logs/correct.log)")
fi
echo "plant_bugs: the correct build's ctest in $(($(date +%s) - correct_start)) s, $(ls "$traces" | wc -l) traces" >&2
ctest --test-dir "$build" --show-only=json-v1 >"$logs/tests.json"
"${tool[@]}" plan --ctest-json "$logs/tests.json" --costs "$build/Testing/Temporary/CTestCostData.txt" \
  --traces "$traces" --budget "$budget" >"$logs/plan.tsv"
declare -A reached=() to_run=() reaches=()
while IFS=$'\t' read -r name _ count numbers comparison_reaches; do
  reached[$name]=$count to_run[$name]=$numbers reaches[$name]=$comparison_reaches
done <"$logs/plan.tsv"

# --- The bugs ---

rows=() missed=()
declare -A suite_catches=()
index=0
for name in "${selected[@]}"; do
  index=$((index + 1))
  bug_start=$(date +%s)
  failed=() ran=0 rounds=0
  if [[ ${to_run[$name]} != - ]]; then
    # Round after round (each within the budget) until a test fails or every test that reaches the bug has run.
    IFS=';' read -r -a round_list <<<"${to_run[$name]}"
    : >"$logs/bug-$name.log"
    for numbers in "${round_list[@]}"; do
      rounds=$((rounds + 1))
      ran=$((ran + $(tr ',' '\n' <<<"$numbers" | wc -l)))
      RASTER_MUTANT=$name ctest --test-dir "$build" -j "$jobs" --timeout 120 -I "0,0,0,$numbers" \
        >"$logs/bug-$name.round.log" 2>&1 || true
      cat "$logs/bug-$name.round.log" >>"$logs/bug-$name.log"
      mapfile -t failed < <(sed -n '/The following tests FAILED/,$p' "$logs/bug-$name.round.log" |
        sed -n -E 's/^[[:space:]]+[0-9]+ - (.*) \((Failed|Timeout|SEGFAULT|Subprocess aborted|Child aborted|Exception|[A-Za-z ]+)\)$/\1/p' |
        sed -E 's/  # .*$//')
      if ((${#failed[@]})); then break; fi
    done
    rm -f "$logs/bug-$name.round.log"
  fi
  comparison_cell="${comparison[$name]}"
  if [[ ${reaches[$name]} != reaches ]]; then comparison_cell+=" (does not reach it)"
  elif printf '%s\n' "${failed[@]}" | grep -qxF -- "${comparison[$name]}"; then comparison_cell+=" (fails)"
  else comparison_cell+=" (passes)"; fi
  declare -A seen_suites=()
  for test in "${failed[@]}"; do
    suite=${test%%[./]*}
    [[ -n ${seen_suites[$suite]:-} ]] && continue
    seen_suites[$suite]=1
    suite_catches[$suite]=$((${suite_catches[$suite]:-0} + 1))
  done
  unset seen_suites
  shown=""
  for test in "${failed[@]:0:3}"; do shown+=${shown:+; }$test; done
  if ((${#failed[@]} > 3)); then shown+="; ..."; fi
  if ((${#failed[@]} == 0)); then
    missed+=("$name")
    outcome="NOT CAUGHT by the $ran tests run of the ${reached[$name]} that reach it"
  else
    outcome="caught by ${#failed[@]} of $ran tests run (${reached[$name]} reach it)"
    if ((rounds > 1)); then outcome+=" in round $rounds"; fi
  fi
  rows+=("| $name | ${family[$name]} | $comparison_cell | ${reached[$name]} | $ran | ${#failed[@]} | ${shown:-none} |")
  echo "plant_bugs: [$index/${#selected[@]}] $name: $outcome, $(($(date +%s) - bug_start)) s" >&2
done

echo "| bug | family | its comparison case | tests reaching it | run | failing | first failing tests |"
echo "|---|---|---|---:|---:|---:|---|"
printf '%s\n' "${rows[@]}"
echo
echo "| test suite | bugs caught |"
echo "|---|---:|"
for suite in "${!suite_catches[@]}"; do echo "${suite_catches[$suite]} $suite"; done | sort -rn -k1,1 |
  while read -r count suite; do echo "| $suite | $count |"; done

echo "plant_bugs: ${#selected[@]} planted, $((${#selected[@]} - ${#missed[@]})) caught by ctest tests," \
     "${#unclean[@]} problems with the correct build, in $(($(date +%s) - start)) s" >&2
status=0
if ((${#missed[@]})); then echo "plant_bugs: NOT CAUGHT: ${missed[*]}" >&2; status=1; fi
if ((${#unclean[@]})); then printf 'plant_bugs: correct build: %s\n' "${unclean[@]}" >&2; status=1; fi
exit "$status"
