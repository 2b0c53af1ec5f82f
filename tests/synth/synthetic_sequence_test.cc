#include "synth/synthetic_sequence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "dataset/tum_dataset.h"
#include "support/temp_dir.h"
#include "synth/trajectory_sampling.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

SyntheticSequenceOptions SmallOptions(Scenario scenario) {
  SyntheticSequenceOptions o;
  o.scenario = scenario;
  o.camera_path = CameraPathPreset::kXyz;
  o.frames = 12;
  o.fps = 5;  // 12 frames span 2.2 s: people move a lot between frames
  o.camera.width = 160;
  o.camera.height = 120;
  o.camera.fx = 535.4 / 4;
  o.camera.fy = 539.2 / 4;
  o.camera.cx = 320.1 / 4;
  o.camera.cy = 247.6 / 4;
  o.room.furniture = 4;
  o.room.texel_size_m = 0.02;  // coarse textures: fast to build, enough for 160x120
  o.seed = 5;
  return o;
}

std::string FileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(SyntheticSequence, MaskIsExactlyTheMovingObjectPixelsAndTheStaticTwinAgreesElsewhere) {
  const SyntheticWorld dynamic_world(SmallOptions(Scenario::kWalkingToward));
  const SyntheticWorld static_world(SmallOptions(Scenario::kNone));
  int frames_with_person = 0;
  for (int i = 0; i < dynamic_world.size(); ++i) {
    const SyntheticFrame a = dynamic_world.RenderFrame(i);
    const SyntheticFrame b = static_world.RenderFrame(i);
    const cv::Mat objects = a.clean.object_id > 0;
    EXPECT_EQ(cv::countNonZero(a.mask != objects), 0) << "frame " << i;
    EXPECT_EQ(cv::countNonZero(b.mask), 0) << "frame " << i;
    // Outside the mask the scene is the same render: colour and depth identical.
    const cv::Mat outside = a.mask == 0;
    cv::Mat diff;
    cv::absdiff(a.clean.bgr, b.clean.bgr, diff);
    std::vector<cv::Mat> channels;
    cv::split(diff, channels);
    const cv::Mat any_diff = (channels[0] | channels[1] | channels[2]) > 0;
    EXPECT_EQ(cv::countNonZero(any_diff & outside), 0) << "frame " << i;
    EXPECT_EQ(cv::countNonZero((a.clean.depth != b.clean.depth) & outside), 0) << "frame " << i;
    // Inside the mask the person is in front of the static scene.
    EXPECT_EQ(cv::countNonZero((a.clean.depth >= b.clean.depth) & a.mask & (b.clean.depth > 0)), 0);
    if (cv::countNonZero(a.mask) > 0) ++frames_with_person;
  }
  EXPECT_GE(frames_with_person, 6);  // the walker is in view for most of the 2.2 s
}

TEST(SyntheticSequence, SameSeedSameBytesOtherSeedOtherImages) {
  test::TempDir dir;
  const fs::path a = dir.path() / "a", b = dir.path() / "b", c = dir.path() / "c";
  SyntheticSequenceOptions o = SmallOptions(Scenario::kTwoCrossing);
  o.frames = 4;
  for (const fs::path& p : {a, b}) {
    PrepareOutputFolder(p.string(), false);
    WriteSyntheticSequence(o, p.string());
  }
  o.seed = 6;
  PrepareOutputFolder(c.string(), false);
  WriteSyntheticSequence(o, c.string());
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), a);
    EXPECT_EQ(FileBytes(entry.path()), FileBytes(b / relative)) << relative;
    ++files;
  }
  EXPECT_EQ(files, 4 * 3 + 7);  // rgb, depth, mask per frame; 4 lists, camera.json, people.txt, stats.csv
  const std::string first_rgb = "rgb/" + FormatStamp(o.start_stamp) + ".png";
  EXPECT_NE(FileBytes(a / first_rgb), FileBytes(c / first_rgb));
}

TEST(SyntheticSequence, OutputLoadsThroughTheReaderAndGroundtruthMatchesTheRenderPoses) {
  test::TempDir dir;
  const std::string folder = (dir.path() / "seq").string();
  SyntheticSequenceOptions o = SmallOptions(Scenario::kWalkingAcross);
  o.camera_path = CameraPathPreset::kHalfsphere;
  o.fps = 30;
  PrepareOutputFolder(folder, false);
  const SyntheticSequenceSummary summary = WriteSyntheticSequence(o, folder);
  EXPECT_EQ(summary.frames, o.frames);

  const TumDataset dataset(folder);
  ASSERT_EQ(dataset.size(), static_cast<size_t>(o.frames));
  EXPECT_EQ(dataset.camera().fx, o.camera.fx);
  EXPECT_EQ(dataset.camera().cy, o.camera.cy);
  EXPECT_EQ(dataset.camera().width, 160);
  EXPECT_EQ(dataset.camera().rolling_shutter_readout_s, 0.0);  // a global shutter
  EXPECT_TRUE(dataset.has_masks());
  const SyntheticWorld world(o);
  for (size_t i = 0; i < dataset.size(); i += 5) {
    const SyntheticFrame expected = world.RenderFrame(static_cast<int>(i));
    EXPECT_EQ(dataset.stamp(i), expected.rgb_stamp);
    const RgbdFrame frame = dataset.Load(i);
    EXPECT_EQ(cv::countNonZero(dataset.LoadMask(i) != expected.mask), 0);
    // Depth readings agree with the clean depth within Kinect noise plus quantisation.
    const cv::Mat valid = frame.depth > 0;
    EXPECT_GT(cv::countNonZero(valid), 0.8 * valid.total());
    cv::Mat error;
    cv::absdiff(frame.depth, expected.clean.depth, error);
    const double mean_error = cv::mean(error, valid)[0];
    EXPECT_LT(mean_error, 0.05) << "frame " << i;
    EXPECT_GT(mean_error, 0.0005) << "frame " << i << ": depth noise is missing";
  }

  const Trajectory gt = ReadTrajectory(folder + "/groundtruth.txt");
  ASSERT_GT(gt.size(), 10u);
  EXPECT_NEAR(gt[1].stamp - gt[0].stamp, 0.01, 1e-6);  // 100 Hz
  EXPECT_LT(gt.front().stamp, dataset.stamp(0));
  EXPECT_GT(gt.back().stamp, dataset.stamp(dataset.size() - 1));
  for (size_t i = 0; i < dataset.size(); ++i) {
    for (const StampedPose& p : gt) EXPECT_NE(p.stamp, dataset.stamp(i));
    Pose interpolated;
    ASSERT_TRUE(InterpolatePose(gt, dataset.stamp(i), 0.02, &interpolated));
    const Pose exact = world.WorldFromCamera(dataset.stamp(i) - o.start_stamp);
    EXPECT_LT((interpolated.translation() - exact.translation()).norm(), 1e-4);  // 10 ms chords of a slow arc
    EXPECT_LT(RotationAngle(Pose(interpolated.inverse() * exact)), 1e-4);
  }
}

TEST(SyntheticSequence, MotionBlurSmearsFastTurnsWithEnoughSubFrames) {
  SyntheticSequenceOptions o = SmallOptions(Scenario::kNone);
  o.camera = TumIntrinsics("fr3", "k");  // 640x480, fx 535
  o.camera_path = CameraPathPreset::kStatic;
  EXPECT_EQ(SyntheticWorld(o).MotionBlurSamples(1.0), 5);  // the minimum: nothing moves
  o.camera_path = CameraPathPreset::kRpyFast;
  const SyntheticWorld world(o);
  int most = 0;
  for (double t = 0; t < 5; t += 0.1) {
    const int n = world.MotionBlurSamples(t);
    EXPECT_EQ(n % 2, 1);
    // The turn over the exposure moves the image centre by about fx * angle; the corners more.
    const double turn = RotationAngle(
        Pose(world.WorldFromCamera(t - 0.5 * o.exposure_s).inverse() * world.WorldFromCamera(t + 0.5 * o.exposure_s)));
    EXPECT_GE(n, std::min(kMaxBlurSamples, static_cast<int>(o.camera.fx * turn / kMaxBlurStepPx) + 1)) << t;
    most = std::max(most, n);
  }
  EXPECT_GE(most, 13);  // about 100 deg/s at the peaks: a 20 px smear
  EXPECT_LE(most, kMaxBlurSamples);
}

TEST(SyntheticSequence, ChecksOptionsNamingTheKey) {
  SyntheticSequenceOptions o = SmallOptions(Scenario::kNone);
  o.frames = 0;
  try {
    o.Check();
    FAIL() << "frames = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("synth.frames"), std::string::npos) << e.what();
  }
  o = SmallOptions(Scenario::kNone);
  o.fps = 100;
  EXPECT_THROW(o.Check(), InputError);
  o = SmallOptions(Scenario::kNone);
  o.camera.distortion[0] = 0.1;
  EXPECT_THROW(o.Check(), InputError);
  o = SmallOptions(Scenario::kNone);
  o.noise.depth_edge_hole_prob = 2;
  EXPECT_THROW(o.Check(), InputError);
  EXPECT_THROW(ParseScenario("running", "--scenario"), InputError);
  EXPECT_THROW(ParseCameraPathPreset("circle", "--camera-path"), InputError);
  EXPECT_THROW(TumIntrinsics("fr4", "--intrinsics"), InputError);
  // Intrinsics the renderer cannot draw: named, not rendered into nonsense.
  for (const auto& [fx, cx] : std::vector<std::pair<double, double>>{{1e-3, 320}, {1e6, 320}, {535, -5}, {535, 700}}) {
    SyntheticSequenceOptions bad;
    bad.camera.fx = fx;
    bad.camera.cx = cx;
    EXPECT_THROW(bad.Check(), InputError) << fx << " " << cx;
  }
}

TEST(SyntheticSequence, ChecksTheRollingShutterReadoutAndBands) {
  SyntheticSequenceOptions o = SmallOptions(Scenario::kNone);  // 5 fps: the readout must stay under 0.2 s
  for (double readout : {0.0, 0.028, 0.1999}) {
    o.rolling_shutter_readout_s = readout;
    EXPECT_NO_THROW(o.Check()) << readout;
  }
  for (double readout : {-0.001, 0.2, 0.5}) {
    o.rolling_shutter_readout_s = readout;
    try {
      o.Check();
      ADD_FAILURE() << "readout " << readout << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("synth.rolling_shutter_readout_s"), std::string::npos) << e.what();
    }
  }
  o = SmallOptions(Scenario::kNone);
  for (int bands : {0, 121}) {  // the camera has 120 rows
    o.rolling_shutter_bands = bands;
    EXPECT_THROW(o.Check(), InputError) << bands;
  }
  o.rolling_shutter_bands = 120;
  EXPECT_NO_THROW(o.Check());
}

TEST(SyntheticSequence, CameraJsonStatesTheRollingShuttersReadout) {
  test::TempDir dir;
  const std::string folder = (dir.path() / "seq").string();
  SyntheticSequenceOptions o = SmallOptions(Scenario::kNone);
  o.frames = 2;
  o.rolling_shutter_readout_s = 0.028;
  PrepareOutputFolder(folder, false);
  WriteSyntheticSequence(o, folder);
  EXPECT_EQ(TumDataset(folder).camera().rolling_shutter_readout_s, 0.028);
}

TEST(SyntheticSequence, RefusesToOverwriteANonEmptyFolderWithoutForce) {
  test::TempDir dir;
  dir.Write("out/notes.txt", "keep me");
  const std::string out = (dir.path() / "out").string();
  EXPECT_THROW(PrepareOutputFolder(out, false), InputError);
  dir.Write("out/rgb/old.png", "stale");
  PrepareOutputFolder(out, true);
  EXPECT_TRUE(fs::exists(dir.path() / "out/notes.txt"));
  EXPECT_FALSE(fs::exists(dir.path() / "out/rgb/old.png"));
}

}  // namespace
}  // namespace dynvo
