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

// The cut-outs of --person (each with its --person-mask or --person-box, in order), the
// drawn person for "--person drawn", or the default photos.
std::vector<dynvo::PersonCutout> LoadCutouts(const std::vector<std::string>& persons,
                                             const std::vector<std::string>& masks,
                                             const std::vector<std::string>& boxes, unsigned seed) {
  if (persons.empty()) {
    if (!masks.empty() || !boxes.empty()) throw dynvo::InputError("--person-mask and --person-box need --person");
    return dynvo::DefaultPersonCutouts();
  }
  if (persons.size() == 1 && persons[0] == "drawn") return {dynvo::MakeSyntheticPersonCutout(seed)};
  if (masks.size() + boxes.size() != persons.size() || (!masks.empty() && !boxes.empty()))
    throw dynvo::InputError("give each --person one --person-mask, or each one --person-box (" +
                            std::to_string(persons.size()) + " --person, " + std::to_string(masks.size()) +
                            " --person-mask, " + std::to_string(boxes.size()) + " --person-box)");
  std::vector<dynvo::PersonCutout> cutouts;
  for (size_t i = 0; i < persons.size(); ++i) {
    if (!masks.empty()) {
      cutouts.push_back(dynvo::LoadPersonCutout(persons[i], masks[i]));
      continue;
    }
    const cv::Mat image = cv::imread(persons[i], cv::IMREAD_COLOR);
    if (image.empty()) throw dynvo::InputError(persons[i] + ": cannot read the person image");
    cutouts.push_back(dynvo::CutoutWithGrabCut(image, ParseBox(boxes[i]), 5, seed, persons[i]));
  }
  return cutouts;
}

}  // namespace

int main(int argc, char** argv) {
  const char* prog = "dynvo-insert-people";
  CLI::App app{
      "Insert people (articulated photo cut-outs) into a real TUM RGB-D sequence: occlusion against "
      "the real depth, ground-truth dynamic masks, per-person labels and coverage"};
  std::string dataset, preset = "tum_walking", out;
  std::vector<std::string> persons, person_masks, person_boxes;
  dynvo::InsertionOptions options;
  unsigned seed = 1;
  bool force = false;
  app.add_option("--dataset", dataset, "real TUM sequence folder with groundtruth.txt")->required();
  app.add_option("--person", persons,
                 "photo of a person (repeat for more people; 'drawn': a drawn person; "
                 "default: two people of opencv-doc's person_multi_det.jpg)");
  auto* mask_opt =
      app.add_option("--person-mask", person_masks, "mask of the person in each --person (non-zero = person)");
  auto* box_opt =
      app.add_option("--person-box", person_boxes, "x,y,w,h box around the person in each --person (GrabCut)");
  mask_opt->excludes(box_opt);
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
    const std::vector<dynvo::PersonCutout> cutouts = LoadCutouts(persons, person_masks, person_boxes, seed);
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
