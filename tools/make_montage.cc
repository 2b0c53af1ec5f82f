// dynvo-montage: a PNG tile grid of frames of a TUM folder: one row per frame with its RGB,
// the RGB with the dynamic mask as a red overlay (when masks.txt exists), and the depth in
// false colour.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "dataset/tum_dataset.h"
#include "synth/tum_writer.h"
#include "tool_main.h"

namespace {

std::vector<int> ParseFrames(const std::string& text) {
  std::vector<int> frames;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      size_t used = 0;
      const int value = std::stoi(item, &used);
      if (used != item.size() || value < 0) throw std::invalid_argument(item);
      frames.push_back(value);
    } catch (const std::exception&) {
      throw dynvo::InputError("--frames must be a comma-separated list of frame indices >= 0, got '" + text + "'");
    }
  }
  if (frames.empty()) throw dynvo::InputError("--frames is empty");
  return frames;
}

cv::Mat Label(cv::Mat tile, const std::string& text) {
  cv::putText(tile, text, {8, 22}, cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
  cv::putText(tile, text, {8, 22}, cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  return tile;
}

// The median of stats.csv's coverage column (written by the generators), or -1 without the file.
double MedianCoverage(const std::filesystem::path& stats_path) {
  std::ifstream in(stats_path);
  if (!in) return -1;
  std::string line;
  std::getline(in, line);
  if (line.rfind("timestamp,coverage,", 0) != 0)
    throw dynvo::InputError(stats_path.string() + ":1: expected the header timestamp,coverage,...");
  std::vector<double> coverage;
  for (int number = 2; std::getline(in, line); ++number) {
    const size_t a = line.find(','), b = line.find(',', a + 1);
    try {
      coverage.push_back(std::stod(line.substr(a + 1, b - a - 1)));
    } catch (const std::exception&) {
      throw dynvo::InputError(stats_path.string() + ":" + std::to_string(number) + ": coverage is not a number");
    }
  }
  if (coverage.empty()) return -1;
  std::nth_element(coverage.begin(), coverage.begin() + static_cast<long>(coverage.size() / 2), coverage.end());
  return coverage[coverage.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const char* prog = "dynvo-montage";
  CLI::App app{"Tile grid of frames of a TUM folder with their dynamic masks and depth"};
  std::string dataset, frames_text = "0,50,100,150", out;
  int tile_width = 320;
  bool force = false;
  app.add_option("--dataset", dataset, "TUM sequence folder")->required();
  app.add_option("--frames", frames_text, "comma-separated frame indices")->capture_default_str();
  app.add_option("--tile-width", tile_width, "width of one tile in pixels")->capture_default_str();
  app.add_option("--out", out, "output PNG")->required();
  app.add_flag("--force", force, "overwrite an existing --out");
  return dynvo::RunToolMain(prog, app, argc, argv, [&] {
    if (tile_width < 64 || tile_width > 2048) throw dynvo::InputError("--tile-width must be in [64, 2048]");
    if (std::filesystem::exists(out) && !force) throw dynvo::InputError(out + ": exists (use --force to overwrite)");
    dynvo::TumDatasetOptions options;
    options.undistort = false;  // show the images as stored, like the masks
    const dynvo::TumDataset sequence(dataset, options);
    std::vector<cv::Mat> rows;
    for (const int index : ParseFrames(frames_text)) {
      if (static_cast<size_t>(index) >= sequence.size())
        throw dynvo::InputError("--frames: frame " + std::to_string(index) + " is out of range, " + dataset + " has " +
                                std::to_string(sequence.size()) + " frames");
      const dynvo::RgbdFrame frame = sequence.Load(static_cast<size_t>(index));
      cv::Mat overlay = frame.bgr.clone();
      std::string label = "mask";
      if (!sequence.has_masks()) label = "no masks.txt";
      if (sequence.has_masks()) {
        const cv::Mat mask = sequence.LoadMask(static_cast<size_t>(index));
        cv::Mat red(overlay.size(), CV_8UC3, cv::Scalar(0, 0, 255)), blended;
        cv::addWeighted(overlay, 0.6, red, 0.4, 0, blended);
        blended.copyTo(overlay, mask);
        std::vector<std::vector<cv::Point>> contours;
        cv::findContours(mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
        cv::drawContours(overlay, contours, -1, cv::Scalar(0, 255, 255), 2);
        label += " " + std::to_string(cv::countNonZero(mask) * 100 / static_cast<int>(mask.total())) + "%";
      }
      cv::Mat depth8, depth_colour;
      frame.depth.convertTo(depth8, CV_8U, 255.0 / 6.0);  // 0..6 m
      cv::applyColorMap(depth8, depth_colour, cv::COLORMAP_TURBO);
      depth_colour.setTo(cv::Scalar(0, 0, 0), frame.depth == 0);
      const double scale = double(tile_width) / frame.bgr.cols;
      cv::Mat raw, a, b;
      cv::resize(frame.bgr, raw, cv::Size(), scale, scale, cv::INTER_AREA);
      cv::resize(overlay, a, raw.size(), 0, 0, cv::INTER_AREA);
      cv::resize(depth_colour, b, raw.size(), 0, 0, cv::INTER_NEAREST);
      cv::Mat row;
      cv::hconcat(
          std::vector<cv::Mat>{Label(raw, "frame " + std::to_string(index) + "  t=" + dynvo::FormatStamp(frame.stamp)),
                               Label(a, label), Label(b, "depth 0-6 m")},
          row);
      rows.push_back(row);
    }
    cv::Mat montage;
    cv::vconcat(rows, montage);
    if (!cv::imwrite(out, montage)) throw dynvo::InputError(out + ": cannot write PNG");
    std::cout << prog << ": wrote " << out << " (" << montage.cols << "x" << montage.rows << ")\n";
    const double coverage = MedianCoverage(std::filesystem::path(dataset) / "stats.csv");
    if (coverage >= 0)
      std::cout << prog << ": people cover " << std::fixed << std::setprecision(1) << 100 * coverage
                << "% of the image (median over the frames of stats.csv)\n";
  });
}
