#pragma once
// Small TUM-style sequence folders written for tests: rgb/, depth/, rgb.txt, depth.txt with
// known stamps and pixel values.

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "support/temp_dir.h"

namespace dynvo::test {

struct TumTestFolderSpec {
  std::string name = "synthetic";  // folder name inside the TempDir
  int frames = 3;
  int width = 640;              // pixels
  int height = 480;             // pixels
  double first_stamp = 100.0;   // s, RGB stamp of frame 0
  double period = 1.0 / 30.0;   // s between RGB frames
  double depth_offset = 0.005;  // s, depth stamp minus RGB stamp
  bool camera_json = true;      // a camera.json with the ROS default intrinsics and no depth factor
};

struct TumTestFolder {
  std::string folder;  // full path
  std::vector<double> rgb_stamps, depth_stamps;
  std::vector<std::string> rgb_files, depth_files;  // relative, as in the lists
};

// RGB image of frame k: B = x mod 256, G = y mod 256, R = 10 k.
cv::Mat TestBgr(int width, int height, int k);
// Depth PNG of frame k (CV_16UC1): 5000 * (1 + k) everywhere, 0 in column 0, 12345 at (1, 1).
cv::Mat TestDepth(int width, int height, int k);

// Writes the folder described by `spec` into `dir` (images, the two lists with stamps of 6
// decimals, and camera.json when asked: a folder named like TUM's needs none).
TumTestFolder WriteTumTestFolder(const TempDir& dir, const TumTestFolderSpec& spec);

// Writes a list file "stamp path" per line into folder/list_name.
void WriteList(const std::string& folder, const std::string& list_name, const std::vector<double>& stamps,
               const std::vector<std::string>& files);

// Writes an image, creating folders; fails the test when OpenCV cannot write it.
void WriteImage(const std::string& path, const cv::Mat& image);

}  // namespace dynvo::test
