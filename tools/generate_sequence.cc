// dynvo-synth: generates a synthetic dynamic RGB-D sequence in the TUM layout, with
// groundtruth.txt, camera.json and a ground-truth dynamic mask per frame (masks/).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "synth/synthetic_sequence.h"
#include "synth/tum_writer.h"
#include "tool_main.h"

namespace {

// The --intrinsics camera scaled to width x height, then the explicit overrides.
dynvo::Camera ScaledCamera(const std::string& intrinsics, int width, int height, const std::optional<double>& fx,
                           const std::optional<double>& fy, const std::optional<double>& cx,
                           const std::optional<double>& cy) {
  dynvo::Camera camera = dynvo::TumIntrinsics(intrinsics, "--intrinsics");
  camera.distortion = {0, 0, 0, 0, 0};
  const double sx = width / 640.0, sy = height / 480.0;
  camera.fx = fx ? *fx : camera.fx * sx;
  camera.fy = fy ? *fy : camera.fy * sy;
  camera.cx = cx ? *cx : (camera.cx + 0.5) * sx - 0.5;
  camera.cy = cy ? *cy : (camera.cy + 0.5) * sy - 0.5;
  camera.width = width;
  camera.height = height;
  return camera;
}

}  // namespace

int main(int argc, char** argv) {
  const char* prog = "dynvo-synth";
  CLI::App app{"Generate a synthetic dynamic RGB-D sequence (TUM layout, ground-truth poses and masks)"};
  std::string scenario = "walking_across", camera_path = "xyz", intrinsics = "fr3", out;
  int frames = 300, width = 640, height = 480;
  double fps = 30;
  std::optional<double> fx, fy, cx, cy;
  unsigned seed = 1;
  bool motion_blur = false, kinect_sensor = false, plain_room = false, repeated_walls = false, force = false;
  app.add_option("--scenario", scenario,
                 "none|tum_walking|tum_toward|tum_away|tum_sitting|walking_across|"
                 "walking_toward|two_crossing|sitting_sway (tum_: articulated photo people, "
                 "motion blur, depth seen a few ms before colour, exposure drift, 28 ms rolling shutter)")
      ->capture_default_str();
  app.add_option("--camera-path", camera_path, "static|xyz|halfsphere|rpy|rpy_fast|loop (one turn in 15 s)")
      ->capture_default_str();
  app.add_option("--frames", frames, "number of RGB-D frames")->capture_default_str();
  app.add_option("--fps", fps, "frames per second (<= 60)")->capture_default_str();
  app.add_option("--width", width, "image width in pixels")->capture_default_str();
  app.add_option("--height", height, "image height in pixels")->capture_default_str();
  app.add_option("--intrinsics", intrinsics,
                 "fr1|fr2|fr3|ros: focal lengths and centre (distortion ignored), "
                 "scaled to --width/--height")
      ->capture_default_str();
  app.add_option("--fx", fx, "focal length x in pixels (overrides --intrinsics)");
  app.add_option("--fy", fy, "focal length y in pixels (overrides --intrinsics)");
  app.add_option("--cx", cx, "principal point x in pixels (overrides --intrinsics)");
  app.add_option("--cy", cy, "principal point y in pixels (overrides --intrinsics)");
  app.add_option("--seed", seed, "random seed: same seed, same sequence")->capture_default_str();
  app.add_flag("--motion-blur", motion_blur, "blur frames over the exposure (20 ms, at most half a frame)");
  app.add_flag("--kinect-sensor", kinect_sensor,
               "Kinect v1 sensor timing for any scenario (always on for tum_*): motion blur, depth seen a few ms "
               "before colour, exposure drift, 28 ms rolling shutter; the static twin of a tum_* sequence");
  app.add_flag("--plain-room", plain_room,
               "walls, floor and furniture in plain paint: low texture, the edges of the room and its furniture");
  app.add_flag("--repeated-walls", repeated_walls,
               "walls papered with one 1.6 m panel over and over: any stretch of wall looks like any other");
  app.add_option("--out", out, "output folder (TUM layout)")->required();
  app.add_flag("--force", force, "replace the generated files of an existing non-empty --out");
  return dynvo::RunToolMain(prog, app, argc, argv, [&] {
    dynvo::SyntheticSequenceOptions options;
    options.scenario = dynvo::ParseScenario(scenario, "--scenario");
    options.camera_path = dynvo::ParseCameraPathPreset(camera_path, "--camera-path");
    options.frames = frames;
    options.fps = fps;
    options.seed = seed;
    options.room.plain = plain_room;
    options.room.repeated_walls = repeated_walls;
    const bool kinect = kinect_sensor || dynvo::IsTumScenario(options.scenario);
    options.motion_blur = motion_blur || kinect;
    options.kinect_timing = kinect;
    if (fps > 0)
      options.exposure_s = std::min(options.exposure_s, 0.5 / fps);  // shutter open half the frame time at most
    // Kinect v1 reads its colour rows out over most of the 33 ms frame time at 30 Hz,
    // the rest being vertical blanking; 28 ms is the readout Kerl et al. (ICCV 2015) simulate
    // for their rolling-shutter RGB-D sequences. The same share (84%) of the frame time above 30 Hz.
    if (kinect && fps > 0) options.rolling_shutter_readout_s = std::min(0.028, 0.84 / fps);
    options.camera = ScaledCamera(intrinsics, width, height, fx, fy, cx, cy);
    options.Check();
    dynvo::PrepareOutputFolder(out, force);
    const auto start = std::chrono::steady_clock::now();
    const dynvo::SyntheticSequenceSummary summary = dynvo::WriteSyntheticSequence(options, out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "%s: wrote %d frames (%dx%d, scenario %s, camera path %s, seed %u) to %s in %.1f s; "
        "%d frames show moving objects, mean dynamic pixel ratio %.3f\n",
        prog, summary.frames, width, height, scenario.c_str(), camera_path.c_str(), seed, out.c_str(), seconds,
        summary.frames_with_people, summary.mean_dynamic_ratio);
  });
}
