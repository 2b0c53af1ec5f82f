#include "synth/people_insertion.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "dataset/image_list.h"
#include "dataset/known_cameras.h"
#include "dataset/stamp_matching.h"
#include "dataset/tum_dataset.h"
#include "support/shared_data.h"
#include "support/temp_dir.h"
#include "synth/trajectory_sampling.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

// Every `step`-th associated RGB-D pair of a TUM folder, with its full groundtruth, copied
// into `out` (a folder whose name keeps "freiburg1" so that the camera is recognised).
void SubsampleSequence(const fs::path& in, const fs::path& out, int step) {
  const std::vector<ImageListEntry> rgb = ReadImageList((in / "rgb.txt").string());
  const std::vector<ImageListEntry> depth = ReadImageList((in / "depth.txt").string());
  std::vector<double> rs, ds;
  for (const auto& e : rgb) rs.push_back(e.stamp);
  for (const auto& e : depth) ds.push_back(e.stamp);
  fs::create_directories(out / "rgb");
  fs::create_directories(out / "depth");
  std::ofstream rgb_list(out / "rgb.txt"), depth_list(out / "depth.txt");
  int k = 0;
  for (const auto& [r, d] : MatchStamps(rs, ds, 0.02)) {
    if (k++ % step != 0) continue;
    rgb_list << FormatStamp(rgb[r].stamp) << " " << rgb[r].path << "\n";
    depth_list << FormatStamp(depth[d].stamp) << " " << depth[d].path << "\n";
    fs::copy_file(in / rgb[r].path, out / rgb[r].path);
    fs::copy_file(in / depth[d].path, out / depth[d].path);
  }
  fs::copy_file(in / "groundtruth.txt", out / "groundtruth.txt");
}

int CountDifferent(const cv::Mat& a, const cv::Mat& b, const cv::Mat& where) {
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  std::vector<cv::Mat> channels;
  cv::split(diff, channels);
  cv::Mat any = channels[0] > 0;
  for (size_t c = 1; c < channels.size(); ++c) any |= channels[c] > 0;
  return cv::countNonZero(any & where);
}

// Samples of the cut-outs' interiors (body-part pixels whose 5x5 neighbourhood is all person:
// away from the outline) at `stamp`, in the camera's frame, within its view cone.
std::vector<cv::Point3d> PersonSamplesInCamera(const InsertionPlan& plan, double stamp, const Pose& camera_from_world) {
  std::vector<cv::Point3d> points;
  for (const TexturedQuad& q : InsertionQuadsAt(plan, stamp)) {
    cv::Mat solid;
    cv::extractChannel(q.texture->levels[0], solid, 3);
    cv::erode(solid, solid, cv::Mat::ones(5, 5, CV_8U));
    for (int r = 2; r < solid.rows; r += 6)
      for (int c = 2; c < solid.cols; c += 6) {
        if (solid.at<uchar>(r, c) == 0) continue;
        const Eigen::Vector3d p =
            camera_from_world * (q.origin + q.edge_u * ((c + 0.5) / solid.cols) + q.edge_v * ((r + 0.5) / solid.rows));
        if (p.z() > 0.1 && std::abs(p.x() / p.z()) < 0.9 && std::abs(p.y() / p.z()) < 0.8)
          points.emplace_back(p.x(), p.y(), p.z());
      }
  }
  return points;
}

// What became of a frame's person samples, projected with cv::projectPoints (independent of
// the insertion's own projection) against the real depth and the written mask.
struct SampleTally {
  int in_view = 0;
  int visible = 0, visible_masked = 0;    // nearer than the real surface by more than 2 cm
  int occluded = 0, occluded_masked = 0;  // farther by more than 2 cm
};
SampleTally TallySamples(const std::vector<cv::Point3d>& points, const Camera& camera, const cv::Mat& real_depth,
                         const cv::Mat& mask) {
  SampleTally t;
  if (points.empty()) return t;
  std::vector<cv::Point2d> pixels;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera.K(), camera.DistCoeffs(), pixels);
  for (size_t k = 0; k < points.size(); ++k) {
    const int u = cvRound(pixels[k].x), v = cvRound(pixels[k].y);
    if (u < 2 || v < 2 || u >= camera.width - 2 || v >= camera.height - 2) continue;
    ++t.in_view;
    const double person = points[k].z * 5000.0;
    const int real = real_depth.at<std::uint16_t>(v, u);
    const bool masked = mask.at<uchar>(v, u) != 0;
    if (real == 0 || person < real - 100) {
      ++t.visible;
      t.visible_masked += masked;
    } else if (person > real + 100) {
      ++t.occluded;
      t.occluded_masked += masked;
    }
  }
  return t;
}

TEST(PeopleInsertion, RealSequenceOcclusionUntouchedPixelsAndMasksWhileInView) {
  DYNVO_REQUIRE_SHARED(shared);
  const fs::path source = fs::path(shared) / "data/tum/rgbd_dataset_freiburg1_rpy_head150";
  test::TempDir dir;
  const fs::path in = dir.path() / "rgbd_dataset_freiburg1_rpy_every3";
  const fs::path out = dir.path() / "inserted";
  SubsampleSequence(source, in, 3);
  const PersonCutout cutout = MakeSyntheticPersonCutout(1);
  InsertionOptions options;
  options.preset = Scenario::kWalkingAcross;
  PrepareOutputFolder(out.string(), false);
  const InsertionSummary summary = InsertPeopleIntoSequence(in.string(), {cutout}, options, out.string());
  ASSERT_EQ(summary.frames, 50);
  EXPECT_EQ(summary.frames_without_pose, 0);

  // The output is a TUM folder the reader loads, with masks and the fr1 camera.
  TumDatasetOptions raw;
  raw.undistort = false;  // masks as stored, on the raw pixel grid
  const TumDataset result(out.string(), raw);
  ASSERT_EQ(result.size(), 50u);
  ASSERT_TRUE(result.has_masks());
  const Camera camera = KnownCameraByName("fr1")->camera;
  EXPECT_EQ(result.raw_camera().distortion, camera.distortion);
  EXPECT_EQ(result.groundtruth().size(), ReadTrajectory((in / "groundtruth.txt").string()).size());

  // Independent check of visibility: sample the cut-out plane, project with cv::projectPoints.
  const std::vector<ImageListEntry> rgb = ReadImageList((in / "rgb.txt").string());
  const std::vector<ImageListEntry> depth = ReadImageList((in / "depth.txt").string());
  const Trajectory gt = ReadTrajectory((in / "groundtruth.txt").string());
  InsertionOptions used = options;
  used.distance_m = summary.distance_m;
  const InsertionPlan plan = PlanInsertion(used, {cutout}, gt, rgb.front().stamp, rgb.back().stamp, camera);

  int frames_with_mask = 0, frames_without = 0;
  SampleTally all;
  for (size_t i = 0; i < rgb.size(); ++i) {
    const cv::Mat in_rgb = cv::imread((in / rgb[i].path).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat out_rgb = cv::imread((out / rgb[i].path).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat in_depth = cv::imread((in / depth[i].path).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat out_depth = cv::imread((out / depth[i].path).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat mask = result.LoadMask(i);
    // Pixels the person does not cover are byte-identical; covered pixels are nearer.
    EXPECT_EQ(CountDifferent(in_rgb, out_rgb, mask == 0), 0) << "frame " << i;
    EXPECT_EQ(CountDifferent(in_depth, out_depth, mask == 0), 0) << "frame " << i;
    // Person depths are nearer than the real surface, but for the sensor noise added after
    // the occlusion test (under 5 cm at the 1-4 m the people walk at).
    EXPECT_EQ(cv::countNonZero(mask & (in_depth > 0) & (out_depth >= in_depth + 250)), 0) << "frame " << i;

    Pose world_from_camera;
    ASSERT_TRUE(InterpolatePose(gt, rgb[i].stamp, 0.1, &world_from_camera));
    const SampleTally t =
        TallySamples(PersonSamplesInCamera(plan, rgb[i].stamp, world_from_camera.inverse()), camera, in_depth, mask);
    all.visible += t.visible;
    all.visible_masked += t.visible_masked;
    all.occluded += t.occluded;
    all.occluded_masked += t.occluded_masked;
    const bool has_mask = cv::countNonZero(mask) > 0;
    if (t.visible >= 3) {
      EXPECT_TRUE(has_mask) << "frame " << i << ": person in view but mask empty";
    }
    if (t.in_view == 0) {  // no sample of a part's interior in view: at most a sliver at the border
      EXPECT_LT(cv::countNonZero(mask), 300) << "frame " << i << ": person out of view but mask set";
    }
    frames_with_mask += has_mask;
    frames_without += !has_mask;
  }
  // The walk enters and leaves the view; the desk hides part of the person.
  EXPECT_GE(frames_with_mask, 10);
  EXPECT_GE(frames_without, 5);
  ASSERT_GT(all.visible, 200);
  EXPECT_GT(all.visible_masked, 0.97 * all.visible);
  ASSERT_GT(all.occluded, 50);
  EXPECT_LT(all.occluded_masked, 0.03 * all.occluded);
}

TEST(PeopleInsertion, CompositeWritesOnlyNearerPixels) {
  RenderResult people;
  people.bgr = cv::Mat(2, 3, CV_8UC3, cv::Scalar(1, 2, 3));
  people.depth = cv::Mat(2, 3, CV_32F, cv::Scalar(2.0));
  people.object_id = cv::Mat(2, 3, CV_16U, cv::Scalar(1));
  people.object_id.at<std::uint16_t>(0, 0) = 0;  // no person here
  people.object_id.at<std::uint16_t>(1, 2) = 2;  // another person
  cv::Mat bgr(2, 3, CV_8UC3, cv::Scalar(9, 9, 9)), ids;
  cv::Mat depth = (cv::Mat_<std::uint16_t>(2, 3) << 5000, 5000, 15000, 0, 9999, 10001);
  EXPECT_EQ(CompositePeople(people, 5000.0, &bgr, &depth, &ids), 3);
  const cv::Mat expected_ids = (cv::Mat_<std::uint16_t>(2, 3) << 0, 0, 1, 1, 0, 2);
  EXPECT_EQ(cv::countNonZero(ids != expected_ids), 0);
  EXPECT_EQ(depth.at<std::uint16_t>(1, 0), 10000);  // no reading: the person is written
  EXPECT_EQ(depth.at<std::uint16_t>(1, 1), 9999);   // real surface nearer: untouched
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 1), cv::Vec3b(9, 9, 9));
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 2), cv::Vec3b(1, 2, 3));
}

TEST(PersonCutout, GrabCutSegmentsAPersonShapeInsideTheBox) {
  // A figure on a cluttered background; the truth is the drawn silhouette.
  const PersonCutout drawn = MakeSyntheticPersonCutout(3);
  cv::Mat image(400, 300, CV_8UC3, cv::Scalar(170, 180, 175));
  cv::RNG rng(7);
  for (int i = 0; i < 300; ++i)
    cv::rectangle(image, cv::Rect(rng.uniform(0, 300), rng.uniform(0, 400), rng.uniform(5, 40), rng.uniform(5, 40)),
                  cv::Scalar(rng.uniform(120, 255), rng.uniform(120, 255), rng.uniform(120, 255)), -1);
  cv::Mat figure, alpha;
  cv::resize(drawn.bgra, figure, cv::Size(100, 300), 0, 0, cv::INTER_NEAREST);
  cv::extractChannel(figure, alpha, 3);
  cv::Mat truth(image.size(), CV_8U, cv::Scalar(0));
  cv::Mat figure_bgr;
  cv::cvtColor(figure, figure_bgr, cv::COLOR_BGRA2BGR);
  figure_bgr = figure_bgr * 0.4;  // darker than the background
  figure_bgr.copyTo(image(cv::Rect(100, 50, 100, 300)), alpha);
  alpha.copyTo(truth(cv::Rect(100, 50, 100, 300)));
  const PersonCutout cut = CutoutWithGrabCut(image, cv::Rect(85, 35, 130, 330), 5, 1, "test image");
  // The cut-out is cropped to the segmented box; compare areas and the box.
  cv::Mat cut_alpha;
  cv::extractChannel(cut.bgra, cut_alpha, 3);
  const double cut_area = cv::countNonZero(cut_alpha), true_area = cv::countNonZero(truth);
  EXPECT_NEAR(cut_area / true_area, 1.0, 0.15);
  // GrabCut may lose the dark head behind the thin neck: at least the body from shoulders down.
  EXPECT_GE(cut.bgra.rows, 225);
  EXPECT_LE(cut.bgra.rows, 315);
  EXPECT_NEAR(cut.bgra.cols, 100, 15);
  EXPECT_THROW(CutoutWithGrabCut(image, cv::Rect(250, 350, 100, 100), 5, 1, "test image"), InputError);
}

TEST(PersonCutout, DepthCutsTheBoxToItsNearestLayer) {
  // A figure 1.5 m away in front of a wall 3 m away, with a hole (no reading) in its chest and
  // a small object at 1.6 m outside it: the cut-out is the figure with its hole, not the object.
  cv::Mat image(200, 160, CV_8UC3, cv::Scalar(90, 100, 110)), depth(200, 160, CV_16U, cv::Scalar(15000));
  const cv::Rect figure(50, 20, 40, 150);
  depth(figure).setTo(7500);
  depth(cv::Rect(65, 60, 3, 3)).setTo(0);
  depth(cv::Rect(110, 150, 10, 10)).setTo(8000);
  const PersonCutout cut = CutoutWithDepth(image, depth, cv::Rect(40, 10, 60, 170), "d.png");
  EXPECT_EQ(cut.bgra.size(), figure.size());
  cv::Mat alpha;
  cv::extractChannel(cut.bgra, alpha, 3);
  EXPECT_EQ(cv::countNonZero(alpha), figure.area());
  // The same box widened over the object: the object is a separate, smaller part.
  EXPECT_EQ(CutoutWithDepth(image, depth, cv::Rect(40, 10, 90, 170), "d.png").bgra.size(), figure.size());
  // A person 0.6 m in front of the one behind: only the nearer one.
  depth(cv::Rect(50, 20, 20, 150)).setTo(4500);
  EXPECT_EQ(CutoutWithDepth(image, depth, cv::Rect(40, 10, 60, 170), "d.png").bgra.size(), cv::Size(20, 150));
  EXPECT_THROW(CutoutWithDepth(image, cv::Mat(200, 160, CV_16U, cv::Scalar(0)), figure, "d.png"), InputError);
  EXPECT_THROW(CutoutWithDepth(image, cv::Mat(100, 160, CV_16U, cv::Scalar(1)), figure, "d.png"), InputError);
  EXPECT_THROW(CutoutWithDepth(image, depth, cv::Rect(150, 20, 40, 40), "d.png"), InputError);
}

TEST(PersonCutout, FromMaskCropsAndRejectsBadInput) {
  cv::Mat image(50, 40, CV_8UC3, cv::Scalar(1, 2, 3)), mask(50, 40, CV_8U, cv::Scalar(0));
  mask(cv::Rect(10, 5, 8, 30)).setTo(255);
  const PersonCutout cut = CutoutFromMask(image, mask, "m.png");
  EXPECT_EQ(cut.bgra.size(), cv::Size(8, 30));
  EXPECT_EQ(cut.bgra.at<cv::Vec4b>(3, 3), cv::Vec4b(1, 2, 3, 255));
  EXPECT_THROW(CutoutFromMask(image, cv::Mat(50, 40, CV_8U, cv::Scalar(0)), "m.png"), InputError);
  EXPECT_THROW(CutoutFromMask(image, cv::Mat(10, 10, CV_8U, cv::Scalar(255)), "m.png"), InputError);
  EXPECT_THROW(LoadPersonCutout("/nonexistent/person.png", "/nonexistent/mask.png"), InputError);
}

TEST(PeopleInsertion, ChecksOptionsNamingTheKey) {
  InsertionOptions o;
  o.distance_m = 0.1;
  try {
    o.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("insert.distance_m"), std::string::npos) << e.what();
  }
  o = InsertionOptions();
  o.preset = Scenario::kNone;
  EXPECT_THROW(o.Check(), InputError);
}

}  // namespace
}  // namespace dynvo
