#include "synth/rolling_shutter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/camera.h"
#include "core/pose.h"
#include "synth/scene.h"
#include "synth/synthetic_sequence.h"

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kReadout = 0.028;  // seconds, the tum_* scenarios' readout
constexpr double kOmega = 2.0;      // rad/s about the camera's y axis: a brisk pan
constexpr double kStamp = 0.4;      // seconds, the image stamp

// A camera 1.4 m up in the room, looking forward (room y), turning about its own y axis (down
// in the image) at kOmega: camera_from_world at `seconds`.
Pose PanningCamera(double seconds) {
  Pose world_from_camera = Pose::Identity();
  world_from_camera.linear() = (Eigen::AngleAxisd(-kPi / 2, Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(kOmega * seconds, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  world_from_camera.translation() = Eigen::Vector3d(0.0, 0.0, 1.4);
  return world_from_camera.inverse();
}

std::vector<TexturedQuad> Room(double texel_size_m) {
  RoomOptions room;
  room.furniture = 4;
  room.texel_size_m = texel_size_m;
  return MakeRoomScene(room, 7);
}

// Whether row `row` of `a` and of `b` agree byte for byte in colour, depth and object id.
bool SameRow(const RenderResult& a, const RenderResult& b, int row) {
  return cv::norm(a.bgr.row(row), b.bgr.row(row), cv::NORM_INF) == 0 &&
         cv::norm(a.depth.row(row), b.depth.row(row), cv::NORM_INF) == 0 &&
         cv::norm(a.object_id.row(row), b.object_id.row(row), cv::NORM_INF) == 0;
}

// The horizontal shift d (pixels, to a tenth or so) minimising the mean absolute grey difference
// between a(row, x) and b(row, x + d) over columns [x0, x1): the best whole shift in
// [-max_shift, max_shift], refined by a parabola through its cost and its neighbours'.
double BestShift(const cv::Mat& a_bgr, const cv::Mat& b_bgr, int row, int x0, int x1, int max_shift) {
  cv::Mat a, b;
  cv::cvtColor(a_bgr.row(row), a, cv::COLOR_BGR2GRAY);
  cv::cvtColor(b_bgr.row(row), b, cv::COLOR_BGR2GRAY);
  std::vector<double> cost;
  for (int d = -max_shift; d <= max_shift; ++d) {
    double sum = 0;
    for (int x = x0; x < x1; ++x) sum += std::abs(int(a.at<uchar>(0, x)) - int(b.at<uchar>(0, x + d)));
    cost.push_back(sum);
  }
  const size_t k = static_cast<size_t>(std::min_element(cost.begin(), cost.end()) - cost.begin());
  if (k == 0 || k + 1 == cost.size()) return static_cast<double>(k) - max_shift;
  const double curvature = cost[k - 1] - 2 * cost[k] + cost[k + 1];
  const double step = curvature > 0 ? 0.5 * (cost[k - 1] - cost[k + 1]) / curvature : 0.0;
  return static_cast<double>(k) - max_shift + step;
}

// A camera 160 pixels wide and `height` rows tall, its principal point at the centre.
Camera SmallCamera(int height) {
  Camera camera;
  camera.width = 160;
  camera.height = height;
  camera.fx = camera.fy = 134.0;
  camera.cx = 79.5;
  camera.cy = (height - 1) / 2.0;
  return camera;
}

TEST(RollingShutter, RowOffsetsSpanTheReadoutWithTheMiddleRowAtTheStamp) {
  EXPECT_DOUBLE_EQ(RowExposureOffset(0, 481, kReadout), -kReadout / 2);
  EXPECT_DOUBLE_EQ(RowExposureOffset(240, 481, kReadout), 0.0);
  EXPECT_DOUBLE_EQ(RowExposureOffset(480, 481, kReadout), kReadout / 2);
  EXPECT_DOUBLE_EQ(RowExposureOffset(120, 481, 0.0), 0.0);
  for (int bands : {1, 16, 7, 480, 1000}) {
    const std::vector<ShutterBand> split = RollingShutterBands(480, kReadout, bands);
    ASSERT_EQ(split.size(), static_cast<size_t>(std::min(bands, 480))) << bands;
    EXPECT_EQ(split.front().row_begin, 0);
    EXPECT_EQ(split.back().row_end, 480);
    for (size_t k = 0; k < split.size(); ++k) {
      EXPECT_LT(split[k].row_begin, split[k].row_end);
      if (k > 0) {
        EXPECT_EQ(split[k].row_begin, split[k - 1].row_end);
      }
      EXPECT_DOUBLE_EQ(split[k].offset_s,
                       RowExposureOffset(0.5 * (split[k].row_begin + split[k].row_end - 1), 480, kReadout));
    }
  }
  // 16 bands of 30 rows: the first band at its row 14.5's time.
  EXPECT_NEAR(RollingShutterBands(480, kReadout, 16).front().offset_s, kReadout * (14.5 / 479 - 0.5), 1e-15);
}

// With one band per row the rolling shutter is exact: every row is the global render at its
// own time, the top row at t - readout/2, the middle row at t, the bottom row at t + readout/2.
TEST(RollingShutter, EachRowIsTheSceneAtItsOwnTimeUnderConstantRotation) {
  const Camera camera = SmallCamera(121);  // odd: the middle row 60 is at the stamp exactly
  const Renderer renderer(camera);
  const std::vector<TexturedQuad> quads = Room(0.02);
  const auto quads_at = [&quads](double) { return quads; };
  const RenderResult rolling = RenderRollingShutter(renderer, quads_at, PanningCamera, kStamp, kReadout, camera.height);
  const RenderResult at_stamp = renderer.Render(quads, PanningCamera(kStamp));
  const RenderResult at_start = renderer.Render(quads, PanningCamera(kStamp - kReadout / 2));
  const RenderResult at_end = renderer.Render(quads, PanningCamera(kStamp + kReadout / 2));
  EXPECT_TRUE(SameRow(rolling, at_start, 0));
  EXPECT_TRUE(SameRow(rolling, at_stamp, 60));
  EXPECT_TRUE(SameRow(rolling, at_end, 120));
  // The pan moves the image by f * omega * readout / 2 = 3.8 pixels between those times: the
  // top and bottom rows are not the global render's.
  EXPECT_FALSE(SameRow(rolling, at_stamp, 0));
  EXPECT_FALSE(SameRow(rolling, at_stamp, 120));
  int rows_at_their_time = 0;
  for (int row = 0; row < camera.height; ++row) {
    const double s = kStamp + RowExposureOffset(row, camera.height, kReadout);
    rows_at_their_time += SameRow(rolling, renderer.Render(quads, PanningCamera(s)), row);
  }
  EXPECT_EQ(rows_at_their_time, camera.height);
}

// The default 16 bands: each row is rendered within half a band (14.5 rows, 0.85 ms) of its
// own time, which under a 2 rad/s pan is 0.85 ms * 2 rad/s * 535 px = 0.9 pixel; the shift
// estimate adds up to 0.4 pixel. The global shutter image is 14.1 pixels away at the top and
// bottom rows (their bands at -+13.2 ms).
TEST(RollingShutter, SixteenBandsStayWithinAPixelOfEachRowsTime) {
  const Camera camera = TumIntrinsics("fr3", "test");  // 640x480, the generator's default
  const Renderer renderer(camera);
  const std::vector<TexturedQuad> quads = Room(0.01);
  const auto quads_at = [&quads](double) { return quads; };
  const RenderResult rolling = RenderRollingShutter(renderer, quads_at, PanningCamera, kStamp, kReadout, 16);
  const RenderResult at_stamp = renderer.Render(quads, PanningCamera(kStamp));
  // Columns within 60 pixels of the centre: the pan moves them sideways, and by less than a
  // pixel up or down (x y / f * omega * readout / 2 <= 0.75 pixel at the top row).
  const int x0 = 260, x1 = 380, max_shift = 30;
  const struct {
    int row;
    double seconds;
  } cases[] = {{0, kStamp - kReadout / 2}, {239, kStamp}, {240, kStamp}, {479, kStamp + kReadout / 2}};
  for (const auto& c : cases) {
    const RenderResult exact = renderer.Render(quads, PanningCamera(c.seconds));
    EXPECT_LE(std::abs(BestShift(rolling.bgr, exact.bgr, c.row, x0, x1, max_shift)), 1.3) << "row " << c.row;
  }
  const double top = BestShift(rolling.bgr, at_stamp.bgr, 0, x0, x1, max_shift);
  const double bottom = BestShift(rolling.bgr, at_stamp.bgr, 479, x0, x1, max_shift);
  EXPECT_NEAR(std::abs(top), 14.1, 1.3);
  EXPECT_NEAR(std::abs(bottom), 14.1, 1.3);
  EXPECT_LT(top * bottom, 0) << "the top and bottom rows lean opposite ways";
}

TEST(RollingShutter, ZeroReadoutIsTheGlobalRenderByteForByte) {
  const Camera camera = SmallCamera(120);
  const Renderer renderer(camera);
  const std::vector<TexturedQuad> quads = Room(0.02);
  const auto quads_at = [&quads](double) { return quads; };
  const RenderResult global = renderer.Render(quads, PanningCamera(kStamp));
  for (int bands : {1, 16, 120}) {
    const RenderResult rolling = RenderRollingShutter(renderer, quads_at, PanningCamera, kStamp, 0.0, bands);
    int same_rows = 0;
    for (int row = 0; row < camera.height; ++row) same_rows += SameRow(rolling, global, row);
    EXPECT_EQ(same_rows, camera.height) << bands << " bands";
  }
}

}  // namespace
}  // namespace dynvo
