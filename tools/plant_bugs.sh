#!/usr/bin/env bash
# plant_bugs.sh: the bug catalogue's run. Writes each bug of mutants/bugs.txt into a scratch copy of raster's
# source, rebuilds, and runs every check against it: the oracle (`raster compare`), every property and the fuzz
# invariants (the raster and differential targets over their corpora). Prints the bug x check matrix.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: tools/plant_bugs.sh [--list] [--check] [--only NAME]... [--catalogue FILE] [--keep] [--jobs N] [--help]

Copies the tracked source tree (git ls-files) into a scratch folder and builds there (Release, benchmarks off) the
targets the checks run: `raster`, the property tests and the raster and differential fuzz targets' corpus
replayers. The correct build must pass every check: `raster compare SCENE FLAGS` of every selected entry exits 0,
every property passes (RC_PARAMS="max_success=100 seed=1" unless RASTER_PLANT_RC_PARAMS says otherwise) and both
replayers pass their corpora and regressions. Then, one bug at a time: checks that the entry's find text occurs
exactly once in its file, applies the replacement, rebuilds incrementally, runs every check, and restores the file.
The worktree itself is never modified.

The checks, each a column of the matrix:
  oracle        `raster compare SCENE FLAGS --json` exits 1 with genuine_total > 0         (reads pixels)
  P:Suite.Name  the property fails on some backend (Suite.Name/BACKEND for a drawing one)  (a drawing property
                reads the samples it drew; the others check matrices, clipped vertices or tables: no pixel)
  fuzz:raster, fuzz:differential   the replayer fails an input of its corpus or regressions (reads pixels)

Progress goes to stderr; stdout gets the matrix, as a Markdown table (bug, family, scene and flags, genuine count
and classes, the properties and fuzz invariants that caught it) and then the catches of each check. For a bug
compare misses, the runner renders the scene with both builds and says whether raster's PNG and PPM bytes changed.

  --list            print the catalogue's entries (name: bug) and exit
  --check           check that every selected entry is well formed and fresh (its find text occurs exactly once in
                    its file, its scene exists) and exit, building nothing: ctest runs this
  --only NAME       run only this entry (repeatable)
  --catalogue FILE  the catalogue to run (default mutants/bugs.txt)
  --keep            keep the scratch folder (its path is printed): src/ (restored), build/ (its raster is the last
                    bug's), raster-correct, runs/NAME.json and .txt (compare's output), logs/ (configure, builds)
  --jobs N          build jobs (default 2)
  --help            this text

Exit codes: 0 every bug caught by a check that reads pixels, every check (with --only: not required) catching a
bug, and the correct build clean; 1 otherwise (each failure named); 2 bad usage, a stale or malformed entry, or a
build that fails.
EOF
}

die_usage() { echo "plant_bugs: $*" >&2; echo "run tools/plant_bugs.sh --help for the options" >&2; exit 2; }
die() { echo "plant_bugs: $*" >&2; exit 2; }

root=$(cd "$(dirname "$0")/.." && pwd)
catalogue=$root/mutants/bugs.txt
only=()
keep=0 list=0 check=0 jobs=2
while (($#)); do
  case $1 in
    --help|-h) usage; exit 0 ;;
    --list) list=1 ;;
    --check) check=1 ;;
    --keep) keep=1 ;;
    --only) (($# >= 2)) || die_usage "--only needs a name"; only+=("$2"); shift ;;
    --catalogue) (($# >= 2)) || die_usage "--catalogue needs a file"; catalogue=$2; shift ;;
    --jobs) [[ ${2:-} =~ ^[1-9][0-9]*$ ]] || die_usage "--jobs needs a positive number"; jobs=$2; shift ;;
    *) die_usage "unknown argument '$1'" ;;
  esac
  shift
done
[[ -f $catalogue ]] || die_usage "no catalogue file '$catalogue'"

# --- The catalogue ---

keys=(bug family file find replace scene flags)
names=()
declare -A entry=()  # entry[NAME.KEY] = value (find and replace unescaped)
declare -A entry_line=()  # entry_line[NAME] = the line of its [NAME] header

# unescape TEXT: sets REPLY to TEXT with \n, \t, \s and \\ decoded; returns 1 on any other escape.
unescape() {
  local text=$1 out="" i char
  for ((i = 0; i < ${#text}; i++)); do
    char=${text:i:1}
    if [[ $char != '\' ]]; then out+=$char; continue; fi
    i=$((i + 1))
    case ${text:i:1} in
      n) out+=$'\n' ;;
      t) out+=$'\t' ;;
      s) out+=' ' ;;
      '\') out+='\' ;;
      *) return 1 ;;
    esac
  done
  REPLY=$out
}

# Reads the catalogue into names/entry; any malformed line stops the run with its file:line.
read_catalogue() {
  local line number=0 name="" key value
  while IFS= read -r line || [[ -n $line ]]; do
    number=$((number + 1))
    [[ $line =~ ^[[:space:]]*(#|$) ]] && continue
    if [[ $line =~ ^\[([A-Za-z0-9_-]+)\][[:space:]]*$ ]]; then
      name=${BASH_REMATCH[1]}
      [[ -z ${entry_line[$name]:-} ]] || die "$catalogue:$number: entry [$name] appears twice"
      names+=("$name")
      entry_line[$name]=$number
      continue
    fi
    [[ $line =~ ^([a-z]+)[[:space:]]*=(.*)$ ]] || die "$catalogue:$number: expected [name], 'key = value' or a comment"
    key=${BASH_REMATCH[1]}
    value=${BASH_REMATCH[2]}
    value=${value#"${value%%[![:space:]]*}"}
    value=${value%"${value##*[![:space:]]}"}
    [[ -n $name ]] || die "$catalogue:$number: '$key' before the first [name]"
    [[ " ${keys[*]} " == *" $key "* ]] || die "$catalogue:$number: unknown key '$key' (keys: ${keys[*]})"
    [[ -z ${entry[$name.$key]+set} ]] || die "$catalogue:$number: [$name] sets '$key' twice"
    if [[ $key == find || $key == replace ]]; then
      unescape "$value" || die "$catalogue:$number: [$name] $key: unknown escape (only \\n \\t \\s \\\\)"
      value=$REPLY
    fi
    entry[$name.$key]=$value
  done <"$catalogue"
  ((${#names[@]})) || die "$catalogue: no entries"
  for name in "${names[@]}"; do
    for key in "${keys[@]}"; do
      [[ -n ${entry[$name.$key]+set} ]] || die "$catalogue:${entry_line[$name]}: [$name] has no '$key'"
    done
    for key in bug file find scene; do
      [[ -n ${entry[$name.$key]} ]] || die "$catalogue:${entry_line[$name]}: [$name] has an empty '$key'"
    done
    case ${entry[$name.file]} in
      oracle/*|harness/*) die "$catalogue:${entry_line[$name]}: [$name] plants into ${entry[$name.file]}:" \
                              "bugs belong in the production path, not in the checks" ;;
    esac
  done
}

# occurrences TEXT PATTERN: prints how many times PATTERN occurs in TEXT (without overlaps).
occurrences() {
  local text=$1 pattern=$2 count=0
  while [[ $text == *"$pattern"* ]]; do
    text=${text#*"$pattern"}
    count=$((count + 1))
  done
  echo "$count"
}

# read_whole FILE: sets REPLY to the file's exact bytes (trailing newlines kept).
read_whole() {
  REPLY=$(cat -- "$1"; printf x)
  REPLY=${REPLY%x}
}

# check_fresh NAME TREE: the entry's find text must occur exactly once in its file under TREE (else exit 2).
check_fresh() {
  local name=$1 tree=$2 file=$2/${entry[$1.file]} count
  local where="catalogue $catalogue:${entry_line[$name]}"
  [[ -f $file ]] || die "[$name] is stale: ${entry[$name.file]} does not exist ($where)"
  read_whole "$file"
  count=$(occurrences "$REPLY" "${entry[$name.find]}")
  [[ $count -eq 1 ]] || die "[$name] is stale: its find text occurs $count times in ${entry[$name.file]}, not once" \
                            "($where); update the entry to the current source"
  [[ -f $tree/${entry[$name.scene]} ]] || die "[$name]: no scene ${entry[$name.scene]} ($where)"
}

read_catalogue
selected=()
if ((${#only[@]})); then
  for name in "${only[@]}"; do
    [[ -n ${entry_line[$name]:-} ]] || die_usage "no entry [$name] in $catalogue (see --list)"
    selected+=("$name")
  done
else
  selected=("${names[@]}")
fi
# The run order: bugs of one file together (restoring one and planting the next then costs one rebuild of what
# includes that file, not two), sources before headers (a header rebuilds everything that includes it), each
# file's bugs in catalogue order.
order_by_file() {
  local name
  for name in "$@"; do
    local file=${entry[$name.file]} kind=0
    [[ $file == *.h ]] && kind=1
    printf '%s\t%s\t%s\n' "$kind" "$file" "$name"
  done | sort -s -t $'\t' -k1,1n -k2,2 | cut -f3
}

if ((list)); then
  for name in "${selected[@]}"; do echo "$name: ${entry[$name.bug]}"; done
  exit 0
fi
mapfile -t selected < <(order_by_file "${selected[@]}")

# Every entry is checked against the worktree before anything is built, so a stale catalogue fails in seconds.
for name in "${selected[@]}"; do check_fresh "$name" "$root"; done
if ((check)); then
  echo "plant_bugs: ${#selected[@]} entries well formed and fresh"
  exit 0
fi
git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1 ||
  die "$root is not a git checkout (git ls-files lists the source)"

# --- The scratch tree and the correct build ---

scratch=$(mktemp -d "${TMPDIR:-/tmp}/plant_bugs.XXXXXX")
if ((keep)); then
  trap 'echo "plant_bugs: scratch folder kept: $scratch" >&2' EXIT
else
  trap 'rm -rf "$scratch"' EXIT
fi
src=$scratch/src build=$scratch/build logs=$scratch/logs runs=$scratch/runs
mkdir -p "$src" "$logs" "$runs"
start=$(date +%s)

# Only tracked files (in their worktree state), so no build folder or stray output comes along.
(cd "$root" && git ls-files -z | while IFS= read -r -d '' tracked; do [[ -e $tracked ]] && printf '%s\0' "$tracked"; done |
  tar --null -T - -cf -) | tar -xf - -C "$src"

targets=(raster raster_properties_test raster_fuzzer differential_fuzzer)
properties_binary=properties/raster_properties_test
rc_params=${RASTER_PLANT_RC_PARAMS:-max_success=100 seed=1}

# build LOG: builds the checks' targets incrementally in $build; prints its seconds; returns the build's status.
build() {
  local log=$1 begin rc=0
  begin=$(date +%s)
  cmake --build "$build" -j "$jobs" --target "${targets[@]}" >"$log" 2>&1 || rc=$?
  echo $(($(date +%s) - begin))
  return "$rc"
}

# With ccache (Debian's ccache, which .ci/install installs), restoring a planted header is a cache hit: each header
# bug then costs one rebuild of what includes it instead of two. Its cache lives and dies with the scratch folder.
launcher=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_DIR=$scratch/ccache CCACHE_MAXSIZE=4G
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# With Ninja (Debian's ninja-build, which .ci/install installs), planting a bug in a source file and rebuilding the
# four targets takes 2-3 s, against 8-11 s with Makefiles, whose dependency scan alone takes 5 s when nothing changed.
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
echo "plant_bugs: building the correct raster, properties and fuzz replayers in $build${launcher[*]:+ (ccache)}" \
     "${generator[*]:+(Ninja)}" >&2
cmake -S "$src" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DRASTER_BUILD_TESTS=ON \
  -DRASTER_BUILD_BENCH=OFF -DRASTER_BUILD_FUZZERS=ON "${launcher[@]}" >"$logs/configure.log" 2>&1 ||
  { tail -n 30 "$logs/configure.log" >&2; die "configuring the scratch copy failed (log above)"; }
seconds=$(build "$logs/build-correct.log") ||
  { tail -n 30 "$logs/build-correct.log" >&2; die "the correct build fails (log above)"; }
[[ -x $build/$properties_binary ]] || die "the scratch build has no $properties_binary"
[[ -x $build/fuzz/raster_fuzzer && -x $build/fuzz/differential_fuzzer ]] ||
  die "the scratch build has no fuzz replayers (is clang-14's FuzzedDataProvider.h installed?)"
cp "$build/raster" "$scratch/raster-correct"
echo "plant_bugs: correct build done in $seconds s" >&2

# --- Properties and fuzz invariants ---

# run_properties LABEL: every property on every backend; sets failed_properties (Suite.Name, backends folded,
# sorted) and failed_drawing (the ones that drew). A crash counts as a failure of the property that was running.
# The correct build's run must pass everything, the registry's tests and the regression cases included.
run_properties() {
  local log=$runs/$1.properties.txt
  (cd "$src" && RC_PARAMS=$rc_params timeout 1200 "$build/$properties_binary" --gtest_color=no; exit $?) >"$log" 2>&1 || true
  local failed running
  failed=$(sed -n -E 's/^\[  FAILED  \] ([A-Za-z0-9_]+\.[A-Za-z0-9_]+(\/[a-z0-9_]+)?)( \(.*)?$/\1/p' "$log" | sort -u)
  running=$(awk '/^\[ RUN      \]/ { t = $4 } /^\[       OK \]|^\[  FAILED  \]/ { t = "" } END { print t }' "$log")
  # The registry's own tests and the fixed regression cases are not properties: they are not columns.
  failed=$(printf '%s\n%s\n' "$failed" "$running" | sed '/^$/d' | grep -v '^PropertyRegistry\.\|^Regressions\.' |
    sort -u || true)
  failed_properties=$(sed -E 's#/.*##' <<<"$failed" | sed '/^$/d' | sort -u | tr '\n' ' ')
  failed_drawing=$(grep '/' <<<"$failed" | sed -E 's#/.*##' | sort -u | tr '\n' ' ' || true)
  failed_properties=${failed_properties% } failed_drawing=${failed_drawing% }
}

# run_fuzz LABEL: each replayer over its corpus and regressions; sets failed_fuzz (fuzz:raster, fuzz:differential).
run_fuzz() {
  local name inputs=() log
  failed_fuzz=""
  for name in raster differential; do
    inputs=("$src/corpus/fuzz/$name")
    [[ -d $src/corpus/regressions/$name ]] && inputs+=("$src/corpus/regressions/$name")
    log=$runs/$1.fuzz-$name.txt
    # A failed check traps; the subshell's own "Illegal instruction" note goes to the log with the rest (the trailing
    # exit keeps bash from exec-ing the last command, which would leave the note to this script's stderr).
    (cd "$src" && timeout 600 "$build/fuzz/${name}_fuzzer" -runs=0 "${inputs[@]}"; exit $?) >"$log" 2>&1 ||
      failed_fuzz+=${failed_fuzz:+ }fuzz:$name
  done
}

# --- Running compare ---

# run_compare BINARY NAME SCENE FLAGS: runs `BINARY compare` in the scratch source tree with --json
# $runs/NAME.json; sets rc, genuine_total and caught_by (the nonzero genuine classes, largest first).
run_compare() {
  local binary=$1 name=$2 scene=$3 flags=() json=$runs/$2.json
  read -r -a flags <<<"$4"
  rm -f "$json"
  rc=0
  (cd "$src" && timeout 900 "$binary" compare "$scene" "${flags[@]}" --json "$json" >"$runs/$name.txt" 2>&1) || rc=$?
  genuine_total="" caught_by=""
  [[ -f $json ]] || return 0
  genuine_total=$(sed -n -E 's/^  "genuine_total": ([0-9]+),?$/\1/p' "$json")
  # The "genuine" object's counts, one "class count" per line; colour also names the formats that showed it.
  local counts png ppm
  counts=$(sed -n -E '/^  "genuine": \{/,/^  \}/s/^    "([a-z_]+)": ([0-9]+),?$/\2 \1/p' "$json" | sort -rn -k1,1 -s)
  png=$(sed -n -E 's/^    "color_png": ([0-9]+),?$/\1/p' "$json")
  ppm=$(sed -n -E 's/^    "color_ppm": ([0-9]+),?$/\1/p' "$json")
  local count class parts=()
  while read -r count class; do
    [[ -n $count && $count != 0 ]] || continue
    if [[ $class == color && $png != "$ppm" ]]; then parts+=("color $count (png $png, ppm $ppm)")
    else parts+=("$class $count"); fi
  done <<<"$counts"
  local part
  for part in "${parts[@]}"; do caught_by+=${caught_by:+, }$part; done
}

# same_output SCENE FLAGS: renders with both builds (PNG and PPM), says which files differ and what that means.
same_output() {
  local scene=$1 flags=() format verdict=()
  read -r -a flags <<<"$2"
  for format in png ppm; do
    (cd "$src" &&
      "$scratch/raster-correct" render "$scene" "${flags[@]}" -o "$scratch/correct.$format" >/dev/null 2>&1 &&
      "$build/raster" render "$scene" "${flags[@]}" -o "$scratch/planted.$format" >/dev/null 2>&1) ||
      { verdict+=("$format: render failed"); continue; }
    if cmp -s "$scratch/correct.$format" "$scratch/planted.$format"; then verdict+=("$format unchanged")
    else verdict+=("$format differs"); fi
  done
  local joined="${verdict[0]}, ${verdict[1]}"
  case $joined in
    *differs*) echo "$joined: compare misses a change in raster's output (an oracle gap)" ;;
    *) echo "$joined: the bug does not show on this scene and flags (choose others)" ;;
  esac
}

describe() { echo "${entry[$1.scene]}${entry[$1.flags]:+ ${entry[$1.flags]}}"; }

# The correct build on every distinct scene and flags the selected entries use: each must be clean.
declare -A correct_rc=()
unclean=()
for name in "${selected[@]}"; do
  run_key=$(describe "$name")
  [[ -z ${correct_rc[$run_key]:-} ]] || continue
  run_compare "$scratch/raster-correct" "correct-$name" "${entry[$name.scene]}" "${entry[$name.flags]}"
  correct_rc[$run_key]=$rc
  if [[ $rc -eq 0 ]]; then echo "plant_bugs: correct raster clean on $run_key" >&2
  else
    echo "plant_bugs: the CORRECT raster is not clean on $run_key: exit $rc, genuine ${genuine_total:-?}" \
         "${caught_by:+($caught_by)}; see $runs/correct-$name.txt" >&2
    unclean+=("$run_key")
  fi
done

# The correct build on the properties and fuzz invariants: both must pass, or their catches mean nothing.
run_properties correct
run_fuzz correct
grep -q '^\[  PASSED  \]' "$runs/correct.properties.txt" && ! grep -q '^\[  FAILED  \]' "$runs/correct.properties.txt" ||
  failed_properties=${failed_properties:-"(see the log)"}
[[ -z $failed_properties ]] || { echo "plant_bugs: the CORRECT build fails properties: $failed_properties" \
  "(see $runs/correct.properties.txt)" >&2; unclean+=("properties: $failed_properties"); }
[[ -z $failed_fuzz ]] || { echo "plant_bugs: the CORRECT build fails $failed_fuzz (see $runs/correct.fuzz-*.txt)" >&2
  unclean+=("$failed_fuzz"); }
((${#unclean[@]})) || echo "plant_bugs: correct build passes every property and fuzz invariant" >&2
# Every property is a column, caught or not: the names come from the correct run's list of tests.
all_properties=$(sed -n -E 's/^\[ RUN      \] ([A-Za-z0-9_]+\.[A-Za-z0-9_]+).*$/\1/p' "$runs/correct.properties.txt" |
  grep -v '^PropertyRegistry\.\|^Regressions\.' | sort -u)
declare -A drawing=()
while read -r test; do drawing[$test]=1; done < <(sed -n -E 's#^\[ RUN      \] ([A-Za-z0-9_]+\.[A-Za-z0-9_]+)/.*$#\1#p' \
  "$runs/correct.properties.txt" | sort -u)
declare -A catches=()
for check in oracle $all_properties fuzz:raster fuzz:differential; do catches[$check]=0; done

# --- The bugs ---

rows=()
missed=()
broken=()
index=0
for name in "${selected[@]}"; do
  index=$((index + 1))
  check_fresh "$name" "$src"
  file=$src/${entry[$name.file]}
  read_whole "$file"
  original=$REPLY
  before=${original%%"${entry[$name.find]}"*}
  after=${original#*"${entry[$name.find]}"}
  printf '%s' "$before${entry[$name.replace]}$after" >"$file"
    if ! seconds=$(build "$logs/build-$name.log"); then
    echo "plant_bugs: [$index/${#selected[@]}] $name: the planted source does not build; see $logs/build-$name.log:" >&2
    grep -m 5 -E 'error' "$logs/build-$name.log" >&2 || true
    broken+=("$name")
    rows+=("| $name | ${entry[$name.family]} | $(describe "$name") | does not build | - | - |")
  else
    check_start=$(date +%s)
    # One after another: run at once, the checks took 66 s on 7 entries against 54 s, since the properties'
    # two-thread backends and compare's threads already keep both cores busy.
    run_compare "$build/raster" "$name" "${entry[$name.scene]}" "${entry[$name.flags]}"
    run_properties "$name"
    run_fuzz "$name"
    check_seconds=$(($(date +%s) - check_start))
    oracle_caught=0 by=()
    if [[ $rc -eq 1 && ${genuine_total:-0} -gt 0 ]]; then
      oracle_caught=1
      oracle_cell="$genuine_total ($caught_by)"
      catches[oracle]=$((catches[oracle] + 1))
    else
      oracle_cell="missed (exit $rc; $(same_output "${entry[$name.scene]}" "${entry[$name.flags]}"))"
    fi
    for check in $failed_properties $failed_fuzz; do
      [[ -n ${catches[$check]+set} ]] || catches[$check]=0
      catches[$check]=$((catches[$check] + 1))
    done
    # What reads pixels: the oracle, a drawing property, a fuzz invariant.
    pixel_catches=$((oracle_caught + $(wc -w <<<"$failed_drawing $failed_fuzz")))
    others=$(( $(wc -w <<<"$failed_properties") - $(wc -w <<<"$failed_drawing") ))
    summary="oracle $([[ $oracle_caught == 1 ]] && echo "$genuine_total" || echo missed), $(wc -w <<<"$failed_properties") properties ($others reading no pixel), ${failed_fuzz:-no fuzz invariant}"
    if ((pixel_catches == 0)); then
      missed+=("$name")
      outcome="NOT CAUGHT by a check that reads pixels: $summary"
    else
      outcome="caught: $summary"
    fi
    rows+=("| $name | ${entry[$name.family]} | $(describe "$name") | $oracle_cell | ${failed_properties:-none} | ${failed_fuzz:-none} |")
    echo "plant_bugs: [$index/${#selected[@]}] $name: build $seconds s, checks $check_seconds s: $outcome" >&2
  fi
  printf '%s' "$original" >"$file"  # a fresh mtime, so the next build recompiles it from the real source
done

echo "| bug | family | scene and flags | oracle: genuine (classes) | properties that fail | fuzz invariants |"
echo "|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
echo
echo "| check | reads pixels | bugs caught |"
echo "|---|---|---:|"
idle=()
for check in oracle $all_properties fuzz:raster fuzz:differential; do
  pixels=no
  [[ $check == oracle || $check == fuzz:* || -n ${drawing[$check]:-} ]] && pixels=yes
  echo "| $check | $pixels | ${catches[$check]} |"
  ((catches[$check] > 0)) || idle+=("$check")
done

echo "plant_bugs: ${#selected[@]} planted, $((${#selected[@]} - ${#missed[@]} - ${#broken[@]})) caught by a check" \
     "that reads pixels, ${#correct_rc[@]} correct compares, ${#unclean[@]} unclean, in $(($(date +%s) - start)) s" >&2
status=0
if ((${#missed[@]})); then echo "plant_bugs: NOT CAUGHT: ${missed[*]}" >&2; status=1; fi
if ((${#unclean[@]})); then printf 'plant_bugs: correct build not clean: %s\n' "${unclean[@]}" >&2; status=1; fi
# A check that catches none of the bugs proves nothing; with --only the selection is too small to say.
if ((${#idle[@]} && ${#only[@]} == 0)); then
  echo "plant_bugs: checks that catch no bug: ${idle[*]}" >&2
  status=1
fi
((${#broken[@]} == 0)) || die "entries whose planted source does not build: ${broken[*]}"
exit "$status"
