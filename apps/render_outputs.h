// The files `raster render` writes for a scene file and its flags: the one render job both `raster render` and
// `raster compare` (which judges what render writes) build.
#pragma once

#include <filesystem>
#include <string>

#include "raster/compat/scene_loader.h"
#include "raster/frame/render_job.h"

namespace raster::cli {

// The kind of image `raster render` writes first for a file: its depth image when the file asks for it (seed 000's
// shading-depth task), else its colour image. raster compare and raster report judge that kind.
OutputKind image_kind_for(const FileRequest& request);

// The image to `output` (default: the file's own output name, else the scene file's stem + ".png" in the current
// directory), the colour image unless the file asks for its depth image; then, with a `depth_out`, the depth
// image there. The job's options are left at their defaults.
RenderJob render_job_for(const std::filesystem::path& scene_path, const FileRequest& request,
                         const std::string& output, const std::string& depth_out);

}  // namespace raster::cli
