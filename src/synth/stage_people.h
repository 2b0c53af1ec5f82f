#pragma once
// Where and how the people of each scenario move, on a stage in front of a reference camera,
// and their articulated bodies at any time. Stage frame: origin on the floor below the
// reference camera, x right, y forward (horizontal), z up; metres. The dolls face the
// reference camera (the photos are flat) and turn their limbs about their walking direction.

#include <vector>

#include <Eigen/Core>

#include "core/pose.h"
#include "synth/articulated_cutout.h"
#include "synth/moving_object.h"
#include "synth/scene.h"

namespace dynvo {

enum class StageMotion {
  kWalk,         // along the route at speed_mps
  kSit,          // seated, moving head and forearms a little
  kSitAndStand,  // seated, standing up and sitting down again every cycle_s
};

struct StagePerson {
  std::vector<Eigen::Vector2d> route;  // metres, stage (x, y) waypoints (one for a seated person)
  bool loop = false;                   // walk the route as a closed loop, else back and forth
  double speed_mps = 0;                // metres per second along the route
  double start_walked_m = 0;           // metres already walked at time 0
  StageMotion motion = StageMotion::kWalk;
  double cycle_s = 8.0;  // seconds per stand-up cycle (kSitAndStand)
  double phase_rad = 0;  // shifts the small motions of seated people
  int doll = 0;          // index into the dolls
};

struct StageGeometry {
  double distance_m = 2.0;      // metres from the reference camera to the middle of the people
  double speed_mps = 1.0;       // metres per second of walkers (TUM presets walk at 0.8x)
  double tan_half_fov = 0.62;   // tangent of half the horizontal field of view
  double person_width_m = 0.5;  // metres, for routes that leave the view
  double duration_s = 10;       // seconds the sequence lasts
};

// The people of `scenario` (none for kNone). TUM presets have everyone in view from time 0
// (tum_walking: two walkers across and around at 1-3 m; tum_toward / tum_away: one walker
// along the optical axis; tum_sitting: two seated people, one standing up and sitting down).
std::vector<StagePerson> PlanStagePeople(Scenario scenario, const StageGeometry& geometry);

// The share of the image a scenario's people cover, median over frames, that dynvo-insert-people
// aims at on TUM's real frames (TUM's walking sequences: 10-50%): tum_walking 10-40%,
// tum_toward and tum_away 3-30%, tum_sitting 5-30%; other scenarios declare none ({0, 1}).
struct CoverageRange {
  double low = 0, high = 1;
};
CoverageRange DeclaredCoverage(Scenario scenario);

// The person's floor position (stage x, y), walking direction (unit, or zero when not
// walking) and body pose at `seconds`.
struct StagePlacement {
  Eigen::Vector2d position{0, 0};
  Eigen::Vector2d direction{0, 0};
  BodyPose pose;
};
StagePlacement PlaceStagePerson(const StagePerson& person, double seconds);

// The quads of every person in the world at `seconds`; person i has object id i + 1.
std::vector<TexturedQuad> StagePeopleQuadsAt(const std::vector<StagePerson>& people,
                                             const std::vector<ArticulatedCutout>& dolls, const Pose& world_from_stage,
                                             double seconds);

// Metres per second of the person's fastest body point at `seconds` (over the preceding
// 1/30 s). A person is labelled moving above kMovingSpeedMps.
double StagePersonSpeed(const StagePerson& person, const ArticulatedCutout& doll, double seconds);
constexpr double kMovingSpeedMps = 0.2;

}  // namespace dynvo
