// The GL backend's GLSL, written from docs/conventions.md "Lighting" and docs/scene-format.md's lights: a vertex
// shader that places world-space corners, and a fragment shader for unlit, Phong and Blinn-Phong.
#pragma once

namespace raster::gl {

inline constexpr int kMaxShaderLights = 8;

const char* vertex_shader_source();
const char* fragment_shader_source();

}  // namespace raster::gl
