// Features, projection matching and pose estimation together on real TUM frames: the motion
// between two frames of fr1_rpy estimated from depth-backed 3D points must agree with the
// motion-capture groundtruth.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/pose.h"
#include "features/feature_extractor.h"
#include "pose/pose_solver.h"
#include "pose/projection_matcher.h"
#include "support/process_cpu_time.h"
#include "support/shared_data.h"

namespace dynvo {
namespace {

struct Stamped {
  double stamp;
  std::vector<std::string> fields;
};

// Non-comment lines of a TUM text file, split on spaces, the first field as a time stamp.
std::vector<Stamped> ReadTumList(const std::string& path) {
  std::vector<Stamped> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Stamped row;
    fields >> row.stamp;
    std::string f;
    while (fields >> f) row.fields.push_back(f);
    rows.push_back(row);
  }
  return rows;
}

// The row whose stamp is nearest to `stamp`.
const Stamped& Nearest(const std::vector<Stamped>& rows, double stamp) {
  return *std::min_element(rows.begin(), rows.end(), [&](const Stamped& a, const Stamped& b) {
    return std::abs(a.stamp - stamp) < std::abs(b.stamp - stamp);
  });
}

// Groundtruth world_from_camera at `stamp`, interpolated (lerp + slerp) between neighbours.
Pose GroundtruthAt(const std::vector<Stamped>& gt, double stamp) {
  size_t i = 1;
  while (i + 1 < gt.size() && gt[i].stamp < stamp) ++i;
  const Stamped& a = gt[i - 1];
  const Stamped& b = gt[i];
  const double s = std::clamp((stamp - a.stamp) / (b.stamp - a.stamp), 0.0, 1.0);
  auto pose = [](const Stamped& r) {
    std::vector<double> v;
    for (const std::string& f : r.fields) v.push_back(std::stod(f));
    return PoseFromTum({v[0], v[1], v[2]}, v[3], v[4], v[5], v[6]);
  };
  const Pose pa = pose(a), pb = pose(b);
  Pose out = Pose::Identity();
  out.linear() = Eigen::Quaterniond(pa.linear()).slerp(s, Eigen::Quaterniond(pb.linear())).toRotationMatrix();
  out.translation() = (1 - s) * pa.translation() + s * pb.translation();
  return out;
}

using test::ProcessCpuMs;

// Frame `i` of the sequence in `dir`: its grey image and the nearest depth image, in metres.
void LoadFrame(const std::string& dir, const std::vector<Stamped>& rgb, const std::vector<Stamped>& depth, int i,
               cv::Mat* gray, cv::Mat* metres) {
  *gray = cv::imread(dir + rgb[i].fields[0], cv::IMREAD_GRAYSCALE);
  const cv::Mat raw = cv::imread(dir + Nearest(depth, rgb[i].stamp).fields[0], cv::IMREAD_UNCHANGED);
  ASSERT_EQ(raw.type(), CV_16UC1);
  raw.convertTo(*metres, CV_32F, 1.0 / 5000.0);  // TUM depth scale
}

// A map of a frame's features with depth, in that frame's camera coordinates ("world").
struct FrameMap {
  std::vector<Eigen::Vector3d> points;
  std::vector<float> angles;
  cv::Mat descriptors;
};
FrameMap MapOf(const FrameFeatures& a) {
  FrameMap map;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a.depths[i] <= 0) continue;
    map.points.push_back(a.points_in_camera[i]);
    map.angles.push_back(a.keypoints[i].angle);
    map.descriptors.push_back(a.descriptors.row(static_cast<int>(i)));
  }
  return map;
}

TEST(RealFrames, MatchedPoseAgreesWithGroundtruth) {
  DYNVO_REQUIRE_SHARED(shared);
  const std::string dir = shared + "/data/tum/rgbd_dataset_freiburg1_rpy_head150/";
  const std::vector<Stamped> rgb = ReadTumList(dir + "rgb.txt");
  const std::vector<Stamped> depth = ReadTumList(dir + "depth.txt");
  const std::vector<Stamped> gt = ReadTumList(dir + "groundtruth.txt");
  ASSERT_GE(rgb.size(), 150u);
  Camera camera;  // TUM freiburg1
  camera.fx = 517.3;
  camera.fy = 516.5;
  camera.cx = 318.6;
  camera.cy = 255.3;
  camera.distortion = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};

  FeatureExtractor extractor{FeatureOptions{}};
  MatchOptions match_options;
  match_options.search_radius_px = 40.0;  // no motion prediction here: identity
  const PoseSolverOptions pose_options;
  std::vector<double> match_ms, pose_ms, rot_err, trans_err;
  for (int first : {5, 25, 45, 65, 85, 105, 125}) {
    const int second = first + 1;  // 1/30 s apart
    cv::Mat gray_a, depth_a, gray_b, depth_b;
    LoadFrame(dir, rgb, depth, first, &gray_a, &depth_a);
    LoadFrame(dir, rgb, depth, second, &gray_b, &depth_b);
    const FrameMap map = MapOf(extractor.Extract(gray_a, depth_a, camera));
    const FrameFeatures b = extractor.Extract(gray_b, cv::Mat(), camera);
    const std::vector<Eigen::Vector3d>& points = map.points;
    ASSERT_GT(points.size(), 300u);

    const double c0 = ProcessCpuMs();
    const std::vector<Match> matches =
        MatchByProjection(points, map.descriptors, b, camera, Pose::Identity(), match_options, &map.angles);
    const double c1 = ProcessCpuMs();
    std::vector<Eigen::Vector3d> matched_points;
    std::vector<Eigen::Vector2d> matched_pixels;
    for (const Match& m : matches) {
      matched_points.push_back(points[m.point_index]);
      matched_pixels.push_back(b.pixels[m.feature_index]);
    }
    const PoseEstimate estimate = EstimatePose(matched_points, matched_pixels, camera, pose_options);
    const double c2 = ProcessCpuMs();
    ASSERT_TRUE(estimate.ok) << "frames " << first << "," << second << ": " << estimate.failure;
    match_ms.push_back(c1 - c0);
    pose_ms.push_back(c2 - c1);

    const Pose b_from_a = GroundtruthAt(gt, rgb[second].stamp).inverse() * GroundtruthAt(gt, rgb[first].stamp);
    const Pose error = estimate.camera_from_world * b_from_a.inverse();
    rot_err.push_back(RotationAngle(error) * 180.0 / M_PI);
    trans_err.push_back((estimate.camera_from_world.translation() - b_from_a.translation()).norm());
    std::cout << "frames " << first << "-" << second << ": " << points.size() << " map points, " << matches.size()
              << " matches, " << estimate.num_inliers << " inliers, rms " << estimate.rms_error_px << " px; motion "
              << RotationAngle(b_from_a) * 180.0 / M_PI << " deg " << b_from_a.translation().norm() << " m (estimated "
              << RotationAngle(estimate.camera_from_world) * 180.0 / M_PI << " deg "
              << estimate.camera_from_world.translation().norm() << " m); error " << rot_err.back() << " deg "
              << trans_err.back() << " m\n";
    EXPECT_GT(estimate.num_inliers, 100);
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::cout << "real frames: median CPU matching " << median(match_ms) << " ms, EstimatePose " << median(pose_ms)
            << " ms; median error " << median(rot_err) << " deg, " << median(trans_err) << " m\n";
  // Groundtruth (motion capture, 100 Hz) and Kinect depth noise: a correct estimate is within
  // a fraction of a degree and about a centimetre; a wrong one is off by the motion itself.
  EXPECT_LT(median(rot_err), 0.5);
  EXPECT_LT(median(trans_err), 0.02);
  EXPECT_LT(*std::max_element(rot_err.begin(), rot_err.end()), 1.5);
  EXPECT_LT(*std::max_element(trans_err.begin(), trans_err.end()), 0.05);
}

}  // namespace
}  // namespace dynvo
