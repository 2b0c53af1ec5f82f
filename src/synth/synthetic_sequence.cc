#include "synth/synthetic_sequence.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "core/executor.h"
#include "core/number_text.h"
#include "dataset/known_cameras.h"
#include "synth/people_labels.h"
#include "synth/rolling_shutter.h"
#include "synth/tum_writer.h"

namespace dynvo {

Camera TumIntrinsics(const std::string& name, const std::string& key) {
  if (name == "fr1" || name == "fr2" || name == "fr3") return KnownCameraByName(name)->camera;
  if (name == "ros") return KnownCameraByName("ros_default")->camera;
  throw InputError(key + " must be one of fr1, fr2, fr3, ros, got '" + name + "'");
}

namespace {

// A camera the renderer can draw: the principal point inside the image, a field of view
// between 0.5 and 160 degrees across (focal length between 0.09 and 100 image widths).
void CheckPinhole(const Camera& camera) {
  const auto fov_ok = [](double focal, int size) { return focal >= 0.09 * size && focal <= 100.0 * size; };
  if (!fov_ok(camera.fx, camera.width) || !fov_ok(camera.fy, camera.height))
    throw InputError("synth.camera: fx " + ShortText(camera.fx) + " and fy " + ShortText(camera.fy) +
                     " must give a field of view of 0.5 to 160 degrees (0.09 to 100 times the image's width and "
                     "height in pixels)");
  if (!(camera.cx >= 0 && camera.cx <= camera.width - 1) || !(camera.cy >= 0 && camera.cy <= camera.height - 1))
    throw InputError("synth.camera: the principal point (" + ShortText(camera.cx) + ", " + ShortText(camera.cy) +
                     ") must lie inside the " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                     " image");
}

}  // namespace

SyntheticSequenceOptions::SyntheticSequenceOptions() : camera(TumIntrinsics("fr3", "")) {}

void SyntheticSequenceOptions::Check() const {
  RequireOption(frames >= 1, "synth", "frames", ">= 1", frames);
  RequireOption(fps > 0 && fps <= 60, "synth", "fps", "in (0, 60]", fps);
  camera.Check("synth.camera");
  if (camera.HasDistortion())
    throw InputError("synth.camera: distortion must be zero (synthetic frames are rendered pinhole)");
  if (camera.width < 16 || camera.height < 16) throw InputError("synth.camera: width and height must be >= 16");
  CheckPinhole(camera);
  RequireOption(motion_blur_samples >= 3 && motion_blur_samples % 2 == 1, "synth", "motion_blur_samples",
                "odd and >= 3", motion_blur_samples);
  RequireOption(exposure_s > 0 && exposure_s < 1.0 / fps, "synth", "exposure_s", "in (0, 1/fps)", exposure_s);
  RequireOption(rolling_shutter_readout_s >= 0 && rolling_shutter_readout_s < 1.0 / fps, "synth",
                "rolling_shutter_readout_s", "in [0, 1/fps)", rolling_shutter_readout_s);
  RequireOption(rolling_shutter_bands >= 1 && rolling_shutter_bands <= camera.height, "synth", "rolling_shutter_bands",
                "in [1, camera.height]", rolling_shutter_bands);
  RequireOption(start_stamp >= 0 && start_stamp < 1e10, "synth", "start_stamp", "in [0, 1e10)", start_stamp);
  room.Check();
  noise.Check();
}

SyntheticWorld::SyntheticWorld(const SyntheticSequenceOptions& options)
    : options_((options.Check(), options)),
      static_quads_(MakeRoomScene(options.room, options.seed)),
      people_(MakeScenarioPeople(options.scenario, options.seed * 1009u + 17u)),
      renderer_(options.camera) {
  if (IsTumScenario(options.scenario)) {
    // The room's free lanes (scene.h) hold the people: the stage is the room seen from the
    // start camera, the people 2 m ahead, the photos taken in turn from the seed on.
    const std::vector<PersonCutout> photos = DefaultPersonCutouts();
    for (size_t k = 0; k < photos.size(); ++k)
      dolls_.push_back(MakeArticulatedCutout(photos[(k + options.seed) % photos.size()], 1.7));
    StageGeometry geometry;
    geometry.distance_m = 2.0;
    geometry.tan_half_fov = std::max(options.camera.cx, options.camera.width - options.camera.cx) / options.camera.fx;
    geometry.person_width_m = dolls_.front().width_m;
    geometry.duration_s = options.frames / options.fps;
    stage_people_ = PlanStagePeople(options.scenario, geometry);
  }
  std::mt19937 rng(options.seed * 7919u + 3u);
  // Depth lags RGB by a few milliseconds, little enough that every depth frame stays
  // nearest to its own RGB frame (TUM association picks the nearest pairs).
  std::uniform_real_distribution<double> jitter(-0.002, 0.002), lag(0.002, std::min(0.012, 0.25 / options.fps));
  for (int i = 0; i < options.frames; ++i) {
    const double rgb = RoundStamp(options.start_stamp + i / options.fps + (i > 0 ? jitter(rng) : 0.0));
    rgb_stamps_.push_back(rgb);
    depth_stamps_.push_back(RoundStamp(rgb + lag(rng)));
  }
}

Pose SyntheticWorld::WorldFromCamera(double seconds) const { return CameraPathPose(options_.camera_path, seconds); }

std::vector<TexturedQuad> SyntheticWorld::QuadsAt(double seconds) const {
  std::vector<TexturedQuad> quads = static_quads_;
  for (const MovingPerson& person : people_) {
    const std::vector<TexturedQuad> parts = PersonQuadsAt(person, seconds);
    quads.insert(quads.end(), parts.begin(), parts.end());
  }
  const std::vector<TexturedQuad> stage = StagePeopleQuadsAt(stage_people_, dolls_, Pose::Identity(), seconds);
  quads.insert(quads.end(), stage.begin(), stage.end());
  return quads;
}

std::vector<bool> SyntheticWorld::MovingAt(double seconds) const {
  std::vector<bool> moving(people_.size(), true);
  for (const StagePerson& person : stage_people_)
    moving.push_back(StagePersonSpeed(person, dolls_.at(static_cast<size_t>(person.doll) % dolls_.size()), seconds) >
                     kMovingSpeedMps);
  return moving;
}

RenderResult SyntheticWorld::RenderAt(double seconds) const {
  return RenderRollingShutter(
      renderer_, [this](double s) { return QuadsAt(s); },
      [this](double s) { return Pose(WorldFromCamera(s).inverse()); }, seconds, options_.rolling_shutter_readout_s,
      options_.rolling_shutter_bands);
}

RenderResult SyntheticWorld::RenderGlobalAt(double seconds) const {
  return renderer_.Render(QuadsAt(seconds), WorldFromCamera(seconds).inverse());
}

double SyntheticWorld::DepthSceneTime(int index) const {
  return DepthStamp(index) - (options_.kinect_timing ? kKinectDepthLeadS : 0.0) - options_.start_stamp;
}

int SyntheticWorld::MotionBlurSamples(double seconds) const {
  const Pose from = WorldFromCamera(seconds - 0.5 * options_.exposure_s);
  const Pose to = WorldFromCamera(seconds + 0.5 * options_.exposure_s);
  const Pose to_from_from = to.inverse() * from;
  const Camera& c = options_.camera;
  double smear_px = 0;
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(0, 0), Eigen::Vector2d(c.width - 1, 0),
                                        Eigen::Vector2d(0, c.height - 1), Eigen::Vector2d(c.width - 1, c.height - 1)}) {
    const Eigen::Vector3d moved = to_from_from * c.Backproject(corner, 1.0);
    if (moved.z() > 0.1) smear_px = std::max(smear_px, (c.Project(moved) - corner).norm());
  }
  const int steps = std::min(kMaxBlurSamples - 1, static_cast<int>(std::ceil(smear_px / kMaxBlurStepPx)));
  return std::max(options_.motion_blur_samples, steps + 1 + steps % 2);  // odd: steps even
}

SyntheticFrame SyntheticWorld::RenderFrame(int index) const {
  SyntheticFrame frame;
  frame.rgb_stamp = RgbStamp(index);
  frame.depth_stamp = DepthStamp(index);
  const double t = frame.rgb_stamp - options_.start_stamp;
  frame.world_from_camera = WorldFromCamera(t);
  frame.clean = RenderAt(t);
  // Every pixel any render of the frame shows a moving object at; of them, where one shows a
  // person not moving, and where one shows anything else.
  const std::vector<bool> moving = MovingAt(t);
  frame.mask = cv::Mat::zeros(frame.clean.object_id.size(), CV_8U);
  cv::Mat still = frame.mask.clone(), others = frame.mask.clone();
  const auto touch = [&](const cv::Mat& object_id) {
    const cv::Mat still_here = StillPeoplePixels(object_id, moving);
    frame.mask |= object_id > 0;
    still |= still_here;
    others |= (object_id > 0) & ~still_here;
  };
  touch(frame.clean.object_id);
  if (options_.motion_blur) {
    const int n = MotionBlurSamples(t);
    cv::Mat sum;
    frame.clean.bgr.convertTo(sum, CV_32FC3);
    for (int k = 0; k < n; ++k) {
      if (k == n / 2) continue;  // the centre sample is the clean render
      const double ts = t + options_.exposure_s * (double(k) / (n - 1) - 0.5);
      const RenderResult sub = RenderAt(ts);  // each row's time shifted alike
      cv::accumulate(sub.bgr, sum);
      touch(sub.object_id);
    }
    sum.convertTo(frame.bgr, CV_8UC3, 1.0 / n);
  } else {
    frame.bgr = frame.clean.bgr.clone();
  }
  const std::uint32_t frame_seed = options_.seed * 2654435761u + static_cast<std::uint32_t>(index) * 40503u;
  cv::Mat depth_m = frame.clean.depth;
  if (options_.kinect_timing) {
    const double td = DepthSceneTime(index);  // all rows at once: no rolling shutter measured
    const RenderResult at_depth = RenderGlobalAt(td);
    depth_m = at_depth.depth;
    touch(at_depth.object_id);  // the people's pixels in either image
    const double gain = 1.0 + 0.1 * std::sin(2 * 3.14159265358979323846 * t / 6.1 + options_.seed);
    frame.bgr.convertTo(frame.bgr, CV_8UC3, gain);
  }
  ApplyRgbNoise(options_.noise, frame_seed, &frame.bgr);
  frame.depth16 = MakeSensorDepth(options_.noise, frame_seed + 1u, depth_m);
  frame.still_people = still & ~others;
  return frame;
}

Trajectory SyntheticWorld::Groundtruth() const {
  Trajectory gt;
  const double first = rgb_stamps_.front() - 0.5, last = rgb_stamps_.back() + 0.5;
  for (int k = 0;; ++k) {
    const double stamp = RoundStamp(first + 0.0043 + 0.01 * k);
    if (stamp > last) break;
    gt.push_back({stamp, WorldFromCamera(stamp - options_.start_stamp)});
  }
  return gt;
}

SyntheticSequenceSummary WriteSyntheticSequence(const SyntheticSequenceOptions& options, const std::string& folder) {
  const SyntheticWorld world(options);
  const long readout_ms = std::lround(options.rolling_shutter_readout_s * 1000.0);
  TumWriter writer(folder, "dynvo synthetic sequence: scenario " + ScenarioName(options.scenario) + ", camera path " +
                               CameraPathPresetName(options.camera_path) + ", seed " + std::to_string(options.seed) +
                               (readout_ms > 0 ? ", rolling shutter " + std::to_string(readout_ms) + " ms" : "") +
                               (options.kinect_timing
                                    ? ", depth " + std::to_string(std::lround(kKinectDepthLeadS * 1000)) + " ms early"
                                    : ""));
  SyntheticSequenceSummary summary;
  double ratio_sum = 0;
  PeopleLabels labels("dynvo-synth");
  // PNG encoding of frame i overlaps the rendering of frame i + 1 (one frame in flight, so
  // the writer is never used by two threads at once); the output does not depend on timing.
  Executor executor(1);
  Task<void> pending;
  for (int i = 0; i < world.size(); ++i) {
    auto frame = std::make_shared<SyntheticFrame>(world.RenderFrame(i));
    const int dynamic = cv::countNonZero(frame->mask);
    ratio_sum += double(dynamic) / frame->mask.total();
    if (dynamic > 0) ++summary.frames_with_people;
    labels.AddFrame(frame->rgb_stamp, frame->clean.object_id, frame->mask,
                    world.MovingAt(frame->rgb_stamp - options.start_stamp));
    if (pending.valid()) pending.Get();  // rethrows a write error
    pending = executor.Submit([&writer, frame] {
      writer.AddFrame(frame->rgb_stamp, frame->bgr, frame->depth_stamp, frame->depth16,
                      LabelStillPeople(frame->mask, frame->still_people));
    });
  }
  if (pending.valid()) pending.Get();
  Camera written = options.camera;  // camera.json tells readers the readout its frames have
  written.rolling_shutter_readout_s = options.rolling_shutter_readout_s;
  writer.Finish(world.Groundtruth(), written, options.noise.depth_factor);
  labels.Write(folder);
  summary.frames = world.size();
  summary.mean_dynamic_ratio = ratio_sum / world.size();
  return summary;
}

}  // namespace dynvo
