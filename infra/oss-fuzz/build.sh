#!/bin/bash -eu
# OSS-Fuzz's build script for raster (projects/raster/build.sh there). The engine runs it in the image's WORKDIR,
# raster's checkout, with its $CXX, $CXXFLAGS, $LIB_FUZZING_ENGINE, $OUT and $WORK; fuzz/build.sh does the work.
# tools/check_fuzz_build.sh runs it the same way here.
bash "$SRC/raster/fuzz/build.sh"
