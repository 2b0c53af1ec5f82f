#include "odometry/sequence_runner.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <set>

#include "core/build_info.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/output_file.h"
#include "dataset/trajectory_io.h"
#include "loop/loop_closer.h"
#include "odometry/debug_panels_writer.h"
#include "odometry/frame_loader.h"
#include "odometry/loop_outputs.h"
#include "odometry/odometry_pipeline.h"
#include "odometry/progress_meter.h"
#include "odometry/timing_csv.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

constexpr const char* kOutputs[] = {"trajectory.txt", "timing.csv", "run.json", "trajectory_online.txt",
                                    "keyframes.txt",  "loops.csv",  "map.ply",  "map_top.png"};

// With --force, the earlier run's outputs go first, so that none of them outlives it.
void RemoveEarlierRun(const fs::path& dir) {
  std::error_code ec;
  std::vector<std::string> names(std::begin(kOutputs), std::end(kOutputs));
  names.insert(names.end(), {"run.json.tmp", "debug"});
  for (const std::string& name : names) {
    fs::remove_all(dir / name, ec);
    if (ec) throw InputError((dir / name).string() + ": cannot remove the earlier run's output: " + ec.message());
  }
}

void PrepareOutputDir(const RunRequest& request) {
  if (request.out_dir.empty()) throw InputError("--out: an output folder is required");
  const fs::path dir(request.out_dir);
  if (fs::exists(dir) && !fs::is_directory(dir)) throw InputError(request.out_dir + ": exists and is not a folder");
  if (!request.force)
    for (const char* name : kOutputs)
      if (fs::exists(dir / name))
        throw InputError((dir / name).string() + ": exists from an earlier run; pass --force to overwrite");
  if (request.force && fs::is_directory(dir)) RemoveEarlierRun(dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(request.out_dir + ": cannot create folder: " + ec.message());
  if (!request.debug_frames.empty()) {
    fs::create_directories(dir / "debug", ec);
    if (ec) throw InputError((dir / "debug").string() + ": cannot create folder: " + ec.message());
  }
}

nlohmann::json Summary(std::vector<double> values) {
  if (values.empty()) return nullptr;
  std::sort(values.begin(), values.end());
  auto at = [&](double q) { return values[static_cast<size_t>(q * (values.size() - 1) + 0.5)]; };
  double sum = 0;
  for (double v : values) sum += v;
  const size_t n = values.size();
  const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  return {{"median", median}, {"mean", sum / n}, {"p90", at(0.9)}, {"max", values.back()}};
}

nlohmann::json CameraJson(const Camera& c) {
  nlohmann::json camera = {{"width", c.width}, {"height", c.height},        {"fx", c.fx}, {"fy", c.fy}, {"cx", c.cx},
                           {"cy", c.cy},       {"distortion", c.distortion}};
  camera["rolling_shutter_readout_s"] = c.rolling_shutter_readout_s;
  return camera;
}

// Collects per-frame figures for run.json.
struct RunTally {
  std::vector<double> processing, load;
  std::map<std::string, std::vector<double>> stages;
  std::map<std::string, int> states;
  int keyframes = 0, mask_computed = 0, mask_failed = 0;
  int local_ba_adjusted = 0, local_ba_converged = 0;  // BA results that joined the map; of them converged
  // With a detector: frames, person-frames (found, judged moving, judged still), failures and time-outs.
  int detector_frames = 0, detected_frames = 0, frames_with_people = 0, detector_failures = 0, detector_timeouts = 0;
  long long people = 0, people_moving = 0, people_still = 0;
  long long features_removed = 0, features_readmitted = 0, new_points_rejected = 0, coherent_motion_rejected = 0;
  MaskCounts mask_total;
  StillFeatureCounts still_features;
  std::vector<double> mask_iou;

  void Add(const FrameRecord& r) {
    processing.push_back(r.times.processing_ms);
    load.push_back(r.times.load_ms);
    const StageTimes& t = r.times;
    stages["dynamic_mask_ms"].push_back(t.dynamic_mask_ms);
    stages["features_ms"].push_back(t.features_ms);
    stages["filter_ms"].push_back(t.filter_ms);
    stages["match_ms"].push_back(t.match_ms);
    stages["pose_ms"].push_back(t.pose_ms);
    stages["map_ms"].push_back(t.map_ms);
    stages["local_ba_ms"].push_back(t.local_ba_ms);
    states[ToString(r.state)]++;
    keyframes += r.keyframe;
    local_ba_adjusted += r.local_ba_converged >= 0;
    local_ba_converged += r.local_ba_converged == 1;
    mask_computed += r.mask_ok;
    mask_failed += !r.mask_ok && !r.mask_note.empty();
    if (r.people >= 0) AddDetector(r);
    features_removed += r.features_removed;
    features_readmitted += r.features_readmitted;
    new_points_rejected += r.new_points_rejected;
    coherent_motion_rejected += r.coherent_motion_rejected;
    if (r.mask_quality) {
      mask_total += *r.mask_quality;
      mask_iou.push_back(r.mask_quality->Iou());
    }
    if (r.still_features) still_features += *r.still_features;
  }

  void AddDetector(const FrameRecord& r) {
    ++detector_frames;
    detected_frames += r.detection_age == 0;
    frames_with_people += r.people > 0;
    detector_failures += r.detection == "failed";
    detector_timeouts += r.detection == "timed_out";
    stages["detector_ms"].push_back(r.times.detector_ms);
    people += r.people;
    if (r.people_moving < 0) return;  // nobody judged
    people_moving += r.people_moving;
    people_still += r.people - r.people_moving;
  }
};

// run.json's description of the run before it starts: dataset, config, outputs.
nlohmann::json RunHeader(const RunRequest& request, const OdometryConfig& config, const TumDataset& dataset,
                         size_t count) {
  const fs::path out(request.out_dir);
  nlohmann::json report;
  report["dynvo_version"] = DynvoVersion();
  report["dynvo_commit"] = BuildCommit();
  report["dataset"] = {{"folder", dataset.folder()},
                       {"name", dataset.name()},
                       {"frames_associated", dataset.size()},
                       {"frames_to_process", count},
                       {"unmatched_rgb", dataset.unmatched_rgb()},
                       {"has_groundtruth", dataset.has_groundtruth()},
                       {"has_masks", dataset.has_masks()},
                       {"camera", CameraJson(dataset.camera())},
                       {"sensor_camera", CameraJson(dataset.raw_camera())},
                       {"camera_source", dataset.camera_origin()},
                       {"depth_factor", dataset.depth_factor()},
                       {"depth_factor_source", dataset.depth_factor_origin()}};
  report["config_file"] = request.config_path;
  report["overrides"] = request.overrides;
  report["config"] = OdometryConfigToJson(config);
  report["mode"] = request.slam ? "slam" : "vo";
  report["outputs"] = {{"trajectory", (out / "trajectory.txt").string()}, {"timing", (out / "timing.csv").string()}};
  if (request.slam)
    report["outputs"].update({{"trajectory_online", (out / "trajectory_online.txt").string()},
                              {"keyframes", (out / "keyframes.txt").string()},
                              {"loops", (out / "loops.csv").string()}});
  if (request.map)
    report["outputs"].update({{"map", (out / "map.ply").string()}, {"map_top", (out / "map_top.png").string()}});

  return report;
}

// How the frame loop ended, and why when it did not complete.
struct RunEnd {
  RunStatus status = RunStatus::kCompleted;
  std::string message;  // the error, or what interrupted the run
};

// run.json's results: status, counts, times, memory and mask quality.
void AddRunResults(const RunTally& tally, double wall_s, const RunEnd& end, int threads, bool evaluate_masks,
                   nlohmann::json* out) {
  nlohmann::json& report = *out;
  double processing_total = 0;
  for (double v : tally.processing) processing_total += v;
  const size_t done = tally.processing.size();
  report["status"] = ToString(end.status);
  if (end.status == RunStatus::kFailed) report["error"] = end.message;
  if (end.status == RunStatus::kInterrupted) report["interrupted"] = end.message;
  report["counts"] = {{"frames", done},
                      {"tracking_states", tally.states},
                      {"keyframes", tally.keyframes},
                      {"local_ba", {{"adjusted", tally.local_ba_adjusted}, {"converged", tally.local_ba_converged}}},
                      {"masks_computed", tally.mask_computed},
                      {"masks_failed", tally.mask_failed},
                      {"features_removed", tally.features_removed},
                      {"features_readmitted", tally.features_readmitted},
                      {"new_points_rejected", tally.new_points_rejected},
                      {"coherent_motion_rejected", tally.coherent_motion_rejected}};
  if (tally.detector_frames > 0)
    report["counts"]["detector"] = {{"frames_detected", tally.detected_frames},
                                    {"frames_with_people", tally.frames_with_people},
                                    {"failures", tally.detector_failures},
                                    {"timed_out", tally.detector_timeouts},
                                    {"people", tally.people},
                                    {"people_moving", tally.people_moving},
                                    {"people_still", tally.people_still}};
  nlohmann::json stages;
  for (const auto& [name, values] : tally.stages) stages[name] = Summary(values);
  report["time"] = {{"processing_ms", Summary(tally.processing)},
                    {"load_ms", Summary(tally.load)},
                    {"stages", stages},
                    {"wall_s", wall_s},
                    {"end_to_end_fps", wall_s > 0 ? done / wall_s : 0.0},
                    {"processing_fps", processing_total > 0 ? 1000.0 * done / processing_total : 0.0},
                    {"threads", threads}};
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  report["memory"] = {{"peak_rss_mb", usage.ru_maxrss / 1024.0}};  // ru_maxrss is in KiB on Linux
  if (evaluate_masks && done > 0) {
    double iou_sum = 0;
    for (double v : tally.mask_iou) iou_sum += v;
    report["mask_quality"] = {
        {"frames", tally.mask_iou.size()},
        {"precision", tally.mask_total.Precision()},
        {"recall", tally.mask_total.Recall()},
        {"iou", tally.mask_total.Iou()},
        {"mean_frame_iou", iou_sum / tally.mask_iou.size()},
        {"pooling",
         "precision, recall and iou over all pixels of all frames; truth: the "
         "moving pixels (a person not moving counts as static)"},
        {"still_people",
         {{"features", tally.still_features.detected}, {"kept_share", tally.still_features.KeptShare()}}}};
  } else {
    report["mask_quality"] = nullptr;
  }
}

// Feeds every frame to `process`, frame t once frame t+1 is loaded (the triplet's backward
// detection and the look-ahead use it), and frame t first when frame t+1 fails to load or a
// stop is requested. Returns how the loop ended.
RunEnd ProcessFrames(FrameLoader* loader, const std::function<void(LoadedFrame&, const RgbdFrame*)>& process,
                     const std::function<bool()>& stop_requested, const RunTally& tally) {
  try {
    std::optional<LoadedFrame> pending;
    for (;;) {
      if (stop_requested && stop_requested()) {
        if (pending) process(*pending, nullptr);
        return {RunStatus::kInterrupted,
                "stopped by a signal after " + std::to_string(tally.processing.size()) + " frames"};
      }
      std::optional<LoadedFrame> loaded;
      try {
        loaded = loader->Next();
      } catch (const std::exception&) {
        if (pending) process(*pending, nullptr);
        throw;
      }
      if (!loaded) break;
      if (pending) process(*pending, &loaded->frame);
      pending = std::move(loaded);
    }
    if (pending) process(*pending, nullptr);
  } catch (const InputError& e) {
    return {RunStatus::kFailed, e.what()};
  } catch (const std::exception& e) {
    // An internal failure must not lose what was computed: record it like a load error.
    return {RunStatus::kFailed,
            "internal error after frame " + std::to_string(tally.processing.size()) + ": " + e.what()};
  }
  return {};
}

// slam mode, after the last frame: the loops closed, their outputs written and summarised in
// run.json. A failure here fails the run (what the frames produced is kept).
void FinishLoops(OdometryPipeline* pipeline, const std::string& out_dir, bool with_map, nlohmann::json* report,
                 RunEnd* end) {
  try {
    const std::optional<LoopClosingResult> loops = pipeline->FinishLoops();
    if (!loops) return;
    WriteLoopOutputs(out_dir, *loops, with_map);
    (*report)["loops"] = LoopsJson(*loops, with_map);
  } catch (const std::exception& e) {
    if (end->status == RunStatus::kFailed) return;  // the first failure first
    *end = {RunStatus::kFailed, std::string("loop closing: ") + e.what()};
  }
}

}  // namespace

const char* ToString(RunStatus status) {
  switch (status) {
    case RunStatus::kCompleted:
      return "completed";
    case RunStatus::kFailed:
      return "failed";
    case RunStatus::kInterrupted:
      return "interrupted";
  }
  return "failed";
}

nlohmann::json RunOdometry(const RunRequest& request) {
  const OdometryConfig config = LoadOdometryConfig(request.config_path, request.overrides);
  const TumDataset dataset(request.dataset, config.ReaderOptions());
  if (request.threads < 0) throw InputError("--threads must be >= 1, got " + std::to_string(request.threads));
  if (request.map && !request.slam) throw InputError("--map needs --mode slam: the map is placed by the closed loops");
  const int threads = request.threads > 0 ? request.threads : Executor::DefaultThreads();
  Executor executor(threads - 1);  // the calling thread is the other one
  LoopClosingOptions loop_closing;
  loop_closing.build_map = request.map;
  loop_closing.bundle_adjustment = config.local_ba;  // its loss, depth weight and rounds
  loop_closing.bundle_adjustment.enabled = true;     // whether or not tracking runs a local BA
  OdometryPipeline pipeline(dataset.camera(), config, dataset.image_area(), &executor,
                            request.slam ? &loop_closing : nullptr);
  if (pipeline.NeedsTruthMask() && !dataset.has_masks())
    throw InputError("mask_source \"ground_truth\": " + dataset.folder() +
                     " has no masks.txt; ground-truth masks come with generated sequences "
                     "(dynvo-synth, dynvo-insert-people, tools/make_sequences.sh)");
  PrepareOutputDir(request);

  const fs::path out(request.out_dir);
  size_t count = dataset.size();
  if (config.run.max_frames > 0) count = std::min(count, static_cast<size_t>(config.run.max_frames));
  const std::set<size_t> debug_frames(request.debug_frames.begin(), request.debug_frames.end());
  for (size_t f : debug_frames)
    if (f >= count)
      throw InputError("--debug-frames: frame " + std::to_string(f) + " is beyond the last frame " +
                       std::to_string(count - 1));

  nlohmann::json report = RunHeader(request, config, dataset, count);
  report["notices"] = pipeline.notices();
  for (const std::string& notice : pipeline.notices()) std::cerr << "dynvo-cli: note: " << notice << "\n";

  const bool evaluate_masks = dataset.has_masks() && config.mask_source != MaskSourceKind::kNone;
  FrameLoader loader(dataset, count, evaluate_masks, executor);
  const DebugPanelsWriter debug_panels((out / "debug").string(), debug_frames);
  TimingCsvWriter timing((out / "timing.csv").string());
  AppendedFile trajectory((out / (request.slam ? "trajectory_online.txt" : "trajectory.txt")).string());
  ProgressMeter progress(count, request.quiet);
  RunTally tally;
  const auto wall_start = std::chrono::steady_clock::now();
  // Slam mode: the loops closed so far, on the progress line (how far the background got).
  const auto loops_closed = [&pipeline] {
    const std::optional<int> loops = pipeline.LoopsClosed();
    return loops ? ", " + std::to_string(*loops) + " loops closed" : std::string();
  };

  auto process = [&](LoadedFrame& current, const RgbdFrame* next) {
    const ProcessedFrame processed = pipeline.Process(current.frame, next, current.truth_mask);
    FrameRecord record = processed.record;
    record.times.load_ms = current.load_ms;
    const cv::Mat moving = evaluate_masks ? cv::Mat(current.truth_mask & ~current.still_people) : cv::Mat();
    if (evaluate_masks) {
      record.mask_quality = CompareMasks(processed.stages.mask.mask, moving);
      record.still_features = CountStillFeatures(processed.stages.features.split, current.still_people);
    }
    debug_panels.OnFrame(current.frame, processed, moving, current.still_people);
    trajectory.Append(FormatTrajectory({{record.stamp, record.world_from_camera}}));
    timing.Write(record);
    tally.Add(record);
    progress.Update(tally.processing.size(), loops_closed);
  };

  RunEnd end = ProcessFrames(&loader, process, request.stop_requested, tally);
  progress.Finish(tally.processing.size(), loops_closed);
  FinishLoops(&pipeline, request.out_dir, request.map, &report, &end);

  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  AddRunResults(tally, wall_s, end, threads, evaluate_masks, &report);
  // Paths may hold any bytes: those that are not UTF-8 are written as U+FFFD, never a throw.
  try {
    WriteFileAtomically((out / "run.json").string(), JsonText(report, 2) + "\n");
  } catch (const InputError& e) {
    if (end.status != RunStatus::kFailed) throw;
    throw InputError(end.message + "; and " + e.what());  // the first failure first
  }
  if (end.status == RunStatus::kFailed) throw InputError(end.message);
  return report;
}

}  // namespace dynvo
