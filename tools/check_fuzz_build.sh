#!/usr/bin/env bash
# Runs infra/oss-fuzz/build.sh the way OSS-Fuzz's (and ClusterFuzzLite's) `compile` step does, then checks what it
# left in $OUT: for every fuzz/NAME_fuzzer.cpp the binary, NAME_fuzzer_seed_corpus.zip (every seed and regression
# input of corpus/fuzz/NAME and corpus/regressions/NAME), NAME_fuzzer.options, NAME_fuzzer.dict where fuzz/NAME.dict
# exists, its shared libraries in $OUT/lib (the engines' runner image has none of the build's packages), and that
# the binary runs its unzipped seed corpus once (-runs=0) and exits 0. Exits 1 naming each problem.
#
#   tools/check_fuzz_build.sh                       fresh temporary $OUT and $WORK, removed afterwards
#   OUT=DIR WORK=DIR tools/check_fuzz_build.sh      those folders, emptied first (the engine's are always fresh)
#                                                   and kept: .ci/run fuzzes the build left in $WORK
#   tools/check_fuzz_build.sh --check DIR           no build: checks DIR as $OUT (for instance the out/raster
#                                                   folder of OSS-Fuzz's `helper.py build_fuzzers`)
#
# The environment is the engine's for an AddressSanitizer build (CXX=clang++-14 here, where the engine has its own
# clang), including -stdlib=libc++, which fuzz/build.sh must cope with. RASTER_SANITIZER_FLAGS replaces the
# sanitizer part (.ci/run adds UndefinedBehaviorSanitizer). It needs no Docker, and does not try the engines'
# images: the packages there are fuzz/packages.txt, here .ci/install's.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

scratch=$(mktemp -d "${TMPDIR:-/tmp}/raster-check-fuzz-build-XXXXXX")
trap 'rm -rf "$scratch"' EXIT

if [[ ${1:-} == --check ]]; then
  OUT=$(cd "${2:?usage: tools/check_fuzz_build.sh --check DIR}" && pwd)
else
  fresh_folder() {  # fresh_folder PATH: PATH emptied (made when missing), printed absolute
    rm -rf "${1:?}" && mkdir -p "$1" && (cd "$1" && pwd)
  }
  OUT=$(fresh_folder "${OUT:-$scratch/out}")
  WORK=$(fresh_folder "${WORK:-$scratch/work}")

  # The image's layout: the checkout at $SRC/raster (its WORKDIR), the project's build.sh copied to $SRC.
  SRC=$scratch/src
  mkdir -p "$SRC"
  ln -s "$root" "$SRC/raster"
  cp "$root/infra/oss-fuzz/build.sh" "$SRC/build.sh"

  sanitizer_flags=${RASTER_SANITIZER_FLAGS:--fsanitize=address -fsanitize-address-use-after-scope}
  common_flags="-O1 -fno-omit-frame-pointer -gline-tables-only -DFUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION"
  echo "check_fuzz_build: building into $OUT (build files in $WORK)"
  (
    cd "$SRC/raster"
    env SRC="$SRC" OUT="$OUT" WORK="$WORK" CC=clang-14 CXX=clang++-14 \
      CFLAGS="$common_flags $sanitizer_flags -fsanitize=fuzzer-no-link" \
      CXXFLAGS="$common_flags $sanitizer_flags -fsanitize=fuzzer-no-link -stdlib=libc++" \
      LIB_FUZZING_ENGINE=-fsanitize=fuzzer FUZZING_ENGINE=libfuzzer SANITIZER=address ARCHITECTURE=x86_64 \
      FUZZING_LANGUAGE=c++ bash -eu "$SRC/build.sh"
  )
fi

problems=0
problem() {
  echo "check_fuzz_build: $*" >&2
  problems=$((problems + 1))
}

# check_libraries TARGET: every shared library the binary loads, beyond the C and C++ runtime, comes from $OUT/lib.
check_libraries() {
  local target=$1 library path
  while read -r library path; do
    [[ $path == "$OUT/lib/"* ]] || problem "$target: loads $library from $path, outside \$OUT/lib"
  done < <(ldd "$OUT/$target" | awk '$2 == "=>" { print $1, $3 }' |
    grep -Ev '^(libc|libm|libdl|librt|libpthread|libgcc_s|libstdc\+\+)\.so' || true)
}

# check_corpus NAME TARGET: the zip holds one entry per distinct file name of the seed and regression folders (as
# a libFuzzer corpus is flat), and the binary runs all of them once and exits 0.
check_corpus() {
  local name=$1 target=$2 zip=$OUT/$2_seed_corpus.zip folders=() expected
  for folder in "$root/corpus/fuzz/$name" "$root/corpus/regressions/$name"; do
    [[ -d $folder ]] && folders+=("$folder")
  done
  if ((${#folders[@]} == 0)); then
    [[ ! -e $zip ]] || problem "$target: a seed corpus zip, but no corpus/fuzz/$name"
    return
  fi
  [[ -s $zip ]] || { problem "$target: no ${target}_seed_corpus.zip, though corpus/fuzz/$name exists"; return; }
  expected=$(find "${folders[@]}" -type f -printf '%f\n' | sort -u | wc -l)
  local unzipped=$scratch/corpus/$name
  mkdir -p "$unzipped"
  if ! unzip -q "$zip" -d "$unzipped" 2>"$scratch/unzip.err"; then
    problem "$target: $(basename "$zip") is not a zip"
    return
  fi
  local found
  found=$(find "$unzipped" -type f | wc -l)
  ((found == expected && found > 0)) || problem "$target: $found inputs in the seed corpus zip, $expected expected"
  if ! "$OUT/$target" -runs=0 "$unzipped" >"$scratch/$target.log" 2>&1; then
    problem "$target: running its seed corpus failed; the end of its output:"
    tail -20 "$scratch/$target.log" >&2
  else
    echo "check_fuzz_build: $target: $found seed inputs run"
  fi
}

sources=("$root"/fuzz/*_fuzzer.cpp)
for source in "${sources[@]}"; do
  target=$(basename "$source" .cpp)
  name=${target%_fuzzer}
  if [[ ! -x $OUT/$target ]]; then
    problem "$target: no binary in \$OUT"
    continue
  fi
  [[ -f $OUT/$target.options ]] || problem "$target: no $target.options"
  if [[ -f $root/fuzz/$name.dict ]]; then
    [[ -s $OUT/$target.dict ]] || problem "$target: no $target.dict, though fuzz/$name.dict exists"
    grep -qx "dict = $target.dict" "$OUT/$target.options" 2>/dev/null ||
      problem "$target: $target.options does not name $target.dict"
  fi
  check_libraries "$target"
  check_corpus "$name" "$target"
done
binaries=$(find "$OUT" -maxdepth 1 -type f -name '*_fuzzer' | wc -l)
((binaries == ${#sources[@]})) || problem "$binaries binaries in \$OUT for ${#sources[@]} fuzz/*_fuzzer.cpp"

if ((problems > 0)); then
  echo "check_fuzz_build: FAILED: $problems problems" >&2
  exit 1
fi
echo "check_fuzz_build: ${#sources[@]} targets built and checked in $OUT"
