// dynvo-insert-people: inserts people (articulated photo cut-outs) into a real TUM sequence
// through its groundtruth poses, with occlusion against the real depth, a ground-truth
// dynamic mask per frame (masks/), per-person labels (people.txt) and coverage (stats.csv).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "synth/people_insertion.h"
#include "synth/person_cutout.h"
#include "synth/tum_writer.h"
#include "tool_main.h"

namespace {

cv::Rect ParseBox(const std::string& text) {
  std::istringstream in(text);
  int v[4];
  char comma = 0;
  for (int i = 0; i < 4; ++i) {
    if (!(in >> v[i]) || (i < 3 && (!(in >> comma) || comma != ',')))
      throw dynvo::InputError("--person-box must be x,y,w,h in pixels, got '" + text + "'");
  }
  return {v[0], v[1], v[2], v[3]};
}

// The people's sources: each --person with its --person-mask, or its --person-box (and
// --person-depth, when given), in order.
struct PersonSources {
  std::vector<std::string> images, masks, boxes, depths;
};

// The cut-out of person `i` of `sources` from its box: by its depth image, else by GrabCut.
dynvo::PersonCutout CutoutInBox(const PersonSources& sources, size_t i, unsigned seed) {
  const std::string& path = sources.images[i];
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw dynvo::InputError(path + ": cannot read the person image");
  const cv::Rect box = ParseBox(sources.boxes[i]);
  if (sources.depths.empty()) return dynvo::CutoutWithGrabCut(image, box, 5, seed, path);
  const cv::Mat depth = cv::imread(sources.depths[i], cv::IMREAD_ANYDEPTH);
  if (depth.empty()) throw dynvo::InputError(sources.depths[i] + ": cannot read the person's depth image");
  return dynvo::CutoutWithDepth(image, depth, box, sources.depths[i]);
}

// The cut-outs of --person (each with its --person-mask or --person-box, in order), the
// drawn person for "--person drawn", or the default photos.
std::vector<dynvo::PersonCutout> LoadCutouts(const PersonSources& sources, unsigned seed) {
  const std::vector<std::string>& persons = sources.images;
  const std::vector<std::string>& masks = sources.masks;
  const std::vector<std::string>& boxes = sources.boxes;
  if (persons.empty()) {
    if (!masks.empty() || !boxes.empty() || !sources.depths.empty())
      throw dynvo::InputError("--person-mask, --person-box and --person-depth need --person");
    return dynvo::DefaultPersonCutouts();
  }
  if (persons.size() == 1 && persons[0] == "drawn") return {dynvo::MakeSyntheticPersonCutout(seed)};
  if (masks.size() + boxes.size() != persons.size() || (!masks.empty() && !boxes.empty()))
    throw dynvo::InputError("give each --person one --person-mask, or each one --person-box (" +
                            std::to_string(persons.size()) + " --person, " + std::to_string(masks.size()) +
                            " --person-mask, " + std::to_string(boxes.size()) + " --person-box)");
  if (!sources.depths.empty() && sources.depths.size() != boxes.size())
    throw dynvo::InputError("give each --person-box one --person-depth, or none (" + std::to_string(boxes.size()) +
                            " --person-box, " + std::to_string(sources.depths.size()) + " --person-depth)");
  std::vector<dynvo::PersonCutout> cutouts;
  for (size_t i = 0; i < persons.size(); ++i)
    cutouts.push_back(masks.empty() ? CutoutInBox(sources, i, seed) : dynvo::LoadPersonCutout(persons[i], masks[i]));
  return cutouts;
}

}  // namespace

int main(int argc, char** argv) {
  const char* prog = "dynvo-insert-people";
  CLI::App app{
      "Insert people (articulated photo cut-outs) into a real TUM RGB-D sequence: occlusion against "
      "the real depth, ground-truth dynamic masks, per-person labels and coverage"};
  std::string dataset, preset = "tum_walking", out;
  PersonSources people;
  dynvo::InsertionOptions options;
  unsigned seed = 1;
  bool force = false;
  app.add_option("--dataset", dataset, "real TUM sequence folder with groundtruth.txt")->required();
  app.add_option("--person", people.images,
                 "photo of a person (repeat for more people; 'drawn': a drawn person; "
                 "default: two people of opencv-doc's person_multi_det.jpg)");
  auto* mask_opt =
      app.add_option("--person-mask", people.masks, "mask of the person in each --person (non-zero = person)");
  auto* box_opt =
      app.add_option("--person-box", people.boxes,
                     "x,y,w,h box around the person in each --person (cut by GrabCut, or by --person-depth)");
  auto* depth_opt = app.add_option("--person-depth", people.depths,
                                   "TUM depth PNG registered to each --person: the box is cut to its nearest "
                                   "depth layer (a person in a real RGB-D frame) instead of by GrabCut");
  mask_opt->excludes(box_opt);
  depth_opt->needs(box_opt);
  app.add_option("--preset", preset,
                 "tum_walking|tum_toward|tum_away|tum_sitting|walking_across|walking_toward|"
                 "two_crossing|sitting_sway")
      ->capture_default_str();
  app.add_option("--height", options.person_height_m, "person height in metres")->capture_default_str();
  app.add_option("--distance", options.distance_m,
                 "metres in front of the middle frame's camera (0: chosen; tum_ presets: in 1-3 m "
                 "covering a fifth of the image, others: in 1-4 m showing the most of the people)")
      ->capture_default_str();
  app.add_option("--speed", options.walk_speed_mps, "walking speed in metres per second")->capture_default_str();
  app.add_option("--camera-height", options.camera_height_m,
                 "metres of the camera above the floor (0: the people's mid-height on the middle frame's "
                 "optical axis for the tum_ presets, else 1.5)")
      ->capture_default_str();
  app.add_option("--seed", seed, "seed of the depth noise, the drawn person and GrabCut")->capture_default_str();
  app.add_option("--out", out, "output folder (TUM layout with masks/, people.txt, stats.csv)")->required();
  app.add_flag("--force", force, "replace the generated files of an existing non-empty --out");
  return dynvo::RunToolMain(prog, app, argc, argv, [&] {
    options.preset = dynvo::ParseScenario(preset, "--preset");
    options.seed = seed;
    options.Check();
    const std::vector<dynvo::PersonCutout> cutouts = LoadCutouts(people, seed);
    if (std::filesystem::exists(out) && std::filesystem::exists(dataset) && std::filesystem::equivalent(out, dataset))
      throw dynvo::InputError(out + ": --out must differ from --dataset");
    dynvo::PrepareOutputFolder(out, force);
    const auto start = std::chrono::steady_clock::now();
    const dynvo::InsertionSummary summary = dynvo::InsertPeopleIntoSequence(dataset, cutouts, options, out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "%s: wrote %d frames to %s in %.1f s; %d frames show people (the first: frame %d), %d frames had no "
        "groundtruth pose; people cover %.1f%% of the image (median over frames, mean %.1f%%); distance %.1f m\n",
        prog, summary.frames, out.c_str(), seconds, summary.frames_with_people, summary.first_frame_with_people,
        summary.frames_without_pose, 100 * summary.median_coverage, 100 * summary.mean_dynamic_ratio,
        summary.distance_m);
    const dynvo::CoverageRange range = dynvo::DeclaredCoverage(options.preset);
    if (summary.median_coverage < range.low || summary.median_coverage > range.high)
      std::fprintf(stderr,
                   "%s: note: preset %s declares a median coverage of %.0f-%.0f%%; this sequence's is %.1f%% "
                   "(near surfaces hide the people, or they leave the view)\n",
                   prog, preset.c_str(), 100 * range.low, 100 * range.high, 100 * summary.median_coverage);
  });
}
