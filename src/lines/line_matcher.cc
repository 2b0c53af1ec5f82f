#include "lines/line_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynvo {

namespace {

constexpr double kMinDepthM = 0.05;       // map line ends nearer the camera are not projected
constexpr double kMinProjectedPx = 10.0;  // shorter projections say nothing about a direction

struct Projected {
  bool ok = false;
  LineSegment segment;
};

Projected Project(const Line3d& in_world, const Camera& camera, const Pose& camera_from_world) {
  const Eigen::Vector3d a = camera_from_world * in_world.start, b = camera_from_world * in_world.end;
  Projected p;
  if (a.z() < kMinDepthM || b.z() < kMinDepthM) return p;
  p.segment = {camera.Project(a), camera.Project(b)};
  p.ok = p.segment.Length() >= kMinProjectedPx;
  return p;
}

// Length of [a0, a1] (either order) within [0, length].
double Overlap(double a0, double a1, double length) {
  return std::max(0.0, std::min(std::max(a0, a1), length) - std::max(std::min(a0, a1), 0.0));
}

}  // namespace

std::vector<LineMatch> MatchLinesByProjection(const std::vector<Line3d>& map_lines_in_world, const FrameLines& frame,
                                              const Camera& camera, const Pose& camera_from_world,
                                              const LineMatchOptions& options) {
  std::vector<Projected> projected;
  projected.reserve(map_lines_in_world.size());
  for (const Line3d& line : map_lines_in_world) projected.push_back(Project(line, camera, camera_from_world));
  const double min_abs_cos = std::cos(options.max_angle_deg * M_PI / 180.0);
  std::vector<LineMatch> matches;
  for (size_t j = 0; j < frame.size(); ++j) {
    const LineSegment& seen = frame.segments[j];
    const double length = seen.Length();
    if (length < kMinProjectedPx) continue;
    const Eigen::Vector3d l = ImageLineCoefficients(seen);
    const Eigen::Vector2d direction = (seen.end - seen.start) / length;
    double best = std::numeric_limits<double>::infinity();
    int best_index = -1;
    for (size_t i = 0; i < projected.size(); ++i) {
      if (!projected[i].ok) continue;
      const LineSegment& m = projected[i].segment;
      const double distance = 0.5 * (std::abs(l.dot(m.start.homogeneous())) + std::abs(l.dot(m.end.homogeneous())));
      if (distance > options.max_distance_px || distance >= best) continue;
      if (std::abs(direction.dot((m.end - m.start) / m.Length())) < min_abs_cos) continue;
      const double shared = Overlap((m.start - seen.start).dot(direction), (m.end - seen.start).dot(direction), length);
      if (shared < options.min_overlap * std::min(length, m.Length())) continue;
      best = distance;
      best_index = static_cast<int>(i);
    }
    if (best_index >= 0) matches.push_back({static_cast<int>(j), best_index});
  }
  return matches;
}

}  // namespace dynvo
