// tinygltf's implementation, compiled here with raster's configuration (and, in the fuzz build, instrumented with
// the fuzzer's coverage and sanitizers) rather than linked from libtinygltf.so, which has a file system of its own.
// Its writer uses std::ofstream whether or not it has a file system (TINYGLTF_NO_FS leaves <fstream> out).
#include <fstream>

#define TINYGLTF_IMPLEMENTATION
#include "raster/gltf/tiny_gltf_config.h"
