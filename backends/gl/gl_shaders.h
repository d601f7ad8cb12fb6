// The GL backend's GLSL, written from docs/conventions.md "Lighting" and docs/scene-format.md's lights: a vertex
// shader that places world-space corners, a fragment shader for unlit, Phong and Blinn-Phong, and the visibility
// pass's shaders.
#pragma once

#include <string>

namespace raster::gl {

inline constexpr int kMaxShaderLights = 8;

const char* vertex_shader_source();
const char* fragment_shader_source();

// The visibility pass: per sample, the scene triangle id (first_triangle + gl_PrimitiveID) into an R32UI attachment
// and the original triangle's barycentrics and the view depth into an RGBA32F one, solved at each sample's position
// from the whole triangle (a geometry shader hands it over) rather than interpolated.
const char* visibility_vertex_shader_source();
// The same pass's vertex shader for triangles handed over in clip space (the GL plugin): each corner's position
// as given, y negated (the backend draws upside down); the view depth left 0, for the caller to derive.
const char* clip_space_vertex_shader_source();
const char* visibility_geometry_shader_source();
const char* visibility_fragment_shader_source();

// Copies both attachments, sample by sample, into two storage buffers in raster's sample order (row 0 the top);
// `multisampled` picks sampler2DMS over sampler2D.
std::string visibility_readback_source(bool multisampled);

}  // namespace raster::gl
