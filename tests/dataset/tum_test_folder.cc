#include "tum_test_folder.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "dataset/camera_file.h"

namespace dynvo::test {

cv::Mat TestBgr(int width, int height, int k) {
  cv::Mat image(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.at<cv::Vec3b>(y, x) =
          cv::Vec3b(static_cast<uchar>(x % 256), static_cast<uchar>(y % 256), static_cast<uchar>((10 * k) % 256));
  return image;
}

cv::Mat TestDepth(int width, int height, int k) {
  cv::Mat depth(height, width, CV_16UC1, cv::Scalar(5000 * (1 + k)));
  depth.col(0).setTo(0);
  depth.at<uint16_t>(1, 1) = 12345;
  return depth;
}

void WriteImage(const std::string& path, const cv::Mat& image) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  // Light compression: the tests write many 640x480 PNGs and only need them readable.
  if (!cv::imwrite(path, image, {cv::IMWRITE_PNG_COMPRESSION, 1})) throw std::runtime_error("cannot write " + path);
}

void WriteList(const std::string& folder, const std::string& list_name, const std::vector<double>& stamps,
               const std::vector<std::string>& files) {
  std::ofstream out(std::filesystem::path(folder) / list_name, std::ios::binary);
  out << "# " << list_name << "\n# timestamp filename\n";
  char buffer[64];
  for (size_t i = 0; i < stamps.size(); ++i) {
    std::snprintf(buffer, sizeof(buffer), "%.6f", stamps[i]);
    out << buffer << " " << files[i] << "\n";
  }
}

TumTestFolder WriteTumTestFolder(const TempDir& dir, const TumTestFolderSpec& spec) {
  TumTestFolder seq;
  seq.folder = (dir.path() / spec.name).string();
  std::filesystem::create_directories(seq.folder);
  char buffer[64];
  for (int k = 0; k < spec.frames; ++k) {
    // Rounded to the 6 decimals the lists hold, so that parsed stamps compare equal.
    const double rgb_stamp = std::round((spec.first_stamp + k * spec.period) * 1e6) / 1e6;
    const double depth_stamp = std::round((rgb_stamp + spec.depth_offset) * 1e6) / 1e6;
    std::snprintf(buffer, sizeof(buffer), "rgb/%.6f.png", rgb_stamp);
    seq.rgb_files.push_back(buffer);
    std::snprintf(buffer, sizeof(buffer), "depth/%.6f.png", depth_stamp);
    seq.depth_files.push_back(buffer);
    seq.rgb_stamps.push_back(rgb_stamp);
    seq.depth_stamps.push_back(depth_stamp);
    WriteImage(seq.folder + "/" + seq.rgb_files.back(), TestBgr(spec.width, spec.height, k));
    WriteImage(seq.folder + "/" + seq.depth_files.back(), TestDepth(spec.width, spec.height, k));
  }
  WriteList(seq.folder, "rgb.txt", seq.rgb_stamps, seq.rgb_files);
  WriteList(seq.folder, "depth.txt", seq.depth_stamps, seq.depth_files);
  if (spec.camera_json) WriteCameraFile(seq.folder + "/camera.json", Camera());
  return seq;
}

}  // namespace dynvo::test
