#!/bin/bash -eu
# ClusterFuzzLite's build script for raster. The engine runs it in the image's WORKDIR, the copied checkout, with
# its $CXX, $CXXFLAGS, $LIB_FUZZING_ENGINE, $OUT and $WORK; fuzz/build.sh does the work, as it does for OSS-Fuzz.
bash "$SRC/raster/fuzz/build.sh"
