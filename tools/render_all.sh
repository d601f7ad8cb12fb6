#!/usr/bin/env bash
# render_all.sh: renders every corpus scene and seed input, in many settings, with one `raster` binary into a folder,
# so that two builds (before and after a change that must not alter output) can be compared byte for byte:
#   tools/render_all.sh OLD/build/raster /tmp/before && tools/render_all.sh build/raster /tmp/after
#   tools/render_all.sh --compare /tmp/before /tmp/after     # exit 0 when every file is identical
# Each render writes its image (and depth image), its exit code and everything it printed except timings.
set -euo pipefail

if [[ ${1:-} == --compare ]]; then
  [[ $# -eq 3 ]] || { echo "usage: $0 --compare BEFORE_DIR AFTER_DIR" >&2; exit 2; }
  before=$2 after=$3
  differing=0 total=0
  while IFS= read -r -d '' file; do
    name=${file#"$before"/}
    total=$((total + 1))
    if [[ ! -f $after/$name ]]; then echo "missing after: $name"; differing=$((differing + 1))
    elif ! cmp -s "$file" "$after/$name"; then echo "differs: $name"; differing=$((differing + 1)); fi
  done < <(find "$before" -type f -print0 | sort -z)
  extra=$(cd "$after" && find . -type f | sed 's|^\./||' | while read -r f; do [[ -f $before/$f ]] || echo "$f"; done)
  [[ -z $extra ]] || { echo "only after:"; echo "$extra"; differing=$((differing + 1)); }
  echo "render_all: $total files compared, $differing differ"
  [[ $differing -eq 0 ]]
  exit
fi

[[ $# -eq 2 ]] || { echo "usage: $0 RASTER_BINARY OUT_DIR | --compare BEFORE_DIR AFTER_DIR" >&2; exit 2; }
raster=$(realpath "$1")
build_dir=$(dirname "$raster")
out=$(realpath -m "$2")
root=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$out"
mkdir -p "$out"
count=0

# run NAME ARGS...: runs raster with ARGS inside a scratch folder; keeps the files it wrote, its exit code and its
# output with the millisecond timings (which vary run to run) removed.
run() {
  local name=$1
  shift
  local dir=$out/$name
  mkdir -p "$dir"
  local rc=0
  (cd "$dir" && "$raster" "$@" >stdout.txt 2>stderr.txt) || rc=$?
  echo "$rc" >"$dir/exit_code.txt"
  sed -i -E 's/"ms_[a-z_]+":[-0-9.e+]+/"ms":_/g' "$dir/stdout.txt"
  sed -i "s|$build_dir/|BUILD/|g" "$dir/stdout.txt" "$dir/stderr.txt"  # the bench scenes' paths name the build
  count=$((count + 1))
}

scenes=("$root"/corpus/scenes/*.yaml "$root"/corpus/seeds/003/myscene.json "$root"/corpus/seeds/001/two_shapes.json
        "$root"/corpus/seeds/001/tetrahedron.json)
variants=(
  "default|"
  "ssaa4|--samples 4"
  "msaa4|--samples 4 --msaa"
  "ssaa16|--samples 16"
  "grid16msaa|--samples 16 --pattern grid --msaa"
  "alpha4|--samples 4 --alpha"
  "unlit|--shading unlit"
  "flat|--shading flat"
  "gouraud|--shading gouraud"
  "phong|--shading phong"
  "cull|--cull back"
  "snap2|--snap-bits 2"
  "snap16|--snap-bits 16 --samples 8"
  "edgesfloat|--edges float"
  "affine|--interpolation affine"
  "depthfloat|--depth-format float"
  "fixed24|--depth-format fixed24 --samples 4"
  "guardband|--clipping guard-band"
  "nohiz|--hierarchical-z off --samples 2"
  "threads1|--threads 1 --samples 4"
  "msaa16|--samples 16 --msaa"
  "cel|--shading cel"
  "gooch|--shading gooch --samples 4"
  "shadows|--shadows"
  "shadowsflat|--shadows --shading flat --samples 4"
  "shadowsgouraud16|--shadows --shading gouraud --samples 16 --msaa --shadow-resolution 256 --pcf 3"
  "weighted4|--transparency weighted --samples 4"
)
for scene in "${scenes[@]}"; do
  stem=$(basename "${scene%.*}")
  for variant in "${variants[@]}"; do
    tag=${variant%%|*}
    read -r -a flags <<<"${variant#*|}"
    run "$stem/$tag" render "$scene" -o image.png --depth-out depth.png --stats "${flags[@]}"
  done
  run "$stem/ppm" render "$scene" -o image.ppm
done

# The generated bench scenes (build/bench/scenes, made by tools/make_bench_meshes at build time), when present:
# fewer settings, as each is tens of thousands of triangles.
bench_variants=("default|" "ssaa4|--samples 4" "msaa4|--samples 4 --msaa" "msaa16|--samples 16 --msaa"
                "shadows|--shadows --shadow-resolution 512" "threads1|--threads 1")
for scene in "$build_dir"/bench/scenes/*.yaml; do
  [[ -f $scene ]] || continue
  stem=bench_$(basename "${scene%.*}")
  for variant in "${bench_variants[@]}"; do
    tag=${variant%%|*}
    read -r -a flags <<<"${variant#*|}"
    run "$stem/$tag" render "$scene" -o image.png --stats "${flags[@]}"
  done
done

# Seed 000: every config as its task asks (writes beside the config, so copy the folder first).
for config in "$root"/corpus/seeds/000/*.yaml; do
  name=$(basename "${config%.yaml}")
  mkdir -p "$out/seed000/$name"
  cp "$root"/corpus/seeds/000/* "$out/seed000/$name/"
  run "seed000/$name" render "$name.yaml"
done
# Seed 001: the document's four 2_1 command lines and the scene parts.
n=0
while read -r line; do
  n=$((n + 1))
  read -r -a words <<<"${line#./balboa }"
  run "seed001/2_1_$n" balboa "${words[@]}" -o image.png
done <"$root/corpus/seeds/001/hw_2_1_commands.txt"
for part in 2_2 2_3 2_4; do
  run "seed001/$part" balboa -hw "$part" "$root/corpus/seeds/001/two_shapes.json" -o image.png
done
# Seed 003: the shading switch.
for shading in flat gouraud phong; do
  run "seed003/$shading" render "$root/corpus/seeds/003/myscene.json" --shading "$shading" -o image.ppm
done
# Bad input: the error texts and exit codes.
run errors/missing render "$root/corpus/scenes/does_not_exist.yaml"
run errors/bad_samples render "$root/corpus/scenes/teapot.yaml" --samples 3
echo "render_all: $count runs into $out"
