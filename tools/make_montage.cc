// dynvo-montage: a PNG tile grid of frames of a TUM folder: one row per frame with its RGB,
// the RGB with the dynamic mask as a red overlay (when masks.txt exists), and the depth in
// false colour.
#include <algorithm>
#include <filesystem>
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
        throw dynvo::InputError("--frames: frame " + std::to_string(index) + " is out of range, " + dataset +
                                " has " + std::to_string(sequence.size()) + " frames");
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
      cv::hconcat(std::vector<cv::Mat>{Label(raw, "frame " + std::to_string(index) + "  t=" + dynvo::FormatStamp(frame.stamp)), Label(a, label),
                                       Label(b, "depth 0-6 m")},
                  row);
      rows.push_back(row);
    }
    cv::Mat montage;
    cv::vconcat(rows, montage);
    if (!cv::imwrite(out, montage)) throw dynvo::InputError(out + ": cannot write PNG");
    std::cout << prog << ": wrote " << out << " (" << montage.cols << "x" << montage.rows << ")\n";
  });
}
