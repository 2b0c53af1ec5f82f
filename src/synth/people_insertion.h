#pragma once
// Moving people inserted into a real TUM sequence: planar cut-outs walking in the world
// frame of the groundtruth, rendered through the groundtruth camera poses and the raw
// (distorted) intrinsics, written only where nearer than the real depth. Pixels the people
// do not cover stay byte-identical; masks/ marks the pixels that were written.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "dataset/trajectory_io.h"
#include "synth/moving_object.h"
#include "synth/person_cutout.h"
#include "synth/renderer.h"

namespace dynvo {

struct InsertionOptions {
  Scenario preset = Scenario::kWalkingAcross;  // walking_across, walking_toward, two_crossing, sitting_sway
  double person_height_m = 1.7;   // metres
  double distance_m = 0.0;        // metres in front of the reference camera: walking line / spot;
                                  // 0: chosen in 1-4 m to show the largest part of the bodies
  double walk_speed_mps = 1.0;    // metres per second
  double camera_height_m = 1.5;   // metres of the reference camera above the people's floor
  double max_pose_gap_s = 0.1;    // seconds: frames farther from groundtruth samples get no people

  // Throws InputError naming the key ("insert.distance_m must be in [0.5, 20], got 0").
  void Check() const;
};

// Where the people walk. Stage frame: origin on the floor below the reference camera (the
// groundtruth pose at the middle frame), x right, y forward (horizontal), z up. "Up" is the
// world z axis when the cameras' mean up direction is within 60 degrees of it (TUM's motion
// capture frames are z-up), else the cameras' mean up direction.
struct InsertionPlan {
  struct Walker {
    Eigen::Vector2d from{0, 0};   // metres, stage (x, y) at start_stamp
    Eigen::Vector2d to{0, 0};     // metres, turning point (ping-pong between from and to)
    double speed_mps = 0;         // metres per second (0: stays at `from`)
    bool sway = false;            // sways sideways by a few centimetres instead of walking
    int texture = 0;              // index into textures
  };
  Pose world_from_stage = Pose::Identity();
  double start_stamp = 0;         // seconds, stamp of the first frame
  double person_height_m = 1.7;   // metres
  double person_width_m = 0.5;    // metres, from the cut-out's aspect ratio
  std::vector<Walker> walkers;
  std::vector<std::shared_ptr<const Texture>> textures;  // the cut-out and its mirror image
};

// Plans the people for a sequence spanning [first_stamp, last_stamp] with the given
// groundtruth and camera (options.distance_m 0 is taken as 2 m here). Throws InputError when
// the groundtruth does not cover the middle of the sequence or the options are invalid.
InsertionPlan PlanInsertion(const InsertionOptions& options, const PersonCutout& cutout,
                            const Trajectory& groundtruth, double first_stamp, double last_stamp,
                            const Camera& camera);

// The people's quads (object ids 1, 2, ...) in the world at `stamp`.
std::vector<TexturedQuad> InsertionQuadsAt(const InsertionPlan& plan, double stamp);

// Writes rendered people into a real frame where they are nearer than the real depth (or
// the real depth has no reading): colour into `bgr` (CV_8UC3), depth * depth_factor into
// `depth16` (CV_16U), 255 into `mask` (CV_8U, set to zeros of the image size first).
// Returns the number of pixels written; other pixels are untouched.
int CompositePeople(const RenderResult& people, double depth_factor, cv::Mat* bgr, cv::Mat* depth16,
                    cv::Mat* mask);

struct InsertionSummary {
  int frames = 0;               // RGB frames in the output
  int frames_with_people = 0;   // frames whose mask is not empty
  int frames_without_pose = 0;  // frames left untouched for lack of groundtruth
  double mean_dynamic_ratio = 0;
  double distance_m = 0;        // metres, the walking distance used (chosen when options say 0)
};

// Reads the TUM folder `dataset` (raw images, raw camera: camera.json, folder name or ROS
// default) with its groundtruth, inserts the people and writes a TUM folder with masks/,
// masks.txt and camera.json into `out_folder` (prepared by PrepareOutputFolder). Untouched
// files are copied byte for byte. Throws InputError naming files on bad input.
InsertionSummary InsertPeopleIntoSequence(const std::string& dataset, const PersonCutout& cutout,
                                          const InsertionOptions& options, const std::string& out_folder);

}  // namespace dynvo
