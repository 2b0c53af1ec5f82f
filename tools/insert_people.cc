// dynvo-insert-people: inserts walking people (planar cut-outs) into a real TUM sequence
// through its groundtruth poses, with occlusion against the real depth and a ground-truth
// dynamic mask per frame (masks/).
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

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

}  // namespace

int main(int argc, char** argv) {
  const char* prog = "dynvo-insert-people";
  CLI::App app{"Insert walking people into a real TUM RGB-D sequence (occlusion against the real depth, "
               "ground-truth dynamic masks)"};
  std::string dataset, person, person_mask, person_box, preset = "walking_across", out;
  dynvo::InsertionOptions options;
  unsigned seed = 1;
  bool force = false;
  app.add_option("--dataset", dataset, "real TUM sequence folder with groundtruth.txt")->required();
  app.add_option("--person", person, "photo of a person (default: a drawn, textured person)");
  auto* mask_opt = app.add_option("--person-mask", person_mask, "mask of the person in --person (non-zero = person)");
  auto* box_opt = app.add_option("--person-box", person_box, "x,y,w,h box around the person in --person (GrabCut)");
  mask_opt->excludes(box_opt);
  app.add_option("--preset", preset, "walking_across|walking_toward|two_crossing|sitting_sway")->capture_default_str();
  app.add_option("--height", options.person_height_m, "person height in metres")->capture_default_str();
  app.add_option("--distance", options.distance_m, "metres in front of the middle frame's camera (0: chosen in 1-4 m to show the most of the people)")->capture_default_str();
  app.add_option("--speed", options.walk_speed_mps, "walking speed in metres per second")->capture_default_str();
  app.add_option("--camera-height", options.camera_height_m, "metres of the camera above the floor")
      ->capture_default_str();
  app.add_option("--seed", seed, "seed of the drawn person and of GrabCut")->capture_default_str();
  app.add_option("--out", out, "output folder (TUM layout with masks/)")->required();
  app.add_flag("--force", force, "replace the generated files of an existing non-empty --out");
  return dynvo::RunToolMain(prog, app, argc, argv, [&] {
    options.preset = dynvo::ParseScenario(preset, "--preset");
    options.Check();
    dynvo::PersonCutout cutout;
    if (person.empty()) {
      if (!person_mask.empty() || !person_box.empty())
        throw dynvo::InputError("--person-mask and --person-box need --person");
      cutout = dynvo::MakeSyntheticPersonCutout(seed);
    } else if (!person_mask.empty()) {
      cutout = dynvo::LoadPersonCutout(person, person_mask);
    } else if (!person_box.empty()) {
      const cv::Mat image = cv::imread(person, cv::IMREAD_COLOR);
      if (image.empty()) throw dynvo::InputError(person + ": cannot read the person image");
      cutout = dynvo::CutoutWithGrabCut(image, ParseBox(person_box), 5, seed, person);
    } else {
      throw dynvo::InputError("--person needs --person-mask or --person-box");
    }
    if (std::filesystem::exists(out) && std::filesystem::exists(dataset) &&
        std::filesystem::equivalent(out, dataset))
      throw dynvo::InputError(out + ": --out must differ from --dataset");
    dynvo::PrepareOutputFolder(out, force);
    const auto start = std::chrono::steady_clock::now();
    const dynvo::InsertionSummary summary = dynvo::InsertPeopleIntoSequence(dataset, cutout, options, out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: wrote %d frames to %s in %.1f s; %d frames show people, %d frames had no groundtruth pose, "
                "mean dynamic pixel ratio %.3f, walking distance %.1f m\n",
                prog, summary.frames, out.c_str(), seconds, summary.frames_with_people, summary.frames_without_pose,
                summary.mean_dynamic_ratio, summary.distance_m);
  });
}
