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
    // The sample's NDC (its pixel's corner plus its position in the pixel); the weights a with
    // corners * a proportional to (x, y, 1) are the homogeneous barycentrics, normalised to sum to 1.
    vec2 ndc = 2.0 * (floor(gl_FragCoord.xy) + gl_SamplePosition) / viewport - 1.0;
    vec3 a = inverse(corners) * vec3(ndc, 1.0);
    vec3 bary = a / (a.x + a.y + a.z);
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
