#pragma once
// Z-buffered rendering of textured quads into a camera with optional Brown-Conrady
// distortion: exact per-pixel ray/plane intersection (no tessellation), trilinear-free
// mip-mapped bilinear texture lookup, one pass for visibility and one for colour.

#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"
#include "synth/scene.h"

namespace dynvo {

struct RenderResult {
  cv::Mat bgr;        // CV_8UC3, black where nothing is seen
  cv::Mat depth;      // CV_32F, metres along the optical axis (z), 0 where nothing is seen
  cv::Mat object_id;  // CV_16U, object_id of the visible quad, 0 for static scene or nothing
};

class Renderer {
 public:
  // Precomputes one viewing ray per pixel (undistorted through the camera's distortion).
  // Throws InputError when the camera is invalid.
  explicit Renderer(const Camera& camera);

  // The quads as seen from `camera_from_world`: each pixel shows the nearest quad whose
  // plane its ray hits inside the quad (with texture alpha >= 0.5 for BGRA textures).
  RenderResult Render(const std::vector<TexturedQuad>& quads, const Pose& camera_from_world) const;

  // Rows [row_begin, row_end) of Render(quads, camera_from_world), byte-identical to it, written
  // into `result` (allocated image-sized with nothing seen when it is not image-sized); its other
  // rows are left as they are. Costs about that share of a full render (the raster box is
  // clipped to the rows), plus a small per-quad setup. Throws InputError on a bad row range.
  void RenderRows(const std::vector<TexturedQuad>& quads, const Pose& camera_from_world, int row_begin, int row_end,
                  RenderResult* result) const;

  // The pixel (with distortion) of a point in camera coordinates (z > 0 expected).
  Eigen::Vector2d ProjectPoint(const Eigen::Vector3d& point_in_camera) const;

  const Camera& camera() const { return camera_; }

 private:
  // Per pixel of image rows [row_begin, row_begin + zbuf.rows): the nearest depth so far, the
  // quad drawn there (-1 = none), its texture coordinates.
  struct RasterBuffers {
    int row_begin = 0;            // image row of the buffers' first row
    double y_min = 0, y_max = 0;  // bounds of the rows' rays' y/z, with margin: quads are clipped to them
    cv::Mat zbuf, index, coords;  // CV_32F, CV_32S, CV_32FC2
  };
  // The pixel box (clipped to the image, with a margin) of a polygon in camera coordinates;
  // false when it is empty.
  bool ScreenBox(const std::vector<Eigen::Vector3d>& polygon, cv::Rect* box) const;
  // Draws one quad into the buffers' rows where it is nearer; `normal` gets its camera-frame normal.
  void RasteriseQuad(const TexturedQuad& quad, int quad_index, const Pose& camera_from_world, RasterBuffers* buffers,
                     Eigen::Vector3d* normal) const;
  // Writes the colour (mip-mapped, bilinear), depth and object id of the buffers' rows into
  // those rows of `result` (image-sized), nothing seen where no quad was drawn.
  void Shade(const std::vector<TexturedQuad>& quads, const RasterBuffers& buffers,
             const std::vector<Eigen::Vector3d>& normals, RenderResult* result) const;

  Camera camera_;
  cv::Mat rays_;                               // CV_32FC2: normalised (x/z, y/z) of each pixel's ray
  double x_min_ = 0, x_max_ = 0;               // bounds of the rays' x/z, with margin
  std::vector<double> row_y_min_, row_y_max_;  // per row: the least and greatest ray y/z
};

}  // namespace dynvo
