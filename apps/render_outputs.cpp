// The render job's outputs from the scene file's request and render's -o and --depth-out.
#include "apps/render_outputs.h"

namespace raster::cli {

OutputKind image_kind_for(const FileRequest& request) {
    return request.depth_image ? OutputKind::depth : OutputKind::colour;
}

RenderJob render_job_for(const std::filesystem::path& scene_path, const FileRequest& request,
                         const std::string& output, const std::string& depth_out) {
    std::filesystem::path image = output;
    if (image.empty()) image = request.output;
    if (image.empty()) image = scene_path.stem().string() + ".png";
    RenderJob job;
    job.outputs.push_back({image, image_kind_for(request)});
    if (!depth_out.empty()) job.outputs.push_back({depth_out, OutputKind::depth});
    return job;
}

}  // namespace raster::cli
