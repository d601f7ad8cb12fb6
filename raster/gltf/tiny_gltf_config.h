// tinygltf as raster uses it: every file that includes tiny_gltf.h includes it here, so all see one configuration.
// No file system of its own (every external file comes through our callbacks, gltf_model.h), no image decoding
// (images stay encoded; raster and the oracle decode them each on their own), no image writing.
#pragma once

#define TINYGLTF_NO_FS
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>
