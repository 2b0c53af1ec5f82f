#pragma once
// Synthetic dynamic RGB-D sequences with ground truth: a textured room, a camera path
// preset, moving people (box people, or for the TUM scenarios the articulated photo people of
// synth/stage_people.h standing in the room's free lanes), sensor noise; camera poses and
// per-frame dynamic masks are exact.
// Deterministic from the seed.

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "dataset/trajectory_io.h"
#include "synth/camera_path.h"
#include "synth/moving_object.h"
#include "synth/renderer.h"
#include "synth/scene.h"
#include "synth/sensor_noise.h"
#include "synth/stage_people.h"

namespace dynvo {

// TUM's published pinhole intrinsics: "fr1", "fr2", "fr3" (with distortion for fr1/fr2),
// or "ros" (the 525 default); 640x480. Throws InputError naming `key` otherwise.
Camera TumIntrinsics(const std::string& name, const std::string& key);

// How long before its stamp a Kinect v1 depth image shows the scene, relative to the colour
// image (which shows it at its stamp), seconds. Measured on the real fr1_rpy_head150 against its
// ground truth: depth images agree best with it 15-20 ms before their stamps, colour images
// 0-4 ms before theirs (docs/findings.md).
constexpr double kKinectDepthLeadS = 0.014;

// Largest image step between consecutive sub-frames of a motion-blurred frame, pixels, and the
// most sub-frames one frame takes (a camera turning 100 deg/s smears about 20 px in 20 ms).
constexpr double kMaxBlurStepPx = 1.5;
constexpr int kMaxBlurSamples = 31;

struct SyntheticSequenceOptions {
  Scenario scenario = Scenario::kWalkingAcross;           // moving objects
  CameraPathPreset camera_path = CameraPathPreset::kXyz;  // camera motion
  int frames = 300;                                       // RGB-D frames to generate
  double fps = 30.0;                                      // frames per second, in (0, 60]
  Camera camera;                                          // intrinsics, no distortion (default: TUM fr3, 640x480)
  std::uint32_t seed = 1;                                 // everything random derives from it
  bool motion_blur = false;                               // average sub-frames over the exposure
  // Sub-frames per blurred frame at least (odd, >= 3); more where the camera moves fast, so that
  // consecutive sub-frames lie at most kMaxBlurStepPx apart (a smear, not a row of copies).
  int motion_blur_samples = 5;
  double exposure_s = 0.02;  // seconds the shutter is open (motion blur)
  // Kinect v1: the depth image stamped a few ms after the colour image but showing the scene
  // kKinectDepthLeadS before its stamp, all rows at once; and a slow auto-exposure drift of the
  // colour image's brightness (+-10%).
  bool kinect_timing = false;
  // Seconds from the first to the last row's exposure of the colour image (and of the depth
  // image without kinect_timing), in [0, 1/fps) (0 = global shutter; see synth/rolling_shutter.h);
  // dynvo-synth sets 28 ms for tum_*.
  double rolling_shutter_readout_s = 0;
  int rolling_shutter_bands = 16;     // horizontal bands rendered at their own time, in [1, camera.height]
  double start_stamp = 1700000000.0;  // seconds, stamp of the first frame
  RoomOptions room;                   // the static scene
  SensorNoiseOptions noise;           // sensor effects

  SyntheticSequenceOptions();
  // Throws InputError naming the key ("synth.frames must be >= 1, got 0").
  void Check() const;
};

// One generated frame.
struct SyntheticFrame {
  double rgb_stamp = 0;    // seconds
  double depth_stamp = 0;  // seconds, a few milliseconds after rgb_stamp
  Pose world_from_camera;  // exact pose at rgb_stamp
  cv::Mat bgr;             // CV_8UC3 with sensor effects
  cv::Mat depth16;         // CV_16U, depth_factor units, 0 = no reading
  cv::Mat mask;            // CV_8U, 255 where a moving object is seen
  cv::Mat still_people;    // CV_8U, 255 where of them only people not moving (MovingAt) are seen
  RenderResult clean;      // the noise-free render at rgb_stamp, rows at their rolling-shutter
                           // times (depth in metres, ids)
};

// The scene, people and camera path of one sequence; renders any frame on demand.
class SyntheticWorld {
 public:
  // Builds the room and people (textures included); throws InputError on bad options.
  explicit SyntheticWorld(const SyntheticSequenceOptions& options);

  int size() const { return options_.frames; }
  double RgbStamp(int index) const { return rgb_stamps_.at(static_cast<size_t>(index)); }
  double DepthStamp(int index) const { return depth_stamps_.at(static_cast<size_t>(index)); }
  // When frame `index`'s depth image sees the scene (seconds after start_stamp): its stamp, or
  // with kinect_timing kKinectDepthLeadS before it.
  double DepthSceneTime(int index) const;
  // Exact camera pose at `seconds` after start_stamp.
  Pose WorldFromCamera(double seconds) const;
  // Static scene quads followed by the moving people's quads at `seconds`.
  std::vector<TexturedQuad> QuadsAt(double seconds) const;
  const std::vector<MovingPerson>& people() const { return people_; }
  // Each person's state at `seconds` (object id k + 1 is person k): the box people of the older
  // scenarios always move; the TUM scenarios' people as StagePersonSpeed says.
  std::vector<bool> MovingAt(double seconds) const;
  // The noise-free image exposed around `seconds` (after start_stamp): WorldFromCamera and
  // QuadsAt rendered at `seconds`, or with a rolling shutter each row at its own time.
  RenderResult RenderAt(double seconds) const;
  // The same with every row at `seconds` (a global shutter).
  RenderResult RenderGlobalAt(double seconds) const;
  // Sub-frames that blur the exposure around `seconds`: odd, at least motion_blur_samples, and
  // enough that the image corners (seen at 1 m) move at most kMaxBlurStepPx from one to the next
  // (at most kMaxBlurSamples).
  int MotionBlurSamples(double seconds) const;

  // Frame `index` with sensor effects; the same for the same options.
  SyntheticFrame RenderFrame(int index) const;
  // Ground truth at 100 Hz from 0.5 s before the first to 0.5 s after the last frame,
  // stamps offset from the frame stamps (as in TUM).
  Trajectory Groundtruth() const;

 private:
  SyntheticSequenceOptions options_;
  std::vector<TexturedQuad> static_quads_;
  std::vector<MovingPerson> people_;       // box people (older scenarios)
  std::vector<StagePerson> stage_people_;  // articulated photo people (TUM scenarios)
  std::vector<ArticulatedCutout> dolls_;
  Renderer renderer_;
  std::vector<double> rgb_stamps_, depth_stamps_;
};

struct SyntheticSequenceSummary {
  int frames = 0;
  double mean_dynamic_ratio = 0;  // mean fraction of mask pixels per frame
  int frames_with_people = 0;     // frames whose mask is not empty
};

// Renders every frame and writes the TUM layout (with masks/, people.txt, stats.csv and
// camera.json) into a folder prepared by PrepareOutputFolder.
SyntheticSequenceSummary WriteSyntheticSequence(const SyntheticSequenceOptions& options, const std::string& folder);

}  // namespace dynvo
