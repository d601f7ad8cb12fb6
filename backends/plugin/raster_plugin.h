/* raster_plugin.h: the C interface through which raster drives your own rasterizer, built as a shared library and
 * loaded with `--backend plugin:PATH` (docs/plugins.md). Installed as <raster/raster_plugin.h>.
 *
 * raster hands the plugin one frame: its triangles in clip space and the frame's conventions (image size, sample
 * positions, sub-pixel bits, culling, the view volume). The plugin answers with each sample's visible triangle and,
 * if it computes them, that sample's barycentrics. raster then shades and resolves those samples with its own
 * shading, writes the image `raster render` would write, and the Embree oracle judges every sample and pixel
 * (`raster compare --backend plugin:PATH`).
 *
 * Conventions (raster's docs/conventions.md):
 *  - Clip space is OpenGL's for x and y (visible where -w <= x, y <= w) with reversed-Z depth: z / w is 1 at the
 *    near plane and 0 at the far plane. A perspective camera's w is the view depth (the distance along the view
 *    direction); an orthographic camera's w is 1 and its view depth is far - (z / w) (far - near).
 *  - Screen space: x right, y DOWN, in pixels; NDC (-1, +1) is screen (0, 0), NDC (+1, -1) is (width, height).
 *    Pixel (x, y) covers [x, x + 1) x [y, y + 1).
 *  - Sample s of pixel (x, y) lies at (x + offset_x[s], y + offset_y[s]); its entry in the per-sample arrays is
 *    (y * width + x) * samples + s, rows from the top.
 *  - Front faces are counter-clockwise in NDC (y up), as OpenGL's default.
 *  - Barycentrics are perspective-correct, with respect to the triangle's three clip-space vertices as given
 *    (not to a clipped polygon's), and sum to 1 (raster stops the frame when they are not finite or their sum is
 *    off by more than 0.01: finer errors are the oracle's to judge).
 *  - Clip coordinates may be huge, infinite or NaN (the properties hand over triangles at the float limits): a
 *    plugin must draw nothing of a triangle it cannot handle rather than fail.
 *
 * Any change to these structs changes RASTER_PLUGIN_ABI_VERSION, and raster refuses a plugin of another version.
 *
 * A plugin exports the three functions below with C linkage. raster calls them from one thread at a time; a plugin
 * may use threads of its own inside raster_plugin_draw.
 */
#ifndef RASTER_PLUGIN_H
#define RASTER_PLUGIN_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The version of this interface. raster refuses a plugin whose raster_plugin_abi_version() differs. */
#define RASTER_PLUGIN_ABI_VERSION 1u

/* A sample no triangle covers. */
#define RASTER_PLUGIN_NO_TRIANGLE 0xFFFFFFFFu

/* The size of raster_plugin_samples.message, the terminating zero included. */
#define RASTER_PLUGIN_MESSAGE_SIZE 512

/* raster_plugin_draw's answers. */
#define RASTER_PLUGIN_DRAWN 0   /* every sample written */
#define RASTER_PLUGIN_REFUSED 1 /* the plugin does not draw this frame (message says why): raster exits 2 */
#define RASTER_PLUGIN_FAILED 2  /* the plugin failed (message says why) */

/* One frame, as raster asks for it. Every pointer is valid for the duration of the call only. */
typedef struct raster_plugin_frame {
    uint32_t abi_version;         /* RASTER_PLUGIN_ABI_VERSION */
    int32_t width, height;        /* pixels, each in [1, 16384] */
    int32_t samples;              /* per pixel, in [1, 64] */
    const float* sample_offsets;  /* 2 * samples floats: x then y of each sample, from the pixel's upper-left
                                     corner, in pixels */
    int32_t subpixel_bits;        /* the precision raster promises for this frame: vertices on a grid of
                                     1 / 2^subpixel_bits pixel (8 by default) */
    int32_t cull_backfaces;       /* 1: draw only front faces; 0: both */
    int32_t orthographic;         /* 1: an orthographic camera (w = 1) */
    float near_plane, far_plane;  /* the view volume's depths along the view direction */
    uint32_t triangle_count;
    const float* clip_positions;  /* 12 * triangle_count floats: each triangle's vertices a, b, c as x, y, z, w */
} raster_plugin_frame;

/* The plugin's answer, in arrays raster owns, each width * height * samples entries long. */
typedef struct raster_plugin_samples {
    uint32_t* triangle;           /* the visible triangle at each sample, an index into the frame's triangles
                                     (0 .. triangle_count - 1) or RASTER_PLUGIN_NO_TRIANGLE, with which raster
                                     fills it before the call */
    float* barycentrics;          /* 3 floats per sample, the weights of a, b and c at it, for the covered samples */
    int32_t barycentrics_written; /* set to 1 when barycentrics holds the plugin's own; left 0, raster solves them
                                     from the clip-space vertices at each covered sample's position */
    char* message;                /* RASTER_PLUGIN_MESSAGE_SIZE bytes for a refusal's or a failure's reason */
} raster_plugin_samples;

/* raster loads plugins with dlopen (POSIX): export with default visibility. */
#define RASTER_PLUGIN_EXPORT __attribute__((visibility("default")))

/* Returns RASTER_PLUGIN_ABI_VERSION as the plugin was compiled. */
RASTER_PLUGIN_EXPORT uint32_t raster_plugin_abi_version(void);

/* A short name for reports, e.g. "naive rasterizer 0.1". */
RASTER_PLUGIN_EXPORT const char* raster_plugin_name(void);

/* Draws the frame into out; returns RASTER_PLUGIN_DRAWN, _REFUSED or _FAILED. */
RASTER_PLUGIN_EXPORT int raster_plugin_draw(const raster_plugin_frame* frame, raster_plugin_samples* out);

#ifdef __cplusplus
}
#endif

#endif /* RASTER_PLUGIN_H */
