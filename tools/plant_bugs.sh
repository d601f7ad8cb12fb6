#!/usr/bin/env bash
# plant_bugs.sh: writes each bug of mutants/planted/bugs.txt into a scratch copy of raster's source, rebuilds the
# real `raster` and requires `raster compare` to find genuine disagreements that the correct build does not find.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: tools/plant_bugs.sh [--list] [--only NAME]... [--catalogue FILE] [--keep] [--jobs N] [--help]

Copies the tracked source tree (git ls-files) into a scratch folder, builds `raster` there (Release, tests, bench
and fuzzers off) and runs the correct `raster compare SCENE FLAGS` of every selected entry (each must exit 0).
Then, one bug at a time: checks that the entry's find text occurs exactly once in its file, applies the
replacement, rebuilds `raster` incrementally, runs `raster compare SCENE FLAGS --json`, requires exit 1 with
genuine_total > 0, and restores the file. The worktree itself is never modified.

Progress goes to stderr; stdout gets a Markdown table (bug, scene and flags, genuine count, the classes that
caught it). For a bug compare misses, the runner renders the scene with both builds and says whether raster's
PNG and PPM bytes changed at all.

  --list            print the catalogue's entries (name: bug) and exit
  --only NAME       run only this entry (repeatable)
  --catalogue FILE  the catalogue to run (default mutants/planted/bugs.txt)
  --keep            keep the scratch folder (its path is printed): src/ (restored), build/ (its raster is the last
                    bug's), raster-correct, runs/NAME.json and .txt (compare's output), logs/ (configure, builds)
  --jobs N          build jobs (default 2)
  --help            this text

Exit codes: 0 every bug caught and every correct run clean; 1 a bug not caught or a correct run not clean (both
named); 2 bad usage, a stale or malformed entry, or a build that fails.
EOF
}

die_usage() { echo "plant_bugs: $*" >&2; echo "run tools/plant_bugs.sh --help for the options" >&2; exit 2; }
die() { echo "plant_bugs: $*" >&2; exit 2; }

root=$(cd "$(dirname "$0")/.." && pwd)
catalogue=$root/mutants/planted/bugs.txt
only=()
keep=0 list=0 jobs=2
while (($#)); do
  case $1 in
    --help|-h) usage; exit 0 ;;
    --list) list=1 ;;
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

keys=(bug file find replace scene flags)
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

if ((list)); then
  for name in "${selected[@]}"; do echo "$name: ${entry[$name.bug]}"; done
  exit 0
fi

# Every entry is checked against the worktree before anything is built, so a stale catalogue fails in seconds.
for name in "${selected[@]}"; do check_fresh "$name" "$root"; done
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

# build LOG: builds the raster target incrementally in $build; prints its seconds; returns the build's status.
build() {
  local log=$1 begin rc=0
  begin=$(date +%s)
  cmake --build "$build" -j "$jobs" --target raster >"$log" 2>&1 || rc=$?
  echo $(($(date +%s) - begin))
  return "$rc"
}

echo "plant_bugs: building the correct raster in $build" >&2
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRASTER_BUILD_TESTS=OFF -DRASTER_BUILD_BENCH=OFF \
  -DRASTER_BUILD_FUZZERS=OFF >"$logs/configure.log" 2>&1 ||
  { tail -n 30 "$logs/configure.log" >&2; die "configuring the scratch copy failed (log above)"; }
seconds=$(build "$logs/build-correct.log") ||
  { tail -n 30 "$logs/build-correct.log" >&2; die "the correct raster does not build (log above)"; }
cp "$build/raster" "$scratch/raster-correct"
echo "plant_bugs: correct raster built in $seconds s" >&2

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
  counts=$(sed -n -E '/^  "genuine": \{/,/^  \}/s/^    "([a-z]+)": ([0-9]+),?$/\2 \1/p' "$json" | sort -rn -k1,1 -s)
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
    rows+=("| $name | $(describe "$name") | - | does not build |")
  else
    compare_start=$(date +%s)
    run_compare "$build/raster" "$name" "${entry[$name.scene]}" "${entry[$name.flags]}"
    compare_seconds=$(($(date +%s) - compare_start))
    if [[ $rc -eq 1 && ${genuine_total:-0} -gt 0 ]]; then
      outcome="caught: genuine $genuine_total ($caught_by)"
      rows+=("| $name | $(describe "$name") | $genuine_total | $caught_by |")
    else
      output=$(same_output "${entry[$name.scene]}" "${entry[$name.flags]}")
      outcome="NOT CAUGHT: compare exit $rc, genuine ${genuine_total:-none}; raster's output: $output"
      missed+=("$name")
      rows+=("| $name | $(describe "$name") | ${genuine_total:-none} | NOT CAUGHT (exit $rc; $output) |")
    fi
    echo "plant_bugs: [$index/${#selected[@]}] $name: build $seconds s, compare $compare_seconds s: $outcome" >&2
  fi
  printf '%s' "$original" >"$file"  # a fresh mtime, so the next build recompiles it from the real source
done

echo "| bug | scene and flags | genuine | caught by |"
echo "|---|---|---|---|"
printf '%s\n' "${rows[@]}"

echo "plant_bugs: ${#selected[@]} planted, $((${#selected[@]} - ${#missed[@]} - ${#broken[@]})) caught," \
     "${#correct_rc[@]} correct runs, ${#unclean[@]} not clean, in $(($(date +%s) - start)) s" >&2
status=0
if ((${#missed[@]})); then echo "plant_bugs: NOT CAUGHT: ${missed[*]}" >&2; status=1; fi
if ((${#unclean[@]})); then printf 'plant_bugs: correct raster not clean on: %s\n' "${unclean[@]}" >&2; status=1; fi
((${#broken[@]} == 0)) || die "entries whose planted source does not build: ${broken[*]}"
exit "$status"
