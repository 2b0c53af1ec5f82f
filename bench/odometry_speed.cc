// Per-frame processing cost of the dynvo pipeline against OpenCV's RGB-D odometry peers
// (cv::rgbd::RgbdOdometry, cv::rgbd::ICPOdometry) on the same frames, in the same process.
// Frames are decoded into memory first, so only processing is timed (as in the paper and
// ORB-SLAM2's reports). Prints medians over frames, the median over runs, the ratio to
// RgbdOdometry (each dynvo run is followed by one run of each peer; the ratio is the median over
// runs of the run's ratio) and the per-stage split of our pipeline. --scale resizes the frames in memory
// (and the intrinsics with them) to measure how the cost grows with resolution; --set
// overrides config keys (e.g. features.num_features) to measure it against other parameters.
//
// --rate feeds dynvo the frames at a live camera's rate instead of back to back, and times each
// frame from its arrival: the latency a robot feels, with the work that runs beside tracking
// (the next frame's features and mask, the local BA, the detector) done in the time between frames.
//
//   odometry_speed --dataset DIR [--config configs/paper.json] [--runs 3] [--frames N]
//                  [--scale 1] [--rate HZ] [--no-peers] [--set key=value]...
//                  [--trajectories-out DIR] [--json FILE]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/rgbd.hpp>

#include "core/build_info.h"
#include "core/error.h"
#include "dataset/trajectory_io.h"
#include "dataset/tum_dataset.h"
#include "odometry/odometry_config.h"
#include "odometry/odometry_pipeline.h"
#include "sample_statistics.h"

namespace {

using Clock = std::chrono::steady_clock;
using dynvo::bench::Mean;
using dynvo::bench::Median;

struct MethodResult {
  std::string name;
  std::vector<double> run_medians;  // median ms/frame of each run
  std::vector<double> last_run;     // ms per frame of the last run
  dynvo::Trajectory trajectory;     // of the last run
};

// Adds the runs of `more` to `into` (medians appended, last run and trajectory replaced).
void AppendRun(MethodResult* into, const MethodResult& more) {
  into->run_medians.insert(into->run_medians.end(), more.run_medians.begin(), more.run_medians.end());
  into->last_run = more.last_run;
  into->trajectory = more.trajectory;
}

// Runs an OpenCV odometry frame to frame, chaining the relative motions.
MethodResult RunPeer(const std::string& name, const cv::Ptr<cv::rgbd::Odometry>& odometry,
                     const std::vector<dynvo::RgbdFrame>& frames, int runs) {
  MethodResult result{name, {}, {}, {}};
  const cv::Mat no_mask;
  for (int r = 0; r < runs; ++r) {
    std::vector<double> times;
    dynvo::Trajectory trajectory{{frames[0].stamp, dynvo::Pose::Identity()}};
    dynvo::Pose world_from_camera = dynvo::Pose::Identity();
    for (size_t i = 1; i < frames.size(); ++i) {
      cv::Mat rt;
      const auto start = Clock::now();
      // OpenCV's Rt maps points of the source (previous) camera into the destination
      // (current) camera: dst_p = Rt * src_p, i.e. current_from_previous.
      const bool ok = odometry->compute(frames[i - 1].gray, frames[i - 1].depth, no_mask, frames[i].gray,
                                        frames[i].depth, no_mask, rt);
      times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      if (ok) {
        Eigen::Matrix4d m;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) m(a, b) = rt.at<double>(a, b);
        dynvo::Pose current_from_previous(m);
        world_from_camera = world_from_camera * current_from_previous.inverse();
      }
      trajectory.push_back({frames[i].stamp, world_from_camera});
    }
    result.run_medians.push_back(Median(times));
    result.last_run = times;
    result.trajectory = trajectory;
  }
  return result;
}

// The image area of frames of `camera` resized to `scaled`'s size (pixel centres scale about
// the image corner, as for the principal point).
dynvo::ImageArea ScaledArea(const dynvo::ImageArea& area, const dynvo::Camera& camera, const dynvo::Camera& scaled) {
  dynvo::ImageArea out;
  const double sx = static_cast<double>(scaled.width) / camera.width;
  const double sy = static_cast<double>(scaled.height) / camera.height;
  for (const cv::Point2f& p : area)
    out.emplace_back(static_cast<float>((p.x + 0.5) * sx - 0.5), static_cast<float>((p.y + 0.5) * sy - 0.5));
  return out;
}

// The camera of images resized by `scale`: focal lengths scale, and the principal point
// with pixel centres kept aligned (pixel i covers [i - 0.5, i + 0.5]).
dynvo::Camera ScaledCamera(const dynvo::Camera& camera, double scale) {
  dynvo::Camera scaled = camera;
  scaled.width = static_cast<int>(std::lround(camera.width * scale));
  scaled.height = static_cast<int>(std::lround(camera.height * scale));
  scaled.fx = camera.fx * scaled.width / camera.width;
  scaled.fy = camera.fy * scaled.height / camera.height;
  scaled.cx = (camera.cx + 0.5) * scaled.width / camera.width - 0.5;
  scaled.cy = (camera.cy + 0.5) * scaled.height / camera.height - 0.5;
  return scaled;
}

// Resizes a frame to the camera's size: colour and grey by area averaging when shrinking and
// bilinearly when enlarging, depth by nearest neighbour (no depth mixed across edges).
void ResizeFrame(dynvo::RgbdFrame& frame, const dynvo::Camera& camera) {
  const cv::Size size(camera.width, camera.height);
  if (frame.gray.size() == size) return;
  const int interpolation = size.width < frame.gray.cols ? cv::INTER_AREA : cv::INTER_LINEAR;
  cv::Mat bgr, gray, depth;
  cv::resize(frame.bgr, bgr, size, 0, 0, interpolation);
  cv::resize(frame.gray, gray, size, 0, 0, interpolation);
  cv::resize(frame.depth, depth, size, 0, 0, cv::INTER_NEAREST);
  frame.bgr = bgr;
  frame.gray = gray;
  frame.depth = depth;
}

struct SpeedArgs {
  std::string dataset_dir, config_path, trajectories_out, json_out;
  std::vector<std::string> overrides;
  int runs = 3, max_frames = 0, threads = dynvo::Executor::DefaultThreads();
  double scale = 1.0, rate = 0.0;
  bool no_peers = false;
};

// One run of dynvo over the frames: its times and trajectory, per-stage times and counts.
struct DynvoRun {
  std::vector<double> times;
  dynvo::Trajectory trajectory;
  std::map<std::string, std::vector<double>> stages;
  std::vector<double> features_total, features_removed, dynamic_ratio, inliers;
  int lost_frames = 0;
};

// When frame `index` of a camera at `rate` frames per second that began at `start` arrives.
Clock::time_point Arrival(Clock::time_point start, size_t index, double rate) {
  return start +
         std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(static_cast<double>(index) / rate));
}

// With `rate` > 0 the frames arrive as from a live camera at that many frames per second: frame
// t is processed once frame t+1 has arrived (the look-ahead the triplet needs), or at once when
// the previous frame ran late, and its time is from then to its pose (waiting included). With
// `rate` 0 the frames follow each other at once and the time is the call's processing time.
DynvoRun RunDynvo(const std::vector<dynvo::RgbdFrame>& frames, const dynvo::Camera& camera,
                  const dynvo::OdometryConfig& config, const dynvo::ImageArea& area, double rate,
                  dynvo::Executor* executor) {
  dynvo::OdometryPipeline pipeline(camera, config, area, executor);
  DynvoRun run;
  const bool live = rate > 0;
  const Clock::time_point start = Clock::now();
  for (size_t i = 0; i < frames.size(); ++i) {
    const bool has_next = i + 1 < frames.size();
    const Clock::time_point ready = live ? Arrival(start, has_next ? i + 1 : i, rate) : start;
    if (live) std::this_thread::sleep_until(ready);
    const dynvo::FrameRecord rec = pipeline.Process(frames[i], has_next ? &frames[i + 1] : nullptr).record;
    run.times.push_back(live ? std::chrono::duration<double, std::milli>(Clock::now() - ready).count()
                             : rec.times.processing_ms);
    run.trajectory.push_back({rec.stamp, rec.world_from_camera});
    run.stages["dynamic_mask"].push_back(rec.times.dynamic_mask_ms);
    run.stages["features"].push_back(rec.times.features_ms);
    run.stages["filter"].push_back(rec.times.filter_ms);
    run.stages["match"].push_back(rec.times.match_ms);
    run.stages["pose"].push_back(rec.times.pose_ms);
    run.stages["map"].push_back(rec.times.map_ms);
    run.stages["local_ba"].push_back(rec.times.local_ba_ms);
    if (rec.lines >= 0) run.stages["lines"].push_back(rec.times.lines_ms);
    // Keyframes apart: they add map points and lines, and start a local BA.
    run.stages[rec.keyframe ? "frame (keyframes)" : "frame (other frames)"].push_back(rec.times.processing_ms);
    run.features_total.push_back(rec.features_total);
    run.features_removed.push_back(rec.features_removed);
    run.dynamic_ratio.push_back(rec.dynamic_ratio);
    run.inliers.push_back(rec.num_inliers);
    if (rec.state == dynvo::TrackingState::kLost) ++run.lost_frames;
  }
  return run;
}

// Prints each method's line and adds it to the report; writes the trajectories when asked.
void ReportMethods(const std::vector<MethodResult>& results, const MethodResult& rgbd, const SpeedArgs& args,
                   nlohmann::json* report) {
  // Ratio to RgbdOdometry: median over runs of the run's ratio (0 = not measured).
  const double reference = args.no_peers ? 0.0 : Median(rgbd.run_medians);
  std::printf("%-22s %10s %10s %10s %10s %18s\n", "method", "median_ms", "mean_ms", "p90_ms", "max_ms",
              "ratio_to_rgbd_odo");
  for (const MethodResult& m : results) {
    std::vector<double> sorted = m.last_run;
    std::sort(sorted.begin(), sorted.end());
    const double p90 = sorted.empty() ? 0 : sorted[static_cast<size_t>(0.9 * (sorted.size() - 1))];
    const double median = Median(m.run_medians);
    std::vector<double> ratios;
    for (size_t r = 0; r < rgbd.run_medians.size() && r < m.run_medians.size(); ++r)
      ratios.push_back(m.run_medians[r] / rgbd.run_medians[r]);
    const double ratio = reference > 0 ? Median(ratios) : 0.0;
    const double max = sorted.empty() ? 0 : sorted.back();
    std::printf("%-22s %10.2f %10.2f %10.2f %10.2f %18s\n", m.name.c_str(), median, Mean(m.last_run), p90, max,
                reference > 0 ? cv::format("%.2f", ratio).c_str() : "-");
    (*report)["methods"][m.name] = {{"median_ms", median},
                                    {"mean_ms", Mean(m.last_run)},
                                    {"p90_ms", p90},
                                    {"max_ms", max},
                                    {"run_medians_ms", m.run_medians}};
    if (reference > 0) {
      (*report)["methods"][m.name]["ratio_to_rgbd_odometry"] = ratio;
      (*report)["methods"][m.name]["run_ratios_to_rgbd_odometry"] = ratios;
    }
    if (!args.trajectories_out.empty()) {
      std::filesystem::create_directories(args.trajectories_out);
      dynvo::WriteTrajectory(args.trajectories_out + "/" + m.name + ".txt", m.trajectory);
    }
  }
}

// Prints dynvo's counts and per-stage split of its last run and adds them to the report.
void ReportLastRun(const DynvoRun& last, nlohmann::json* report) {
  (*report)["dynvo_last_run"] = {{"features_total_mean", Mean(last.features_total)},
                                 {"features_removed_mean", Mean(last.features_removed)},
                                 {"dynamic_ratio_mean", Mean(last.dynamic_ratio)},
                                 {"pose_inliers_mean", Mean(last.inliers)},
                                 {"lost_frames", last.lost_frames}};
  std::printf(
      "\ndynvo (last run): %.0f features per frame, %.1f removed, dynamic pixels %.2f%%, "
      "%.0f pose inliers, %d frames lost\n",
      Mean(last.features_total), Mean(last.features_removed), 100.0 * Mean(last.dynamic_ratio), Mean(last.inliers),
      last.lost_frames);
  std::printf("dynvo per-stage split (last run): median_ms mean_ms\n");
  for (const auto& [stage, values] : last.stages) {
    std::printf("  %-14s %8.3f %8.3f\n", stage.c_str(), Median(values), Mean(values));
    (*report)["stages"][stage] = {{"median_ms", Median(values)}, {"mean_ms", Mean(values)}};
  }
}

// Times dynvo and (unless no_peers) the OpenCV peers over `runs` interleaved runs and reports.
int MeasureSpeed(const SpeedArgs& args) {
  const dynvo::OdometryConfig config = dynvo::LoadOdometryConfig(args.config_path, args.overrides);
  const dynvo::TumDataset dataset(args.dataset_dir, config.ReaderOptions());
  size_t count = dataset.size();
  if (args.max_frames > 0) count = std::min(count, static_cast<size_t>(args.max_frames));
  const dynvo::Camera camera = ScaledCamera(dataset.camera(), args.scale);
  const dynvo::ImageArea area = ScaledArea(dataset.image_area(), dataset.camera(), camera);
  std::vector<dynvo::RgbdFrame> frames;
  for (size_t i = 0; i < count; ++i) {
    frames.push_back(dataset.Load(i));
    ResizeFrame(frames.back(), camera);
  }
  std::fprintf(stderr, "odometry_speed: %zu frames of %s (%dx%d) in memory, %d runs each\n", frames.size(),
               dataset.name().c_str(), camera.width, camera.height, args.runs);
  // Each run of dynvo is followed by one run of each peer on the same frames, so that the
  // ratio of a run compares methods timed within seconds of each other on this shared machine.
  MethodResult ours{"dynvo", {}, {}, {}};
  MethodResult rgbd{"opencv_rgbd_odometry", {}, {}, {}}, icp{"opencv_icp_odometry", {}, {}, {}};
  cv::Mat k32;
  camera.K().convertTo(k32, CV_32F);
  const cv::Ptr<cv::rgbd::Odometry> rgbd_odometry = cv::rgbd::RgbdOdometry::create(k32);
  const cv::Ptr<cv::rgbd::Odometry> icp_odometry = cv::rgbd::ICPOdometry::create(k32);
  dynvo::Executor executor(args.threads - 1);  // the calling thread is the other one, as in dynvo-cli run
  DynvoRun last;
  for (int r = 0; r < args.runs; ++r) {
    last = RunDynvo(frames, camera, config, area, args.rate, &executor);
    AppendRun(&ours, MethodResult{"dynvo", {Median(last.times)}, last.times, last.trajectory});
    if (args.no_peers) continue;
    AppendRun(&rgbd, RunPeer(rgbd.name, rgbd_odometry, frames, 1));
    AppendRun(&icp, RunPeer(icp.name, icp_odometry, frames, 1));
  }
  nlohmann::json report = {{"dataset", dataset.name()},
                           {"frames", frames.size()},
                           {"runs", args.runs},
                           {"config", args.config_path.empty() ? "defaults" : args.config_path},
                           {"overrides", args.overrides},
                           {"threads", args.threads},
                           {"scale", args.scale},
                           {"rate", args.rate},
                           {"width", camera.width},
                           {"height", camera.height},
                           {"features", {{"num_features", config.features.num_features}}}};
  std::printf("per-frame %s, %zu frames of %s at %dx%d, median over frames, median of %d runs\n",
              args.rate > 0 ? cv::format("time from arrival at %g frames/s", args.rate).c_str() : "processing time",
              frames.size(), dataset.name().c_str(), camera.width, camera.height, args.runs);
  std::vector<MethodResult> results = {ours};
  if (!args.no_peers) results.insert(results.end(), {rgbd, icp});
  ReportMethods(results, rgbd, args, &report);
  ReportLastRun(last, &report);
  if (!args.json_out.empty()) std::ofstream(args.json_out) << report.dump(2) << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"odometry_speed: dynvo per-frame cost against OpenCV RgbdOdometry and ICPOdometry"};
  SpeedArgs args;
  app.add_option("--dataset", args.dataset_dir, "TUM sequence folder")->required();
  app.add_option("--config", args.config_path, "dynvo config (default: the built-in recommended config)");
  app.add_option("--set", args.overrides, "config override key=value (repeatable)");
  app.add_option("--runs", args.runs, "repetitions of each method (median over runs)")->check(CLI::Range(1, 100));
  app.add_option("--frames", args.max_frames, "use at most this many frames (0 = all)");
  app.add_option("--scale", args.scale,
                 "resize the frames by this factor (depth nearest-neighbour) and scale the "
                 "intrinsics: 0.5 gives 320x240 from 640x480, 2 gives 1280x960")
      ->check(CLI::Range(0.1, 4.0));
  app.add_option("--threads", args.threads, "threads dynvo uses (default: the machine's cores, as dynvo-cli run)")
      ->check(CLI::PositiveNumber);
  app.add_option("--rate", args.rate,
                 "feed dynvo the frames as a live camera at this many frames per second and time each "
                 "frame from its arrival (0 = back to back, the call's time)")
      ->check(CLI::Range(0.0, 1000.0));
  app.add_flag("--no-peers", args.no_peers, "time dynvo only, not the OpenCV odometries");
  app.add_option("--trajectories-out", args.trajectories_out, "write each method's trajectory here");
  app.add_option("--json", args.json_out, "write the figures as JSON to this file");
  app.set_version_flag("--version", dynvo::VersionLine("odometry_speed"));
  CLI11_PARSE(app, argc, argv);
  try {
    return MeasureSpeed(args);
  } catch (const dynvo::InputError& e) {
    std::fprintf(stderr, "odometry_speed: error: %s\n", e.what());
    return 1;
  }
}
