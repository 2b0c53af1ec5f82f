#include "synth/people_insertion.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "core/number_text.h"
#include "dataset/camera_file.h"
#include "dataset/image_list.h"
#include "dataset/stamp_matching.h"
#include "dataset/tum_dataset.h"
#include "synth/people_labels.h"
#include "synth/sensor_noise.h"
#include "synth/trajectory_sampling.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace fs = std::filesystem;

namespace {

void RequireRange(double value, double lo, double hi, const char* key) {
  if (!(value >= lo && value <= hi))
    throw InputError(std::string("insert.") + key + " must be in [" + ShortText(lo) + ", " + ShortText(hi) + "], got " +
                     ShortText(value));
}

void CopyFile(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_directories(to.parent_path(), ec);
  fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  if (ec) throw InputError(from.string() + ": cannot copy to " + to.string() + ": " + ec.message());
}

}  // namespace

void InsertionOptions::Check() const {
  if (preset == Scenario::kNone) throw InputError("insert.preset must not be none (nothing would be inserted)");
  RequireRange(person_height_m, 0.3, 3.0, "person_height_m");
  if (distance_m != 0) RequireRange(distance_m, 0.5, 20.0, "distance_m");
  RequireRange(walk_speed_mps, 0.0, 5.0, "walk_speed_mps");
  RequireRange(camera_height_m, 0.0, 5.0, "camera_height_m");
  RequireRange(max_pose_gap_s, 0.001, 10.0, "max_pose_gap_s");
}

namespace {

// The stage: origin on the floor below the reference camera, y its horizontal forward.
Pose WorldFromStage(const InsertionOptions& options, const Trajectory& groundtruth, double first_stamp,
                    double last_stamp) {
  const double middle = 0.5 * (first_stamp + last_stamp);
  Pose reference;
  if (!InterpolatePose(groundtruth, middle, options.max_pose_gap_s, &reference))
    throw InputError("groundtruth does not cover the middle of the sequence (stamp " + FormatStamp(middle) + ")");
  // Up: the mean of the cameras' "up" (-y) axes over the sequence, so hand-held roll averages out.
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  for (const StampedPose& p : groundtruth)
    if (p.stamp >= first_stamp && p.stamp <= last_stamp) up -= p.world_from_camera.linear().col(1);
  if (up.norm() < 1e-6) up = -reference.linear().col(1);
  up.normalize();
  if (up.z() > 0.5) up = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d forward = reference.linear().col(2);
  forward -= forward.dot(up) * up;
  if (forward.norm() < 0.1) throw InputError("the reference camera looks straight up or down: no walking plane");
  forward.normalize();
  Pose world_from_stage = Pose::Identity();
  world_from_stage.linear().col(0) = forward.cross(up);
  world_from_stage.linear().col(1) = forward;
  world_from_stage.linear().col(2) = up;
  double camera_height = options.camera_height_m;
  if (camera_height == 0 && IsTumScenario(options.preset)) {
    const Eigen::Vector3d axis = reference.linear().col(2);
    const double below = -axis.dot(up) / std::max(0.1, axis.dot(forward));  // metres down per metre ahead
    camera_height = 0.5 * options.person_height_m + (options.distance_m > 0 ? options.distance_m : 2.0) * below;
  } else if (camera_height == 0) {
    camera_height = 1.5;
  }
  world_from_stage.translation() = reference.translation() - camera_height * up;
  return world_from_stage;
}

}  // namespace

namespace {

// The dolls of the cut-outs, then of their mirror images (a second person from one photo).
std::vector<ArticulatedCutout> MakeDolls(const std::vector<PersonCutout>& cutouts, double height_m) {
  if (cutouts.empty()) throw InputError("no person cut-out to insert");
  std::vector<ArticulatedCutout> dolls;
  for (const PersonCutout& cutout : cutouts) dolls.push_back(MakeArticulatedCutout(cutout, height_m));
  for (const PersonCutout& cutout : cutouts) {
    PersonCutout mirrored;
    cv::flip(cutout.bgra, mirrored.bgra, 1);
    dolls.push_back(MakeArticulatedCutout(mirrored, height_m));
  }
  return dolls;
}

// PlanInsertion with the dolls of `photos` cut-outs already made (MakeDolls).
InsertionPlan PlanWithDolls(const InsertionOptions& options, const std::vector<ArticulatedCutout>& dolls, size_t photos,
                            const Trajectory& groundtruth, double first_stamp, double last_stamp,
                            const Camera& camera) {
  options.Check();
  InsertionPlan plan;
  plan.world_from_stage = WorldFromStage(options, groundtruth, first_stamp, last_stamp);
  plan.start_stamp = first_stamp;
  plan.dolls = dolls;
  StageGeometry geometry;
  geometry.distance_m = options.distance_m > 0 ? options.distance_m : 2.0;
  geometry.speed_mps = options.walk_speed_mps;
  geometry.tan_half_fov = std::max(camera.cx, camera.width - camera.cx) / camera.fx;
  geometry.person_width_m = plan.dolls.front().width_m;
  geometry.duration_s = last_stamp - first_stamp;
  plan.people = PlanStagePeople(options.preset, geometry);
  // Person k takes cut-out k; with fewer cut-outs than people, the mirror images follow.
  for (size_t k = 0; k < plan.people.size(); ++k)
    plan.people[k].doll = static_cast<int>(k < photos ? k : photos + (k - photos) % photos);
  return plan;
}

}  // namespace

InsertionPlan PlanInsertion(const InsertionOptions& options, const std::vector<PersonCutout>& cutouts,
                            const Trajectory& groundtruth, double first_stamp, double last_stamp,
                            const Camera& camera) {
  options.Check();
  return PlanWithDolls(options, MakeDolls(cutouts, options.person_height_m), cutouts.size(), groundtruth, first_stamp,
                       last_stamp, camera);
}

std::vector<TexturedQuad> InsertionQuadsAt(const InsertionPlan& plan, double stamp) {
  return StagePeopleQuadsAt(plan.people, plan.dolls, plan.world_from_stage, stamp - plan.start_stamp);
}

int CompositePeople(const RenderResult& people, double depth_factor, cv::Mat* bgr, cv::Mat* depth16,
                    cv::Mat* person_id) {
  CV_Assert(bgr->type() == CV_8UC3 && depth16->type() == CV_16U && bgr->size() == people.bgr.size() &&
            depth16->size() == people.bgr.size());
  *person_id = cv::Mat::zeros(bgr->size(), CV_16U);
  int written = 0;
  for (int y = 0; y < bgr->rows; ++y) {
    const std::uint16_t* id = people.object_id.ptr<std::uint16_t>(y);
    const float* z = people.depth.ptr<float>(y);
    const cv::Vec3b* colour = people.bgr.ptr<cv::Vec3b>(y);
    cv::Vec3b* out = bgr->ptr<cv::Vec3b>(y);
    std::uint16_t* depth = depth16->ptr<std::uint16_t>(y);
    std::uint16_t* who = person_id->ptr<std::uint16_t>(y);
    for (int x = 0; x < bgr->cols; ++x) {
      if (id[x] == 0) continue;
      const double person = std::round(z[x] * depth_factor);
      if (depth[x] != 0 && !(person < depth[x])) continue;  // the real surface is nearer
      out[x] = colour[x];
      depth[x] = static_cast<std::uint16_t>(std::clamp(person, 1.0, 65535.0));
      who[x] = id[x];
      ++written;
    }
  }
  return written;
}

void AddPersonDepthNoise(const cv::Mat& person_id, double depth_factor, std::uint32_t seed, cv::Mat* depth16) {
  CV_Assert(person_id.type() == CV_16U && depth16->type() == CV_16U && person_id.size() == depth16->size());
  cv::Mat clean_m(depth16->size(), CV_32F, cv::Scalar(0));
  depth16->convertTo(clean_m, CV_32F, 1.0 / depth_factor);
  clean_m.setTo(0, person_id == 0);
  SensorNoiseOptions noise;
  noise.depth_factor = depth_factor;
  noise.depth_max_m = std::min(noise.depth_max_m, 65535.0 / depth_factor);
  const cv::Mat sensed = MakeSensorDepth(noise, seed, clean_m);
  sensed.copyTo(*depth16, person_id != 0);
}

namespace {

// The rgb and depth lists of a TUM folder and the depth image matched to each colour image.
struct ImagePairs {
  std::vector<ImageListEntry> rgb, depth;
  std::vector<double> rgb_stamps;
  std::vector<int> depth_of_rgb;  // -1: no depth image within the tolerance
};

ImagePairs ReadImagePairs(const fs::path& in, double max_time_difference) {
  ImagePairs pairs;
  pairs.rgb = ReadImageList((in / "rgb.txt").string());
  pairs.depth = ReadImageList((in / "depth.txt").string());
  std::vector<double> depth_stamps;
  for (const ImageListEntry& e : pairs.rgb) pairs.rgb_stamps.push_back(e.stamp);
  for (const ImageListEntry& e : pairs.depth) depth_stamps.push_back(e.stamp);
  pairs.depth_of_rgb.assign(pairs.rgb.size(), -1);
  for (const auto& [r, d] : MatchStamps(pairs.rgb_stamps, depth_stamps, max_time_difference))
    pairs.depth_of_rgb[r] = static_cast<int>(d);
  return pairs;
}

cv::Mat ReadImageOfCamera(const std::string& path, int type, const Camera& camera, const char* expected) {
  cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (image.type() != type || image.cols != camera.width || image.rows != camera.height)
    ThrowFileError(path, 0, std::string("expected ") + expected + " of the camera's size");
  return image;
}

// The distance of the people: for the TUM presets, the farthest in 0.7-3 m at which they cover
// at least a fifth of the image (median over a few spread frames, the first among them; TUM's
// people cover 10-50%), else the one at which they cover the most. For the other presets, the
// distance in 1-4 m that shows the largest part of the bodies: visible pixels times distance
// squared (a body's image area falls with it), neither occluded nor cut off by the border.
double ChooseDistance(const InsertionOptions& options, const std::vector<ArticulatedCutout>& dolls, size_t photos,
                      const TumDataset& sequence, const fs::path& in, const ImagePairs& pairs) {
  const Camera camera = sequence.raw_camera();
  const Renderer renderer(camera);
  std::vector<std::pair<size_t, cv::Mat>> probes;  // rgb index, real depth
  for (int k = 0; k <= 5; ++k) {
    const size_t i = (pairs.rgb.size() - 1) * static_cast<size_t>(k) / 6;
    if (pairs.depth_of_rgb[i] < 0) continue;
    const std::string path = (in / pairs.depth[static_cast<size_t>(pairs.depth_of_rgb[i])].path).string();
    probes.emplace_back(i, ReadImageOfCamera(path, CV_16U, camera, "a 16-bit 1-channel PNG"));
  }
  const bool tum = IsTumScenario(options.preset);
  InsertionOptions chosen = options;
  double best_score = -1, best = 2.0;
  for (double d = tum ? 0.7 : 1.0; d <= (tum ? 3.01 : 4.01); d += tum ? 0.1 : 0.2) {
    chosen.distance_m = d;
    const InsertionPlan plan = PlanWithDolls(chosen, dolls, photos, sequence.groundtruth(), pairs.rgb_stamps.front(),
                                             pairs.rgb_stamps.back(), camera);
    std::vector<double> coverage;
    for (const auto& [i, real_depth] : probes) {
      Pose world_from_camera;
      if (!InterpolatePose(sequence.groundtruth(), pairs.rgb_stamps[i], options.max_pose_gap_s, &world_from_camera))
        continue;
      cv::Mat bgr(real_depth.size(), CV_8UC3), depth16 = real_depth.clone(), ids;
      const RenderResult people =
          renderer.Render(InsertionQuadsAt(plan, pairs.rgb_stamps[i]), world_from_camera.inverse());
      coverage.push_back(double(CompositePeople(people, sequence.depth_factor(), &bgr, &depth16, &ids)) / ids.total());
    }
    double sum = 0;
    for (double c : coverage) sum += c;
    const double score = tum ? (MedianOf(coverage) >= 0.2 ? 1.0 + d : MedianOf(coverage)) : sum * d * d;
    if (score > best_score) {
      best_score = score;
      best = d;
    }
  }
  return best;
}

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out.flush()) ThrowFileError(path.string(), 0, "cannot write file");
}

// Each person's state at `stamp`.
std::vector<bool> MovingAt(const InsertionPlan& plan, double stamp) {
  std::vector<bool> moving;
  for (const StagePerson& person : plan.people)
    moving.push_back(StagePersonSpeed(person, plan.dolls.at(static_cast<size_t>(person.doll)),
                                      stamp - plan.start_stamp) > kMovingSpeedMps);
  return moving;
}

}  // namespace

InsertionSummary InsertPeopleIntoSequence(const std::string& dataset, const std::vector<PersonCutout>& cutouts,
                                          const InsertionOptions& options, const std::string& out_folder) {
  options.Check();
  TumDatasetOptions dataset_options;
  dataset_options.undistort = false;
  const TumDataset sequence(dataset, dataset_options);
  const fs::path in(dataset), out(out_folder);
  if (!sequence.has_groundtruth() || sequence.groundtruth().empty())
    ThrowFileError((in / "groundtruth.txt").string(), 0, "missing or empty: people are placed with the groundtruth");
  const ImagePairs pairs = ReadImagePairs(in, dataset_options.max_time_difference);
  if (pairs.rgb.empty()) ThrowFileError((in / "rgb.txt").string(), 0, "lists no image");
  const Camera camera = sequence.raw_camera();
  const double factor = sequence.depth_factor();
  const std::vector<ArticulatedCutout> dolls = MakeDolls(cutouts, options.person_height_m);
  InsertionOptions chosen = options;
  if (chosen.distance_m == 0) chosen.distance_m = ChooseDistance(options, dolls, cutouts.size(), sequence, in, pairs);
  const InsertionPlan plan = PlanWithDolls(chosen, dolls, cutouts.size(), sequence.groundtruth(),
                                           pairs.rgb_stamps.front(), pairs.rgb_stamps.back(), camera);

  // Everything as it was first; frames with people are rewritten below.
  for (const char* name : {"rgb.txt", "depth.txt", "groundtruth.txt", "accelerometer.txt", "camera.json"})
    if (fs::is_regular_file(in / name)) CopyFile(in / name, out / name);
  if (!fs::is_regular_file(in / "camera.json")) WriteCameraFile((out / "camera.json").string(), camera, factor);
  for (const ImageListEntry& e : pairs.rgb) CopyFile(in / e.path, out / e.path);
  for (const ImageListEntry& e : pairs.depth) CopyFile(in / e.path, out / e.path);
  fs::create_directories(out / "masks");

  const Renderer renderer(camera);
  InsertionSummary summary;
  PeopleLabels labels("dynvo-insert-people");
  std::string masks_list =
      "# dynamic masks (255 = pixel of an inserted person, 128 = of one not moving), one per color image\n"
      "# people inserted by dynvo-insert-people into " +
      sequence.name() + "\n# timestamp filename\n";
  for (size_t i = 0; i < pairs.rgb.size(); ++i) {
    const double stamp = pairs.rgb_stamps[i];
    const std::string mask_name = "masks/" + FormatStamp(stamp) + ".png";
    masks_list += FormatStamp(stamp) + " " + mask_name + "\n";
    cv::Mat person_id = cv::Mat::zeros(camera.height, camera.width, CV_16U);
    Pose world_from_camera;
    const bool posed = InterpolatePose(sequence.groundtruth(), stamp, options.max_pose_gap_s, &world_from_camera);
    if (!posed) ++summary.frames_without_pose;
    const int d = pairs.depth_of_rgb[i];
    if (posed && d >= 0) {
      const std::string rgb_path = (in / pairs.rgb[i].path).string();
      const std::string depth_path = (in / pairs.depth[static_cast<size_t>(d)].path).string();
      cv::Mat bgr = ReadImageOfCamera(rgb_path, CV_8UC3, camera, "an 8-bit 3-channel PNG");
      cv::Mat depth16 = ReadImageOfCamera(depth_path, CV_16U, camera, "a 16-bit 1-channel PNG");
      const RenderResult people = renderer.Render(InsertionQuadsAt(plan, stamp), world_from_camera.inverse());
      if (CompositePeople(people, factor, &bgr, &depth16, &person_id) > 0) {
        AddPersonDepthNoise(person_id, factor, options.seed * 7919u + static_cast<std::uint32_t>(i), &depth16);
        WritePng((out / pairs.rgb[i].path).string(), bgr);
        WritePng((out / pairs.depth[static_cast<size_t>(d)].path).string(), depth16);
        ++summary.frames_with_people;
        if (summary.first_frame_with_people < 0) summary.first_frame_with_people = static_cast<int>(i);
      }
    }
    const cv::Mat mask = person_id > 0;
    const std::vector<bool> moving = MovingAt(plan, stamp);
    labels.AddFrame(stamp, person_id, mask, moving);
    WritePng((out / mask_name).string(), LabelStillPeople(mask, StillPeoplePixels(person_id, moving)));
  }
  WriteText(out / "masks.txt", masks_list);
  labels.Write(out.string());
  summary.frames = static_cast<int>(pairs.rgb.size());
  summary.distance_m = chosen.distance_m;
  double sum = 0;
  for (double c : labels.coverage()) sum += c;
  summary.mean_dynamic_ratio = sum / labels.coverage().size();
  summary.median_coverage = MedianOf(labels.coverage());
  return summary;
}

}  // namespace dynvo
