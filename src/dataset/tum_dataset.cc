#include "dataset/tum_dataset.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/config_registry.h"
#include "core/error.h"
#include "core/number_text.h"
#include "dataset/stamp_matching.h"
#include "dataset/text_lines.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

// Mask stamps are written from the RGB stamps; this absorbs formatting differences only.
constexpr double kMaskStampTolerance = 1e-4;  // s

std::string Stamp(double stamp) { return StampText(stamp); }

std::string BaseName(const std::string& folder) {
  fs::path path = fs::absolute(fs::path(folder)).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();  // trailing separator
  return path.filename().string();
}

std::string TypeName(const cv::Mat& image) {
  const int depth = image.depth();
  const char* name = depth == CV_8U    ? "8-bit"
                     : depth == CV_16U ? "16-bit"
                     : depth == CV_8S  ? "8-bit signed"
                     : depth == CV_16S ? "16-bit signed"
                     : depth == CV_32F ? "32-bit float"
                                       : "other";
  return std::string(name) + " " + std::to_string(image.channels()) + "-channel";
}

}  // namespace

void TumDatasetOptions::Check() const {
  if (!std::isfinite(max_time_difference) || !(max_time_difference > 0))
    throw InputError("dataset.max_time_difference must be > 0 (seconds), got " + ShortText(max_time_difference));
  if (!std::isfinite(depth_factor) || !(depth_factor >= 0))
    throw InputError("dataset.depth_factor must be >= 0 (PNG value per metre; 0: by the camera), got " +
                     ShortText(depth_factor));
  camera.Check();
}

TumDataset::TumDataset(const std::string& folder, const TumDatasetOptions& options)
    : folder_(folder), options_(options) {
  options_.Check();
  if (!fs::is_directory(PathStatus(folder_))) ThrowFileError(folder_, 0, "no such folder");
  name_ = BaseName(folder_);
  rgb_list_ = (fs::path(folder_) / "rgb.txt").string();
  depth_list_ = (fs::path(folder_) / "depth.txt").string();
  masks_list_ = (fs::path(folder_) / "masks.txt").string();
  for (const std::string* list : {&rgb_list_, &depth_list_})
    if (!fs::is_regular_file(PathStatus(*list)))
      ThrowFileError(*list, 0, "missing file (a TUM sequence folder has rgb.txt and depth.txt)");
  rgb_ = ReadImageList(rgb_list_);
  depth_ = ReadImageList(depth_list_);

  const ChosenCamera chosen = ChooseCamera(folder_, name_, options_.camera, options_.depth_factor);
  raw_camera_ = chosen.camera;
  depth_factor_ = chosen.depth_factor;
  camera_origin_ = chosen.camera_origin;
  depth_factor_origin_ = chosen.depth_factor_origin;
  camera_ = raw_camera_;
  remap_ = options_.undistort && raw_camera_.HasDistortion();
  if (remap_) {
    camera_.distortion = {0, 0, 0, 0, 0};
    const cv::Size size(raw_camera_.width, raw_camera_.height);
    cv::Mat map_x, map_y;
    cv::initUndistortRectifyMap(raw_camera_.K(), raw_camera_.DistCoeffs(), cv::Mat(), raw_camera_.K(), size, CV_32FC1,
                                map_x, map_y);
    // Fixed-point maps remap fastest; the nearest one is rounded (not truncated) so that
    // depth and masks are sampled at the closest source pixel.
    cv::convertMaps(map_x, map_y, linear_map1_, linear_map2_, CV_16SC2, false);
    cv::Mat unused;
    cv::convertMaps(map_x, map_y, nearest_map_, unused, CV_16SC2, true);
    // Pixels whose bilinear sample lies wholly inside the sensor image.
    cv::Mat covered;
    cv::remap(cv::Mat(size, CV_8UC1, cv::Scalar(255)), covered, linear_map1_, linear_map2_, cv::INTER_LINEAR,
              cv::BORDER_CONSTANT, cv::Scalar(0));
    image_area_ = ConvexAreaInside(covered == 255);
  }

  // RGB-depth association, associate.py semantics.
  std::vector<double> rgb_stamps, depth_stamps;
  for (const ImageListEntry& e : rgb_) rgb_stamps.push_back(e.stamp);
  for (const ImageListEntry& e : depth_) depth_stamps.push_back(e.stamp);
  for (const auto& [r, d] : MatchStamps(rgb_stamps, depth_stamps, options_.max_time_difference))
    frames_.push_back({r, d, -1});
  if (frames_.empty())
    ThrowFileError(rgb_list_, 0,
                   "no RGB frame (of " + std::to_string(rgb_.size()) + ") has a depth frame in " + depth_list_ +
                       " closer than dataset.max_time_difference = " + ShortText(options_.max_time_difference) + " s");
  unmatched_rgb_ = rgb_.size() - frames_.size();

  const std::string groundtruth = (fs::path(folder_) / "groundtruth.txt").string();
  if (fs::exists(PathStatus(groundtruth))) {
    groundtruth_ = ReadTrajectory(groundtruth);
    has_groundtruth_ = true;
  }

  if (fs::exists(PathStatus(masks_list_))) {
    has_masks_ = true;
    masks_ = ReadImageList(masks_list_);
    for (FramePaths& frame : frames_) {
      const double stamp = rgb_[frame.rgb].stamp;
      const auto it = std::lower_bound(masks_.begin(), masks_.end(), stamp - kMaskStampTolerance,
                                       [](const ImageListEntry& e, double value) { return e.stamp < value; });
      if (it != masks_.end() && std::abs(it->stamp - stamp) <= kMaskStampTolerance)
        frame.mask = static_cast<int>(it - masks_.begin());
    }
  }
}

size_t TumDataset::size() const { return frames_.size(); }

double TumDataset::stamp(size_t i) const { return rgb_[frames_.at(i).rgb].stamp; }

const Camera& TumDataset::camera() const { return camera_; }

const Camera& TumDataset::raw_camera() const { return raw_camera_; }

const ImageArea& TumDataset::image_area() const { return image_area_; }

double TumDataset::depth_factor() const { return depth_factor_; }

const std::string& TumDataset::camera_origin() const { return camera_origin_; }

const std::string& TumDataset::depth_factor_origin() const { return depth_factor_origin_; }

bool TumDataset::has_groundtruth() const { return has_groundtruth_; }

const Trajectory& TumDataset::groundtruth() const { return groundtruth_; }

bool TumDataset::has_masks() const { return has_masks_; }

size_t TumDataset::unmatched_rgb() const { return unmatched_rgb_; }

const std::string& TumDataset::folder() const { return folder_; }

std::string TumDataset::name() const { return name_; }

cv::Mat TumDataset::ReadPng(const ImageListEntry& entry, const std::string& list_path) const {
  const std::string path = (fs::path(folder_) / entry.path).string();
  const std::string where = " (listed at " + list_path + ":" + std::to_string(entry.line) + ")";
  fs::file_status status;
  try {
    status = PathStatus(path);  // a symlink loop or a name too long: an input error like any other
  } catch (const InputError& e) {
    throw InputError(e.what() + where);
  }
  if (!fs::is_regular_file(status)) ThrowFileError(path, 0, "missing image" + where);
  cv::Mat image;
  try {
    image = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    ThrowFileError(path, 0, std::string("cannot decode image: ") + e.what() + where);
  }
  if (image.empty()) ThrowFileError(path, 0, "cannot decode image" + where);
  if (image.cols != raw_camera_.width || image.rows != raw_camera_.height)
    ThrowFileError(path, 0,
                   "image is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) + ", the camera is " +
                       std::to_string(raw_camera_.width) + "x" + std::to_string(raw_camera_.height) + where);
  return image;
}

RgbdFrame TumDataset::Load(size_t i) const {
  const FramePaths& paths = frames_.at(i);
  const ImageListEntry& rgb_entry = rgb_[paths.rgb];
  const ImageListEntry& depth_entry = depth_[paths.depth];
  RgbdFrame frame;
  frame.index = i;
  frame.stamp = rgb_entry.stamp;
  frame.depth_stamp = depth_entry.stamp;

  cv::Mat rgb = ReadPng(rgb_entry, rgb_list_);
  if (rgb.depth() != CV_8U || (rgb.channels() != 1 && rgb.channels() != 3 && rgb.channels() != 4))
    ThrowFileError((fs::path(folder_) / rgb_entry.path).string(), 0,
                   "RGB image must be 8-bit with 3 channels (1 or 4 accepted), got " + TypeName(rgb));
  if (rgb.channels() == 1) cv::cvtColor(rgb, rgb, cv::COLOR_GRAY2BGR);
  if (rgb.channels() == 4) cv::cvtColor(rgb, rgb, cv::COLOR_BGRA2BGR);

  cv::Mat depth = ReadPng(depth_entry, depth_list_);
  if (depth.type() != CV_16UC1)
    ThrowFileError((fs::path(folder_) / depth_entry.path).string(), 0,
                   "depth image must be 16-bit 1-channel, got " + TypeName(depth));

  if (remap_) {
    cv::remap(rgb, frame.bgr, linear_map1_, linear_map2_, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
    cv::Mat undistorted_depth;
    cv::remap(depth, undistorted_depth, nearest_map_, cv::noArray(), cv::INTER_NEAREST, cv::BORDER_CONSTANT,
              cv::Scalar::all(0));
    depth = undistorted_depth;
  } else {
    frame.bgr = rgb;
  }
  depth.convertTo(frame.depth, CV_32F, 1.0 / depth_factor_);
  cv::cvtColor(frame.bgr, frame.gray, cv::COLOR_BGR2GRAY);
  return frame;
}

cv::Mat TumDataset::LoadMask(size_t i) const {
  cv::Mat mask = LoadMaskLabels(i);
  cv::threshold(mask, mask, 0, 255, cv::THRESH_BINARY);
  return mask;
}

cv::Mat TumDataset::LoadMaskLabels(size_t i) const {
  const FramePaths& paths = frames_.at(i);
  if (!has_masks_) ThrowFileError(masks_list_, 0, "missing file: this sequence has no masks");
  if (paths.mask < 0)
    ThrowFileError(masks_list_, 0,
                   "no mask entry with the stamp of frame " + std::to_string(i) + " (" + rgb_list_ + ":" +
                       std::to_string(rgb_[paths.rgb].line) + ", " + Stamp(rgb_[paths.rgb].stamp) + ")");
  const ImageListEntry& entry = masks_[static_cast<size_t>(paths.mask)];
  cv::Mat mask = ReadPng(entry, masks_list_);
  if (mask.type() != CV_8UC1)
    ThrowFileError((fs::path(folder_) / entry.path).string(), 0, "mask must be 8-bit 1-channel, got " + TypeName(mask));
  if (!remap_) return mask;
  cv::Mat undistorted;
  cv::remap(mask, undistorted, nearest_map_, cv::noArray(), cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  return undistorted;
}

void BindConfigKeys(const std::string& prefix, TumDatasetOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".max_time_difference", &o->max_time_difference,
          "seconds; RGB and depth stamps further apart are not associated");
  r->Bind(prefix + ".depth_factor", &o->depth_factor,
          "depth PNG value per metre; 0 = by the camera: camera.json's depth_factor, else 5208 for the TUM "
          "freiburg2 camera (its Kinect reads depth about 4% too far, as ORB-SLAM2 corrects), else 5000");
  r->Bind(prefix + ".undistort", &o->undistort,
          "remap images to an undistorted pinhole camera when the camera has distortion");
}

}  // namespace dynvo
