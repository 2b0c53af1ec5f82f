#pragma once
// People inserted into a real TUM sequence: articulated photo cut-outs (synth/stage_people.h)
// moving in the world frame of the groundtruth, rendered through the groundtruth camera poses
// and the raw (distorted) intrinsics with a rounded depth and Kinect-like depth noise and
// holes, written only where nearer than the real depth. Pixels the people do not cover stay
// byte-identical; masks/ marks the pixels that were written, people.txt labels each person
// per frame (moving or still) and stats.csv gives the share of the image they cover.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "dataset/trajectory_io.h"
#include "synth/articulated_cutout.h"
#include "synth/moving_object.h"
#include "synth/person_cutout.h"
#include "synth/renderer.h"
#include "synth/stage_people.h"

namespace dynvo {

struct InsertionOptions {
  Scenario preset = Scenario::kTumWalking;  // any scenario but none (moving_object.h)
  double person_height_m = 1.7;             // metres
  double distance_m = 0.0;                  // metres in front of the reference camera: walking line / spot;
                                            // 0: chosen (TUM presets: in 1-3 m, covering a fifth of the
                                            // image; others: in 1-4 m, showing the most of the bodies)
  double walk_speed_mps = 1.0;              // metres per second
  double camera_height_m = 0;               // metres of the reference camera above the people's floor; 0: the
                                            // people's mid-height on its optical axis at distance_m (TUM
                                            // presets: people in the middle of the view), else 1.5
  double max_pose_gap_s = 0.1;              // seconds: frames farther from groundtruth samples get no people
  std::uint32_t seed = 1;                   // depth noise of the people

  // Throws InputError naming the key ("insert.distance_m must be in [0.5, 20], got 0").
  void Check() const;
};

// Where the people move. Stage frame (stage_people.h): origin on the floor below the
// reference camera (the groundtruth pose at the middle frame). "Up" is the world z axis when
// the cameras' mean up direction is within 60 degrees of it (TUM's motion capture frames are
// z-up), else the cameras' mean up direction.
struct InsertionPlan {
  Pose world_from_stage = Pose::Identity();
  double start_stamp = 0;                // seconds, stamp of the first frame
  std::vector<StagePerson> people;       // person i has object id i + 1
  std::vector<ArticulatedCutout> dolls;  // one per cut-out, then their mirror images
};

// Plans the people for a sequence spanning [first_stamp, last_stamp] with the given
// groundtruth and camera (options.distance_m 0 is taken as 2 m here). People take the
// cut-outs in turn. Throws InputError when the groundtruth does not cover the middle of the
// sequence, there is no cut-out or the options are invalid.
InsertionPlan PlanInsertion(const InsertionOptions& options, const std::vector<PersonCutout>& cutouts,
                            const Trajectory& groundtruth, double first_stamp, double last_stamp, const Camera& camera);

// The people's quads (object ids 1, 2, ...) in the world at `stamp`.
std::vector<TexturedQuad> InsertionQuadsAt(const InsertionPlan& plan, double stamp);

// Writes rendered people into a real frame where they are nearer than the real depth (or
// the real depth has no reading): colour into `bgr` (CV_8UC3), depth * depth_factor into
// `depth16` (CV_16U), the person's object id into `person_id` (CV_16U, set to zeros of the
// image size first). Returns the number of pixels written; other pixels are untouched.
int CompositePeople(const RenderResult& people, double depth_factor, cv::Mat* bgr, cv::Mat* depth16,
                    cv::Mat* person_id);

// Replaces the depth of the pixels where `person_id` is non-zero by a Kinect-like reading of
// it: noise growing with distance, disparity steps, holes along the silhouette (as
// MakeSensorDepth); deterministic from the seed. Other pixels are untouched.
void AddPersonDepthNoise(const cv::Mat& person_id, double depth_factor, std::uint32_t seed, cv::Mat* depth16);

struct InsertionSummary {
  int frames = 0;               // RGB frames in the output
  int frames_with_people = 0;   // frames whose mask is not empty
  int frames_without_pose = 0;  // frames left untouched for lack of groundtruth
  double mean_dynamic_ratio = 0;
  double median_coverage = 0;  // median over frames of the share of the image people cover
  int first_frame_with_people = -1;
  double distance_m = 0;  // metres, the walking distance used (chosen when options say 0)
};

// Reads the TUM folder `dataset` (raw images, raw camera: camera.json, folder name or ROS
// default) with its groundtruth, inserts the people and writes a TUM folder with masks/,
// masks.txt, people.txt, stats.csv and camera.json into `out_folder` (prepared by
// PrepareOutputFolder). Untouched files are copied byte for byte. Throws InputError naming
// files on bad input.
InsertionSummary InsertPeopleIntoSequence(const std::string& dataset, const std::vector<PersonCutout>& cutouts,
                                          const InsertionOptions& options, const std::string& out_folder);

}  // namespace dynvo
