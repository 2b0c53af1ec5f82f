#include "synth/tum_writer.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "core/number_text.h"
#include "dataset/camera_file.h"

namespace dynvo {
namespace fs = std::filesystem;

namespace {

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw InputError(path + ": cannot write file");
}

std::string ListText(const std::string& title, const std::string& comment, const std::vector<std::string>& lines) {
  std::string text = "# " + title + "\n# " + comment + "\n# timestamp filename\n";
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

}  // namespace

void PrepareOutputFolder(const std::string& folder, bool force) {
  std::error_code ec;
  if (fs::exists(folder, ec)) {
    if (!fs::is_directory(folder, ec)) throw InputError(folder + ": output path exists and is not a folder");
    if (!fs::is_empty(folder, ec)) {
      if (!force) throw InputError(folder + ": output folder exists and is not empty (use --force to overwrite)");
      for (const char* name : {"rgb", "depth", "masks", "rgb.txt", "depth.txt", "masks.txt", "groundtruth.txt",
                               "camera.json", "accelerometer.txt", "people.txt", "stats.csv"})
        fs::remove_all(fs::path(folder) / name, ec);
    }
  }
  fs::create_directories(fs::path(folder) / "rgb", ec);
  fs::create_directories(fs::path(folder) / "depth", ec);
  if (!fs::is_directory(fs::path(folder) / "rgb")) throw InputError(folder + ": cannot create output folder");
}

std::string FormatStamp(double stamp) { return FixedText(stamp, 6); }

double RoundStamp(double stamp) { return std::stod(FormatStamp(stamp)); }

void WritePng(const std::string& path, const cv::Mat& image) {
  bool ok = false;
  try {
    // No parameters: OpenCV then picks zlib's fastest level with the SUB filter, which
    // measured fastest at nearly the smallest size for noisy 8- and 16-bit frames.
    ok = cv::imwrite(path, image);
  } catch (const cv::Exception& e) {
    throw InputError(path + ": cannot write PNG: " + e.what());
  }
  if (!ok) throw InputError(path + ": cannot write PNG");
}

TumWriter::TumWriter(std::string folder, std::string comment)
    : folder_(std::move(folder)), comment_(std::move(comment)) {}

void TumWriter::AddFrame(double rgb_stamp, const cv::Mat& bgr, double depth_stamp, const cv::Mat& depth16,
                         const cv::Mat& mask) {
  const std::string rgb_name = "rgb/" + FormatStamp(rgb_stamp) + ".png";
  const std::string depth_name = "depth/" + FormatStamp(depth_stamp) + ".png";
  WritePng(folder_ + "/" + rgb_name, bgr);
  WritePng(folder_ + "/" + depth_name, depth16);
  rgb_lines_.push_back(FormatStamp(rgb_stamp) + " " + rgb_name);
  depth_lines_.push_back(FormatStamp(depth_stamp) + " " + depth_name);
  if (!mask.empty()) {
    if (mask_lines_.empty()) fs::create_directories(fs::path(folder_) / "masks");
    const std::string mask_name = "masks/" + FormatStamp(rgb_stamp) + ".png";
    WritePng(folder_ + "/" + mask_name, mask);
    mask_lines_.push_back(FormatStamp(rgb_stamp) + " " + mask_name);
  }
}

void TumWriter::Finish(const Trajectory& groundtruth, const Camera& camera, double depth_factor) const {
  WriteText(folder_ + "/rgb.txt", ListText("color images", comment_, rgb_lines_));
  WriteText(folder_ + "/depth.txt", ListText("depth maps", comment_, depth_lines_));
  if (!mask_lines_.empty())
    WriteText(
        folder_ + "/masks.txt",
        ListText("dynamic masks (255 = pixel of a moving object, 128 = of a person not moving), one per color image",
                 comment_, mask_lines_));
  WriteText(folder_ + "/groundtruth.txt", "# ground truth trajectory\n# " + comment_ +
                                              "\n# timestamp tx ty tz qx qy qz qw\n" + FormatTrajectory(groundtruth));
  WriteCameraFile(folder_ + "/camera.json", camera, depth_factor);
}

}  // namespace dynvo
