#pragma once
// Writing sequences in the TUM RGB-D layout: rgb/, depth/, masks/ PNGs, rgb.txt,
// depth.txt, masks.txt, groundtruth.txt and camera.json (intrinsics for the reader).

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "dataset/trajectory_io.h"

namespace dynvo {

// Makes `folder` ready for output: creates it, or when it exists and is not empty throws
// InputError "<folder>: output folder exists and is not empty (use --force to overwrite)"
// unless `force`; with `force` the generated entries (rgb/, depth/, masks/, the list files,
// groundtruth.txt, camera.json) are removed first and other files are left alone.
void PrepareOutputFolder(const std::string& folder, bool force);

// "%.6f" of a stamp: the file name stem and list entry used for that frame.
std::string FormatStamp(double stamp);

// The stamp rounded to the 6 decimals it is written with.
double RoundStamp(double stamp);

// Writes one PNG (fast compression); throws InputError naming the file on failure.
void WritePng(const std::string& path, const cv::Mat& image);

// Collects frames and writes the list files at Finish(). PNGs are written immediately.
class TumWriter {
 public:
  // `folder` must have been prepared; `comment` goes into the list file headers.
  TumWriter(std::string folder, std::string comment);

  // Writes rgb/<stamp>.png (CV_8UC3 BGR), depth/<depth_stamp>.png (CV_16U) and, when
  // `mask` is not empty, masks/<stamp>.png (CV_8U, 255 = moving object).
  void AddFrame(double rgb_stamp, const cv::Mat& bgr, double depth_stamp, const cv::Mat& depth16, const cv::Mat& mask);

  // Writes rgb.txt, depth.txt, masks.txt (when masks were given), groundtruth.txt and
  // camera.json.
  void Finish(const Trajectory& groundtruth, const Camera& camera, double depth_factor) const;

 private:
  std::string folder_, comment_;
  std::vector<std::string> rgb_lines_, depth_lines_, mask_lines_;
};

}  // namespace dynvo
