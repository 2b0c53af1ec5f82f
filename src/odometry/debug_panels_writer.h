#pragma once
// Writes the paper's Fig. 1 / Fig. 3 panels of a frame as PNGs, one file per panel and a
// labelled montage of all of them, and the frame's features as CSV.

#include <string>

#include "odometry/odometry_pipeline.h"

namespace dynvo {

// Writes <dir>/frame_<index>_<panel>.png for each non-empty panel (background, depth_change,
// map_occlusion and map_occlusion_candidates too, though they are not in the montage),
// <dir>/frame_<index>_panels.png (2 x 3 grid with titles) and <dir>/frame_<index>_features.csv
// (one line per feature: x, y, octave, depth_m, status kept/removed/readmitted, inlier 0/1).
// Throws InputError when a file cannot be written.
void WriteDebugPanels(const std::string& dir, size_t frame_index, const cv::Mat& current_bgr,
                      const DebugPanels& panels);

}  // namespace dynvo
