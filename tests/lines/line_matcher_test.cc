#include "lines/line_matcher.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

// Map lines 2-4 m in front of a camera at `camera_from_world`, and the frame seeing them.
struct View {
  Camera camera;
  Pose camera_from_world = PoseFromAxisAngle({0.02, -0.05, 0.01}, {0.1, 0.0, -0.2});
  std::vector<Line3d> map_lines;
  FrameLines frame;
};

LineSegment Seen(const View& v, const Line3d& in_world) {
  return {v.camera.Project(v.camera_from_world * in_world.start), v.camera.Project(v.camera_from_world * in_world.end)};
}

View MakeView() {
  View v;
  const Pose world_from_camera = v.camera_from_world.inverse();
  const std::vector<Line3d> in_camera = {{{-1.0, -0.5, 3.0}, {1.0, -0.5, 3.0}},  // horizontal
                                         {{-0.8, -0.6, 2.5}, {-0.8, 0.6, 2.5}},  // vertical
                                         {{0.5, 0.4, 2.0}, {1.0, 0.6, 4.0}},     // receding
                                         {{-0.5, 0.8, 3.5}, {0.6, 0.3, 3.5}}};   // slanted
  for (const Line3d& l : in_camera) v.map_lines.push_back({world_from_camera * l.start, world_from_camera * l.end});
  for (const Line3d& l : v.map_lines) v.frame.segments.push_back(Seen(v, l));
  v.frame.detected = v.frame.segments;
  return v;
}

TEST(MatchLinesByProjection, MatchesEachFrameLineToTheMapLineItSees) {
  View v = MakeView();
  // Seen 1.5 px off and shorter at one end (a detector rarely finds the whole segment).
  for (LineSegment& s : v.frame.segments) {
    const Eigen::Vector2d d = (s.end - s.start).normalized();
    s.start += 1.5 * Eigen::Vector2d(-d.y(), d.x()) + 0.2 * (s.end - s.start);
    s.end += 1.5 * Eigen::Vector2d(-d.y(), d.x());
  }
  std::swap(v.frame.segments[0], v.frame.segments[3]);  // frame order differs from map order
  const std::vector<LineMatch> matches =
      MatchLinesByProjection(v.map_lines, v.frame, v.camera, v.camera_from_world, LineMatchOptions{});
  ASSERT_EQ(matches.size(), 4u);
  const int expected_map_line[] = {3, 1, 2, 0};
  for (const LineMatch& m : matches) EXPECT_EQ(m.map_line, expected_map_line[m.frame_line]) << m.frame_line;
}

TEST(MatchLinesByProjection, TakesTheNearestOfTwoParallelMapLines) {
  View v = MakeView();
  Line3d twin = v.map_lines[0];  // 3 px beside the first in the image, further from the frame line
  const Eigen::Vector3d shift = v.camera_from_world.linear().transpose() * Eigen::Vector3d(0.0, 3.0 * 3.0 / 525.0, 0.0);
  twin.start += shift;
  twin.end += shift;
  v.map_lines.insert(v.map_lines.begin(), twin);  // first: a tie would go to it
  const std::vector<LineMatch> matches =
      MatchLinesByProjection(v.map_lines, v.frame, v.camera, v.camera_from_world, LineMatchOptions{});
  ASSERT_FALSE(matches.empty());
  EXPECT_EQ(matches[0].frame_line, 0);
  EXPECT_EQ(matches[0].map_line, 1);
}

TEST(MatchLinesByProjection, RejectsLinesTooFarTurnedOrNotOverlapping) {
  const View v = MakeView();
  const LineSegment& s = v.frame.segments[0];  // horizontal, about 350 px long
  const Eigen::Vector2d d = (s.end - s.start).normalized(), across(-d.y(), d.x());
  const Eigen::Vector2d mid = 0.5 * (s.start + s.end);
  const double half = 0.5 * s.Length();
  const auto match_one = [&](const LineSegment& seen) {
    FrameLines frame;
    frame.segments = frame.detected = {seen};
    return MatchLinesByProjection({v.map_lines[0]}, frame, v.camera, v.camera_from_world, LineMatchOptions{});
  };
  EXPECT_EQ(match_one({s.start + 3.0 * across, s.end + 3.0 * across}).size(), 1u);  // within 4 px
  EXPECT_TRUE(match_one({s.start + 6.0 * across, s.end + 6.0 * across}).empty());   // 6 px away
  // A short map line (35 px) seen turned by 5 degrees: its ends lie within 2 px of the frame line.
  const Line3d& whole = v.map_lines[0];
  const Line3d short_line{whole.start + 0.45 * (whole.end - whole.start),
                          whole.start + 0.55 * (whole.end - whole.start)};
  const double turn = 5.0 * M_PI / 180.0;
  const Eigen::Vector2d turned = std::cos(turn) * d + std::sin(turn) * across;
  FrameLines frame;
  frame.segments = frame.detected = {{mid - 100.0 * turned, mid + 100.0 * turned}};
  EXPECT_TRUE(MatchLinesByProjection({short_line}, frame, v.camera, v.camera_from_world, LineMatchOptions{}).empty());
  frame.segments = frame.detected = {{mid - 100.0 * d, mid + 100.0 * d}};  // not turned: matched
  EXPECT_EQ(MatchLinesByProjection({short_line}, frame, v.camera, v.camera_from_world, LineMatchOptions{}).size(), 1u);
  // On the same image line but beyond its end.
  EXPECT_TRUE(match_one({s.end + 10.0 * d, s.end + (10.0 + half) * d}).empty());
}

}  // namespace
}  // namespace dynvo
