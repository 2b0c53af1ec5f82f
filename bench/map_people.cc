// How much of a slam run's static map lies on the people of its generated sequence (ground-
// truth masks), as JSON: `map_people --dataset SEQ --run RUN_DIR` reads RUN_DIR/map.ply and
// RUN_DIR/trajectory.txt (eval/map_on_people.h). Used by tools/table3.sh.

#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "dataset/trajectory_io.h"
#include "dataset/tum_dataset.h"
#include "eval/map_on_people.h"
#include "loop/static_map.h"

int main(int argc, char** argv) {
  CLI::App app{"The share of a slam run's map.ply on the people of its sequence (ground-truth masks)"};
  std::string dataset, run;
  app.add_option("--dataset", dataset, "the generated sequence (with masks.txt)")->required();
  app.add_option("--run", run, "the dynvo-cli run --mode slam --map folder")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    const dynvo::TumDataset sequence(dataset);
    const dynvo::StaticMap map = dynvo::ReadMapPly(run + "/map.ply");
    const dynvo::MapOnPeople result =
        dynvo::MapPointsOnPeople(map.points, sequence, dynvo::ReadTrajectory(run + "/trajectory.txt"));
    std::printf("{\"points\": %zu, \"on_people\": %zu, \"share\": %.6f}\n", result.points, result.on_people,
                result.share());
  } catch (const dynvo::InputError& e) {
    std::fprintf(stderr, "map_people: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
