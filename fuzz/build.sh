#!/usr/bin/env bash
# OSS-Fuzz / ClusterFuzzLite build script: every fuzz target built with $CXX, $CXXFLAGS and $LIB_FUZZING_ENGINE into $OUT.
#
# Beside each target NAME_fuzzer it writes NAME_seed_corpus.zip (corpus/fuzz/NAME and corpus/regressions/NAME),
# NAME.dict (text formats) and NAME.options. Build files go to $WORK/raster-fuzz-build ($WORK defaults to a fresh
# temporary folder). Locally, for example (.ci/run does this):
#   CXX=clang++-14 CXXFLAGS="-fsanitize=address,undefined,fuzzer-no-link" LIB_FUZZING_ENGINE=-fsanitize=fuzzer \
#   OUT=build-ossfuzz/out WORK=build-ossfuzz/work bash fuzz/build.sh
set -euo pipefail
: "${CXX:?set CXX}" "${LIB_FUZZING_ENGINE:?set LIB_FUZZING_ENGINE}" "${OUT:?set OUT}"
CXXFLAGS=${CXXFLAGS:-}
root=$(cd "$(dirname "$0")/.." && pwd)
work=${WORK:-$(mktemp -d)}
mkdir -p "$OUT" "$work"
OUT=$(cd "$OUT" && pwd)
build=$(cd "$work" && pwd)/raster-fuzz-build

# A build type of our own has no flags of its own: $CXXFLAGS alone decides optimisation and instrumentation.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=OssFuzz -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DRASTER_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" -DRASTER_BUILD_TESTS=OFF -DRASTER_BUILD_BENCH=OFF
cmake --build "$build" --target fuzzers -j"$(nproc)"

count=0
for binary in "$build"/fuzz/*_fuzzer; do
  target=$(basename "$binary")
  name=${target%_fuzzer}
  cp "$binary" "$OUT/$target"
  rm -f "$OUT/${target}_seed_corpus.zip"
  for folder in "$root/corpus/fuzz/$name" "$root/corpus/regressions/$name"; do
    # -j: flat file names, as a libFuzzer corpus is (a later folder's file replaces a same-named one).
    [[ -d $folder ]] && find "$folder" -type f -print0 | xargs -0 -r zip -q -j "$OUT/${target}_seed_corpus.zip"
  done
  [[ -f $root/fuzz/$name.dict ]] && cp "$root/fuzz/$name.dict" "$OUT/$target.dict"
  if [[ -f $root/fuzz/$name.options ]]; then
    # The dictionary beside the binary is named after it.
    sed "s/^dict = .*/dict = $target.dict/" "$root/fuzz/$name.options" >"$OUT/$target.options"
  fi
  count=$((count + 1))
done
echo "build.sh: $count fuzz targets in $OUT"
