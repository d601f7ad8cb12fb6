#!/usr/bin/env bash
# check_debian_package.sh BUILD: packs BUILD with CPack into a .deb, installs it with apt-get (sudo when not root),
# checks that the installed raster prints its version and renders /usr/share/raster/examples/scenes/teapot.yaml
# from a scratch folder to a PNG, that the installed example plugin's source builds against the installed
# <raster/raster_plugin.h> and that the oracle finds its bugs in the installed teapot (docs/plugins.md), then removes
# the package. Exit 0 when all of it works, 1 otherwise.
set -euo pipefail
build=${1:?usage: tools/check_debian_package.sh BUILD}
build=$(cd "$build" && pwd)
sudo=""
[[ $(id -u) -eq 0 ]] || sudo="sudo"
if dpkg -s raster > /dev/null 2>&1; then
  echo "check_debian_package: a raster package is already installed; remove it first (apt-get remove raster)" >&2
  exit 1
fi
scratch=$(mktemp -d)
trap '$sudo apt-get remove -y -qq raster > /dev/null 2>&1 || true; rm -rf "$scratch"' EXIT
(cd "$scratch" && cpack --config "$build/CPackConfig.cmake" -G DEB > cpack.log 2>&1) || {
  cat "$scratch/cpack.log" >&2
  exit 1
}
deb=$(ls "$scratch"/raster_*.deb)
echo "check_debian_package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB"
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$deb" > "$scratch/apt.log" 2>&1 || {
  cat "$scratch/apt.log" >&2
  exit 1
}
/usr/bin/raster --version
(cd "$scratch" && /usr/bin/raster render /usr/share/raster/examples/scenes/teapot.yaml -o teapot.png)
if [[ ! -s "$scratch/teapot.png" ]] || [[ "$(head -c 8 "$scratch/teapot.png" | od -An -tx1 | tr -d ' \n')" != 89504e470d0a1a0a ]]; then
  echo "check_debian_package: the installed raster wrote no PNG" >&2
  exit 1
fi
# A plugin built as a user would, against the installed header only.
cc -shared -fPIC -O2 /usr/share/raster/examples/plugin/naive_rasterizer.c -o "$scratch/libmine.so" -lm
status=0
(cd "$scratch" && /usr/bin/raster compare /usr/share/raster/examples/scenes/teapot.yaml --backend plugin:./libmine.so \
  > compare.txt 2>&1) || status=$?
if [[ $status -ne 1 ]] || ! grep -q "plugin naive rasterizer" "$scratch/compare.txt"; then
  echo "check_debian_package: raster compare of the installed example plugin exited $status, not 1 (its bugs found):" >&2
  cat "$scratch/compare.txt" >&2
  exit 1
fi
echo "check_debian_package: installed, rendered the teapot, built the example plugin and found its bugs, removed"
