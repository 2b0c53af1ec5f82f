// Fuzz tests of every input parser and entry point: image lists, trajectories, configs and
// camera.json, the rpe/ate computations, and a sequence folder opened and read as `dynvo-cli
// run` does. Seeded mutations of valid files (tests/support/text_mutator.h) must each end in
// a result that holds its promises or in an InputError: never another exception, a crash or
// a hang. DYNVO_FUZZ_ITERATIONS sets the inputs per target (bench/fuzz.sh runs 10^6).

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "core/json_file.h"
#include "dataset/camera_file.h"
#include "dataset/image_list.h"
#include "dataset/trajectory_io.h"
#include "dataset/tum_dataset.h"
#include "eval/ate.h"
#include "eval/rpe.h"
#include "odometry/odometry_config.h"
#include "support/temp_dir.h"
#include "support/text_mutator.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

size_t Iterations(size_t in_ctest) {
  const char* value = std::getenv("DYNVO_FUZZ_ITERATIONS");
  return value && *value ? std::strtoull(value, nullptr, 10) : in_ctest;
}

// The input as a C string literal, for a failure message that reproduces it.
std::string Escaped(const std::string& input) {
  std::ostringstream out;
  for (unsigned char c : input) {
    if (c == '\n') {
      out << "\\n";
    } else if (c < 32 || c >= 127 || c == '"' || c == '\\') {
      out << "\\x" << std::hex << static_cast<int>(c) << std::dec << "\"\"";
    } else {
      out << c;
    }
  }
  return "\"" + out.str() + "\"";
}

// Feeds `iterations` mutations of the seeds to `run`; an InputError is a refused input, any
// other exception a failure that names the input. Both outcomes must occur.
void Fuzz(const std::string& target, const std::vector<std::string>& seeds, size_t iterations,
          const std::function<void(const std::string&)>& run) {
  test::TextMutator mutator(20261128);
  size_t accepted = 0, refused = 0;
  for (size_t i = 0; i < iterations; ++i) {
    const std::string input = mutator.Mutate(seeds[i % seeds.size()]);
    try {
      run(input);
      ++accepted;
    } catch (const InputError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << target << ": input " << i << " threw " << e.what() << "\ninput: " << Escaped(input);
      return;
    }
  }
  std::cout << target << ": " << iterations << " inputs, " << accepted << " accepted, " << refused << " refused\n";
  EXPECT_GT(accepted, 0u) << target;
  EXPECT_GT(refused, 0u) << target;
}

// A promise of an accepted input that does not hold: a failure like a crash.
void Require(bool promise, const std::string& what) {
  if (!promise) throw std::logic_error("accepted input breaks its promise: " + what);
}

std::string TrajectorySeed(double first_stamp, double speed) {
  Trajectory trajectory;
  for (int k = 0; k < 40; ++k)
    trajectory.push_back({first_stamp + 0.033 * k, PoseFromAxisAngle({0.01 * k, 0.02, -0.01 * k},
                                                                     {speed * k * 0.033, 0.1 * std::sin(0.2 * k), 1})});
  return "# timestamp tx ty tz qx qy qz qw\n" + FormatTrajectory(trajectory);
}

void RequireValidTrajectory(const Trajectory& t) {
  for (size_t k = 0; k < t.size(); ++k) {
    Require(std::isfinite(t[k].stamp) && std::abs(t[k].stamp) < 1e12, "finite stamps in seconds");
    Require(k == 0 || t[k].stamp > t[k - 1].stamp, "increasing stamps");
    Require(t[k].world_from_camera.matrix().allFinite(), "finite poses");
  }
}

TEST(InputFuzz, ImageLists) {
  const std::string seed =
      "# color images\n# timestamp filename\n1305031102.175304 rgb/1305031102.175304.png\n"
      "1305031102.211214 rgb/1305031102.211214.png\r\n1305031102.243211\trgb/1305031102.243211.png\n";
  Fuzz("image lists", {seed}, Iterations(20000), [](const std::string& text) {
    const std::vector<ImageListEntry> entries = ParseImageList(text, "rgb.txt");
    for (size_t k = 0; k < entries.size(); ++k) {
      Require(std::isfinite(entries[k].stamp) && std::abs(entries[k].stamp) < 1e12, "finite stamps in seconds");
      Require(k == 0 || entries[k].stamp > entries[k - 1].stamp, "strictly increasing stamps");
      Require(!entries[k].path.empty(), "a file name");
    }
  });
}

TEST(InputFuzz, TrajectoriesAndTheMetricsOnThem) {
  const std::string gt = TrajectorySeed(1305031102.1, 0.5), est = TrajectorySeed(1305031102.1, 0.45);
  Fuzz("trajectories, rpe, ate", {gt, est}, Iterations(20000), [&](const std::string& text) {
    const Trajectory mutated = ParseTrajectory(text, "estimate.txt");
    RequireValidTrajectory(mutated);
    const Trajectory reference = ParseTrajectory(gt, "groundtruth.txt");
    for (const DeltaUnit unit : {DeltaUnit::kSeconds, DeltaUnit::kFrames, DeltaUnit::kMeters}) {
      RpeOptions options;
      options.unit = unit;
      options.delta = unit == DeltaUnit::kMeters ? 0.1 : 1.0;
      try {
        const RpeResult rpe = ComputeRpe(reference, mutated, options);
        Require(std::isfinite(rpe.translation_m.rmse) && std::isfinite(rpe.rotation_deg.rmse), "a finite RPE");
      } catch (const InputError&) {
      }
    }
    const AteResult ate = ComputeAte(reference, mutated, AteOptions{});
    Require(std::isfinite(ate.translation_m.rmse), "a finite ATE");
  });
}

TEST(InputFuzz, ConfigsAndCameraFiles) {
  std::vector<std::string> configs;
  for (const char* name : {"dynvo.json", "paper.json", "baseline.json"}) {
    std::ifstream in(std::string(DYNVO_SOURCE_DIR) + "/configs/" + name);
    std::ostringstream text;
    text << in.rdbuf();
    configs.push_back(text.str());
  }
  Fuzz("configs", configs, Iterations(5000), [](const std::string& text) {
    const OdometryConfig config = ParseOdometryConfig(text, "config.json", {});
    // What is accepted reloads to itself, as run.json's echo promises.
    const std::string echo = JsonText(OdometryConfigToJson(config));
    Require(JsonText(OdometryConfigToJson(ParseOdometryConfig(echo, "echo", {}))) == echo,
            "the echo reloads to the same config");
  });
  Fuzz("--set overrides",
       {"features.num_features=1000", "camera.source=custom", "dynamic_mask.backward=triplet",
        "detector.classes=[0, 2]", "camera.fx=540.5", "run.max_frames=10"},
       Iterations(20000), [](const std::string& text) {
         const OdometryConfig config = ParseOdometryConfig("", "", {text});
         JsonText(OdometryConfigToJson(config), 2);  // run.json's echo of it
       });
  const std::string camera =
      R"({"width": 640, "height": 480, "fx": 535.4, "fy": 539.2, "cx": 320.1, "cy": 247.6,
          "distortion": [0.1, -0.2, 0, 0, 0.05], "depth_factor": 5000})";
  Fuzz("camera.json", {camera}, Iterations(20000), [](const std::string& text) {
    const CameraFile file = ParseCameraFile(text, "camera.json");
    file.camera.Check("camera.json");
    Require(!file.depth_factor || *file.depth_factor > 0, "a positive depth factor");
  });
}

// A 4-frame folder of 32x24 images, its lists and camera.json, as `dynvo-cli run` reads it.
struct TinySequence {
  explicit TinySequence(const test::TempDir& dir) : folder((dir.path() / "seq").string()) {
    fs::create_directories(fs::path(folder) / "rgb");
    fs::create_directories(fs::path(folder) / "depth");
    std::ostringstream rgb, depth;
    for (int k = 0; k < 4; ++k) {
      const std::string name = std::to_string(k) + ".png";
      cv::imwrite(folder + "/rgb/" + name, cv::Mat(24, 32, CV_8UC3, cv::Scalar(10 * k, 20, 30)));
      cv::imwrite(folder + "/depth/" + name, cv::Mat(24, 32, CV_16UC1, cv::Scalar(5000 + k)));
      rgb << 100 + 0.033 * k << " rgb/" << name << "\n";
      depth << 100.005 + 0.033 * k << " depth/" << name << "\n";
    }
    files = {{"rgb.txt", rgb.str()},
             {"depth.txt", depth.str()},
             {"camera.json", R"({"width": 32, "height": 24, "fx": 30, "fy": 30, "cx": 15.5, "cy": 11.5})"},
             {"groundtruth.txt", TrajectorySeed(99.9, 0.2)}};
  }
  void Write(const std::string& name, const std::string& text) const {
    std::ofstream(fs::path(folder) / name, std::ios::binary | std::ios::trunc) << text;
  }
  std::string folder;
  std::vector<std::pair<std::string, std::string>> files;
};

TEST(InputFuzz, SequenceFoldersOpenedAndReadAsARunDoes) {
  test::TempDir dir;
  const TinySequence sequence(dir);
  std::vector<std::string> seeds;
  for (const auto& [name, text] : sequence.files) seeds.push_back(text);
  size_t round = 0;
  Fuzz("sequence folders", seeds, Iterations(2000), [&](const std::string& text) {
    // The file this input replaces: the one whose seed it came from.
    const size_t which = round++ % sequence.files.size();
    for (size_t k = 0; k < sequence.files.size(); ++k)
      sequence.Write(sequence.files[k].first, k == which ? text : sequence.files[k].second);
    const TumDataset dataset(sequence.folder);
    for (size_t i = 0; i < dataset.size(); ++i) {
      const RgbdFrame frame = dataset.Load(i);
      Require(frame.depth.size() == frame.gray.size() && !frame.gray.empty(), "a whole frame");
    }
    if (dataset.has_groundtruth()) RequireValidTrajectory(dataset.groundtruth());
  });
}

}  // namespace
}  // namespace dynvo
