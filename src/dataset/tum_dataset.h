#pragma once
// A TUM RGB-D sequence folder (rgb.txt, depth.txt, optional groundtruth.txt, optional
// camera.json and masks.txt from our generators) read as associated, undistorted RGB-D
// frames with depth in metres.

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/camera.h"
#include "core/image_area.h"
#include "dataset/camera_choice.h"
#include "dataset/image_list.h"
#include "dataset/trajectory_io.h"

namespace dynvo {

// The masks/ value of a generated sequence's pixel showing a person who is not moving (people.txt
// says who): dynamic for a mask source, static for the mask's precision and recall.
constexpr unsigned char kStillPersonLabel = 128;

class ConfigRegistry;

struct TumDatasetOptions {
  double max_time_difference = 0.02;  // s, RGB-depth association (strictly below)
  double depth_factor = 0.0;          // PNG value per metre; 0: by the camera (ChooseCamera)
  bool undistort = true;              // remap images when the camera has distortion
  CameraChoice camera;                // where the intrinsics come from

  // Throws InputError naming "dataset.max_time_difference", "dataset.depth_factor" or the
  // camera.* key when a value is out of range.
  void Check() const;
};

// The config keys of the reader (section "dataset"): max_time_difference, depth_factor, undistort.
void BindConfigKeys(const std::string& prefix, TumDatasetOptions* options, ConfigRegistry* registry);

struct RgbdFrame {
  size_t index = 0;
  double stamp = 0;        // RGB timestamp, s
  double depth_stamp = 0;  // s
  cv::Mat bgr;             // CV_8UC3
  cv::Mat gray;            // CV_8UC1
  cv::Mat depth;           // CV_32FC1 metres, 0 = no data
};

// Immutable once constructed: Load() and LoadMask() may run concurrently from several threads.
class TumDataset {
 public:
  // Opens a TUM folder: reads the lists, associates RGB with depth (associate.py semantics)
  // and picks the camera (ChooseCamera: the config's camera.source, else camera.json, else
  // the camera the folder's name announces). Throws InputError naming the folder or file:
  // missing folder, missing rgb.txt/depth.txt, bad list lines, no camera to be found, bad
  // camera.json, bad groundtruth.txt or masks.txt, no associated frame.
  explicit TumDataset(const std::string& folder, const TumDatasetOptions& options = {});

  // Associated RGB-D frames, in RGB time order.
  size_t size() const;
  // RGB stamp of frame i, s.
  double stamp(size_t i) const;
  // The camera of the images Load() returns (distortion zero when undistorted).
  const Camera& camera() const;
  // The sensor's camera, with its distortion.
  const Camera& raw_camera() const;
  // The convex part of every image Load() returns that holds image data: without the black
  // border undistortion leaves (empty = the whole image, when there is no undistortion).
  const ImageArea& image_area() const;
  // PNG value per metre used for depth (dataset.depth_factor, else camera.json's, else the
  // chosen camera's).
  double depth_factor() const;
  // Where the camera and the depth factor came from, in words (for run.json).
  const std::string& camera_origin() const;
  const std::string& depth_factor_origin() const;

  // Frame i, undistorted when the option asks and the camera has distortion (RGB bilinear,
  // depth nearest). Throws InputError naming the PNG when it is missing, unreadable, of the
  // wrong type (RGB 8-bit with 3 channels, 1 or 4 accepted and converted; depth 16-bit 1
  // channel) or of a size other than the camera's; std::out_of_range when i >= size().
  RgbdFrame Load(size_t i) const;

  bool has_groundtruth() const;
  // groundtruth.txt as ReadTrajectory reads it; empty when the file is absent.
  const Trajectory& groundtruth() const;

  // True when the folder has a masks.txt.
  bool has_masks() const;
  // CV_8UC1 mask of frame i (255 = dynamic pixel, any non-zero PNG value counts), undistorted
  // like the images (nearest). masks.txt lines are "stamp masks/<file>.png" with the stamps
  // of rgb.txt (equal within 0.1 ms). Throws InputError when there is no masks.txt, no entry
  // for the frame, or the PNG is missing, not 8-bit 1 channel or of the wrong size.
  cv::Mat LoadMask(size_t i) const;
  // Frame i's mask with its PNG values (kStillPersonLabel marks a person standing or sitting
  // still in the generated sequences), undistorted like LoadMask; throws as LoadMask does.
  cv::Mat LoadMaskLabels(size_t i) const;

  // RGB frames dropped for lack of a depth within max_time_difference.
  size_t unmatched_rgb() const;
  const std::string& folder() const;
  // The folder's base name.
  std::string name() const;

 private:
  struct FramePaths {
    size_t rgb = 0;    // index into rgb_
    size_t depth = 0;  // index into depth_
    int mask = -1;     // index into masks_, -1 when none
  };

  // The PNG of a list entry, as stored; throws when missing, undecodable or of the wrong size.
  cv::Mat ReadPng(const ImageListEntry& entry, const std::string& list_path) const;

  std::string folder_;
  std::string name_;
  std::string rgb_list_, depth_list_, masks_list_;  // paths of the list files
  TumDatasetOptions options_;
  Camera raw_camera_;
  Camera camera_;
  double depth_factor_ = 5000.0;
  std::string camera_origin_, depth_factor_origin_;
  bool remap_ = false;
  ImageArea image_area_;
  cv::Mat linear_map1_, linear_map2_;  // CV_16SC2 + CV_16UC1 fixed-point maps, bilinear
  cv::Mat nearest_map_;                // CV_16SC2 rounded map, nearest neighbour
  std::vector<ImageListEntry> rgb_, depth_, masks_;
  std::vector<FramePaths> frames_;
  size_t unmatched_rgb_ = 0;
  bool has_groundtruth_ = false;
  bool has_masks_ = false;
  Trajectory groundtruth_;
};

}  // namespace dynvo
