#include "synth/people_insertion.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "dataset/camera_file.h"
#include "dataset/image_list.h"
#include "dataset/stamp_matching.h"
#include "dataset/tum_dataset.h"
#include "synth/trajectory_sampling.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string Number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void RequireRange(double value, double lo, double hi, const char* key) {
  if (!(value >= lo && value <= hi))
    throw InputError(std::string("insert.") + key + " must be in [" + Number(lo) + ", " + Number(hi) + "], got " +
                     Number(value));
}

// Position along a ping-pong path between a and b after `walked` metres.
Eigen::Vector2d PingPong(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double walked) {
  const double length = (b - a).norm();
  if (length < 1e-9) return a;
  double along = std::fmod(walked, 2 * length);
  if (along < 0) along += 2 * length;
  const double x = along <= length ? along : 2 * length - along;
  return a + (b - a) * (x / length);
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

InsertionPlan PlanInsertion(const InsertionOptions& options, const PersonCutout& cutout,
                            const Trajectory& groundtruth, double first_stamp, double last_stamp,
                            const Camera& camera) {
  options.Check();
  if (cutout.bgra.empty() || cutout.bgra.type() != CV_8UC4) throw InputError("person cut-out must be 8-bit BGRA");
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
  const Eigen::Vector3d right = forward.cross(up);

  InsertionPlan plan;
  plan.world_from_stage.linear().col(0) = right;
  plan.world_from_stage.linear().col(1) = forward;
  plan.world_from_stage.linear().col(2) = up;
  plan.world_from_stage.translation() = reference.translation() - options.camera_height_m * up;
  plan.start_stamp = first_stamp;
  plan.person_height_m = options.person_height_m;
  plan.person_width_m = options.person_height_m * cutout.bgra.cols / cutout.bgra.rows;
  const double texel = options.person_height_m / cutout.bgra.rows;
  plan.textures.push_back(MakeTexture(cutout.bgra, texel));
  cv::Mat mirrored;
  cv::flip(cutout.bgra, mirrored, 1);
  plan.textures.push_back(MakeTexture(mirrored, texel));

  // Half the horizontal field of view: walkers turn where they are out of view.
  const double tan_half = std::max(camera.cx, camera.width - camera.cx) / camera.fx;
  const double v = options.walk_speed_mps;
  const double d = options.distance_m > 0 ? options.distance_m : 2.0;
  const double duration = last_stamp - first_stamp;
  auto across = [&](double depth, double direction, double speed, int texture) {
    const double half = std::max(depth * tan_half + plan.person_width_m + 0.3, 0.5 * speed * duration + 0.2);
    InsertionPlan::Walker w;
    w.from = {-direction * half, depth};
    w.to = {direction * half, depth};
    w.speed_mps = speed;
    w.texture = texture;
    return w;
  };
  switch (options.preset) {
    case Scenario::kWalkingAcross: plan.walkers.push_back(across(d, 1.0, v, 0)); break;
    case Scenario::kTwoCrossing:
      plan.walkers.push_back(across(d, 1.0, v, 0));
      plan.walkers.push_back(across(d + 1.2, -1.0, 1.15 * v, 1));
      break;
    case Scenario::kWalkingToward: {
      InsertionPlan::Walker w;
      w.from = {0.15, d + 2.5};
      w.to = {0.1, std::max(0.6, d - 1.2)};
      w.speed_mps = v;
      plan.walkers.push_back(w);
      break;
    }
    case Scenario::kSittingSway: {
      InsertionPlan::Walker w;
      w.from = {0.3, d};
      w.to = w.from;
      w.sway = true;
      plan.walkers.push_back(w);
      break;
    }
    case Scenario::kNone: break;
  }
  return plan;
}

std::vector<TexturedQuad> InsertionQuadsAt(const InsertionPlan& plan, double stamp) {
  std::vector<TexturedQuad> quads;
  const double t = stamp - plan.start_stamp;
  for (size_t i = 0; i < plan.walkers.size(); ++i) {
    const InsertionPlan::Walker& w = plan.walkers[i];
    Eigen::Vector2d at = PingPong(w.from, w.to, w.speed_mps * t);
    double lean = 0;
    if (w.sway) {
      at.x() += 0.08 * std::sin(2 * kPi * t / 3.1);
      lean = 0.05 * std::sin(2 * kPi * t / 3.1 + 0.6);  // radians about the feet
    }
    const double h = plan.person_height_m, half = 0.5 * plan.person_width_m;
    // Cut-out plane faces the reference camera (stage -y); texture rows run downwards.
    const Eigen::Vector3d up(std::sin(lean), 0, std::cos(lean)), side(std::cos(lean), 0, -std::sin(lean));
    const Eigen::Vector3d feet(at.x(), at.y(), 0);
    TexturedQuad q;
    q.origin = plan.world_from_stage * (feet - half * side + h * up);
    q.edge_u = plan.world_from_stage.linear() * (2 * half * side);
    q.edge_v = plan.world_from_stage.linear() * (-h * up);
    q.texture = plan.textures.at(static_cast<size_t>(w.texture));
    q.shade = 1.0f;
    q.object_id = static_cast<int>(i) + 1;
    quads.push_back(q);
  }
  return quads;
}

int CompositePeople(const RenderResult& people, double depth_factor, cv::Mat* bgr, cv::Mat* depth16, cv::Mat* mask) {
  CV_Assert(bgr->type() == CV_8UC3 && depth16->type() == CV_16U && bgr->size() == people.bgr.size() &&
            depth16->size() == people.bgr.size());
  *mask = cv::Mat::zeros(bgr->size(), CV_8U);
  int written = 0;
  for (int y = 0; y < bgr->rows; ++y) {
    const std::uint16_t* id = people.object_id.ptr<std::uint16_t>(y);
    const float* z = people.depth.ptr<float>(y);
    const cv::Vec3b* colour = people.bgr.ptr<cv::Vec3b>(y);
    cv::Vec3b* out = bgr->ptr<cv::Vec3b>(y);
    std::uint16_t* depth = depth16->ptr<std::uint16_t>(y);
    uchar* m = mask->ptr<uchar>(y);
    for (int x = 0; x < bgr->cols; ++x) {
      if (id[x] == 0) continue;
      const double person = std::round(z[x] * depth_factor);
      if (depth[x] != 0 && !(person < depth[x])) continue;  // the real surface is nearer
      out[x] = colour[x];
      depth[x] = static_cast<std::uint16_t>(std::clamp(person, 1.0, 65535.0));
      m[x] = 255;
      ++written;
    }
  }
  return written;
}

InsertionSummary InsertPeopleIntoSequence(const std::string& dataset, const PersonCutout& cutout,
                                          const InsertionOptions& options, const std::string& out_folder) {
  options.Check();
  TumDatasetOptions dataset_options;
  dataset_options.undistort = false;
  const TumDataset sequence(dataset, dataset_options);
  const fs::path in(dataset), out(out_folder);
  if (!sequence.has_groundtruth() || sequence.groundtruth().empty())
    ThrowFileError((in / "groundtruth.txt").string(), 0, "missing or empty: people are placed with the groundtruth");
  const std::vector<ImageListEntry> rgb = ReadImageList((in / "rgb.txt").string());
  const std::vector<ImageListEntry> depth = ReadImageList((in / "depth.txt").string());
  std::vector<double> rgb_stamps, depth_stamps;
  for (const ImageListEntry& e : rgb) rgb_stamps.push_back(e.stamp);
  for (const ImageListEntry& e : depth) depth_stamps.push_back(e.stamp);
  std::vector<int> depth_of_rgb(rgb.size(), -1);
  for (const auto& [r, d] : MatchStamps(rgb_stamps, depth_stamps, dataset_options.max_time_difference))
    depth_of_rgb[r] = static_cast<int>(d);

  const Camera camera = sequence.raw_camera();
  double summary_distance = options.distance_m;
  const double factor = sequence.depth_factor();
  const Renderer renderer(camera);
  InsertionOptions chosen = options;
  if (chosen.distance_m == 0) {
    // The distance that shows the largest part of the people's bodies: visible pixels summed
    // over a few spread frames, times distance squared (a body's image area falls with it), so
    // neither occluded nor cut off by the image border. (Plain pixel counts would always pick
    // people right in front of the lens.)
    std::vector<std::pair<size_t, cv::Mat>> probes;  // rgb index, real depth
    for (int k = 1; k <= 5; ++k) {
      const size_t i = (rgb.size() - 1) * static_cast<size_t>(k) / 6;
      if (depth_of_rgb[i] < 0) continue;
      const std::string path = (in / depth[static_cast<size_t>(depth_of_rgb[i])].path).string();
      cv::Mat depth16 = cv::imread(path, cv::IMREAD_UNCHANGED);
      if (depth16.type() != CV_16U || depth16.cols != camera.width || depth16.rows != camera.height)
        ThrowFileError(path, 0, "expected a 16-bit 1-channel PNG of the camera's size");
      probes.emplace_back(i, depth16);
    }
    double best_score = -1;
    for (double d = 1.0; d <= 4.01; d += 0.2) {
      chosen.distance_m = d;
      const InsertionPlan plan = PlanInsertion(chosen, cutout, sequence.groundtruth(), rgb_stamps.front(),
                                               rgb_stamps.back(), camera);
      int pixels = 0;
      for (const auto& [i, real_depth] : probes) {
        Pose world_from_camera;
        if (!InterpolatePose(sequence.groundtruth(), rgb[i].stamp, options.max_pose_gap_s, &world_from_camera))
          continue;
        cv::Mat bgr(real_depth.size(), CV_8UC3), depth16 = real_depth.clone(), mask;
        pixels += CompositePeople(renderer.Render(InsertionQuadsAt(plan, rgb[i].stamp), world_from_camera.inverse()),
                                  factor, &bgr, &depth16, &mask);
      }
      if (pixels * d * d > best_score) {
        best_score = pixels * d * d;
        summary_distance = d;
      }
    }
    chosen.distance_m = summary_distance;
  }
  const InsertionPlan plan = PlanInsertion(chosen, cutout, sequence.groundtruth(), rgb_stamps.front(),
                                           rgb_stamps.back(), camera);

  // Everything as it was first; frames with people are rewritten below.
  for (const char* name : {"rgb.txt", "depth.txt", "groundtruth.txt", "accelerometer.txt", "camera.json"})
    if (fs::is_regular_file(in / name)) CopyFile(in / name, out / name);
  if (!fs::is_regular_file(in / "camera.json")) WriteCameraFile((out / "camera.json").string(), camera, factor);
  for (const ImageListEntry& e : rgb) CopyFile(in / e.path, out / e.path);
  for (const ImageListEntry& e : depth) CopyFile(in / e.path, out / e.path);
  fs::create_directories(out / "masks");

  InsertionSummary summary;
  std::string masks_list = "# dynamic masks (255 = pixel of an inserted person), one per color image\n"
                           "# people inserted by dynvo-insert-people into " + sequence.name() +
                           "\n# timestamp filename\n";
  double ratio_sum = 0;
  for (size_t i = 0; i < rgb.size(); ++i) {
    const std::string mask_name = "masks/" + FormatStamp(rgb[i].stamp) + ".png";
    masks_list += FormatStamp(rgb[i].stamp) + " " + mask_name + "\n";
    cv::Mat mask = cv::Mat::zeros(camera.height, camera.width, CV_8U);
    Pose world_from_camera;
    const bool posed = InterpolatePose(sequence.groundtruth(), rgb[i].stamp, options.max_pose_gap_s, &world_from_camera);
    if (!posed) ++summary.frames_without_pose;
    if (posed && depth_of_rgb[i] >= 0) {
      const std::string rgb_path = (in / rgb[i].path).string();
      const std::string depth_path = (in / depth[static_cast<size_t>(depth_of_rgb[i])].path).string();
      cv::Mat bgr = cv::imread(rgb_path, cv::IMREAD_UNCHANGED);
      cv::Mat depth16 = cv::imread(depth_path, cv::IMREAD_UNCHANGED);
      if (bgr.type() != CV_8UC3 || bgr.cols != camera.width || bgr.rows != camera.height)
        ThrowFileError(rgb_path, 0, "expected an 8-bit 3-channel PNG of the camera's size");
      if (depth16.type() != CV_16U || depth16.size() != bgr.size())
        ThrowFileError(depth_path, 0, "expected a 16-bit 1-channel PNG of the camera's size");
      const RenderResult people =
          renderer.Render(InsertionQuadsAt(plan, rgb[i].stamp), world_from_camera.inverse());
      if (CompositePeople(people, factor, &bgr, &depth16, &mask) > 0) {
        WritePng((out / rgb[i].path).string(), bgr);
        WritePng((out / depth[static_cast<size_t>(depth_of_rgb[i])].path).string(), depth16);
        ++summary.frames_with_people;
      }
    }
    ratio_sum += double(cv::countNonZero(mask)) / mask.total();
    WritePng((out / mask_name).string(), mask);
  }
  std::ofstream(out / "masks.txt") << masks_list;
  summary.frames = static_cast<int>(rgb.size());
  summary.distance_m = chosen.distance_m;
  summary.mean_dynamic_ratio = rgb.empty() ? 0 : ratio_sum / rgb.size();
  return summary;
}

}  // namespace dynvo
