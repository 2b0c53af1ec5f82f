// The static map of slam mode on a generated sequence whose people are known: two people cross
// the view of a camera moving along x/y/z (dynvo-synth --scenario two_crossing --camera-path xyz
// --frames 90 --seed 2). With the dynamic mask, the map holds (almost) no point on a person;
// without it, a quarter of its points are on them.

#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "dataset/trajectory_io.h"
#include "dataset/tum_dataset.h"
#include "odometry/sequence_runner.h"
#include "support/temp_dir.h"
#include "synth/synthetic_sequence.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace {

std::vector<Eigen::Vector3f> ReadPlyPoints(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  size_t vertices = 0;
  while (std::getline(in, line) && line != "end_header")
    if (line.rfind("element vertex ", 0) == 0) vertices = std::stoul(line.substr(15));
  std::vector<Eigen::Vector3f> points(vertices);
  for (Eigen::Vector3f& p : points) {
    char vertex[19];
    in.read(vertex, sizeof(vertex));
    std::memcpy(p.data(), vertex, 3 * sizeof(float));
  }
  EXPECT_TRUE(in.good()) << path << " holds fewer points than it declares";
  return points;
}

// Map points on a person: seen by some frame (estimated pose) inside the person's true mask
// at the depth the frame measures there (within 3 cm), that is on the person's surface (or
// touching it: the floor at a person's feet).
size_t PointsOnPeople(const std::vector<Eigen::Vector3f>& points, const TumDataset& dataset,
                      const Trajectory& trajectory) {
  std::vector<bool> on_person(points.size(), false);
  const Camera& c = dataset.camera();
  for (size_t i = 0; i < dataset.size(); i += 3) {
    const RgbdFrame frame = dataset.Load(i);
    const cv::Mat mask = dataset.LoadMask(i);
    const Pose camera_from_world = trajectory[i].world_from_camera.inverse();
    for (size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector3d p = camera_from_world * points[k].cast<double>();
      if (p.z() <= 0.1) continue;
      const int u = static_cast<int>(c.fx * p.x() / p.z() + c.cx + 0.5),
                v = static_cast<int>(c.fy * p.y() / p.z() + c.cy + 0.5);
      if (u < 0 || v < 0 || u >= c.width || v >= c.height || mask.at<uint8_t>(v, u) == 0) continue;
      if (std::abs(frame.depth.at<float>(v, u) - p.z()) < 0.03) on_person[k] = true;
    }
  }
  return static_cast<size_t>(std::count(on_person.begin(), on_person.end(), true));
}

TEST(SlamMapEndToEnd, PeopleStayOutOfTheMap) {
  test::TempDir dir;
  SyntheticSequenceOptions options;
  options.scenario = Scenario::kTwoCrossing;
  options.camera_path = CameraPathPreset::kXyz;
  options.frames = 90;
  options.seed = 2;
  const std::string sequence = (dir.path() / "sequence").string();
  PrepareOutputFolder(sequence, /*force=*/false);
  WriteSyntheticSequence(options, sequence);
  const TumDataset dataset(sequence);

  const auto run = [&](const std::string& name, const std::string& mask_source) {
    RunRequest request;
    request.dataset = sequence;
    request.config_path = std::string(DYNVO_SOURCE_DIR) + "/configs/baseline.json";
    request.overrides = {"mask_source=" + mask_source};
    request.out_dir = (dir.path() / name).string();
    request.quiet = true;
    request.slam = request.map = true;
    const nlohmann::json report = RunOdometry(request);
    const std::vector<Eigen::Vector3f> points = ReadPlyPoints(request.out_dir + "/map.ply");
    EXPECT_EQ(points.size(), report["loops"]["map_points"].get<size_t>());
    EXPECT_TRUE(std::filesystem::exists(request.out_dir + "/map_top.png"));
    const size_t on_people = PointsOnPeople(points, dataset, ReadTrajectory(request.out_dir + "/trajectory.txt"));
    return std::make_pair(points.size(), on_people);
  };
  const auto [masked_points, masked_on_people] = run("masked", "ground_truth");
  const auto [open_points, open_on_people] = run("unmasked", "none");
  EXPECT_GT(masked_points, 10000u);
  // At most 0.5% (the bound; measured when written: 8 of 12658, floor at the feet).
  EXPECT_LE(masked_on_people, masked_points / 200);
  // The check finds people when nothing leaves them out (7717 of 30043 when written).
  EXPECT_GT(open_on_people, open_points / 10);
}

}  // namespace
}  // namespace dynvo
