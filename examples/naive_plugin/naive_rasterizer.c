/* naive_rasterizer.c: an example raster plugin (raster_plugin.h), deliberately the rasterizer a course starts from,
 * so that the framework has something to find in it (docs/plugins.md says what it finds):
 *  - a triangle with a vertex in front of the near plane (w below it) is dropped whole, not clipped, and nothing is
 *    clipped against the far plane or, in an orthographic frame, against either;
 *  - vertices are not snapped: edge functions are evaluated in float on the raw screen positions;
 *  - no fill rule: a sample exactly on an edge is inside (E >= 0), so a shared edge's samples go to both triangles
 *    and the z-buffer keeps whichever the depth test lets through;
 *  - barycentrics are the screen-space (affine) ones, without perspective correction.
 * It honours the sample positions, culling and the reversed-Z depth test, and keeps to defined C on any input
 * (non-finite and huge coordinates included). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <raster/raster_plugin.h>

typedef struct { float x, y, z; } ScreenVertex;

static float edge(ScreenVertex a, ScreenVertex b, float px, float py) {
    return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

static float clamp_to(float value, float low, float high) {
    return value > low ? (value < high ? value : high) : low; /* NaN goes to low */
}

RASTER_PLUGIN_EXPORT uint32_t raster_plugin_abi_version(void) { return RASTER_PLUGIN_ABI_VERSION; }

RASTER_PLUGIN_EXPORT const char* raster_plugin_name(void) { return "naive rasterizer (float edges, no fill rule)"; }

RASTER_PLUGIN_EXPORT int raster_plugin_draw(const raster_plugin_frame* frame, raster_plugin_samples* out) {
    const size_t count = (size_t)frame->width * (size_t)frame->height * (size_t)frame->samples;
    float* depth = malloc(count * sizeof(float));
    if (!depth) {
        snprintf(out->message, RASTER_PLUGIN_MESSAGE_SIZE, "out of memory for a %dx%d depth buffer", frame->width,
                 frame->height);
        return RASTER_PLUGIN_FAILED;
    }
    for (size_t i = 0; i < count; ++i) depth[i] = -1.0f; /* reversed Z: larger is nearer */

    for (uint32_t t = 0; t < frame->triangle_count; ++t) {
        const float* clip = frame->clip_positions + 12 * (size_t)t;
        ScreenVertex v[3];
        int behind = 0;
        for (int i = 0; i < 3; ++i) {
            const float x = clip[4 * i], y = clip[4 * i + 1], z = clip[4 * i + 2], w = clip[4 * i + 3];
            if (w <= 0.0f || (!frame->orthographic && w < frame->near_plane)) behind = 1;
            v[i].x = (x / w + 1.0f) * 0.5f * (float)frame->width;
            v[i].y = (1.0f - y / w) * 0.5f * (float)frame->height;
            v[i].z = z / w;
        }
        if (behind) continue;
        float area = edge(v[0], v[1], v[2].x, v[2].y);
        if (area == 0.0f || !isfinite(area)) continue; /* also every triangle with a non-finite vertex */
        /* Front faces are counter-clockwise with y up: clockwise on screen, negative area. */
        if (frame->cull_backfaces && area > 0.0f) continue;
        int corner[3] = {0, 1, 2}; /* which of the frame's a, b, c each of v is */
        if (area < 0.0f) {         /* wind it so that the inside is positive */
            const ScreenVertex swap = v[1];
            v[1] = v[2];
            v[2] = swap;
            corner[1] = 2;
            corner[2] = 1;
            area = -area;
        }
        /* The bounding box, clamped to the image in float: converting a float beyond int's range is undefined. */
        const int x0 = (int)clamp_to(floorf(fminf(v[0].x, fminf(v[1].x, v[2].x))), 0.0f, (float)(frame->width - 1));
        const int x1 = (int)clamp_to(ceilf(fmaxf(v[0].x, fmaxf(v[1].x, v[2].x))), -1.0f, (float)(frame->width - 1));
        const int y0 = (int)clamp_to(floorf(fminf(v[0].y, fminf(v[1].y, v[2].y))), 0.0f, (float)(frame->height - 1));
        const int y1 = (int)clamp_to(ceilf(fmaxf(v[0].y, fmaxf(v[1].y, v[2].y))), -1.0f, (float)(frame->height - 1));
        for (int py = y0; py <= y1; ++py)
            for (int px = x0; px <= x1; ++px)
                for (int s = 0; s < frame->samples; ++s) {
                    const float sx = (float)px + frame->sample_offsets[2 * s];
                    const float sy = (float)py + frame->sample_offsets[2 * s + 1];
                    const float e0 = edge(v[1], v[2], sx, sy), e1 = edge(v[2], v[0], sx, sy),
                                e2 = edge(v[0], v[1], sx, sy);
                    if (e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) continue;
                    const float l0 = e0 / area, l1 = e1 / area, l2 = e2 / area;
                    const float z = l0 * v[0].z + l1 * v[1].z + l2 * v[2].z;
                    const size_t i = ((size_t)py * (size_t)frame->width + (size_t)px) * (size_t)frame->samples + s;
                    if (!(z > depth[i])) continue;
                    depth[i] = z;
                    out->triangle[i] = t;
                    out->barycentrics[3 * i + corner[0]] = l0;
                    out->barycentrics[3 * i + corner[1]] = l1;
                    out->barycentrics[3 * i + corner[2]] = l2;
                }
    }
    out->barycentrics_written = 1;
    free(depth);
    return RASTER_PLUGIN_DRAWN;
}
