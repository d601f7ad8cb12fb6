#!/usr/bin/env bash
# OSS-Fuzz / ClusterFuzzLite build script: every fuzz target built with $CXX, $CXXFLAGS and $LIB_FUZZING_ENGINE into $OUT.
#
# Beside each target NAME_fuzzer it writes NAME_fuzzer_seed_corpus.zip (corpus/fuzz/NAME and corpus/regressions/NAME),
# NAME_fuzzer.dict (text formats) and NAME_fuzzer.options, and the shared libraries the targets link go to $OUT/lib.
# Build files go to $WORK/raster-fuzz-build ($WORK defaults to a fresh temporary folder). infra/oss-fuzz/build.sh
# and .clusterfuzzlite/build.sh call it; tools/check_fuzz_build.sh runs it as those engines do and checks $OUT
# (.ci/run does that), or by hand, for example:
#   CXX=clang++-14 CXXFLAGS="-fsanitize=address,undefined,fuzzer-no-link" LIB_FUZZING_ENGINE=-fsanitize=fuzzer \
#   OUT=build-ossfuzz/out WORK=build-ossfuzz/work bash fuzz/build.sh
set -euo pipefail
: "${CXX:?set CXX}" "${LIB_FUZZING_ENGINE:?set LIB_FUZZING_ENGINE}" "${OUT:?set OUT}"
CXXFLAGS=${CXXFLAGS:-}
# OSS-Fuzz and ClusterFuzzLite add -stdlib=libc++ for C++ projects, but Debian's and Ubuntu's yaml-cpp is built
# against libstdc++, whose std::string it takes: linking both would leave its symbols unresolved.
CXXFLAGS=${CXXFLAGS//-stdlib=libc++/}
root=$(cd "$(dirname "$0")/.." && pwd)
work=${WORK:-$(mktemp -d)}
mkdir -p "$OUT" "$work"
OUT=$(cd "$OUT" && pwd)
build=$(cd "$work" && pwd)/raster-fuzz-build

# A build type of our own has no flags of its own: $CXXFLAGS alone decides optimisation and instrumentation.
# The engines run $OUT in an image without the packages the build installed, so the binaries look for their shared
# libraries in $OUT/lib first; an RPATH rather than a RUNPATH (--disable-new-dtags), because only an RPATH also
# serves the libraries' own dependencies (Embree's TBB).
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=OssFuzz -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DCMAKE_BUILD_RPATH='$ORIGIN/lib' -DCMAKE_EXE_LINKER_FLAGS=-Wl,--disable-new-dtags \
  -DRASTER_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" -DRASTER_BUILD_TESTS=OFF -DRASTER_BUILD_BENCH=OFF
cmake --build "$build" --target fuzzers -j"$(nproc)"

# The shared libraries a binary links that are not the C and C++ runtime every image has, one path a line.
bundled_libraries_of() {
  ldd "$1" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' |
    grep -Ev '/(libc|libm|libdl|librt|libpthread|libgcc_s|libstdc\+\+|ld-linux[^/]*)\.so[^/]*$' || true
}

mkdir -p "$OUT/lib"
count=0
for binary in "$build"/fuzz/*_fuzzer; do
  target=$(basename "$binary")
  name=${target%_fuzzer}
  cp "$binary" "$OUT/$target"
  bundled_libraries_of "$binary" | while read -r library; do cp -L "$library" "$OUT/lib/"; done
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
