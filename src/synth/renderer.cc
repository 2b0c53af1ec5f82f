#include "synth/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Dense>
#include <opencv2/calib3d.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

constexpr double kNear = 0.05;  // metres: nothing nearer is drawn

using Polygon = std::vector<Eigen::Vector3d>;

// Keeps the part of the polygon where plane(p) = n.p + d >= 0 (Sutherland-Hodgman).
Polygon ClipPolygon(const Polygon& in, const Eigen::Vector3d& n, double d) {
  Polygon out;
  const size_t count = in.size();
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d& a = in[i];
    const Eigen::Vector3d& b = in[(i + 1) % count];
    const double da = n.dot(a) + d, db = n.dot(b) + d;
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// Metres the quad's surface stands out toward the camera at texture coordinates `ab`.
float ReliefAt(const TexturedQuad& quad, const cv::Vec2f& ab) {
  const cv::Mat& relief = quad.texture->relief;
  if (quad.relief_m <= 0 || relief.empty()) return 0.0f;
  const int tx = std::min(relief.cols - 1, static_cast<int>(ab[0] * relief.cols));
  const int ty = std::min(relief.rows - 1, static_cast<int>(ab[1] * relief.rows));
  return static_cast<float>(quad.relief_m) * relief.at<float>(ty, tx);
}

// The colour of texture image `img` at texture coordinates `uv` in [0, 1), bilinear, times `shade`.
cv::Vec3b SampleBilinear(const cv::Mat& img, const cv::Vec2f& uv, float shade) {
  const float fu = std::clamp(uv[0] * img.cols - 0.5f, 0.0f, img.cols - 1.001f);
  const float fv = std::clamp(uv[1] * img.rows - 0.5f, 0.0f, img.rows - 1.001f);
  const int iu = static_cast<int>(fu), iv = static_cast<int>(fv);
  const float du = fu - iu, dv = fv - iv;
  const int cn = img.channels();
  const uchar* r0 = img.ptr<uchar>(iv) + iu * cn;
  const uchar* r1 = img.ptr<uchar>(std::min(iv + 1, img.rows - 1)) + iu * cn;
  const int step = iu + 1 < img.cols ? cn : 0;
  cv::Vec3b out;
  for (int c = 0; c < 3; ++c) {
    const float top = r0[c] + du * (r0[c + step] - r0[c]);
    const float bottom = r1[c] + du * (r1[c + step] - r1[c]);
    out[c] = cv::saturate_cast<uchar>((top + dv * (bottom - top)) * shade);
  }
  return out;
}

// Whether the result's three images are `w` x `h` with RenderResult's types.
bool HoldsImage(const RenderResult& result, int w, int h) {
  const cv::Size size(w, h);
  return result.bgr.size() == size && result.bgr.type() == CV_8UC3 && result.depth.size() == size &&
         result.depth.type() == CV_32F && result.object_id.size() == size && result.object_id.type() == CV_16U;
}

}  // namespace

Renderer::Renderer(const Camera& camera) : camera_(camera) {
  camera_.Check("renderer camera");
  const int w = camera_.width, h = camera_.height;
  rays_.create(h, w, CV_32FC2);
  if (!camera_.HasDistortion()) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        rays_.at<cv::Vec2f>(y, x) = cv::Vec2f(static_cast<float>((x - camera_.cx) / camera_.fx),
                                              static_cast<float>((y - camera_.cy) / camera_.fy));
  } else {
    std::vector<cv::Point2f> pixels;
    pixels.reserve(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) pixels.emplace_back(static_cast<float>(x), static_cast<float>(y));
    std::vector<cv::Point2f> normalised;
    cv::undistortPoints(pixels, normalised, camera_.K(), camera_.DistCoeffs(), cv::noArray(), cv::noArray(),
                        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-10));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const cv::Point2f& p = normalised[static_cast<size_t>(y) * w + x];
        rays_.at<cv::Vec2f>(y, x) = cv::Vec2f(p.x, p.y);
      }
  }
  double x_lo = 1e9, x_hi = -1e9;
  row_y_min_.assign(static_cast<size_t>(h), 1e9);
  row_y_max_.assign(static_cast<size_t>(h), -1e9);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const cv::Vec2f& ray = rays_.at<cv::Vec2f>(y, x);
      x_lo = std::min(x_lo, static_cast<double>(ray[0]));
      x_hi = std::max(x_hi, static_cast<double>(ray[0]));
      row_y_min_[static_cast<size_t>(y)] = std::min(row_y_min_[static_cast<size_t>(y)], static_cast<double>(ray[1]));
      row_y_max_[static_cast<size_t>(y)] = std::max(row_y_max_[static_cast<size_t>(y)], static_cast<double>(ray[1]));
    }
  x_min_ = x_lo - 0.05 * (x_hi - x_lo);
  x_max_ = x_hi + 0.05 * (x_hi - x_lo);
}

Eigen::Vector2d Renderer::ProjectPoint(const Eigen::Vector3d& p) const {
  const double x = p.x() / p.z(), y = p.y() / p.z();
  const auto& k = camera_.distortion;  // k1 k2 p1 p2 k3, OpenCV's model
  const double r2 = x * x + y * y;
  const double radial = 1 + k[0] * r2 + k[1] * r2 * r2 + k[4] * r2 * r2 * r2;
  const double xd = x * radial + 2 * k[2] * x * y + k[3] * (r2 + 2 * x * x);
  const double yd = y * radial + k[2] * (r2 + 2 * y * y) + 2 * k[3] * x * y;
  return {camera_.fx * xd + camera_.cx, camera_.fy * yd + camera_.cy};
}

bool Renderer::ScreenBox(const std::vector<Eigen::Vector3d>& polygon, cv::Rect* box) const {
  const bool distorted = camera_.HasDistortion();
  double bx0 = 1e18, by0 = 1e18, bx1 = -1e18, by1 = -1e18;
  const int samples = distorted ? 8 : 1;
  for (size_t i = 0; i < polygon.size(); ++i)
    for (int s = 0; s < samples; ++s) {
      const Eigen::Vector3d p = polygon[i] + (polygon[(i + 1) % polygon.size()] - polygon[i]) * (double(s) / samples);
      const Eigen::Vector2d px = distorted ? ProjectPoint(p) : camera_.Project(p);
      bx0 = std::min(bx0, px.x());
      by0 = std::min(by0, px.y());
      bx1 = std::max(bx1, px.x());
      by1 = std::max(by1, px.y());
    }
  const int margin = distorted ? 3 : 1;
  const int x0 = std::max(0, static_cast<int>(std::floor(bx0)) - margin);
  const int y0 = std::max(0, static_cast<int>(std::floor(by0)) - margin);
  const int x1 = std::min(camera_.width - 1, static_cast<int>(std::ceil(bx1)) + margin);
  const int y1 = std::min(camera_.height - 1, static_cast<int>(std::ceil(by1)) + margin);
  if (x0 > x1 || y0 > y1) return false;
  *box = cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1);
  return true;
}

void Renderer::RasteriseQuad(const TexturedQuad& quad, int quad_index, const Pose& camera_from_world,
                             RasterBuffers* buffers, Eigen::Vector3d* normal) const {
  if (!quad.texture || quad.texture->levels.empty()) return;
  const Eigen::Matrix3d rot = camera_from_world.linear();
  const Eigen::Vector3d p0 = camera_from_world * quad.origin;
  const Eigen::Vector3d u = rot * quad.edge_u, v = rot * quad.edge_v;
  *normal = u.cross(v).normalized();
  Polygon poly = {p0, p0 + u, p0 + u + v, p0 + v};
  poly = ClipPolygon(poly, Eigen::Vector3d(0, 0, 1), -kNear);
  if (poly.size() >= 3) poly = ClipPolygon(poly, Eigen::Vector3d(0, 1, -buffers->y_min), 0);
  if (poly.size() >= 3) poly = ClipPolygon(poly, Eigen::Vector3d(0, -1, buffers->y_max), 0);
  if (poly.size() >= 3) poly = ClipPolygon(poly, Eigen::Vector3d(1, 0, -x_min_), 0);
  if (poly.size() >= 3) poly = ClipPolygon(poly, Eigen::Vector3d(-1, 0, x_max_), 0);
  cv::Rect box;
  if (poly.size() < 3 || !ScreenBox(poly, &box)) return;
  box &= cv::Rect(0, buffers->row_begin, camera_.width, buffers->zbuf.rows);  // only the buffers' rows
  if (box.empty()) return;
  Eigen::Matrix3d a;
  a.col(0) = u;
  a.col(1) = v;
  a.col(2) = p0;
  if (std::abs(a.determinant()) < 1e-12) return;  // seen exactly edge-on
  const Eigen::Matrix3d m = a.inverse();
  const float m00 = float(m(0, 0)), m01 = float(m(0, 1)), m02 = float(m(0, 2));
  const float m10 = float(m(1, 0)), m11 = float(m(1, 1)), m12 = float(m(1, 2));
  const float m20 = float(m(2, 0)), m21 = float(m(2, 1)), m22 = float(m(2, 2));
  const cv::Mat& base = quad.texture->levels[0];
  const bool has_alpha = base.channels() == 4;
  const float z_near = static_cast<float>(kNear);
  for (int y = box.y; y < box.y + box.height; ++y) {
    const cv::Vec2f* ray = rays_.ptr<cv::Vec2f>(y);
    float* zrow = buffers->zbuf.ptr<float>(y - buffers->row_begin);
    int* irow = buffers->index.ptr<int>(y - buffers->row_begin);
    cv::Vec2f* crow = buffers->coords.ptr<cv::Vec2f>(y - buffers->row_begin);
    for (int x = box.x; x < box.x + box.width; ++x) {
      const float rx = ray[x][0], ry = ray[x][1];
      const float q2 = m20 * rx + m21 * ry + m22;
      if (q2 <= 0.0f) continue;
      const float z = 1.0f / q2;
      if (z >= zrow[x] || z < z_near) continue;
      const float qa = (m00 * rx + m01 * ry + m02) * z;
      if (qa < 0.0f || qa >= 1.0f) continue;
      const float qb = (m10 * rx + m11 * ry + m12) * z;
      if (qb < 0.0f || qb >= 1.0f) continue;
      if (has_alpha) {
        const int tx = std::min(base.cols - 1, static_cast<int>(qa * base.cols));
        const int ty = std::min(base.rows - 1, static_cast<int>(qb * base.rows));
        if (base.ptr<cv::Vec4b>(ty)[tx][3] < 128) continue;
      }
      zrow[x] = z;
      irow[x] = quad_index;
      crow[x] = cv::Vec2f(qa, qb);
    }
  }
}

RenderResult Renderer::Render(const std::vector<TexturedQuad>& quads, const Pose& camera_from_world) const {
  RenderResult result;
  RenderRows(quads, camera_from_world, 0, camera_.height, &result);
  return result;
}

void Renderer::RenderRows(const std::vector<TexturedQuad>& quads, const Pose& camera_from_world, int row_begin,
                          int row_end, RenderResult* result) const {
  const int w = camera_.width, h = camera_.height;
  if (row_begin < 0 || row_end > h || row_begin >= row_end)
    throw InputError("Renderer::RenderRows: rows [" + std::to_string(row_begin) + ", " + std::to_string(row_end) +
                     ") are not a non-empty range inside [0, " + std::to_string(h) + ")");
  if (!HoldsImage(*result, w, h)) {
    result->bgr = cv::Mat(h, w, CV_8UC3, cv::Scalar::all(0));
    result->depth = cv::Mat(h, w, CV_32F, cv::Scalar(0));
    result->object_id = cv::Mat(h, w, CV_16U, cv::Scalar(0));
  }
  const int rows = row_end - row_begin;
  RasterBuffers buffers;
  buffers.row_begin = row_begin;
  // The rows' rays with a margin of 5% of their span, and at least a row: the whole image's
  // bounds for a full render, a band's for a band, so quads beside the band are dropped early.
  const auto first = row_y_min_.begin(), last = row_y_max_.begin();
  const double y_lo = *std::min_element(first + row_begin, first + row_end);
  const double y_hi = *std::max_element(last + row_begin, last + row_end);
  const double margin = std::max(0.05 * (y_hi - y_lo), 1.0 / camera_.fy);
  buffers.y_min = y_lo - margin;
  buffers.y_max = y_hi + margin;
  buffers.zbuf = cv::Mat(rows, w, CV_32F, cv::Scalar(std::numeric_limits<float>::infinity()));
  buffers.index = cv::Mat(rows, w, CV_32S, cv::Scalar(-1));
  buffers.coords = cv::Mat(rows, w, CV_32FC2);
  std::vector<Eigen::Vector3d> normals(quads.size(), Eigen::Vector3d::UnitZ());
  for (size_t qi = 0; qi < quads.size(); ++qi)
    RasteriseQuad(quads[qi], static_cast<int>(qi), camera_from_world, &buffers, &normals[qi]);
  Shade(quads, buffers, normals, result);
}

void Renderer::Shade(const std::vector<TexturedQuad>& quads, const RasterBuffers& buffers,
                     const std::vector<Eigen::Vector3d>& normals, RenderResult* result) const {
  const int w = camera_.width;
  const cv::Range rows(buffers.row_begin, buffers.row_begin + buffers.index.rows);
  result->bgr.rowRange(rows).setTo(cv::Scalar::all(0));
  result->depth.rowRange(rows).setTo(0);
  result->object_id.rowRange(rows).setTo(0);
  // Per quad: 1 / (focal * texel)^2 for the mip level choice.
  const double focal = 0.5 * (camera_.fx + camera_.fy);
  std::vector<float> inv_footprint2(quads.size(), 0.0f);
  for (size_t qi = 0; qi < quads.size(); ++qi)
    if (quads[qi].texture) {
      const double f = focal * quads[qi].texture->texel_size_m;
      inv_footprint2[qi] = static_cast<float>(1.0 / (f * f));
    }
  // Level L is used from (texels per pixel) >= 2^(L - 0.3); compared squared.
  float level_threshold2[8];
  for (int l = 0; l < 8; ++l) level_threshold2[l] = std::pow(2.0f, 2.0f * (l + 1) - 0.6f);
  for (int y = rows.start; y < rows.end; ++y) {
    const int* irow = buffers.index.ptr<int>(y - rows.start);
    const float* zrow = buffers.zbuf.ptr<float>(y - rows.start);
    const cv::Vec2f* crow = buffers.coords.ptr<cv::Vec2f>(y - rows.start);
    const cv::Vec2f* ray = rays_.ptr<cv::Vec2f>(y);
    cv::Vec3b* out = result->bgr.ptr<cv::Vec3b>(y);
    float* dout = result->depth.ptr<float>(y);
    std::uint16_t* iout = result->object_id.ptr<std::uint16_t>(y);
    for (int x = 0; x < w; ++x) {
      const int qi = irow[x];
      if (qi < 0) continue;
      const TexturedQuad& quad = quads[static_cast<size_t>(qi)];
      const Texture& tex = *quad.texture;
      const float z = zrow[x];
      dout[x] = z - ReliefAt(quad, crow[x]);
      iout[x] = static_cast<std::uint16_t>(std::clamp(quad.object_id, 0, 65535));
      // Mip level from the texel footprint (texels per pixel), stretched by the viewing
      // obliquity: squared, (z |r| / (f texel))^2 / cos, cos = |n.r| / |r|.
      const Eigen::Vector3d& n = normals[static_cast<size_t>(qi)];
      const float rx = ray[x][0], ry = ray[x][1];
      const float r2 = rx * rx + ry * ry + 1.0f;
      const float cosine =
          std::max(0.05f, std::abs(float(n.x()) * rx + float(n.y()) * ry + float(n.z())) / std::sqrt(r2));
      const float footprint2 = z * z * r2 * inv_footprint2[static_cast<size_t>(qi)] / cosine;
      const int max_level = static_cast<int>(tex.levels.size()) - 1;
      int level = 0;
      while (level < max_level && footprint2 >= level_threshold2[level]) ++level;
      out[x] = SampleBilinear(tex.levels[static_cast<size_t>(level)], crow[x], quad.shade);
    }
  }
}

}  // namespace dynvo
