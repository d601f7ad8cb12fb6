// The GL backend's GLSL (gl_shaders.h).
#include "backends/gl/gl_shaders.h"

#include <string>

namespace raster::gl {

const char* vertex_shader_source() {
    return R"GLSL(#version 450 core
layout(location = 0) in vec3 position;  // world
layout(location = 1) in vec3 normal;    // world, unit
layout(location = 2) in vec3 colour;    // linear RGB
uniform mat4 view_projection;
invariant gl_Position;  // both passes place every corner alike, so their depth tests pick the same triangles
out vec3 world_position;
out vec3 world_normal;
out vec3 base_colour;
void main() {
    world_position = position;
    world_normal = normal;
    base_colour = colour;
    gl_Position = view_projection * vec4(position, 1.0);
}
)GLSL";
}

const char* fragment_shader_source() {
    return R"GLSL(#version 450 core
// mode: 0 unlit, 1 Phong, 2 Blinn-Phong. Lights: type 0 point, 1 directional, 2 spot; radiance = intensity * colour.
const int MAX_LIGHTS = 8;
uniform int mode;
uniform vec3 ambient, diffuse, specular;  // the material's
uniform float exponent;
uniform vec3 ambient_light;
uniform vec3 eye;
uniform bool orthographic;
uniform vec3 back_direction;  // orthographic: normalize(eye - target), the view vector everywhere
uniform int light_count;
uniform int light_type[MAX_LIGHTS];
uniform vec3 light_position[MAX_LIGHTS];
uniform vec3 light_direction[MAX_LIGHTS];  // unit, where the light travels
uniform vec3 light_radiance[MAX_LIGHTS];
uniform bool light_attenuate[MAX_LIGHTS];
uniform vec2 light_spot[MAX_LIGHTS];  // the spot fade's scale and offset
in vec3 world_position;
in vec3 world_normal;
in vec3 base_colour;
layout(location = 0) out vec4 out_colour;
void main() {
    if (mode == 0) {
        out_colour = vec4(base_colour, 1.0);
        return;
    }
    vec3 n = normalize(world_normal);
    vec3 to_eye = orthographic ? back_direction : normalize(eye - world_position);
    vec3 lit = ambient * ambient_light;
    vec3 highlights = vec3(0.0);
    for (int i = 0; i < light_count; ++i) {
        vec3 to_light;
        float distance_squared = 1.0;
        if (light_type[i] == 1) {
            to_light = -light_direction[i];
        } else {
            vec3 d = light_position[i] - world_position;
            distance_squared = dot(d, d);
            if (!(distance_squared > 0.0)) continue;
            to_light = d / sqrt(distance_squared);
        }
        float n_dot_l = dot(n, to_light);
        if (!(n_dot_l > 0.0)) continue;
        vec3 radiance = light_radiance[i];
        if (light_type[i] == 2) {
            float fade = clamp(dot(light_direction[i], -to_light) * light_spot[i].x + light_spot[i].y, 0.0, 1.0);
            radiance *= fade * fade;
        }
        if (light_attenuate[i] && light_type[i] != 1) radiance /= distance_squared;
        float lobe;
        if (mode == 1) {
            lobe = dot(2.0 * n_dot_l * n - to_light, to_eye);
        } else {
            vec3 h = to_light + to_eye;
            float h_length = length(h);
            lobe = h_length > 0.0 ? dot(n, h) / h_length : 0.0;
        }
        float highlight = exponent == 0.0 ? 1.0 : pow(max(lobe, 0.0), exponent);
        lit += n_dot_l * diffuse * radiance;
        highlights += highlight * specular * radiance;
    }
    out_colour = vec4(base_colour * lit + highlights, 1.0);
}
)GLSL";
}

const char* visibility_vertex_shader_source() {
    return R"GLSL(#version 450 core
layout(location = 0) in vec3 position;  // world
uniform mat4 view_projection;
uniform vec3 eye;
uniform vec3 forward;  // the unit view direction: view depth is the distance along it
invariant gl_Position;
out float corner_depth;
void main() {
    corner_depth = dot(position - eye, forward);
    gl_Position = view_projection * vec4(position, 1.0);
}
)GLSL";
}

const char* clip_space_vertex_shader_source() {
    return R"GLSL(#version 450 core
layout(location = 0) in vec4 clip;
invariant gl_Position;
out float corner_depth;
void main() {
    corner_depth = 0.0;
    gl_Position = vec4(clip.x, -clip.y, clip.z, clip.w);
}
)GLSL";
}

const char* visibility_geometry_shader_source() {
    return R"GLSL(#version 450 core
// Hands every fragment the whole original triangle, before clipping: its corners' clip x, y and w, and their view
// depths. (llvmpipe divides a sample's perspective-correct inputs by the pixel centre's 1/w, docs/gl.md: the
// fragment shader solves for the barycentrics itself.)
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in float corner_depth[];
flat out mat3 corners;
flat out vec3 depths;
void main() {
    mat3 m = mat3(gl_in[0].gl_Position.xyw, gl_in[1].gl_Position.xyw, gl_in[2].gl_Position.xyw);
    for (int k = 0; k < 3; ++k) {
        corners = m;
        depths = vec3(corner_depth[0], corner_depth[1], corner_depth[2]);
        gl_PrimitiveID = gl_PrimitiveIDIn;
        gl_Position = gl_in[k].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
)GLSL";
}

const char* visibility_fragment_shader_source() {
    return R"GLSL(#version 450 core
uniform uint first_triangle;  // the draw's first scene triangle
uniform vec2 viewport;        // width, height in pixels
flat in mat3 corners;         // the original triangle's clip x, y, w, a column per corner
flat in vec3 depths;          // its corners' view depths
layout(location = 0) out uint triangle_id;
layout(location = 1) out vec4 sample_data;
void main() {
    // The sample's NDC point P (its pixel's corner plus its position in the pixel). The weights a with
    // sum_i a_i (x_i, y_i) = P sum_i a_i w_i are the null vector of the rows (x_i - P.x w_i) and (y_i - P.y w_i),
    // their cross product: differences before products, so that a sub-pixel triangle, whose corners nearly
    // coincide, keeps its weights, and no division by its vanishing determinant. Each corner is first scaled to its
    // largest component and its weight divided by that scale again (all of them by the same factor), so that corners
    // near the float limits do not overflow.
    vec2 ndc = 2.0 * (floor(gl_FragCoord.xy) + gl_SamplePosition) / viewport - 1.0;
    vec3 size = vec3(max(abs(corners[0].x), max(abs(corners[0].y), abs(corners[0].z))),
                     max(abs(corners[1].x), max(abs(corners[1].y), abs(corners[1].z))),
                     max(abs(corners[2].x), max(abs(corners[2].y), abs(corners[2].z))));
    mat3 unit = mat3(corners[0] / size.x, corners[1] / size.y, corners[2] / size.z);
    vec3 along_x = vec3(unit[0].x - ndc.x * unit[0].z, unit[1].x - ndc.x * unit[1].z, unit[2].x - ndc.x * unit[2].z);
    vec3 along_y = vec3(unit[0].y - ndc.y * unit[0].z, unit[1].y - ndc.y * unit[1].z, unit[2].y - ndc.y * unit[2].z);
    vec3 a = cross(along_x, along_y) * (min(size.x, min(size.y, size.z)) / size);  // a_i = a'_i / size_i, scaled
    float sum = a.x + a.y + a.z;
    vec3 bary = sum != 0.0 ? a / sum : vec3(1.0 / 3.0);  // 0: the sample sees the triangle's plane edge-on
    triangle_id = first_triangle + uint(gl_PrimitiveID);
    sample_data = vec4(bary, dot(bary, depths));
}
)GLSL";
}

std::string visibility_readback_source(bool multisampled) {
    std::string source = R"GLSL(#version 450 core
layout(local_size_x = 64) in;
uniform int width;
uniform int samples;
uniform int count;
layout(binding = 0) uniform usampler2D@MS@ ids;
layout(binding = 1) uniform sampler2D@MS@ data;
layout(std430, binding = 0) writeonly buffer Ids { uint out_ids[]; };
layout(std430, binding = 1) writeonly buffer Data { vec4 out_data[]; };
void main() {
    int i = int(gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u + gl_GlobalInvocationID.x);
    if (i >= count) return;
    int pixel = i / samples, s = i % samples;
    ivec2 xy = ivec2(pixel % width, pixel / width);
    out_ids[i] = texelFetch(ids, xy, s).r;  // one sample: s is 0, the level
    out_data[i] = texelFetch(data, xy, s);
}
)GLSL";
    for (size_t at = source.find("@MS@"); at != std::string::npos; at = source.find("@MS@"))
        source.replace(at, 4, multisampled ? "MS" : "");
    return source;
}

}  // namespace raster::gl
