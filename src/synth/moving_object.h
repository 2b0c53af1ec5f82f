#pragma once
// Moving people for synthetic scenes: an articulated, textured box model (legs, torso, arms,
// head) and its path in the room, as plain data; the quads at any time follow from them.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "synth/scene.h"

namespace dynvo {

enum class Scenario {
  kNone,           // no moving object (the static twin of every other scenario)
  kWalkingAcross,  // one person walks left to right and back across the view
  kWalkingToward,  // one person walks toward the camera and away again
  kTwoCrossing,    // two people cross each other in opposite directions
  kSittingSway,    // a person seated behind a desk sways and turns (low dynamic)
  // As TUM films its dynamic sequences: articulated people from photos, in view from the
  // first frame, 1-3 m from the camera (see synth/stage_people.h).
  kTumWalking,  // two people walking across and around the scene
  kTumToward,   // one person walking toward the camera along the optical axis, then back
  kTumAway,     // one person walking away from the camera along the optical axis, then back
  kTumSitting,  // two seated people moving head and arms; one stands up and sits down
};

// True for the kTum* scenarios (articulated photo people, in view from the first frame).
bool IsTumScenario(Scenario scenario);

// Parses "none", "walking_across", "walking_toward", "two_crossing", "sitting_sway",
// "tum_walking", "tum_toward", "tum_away", "tum_sitting";
// throws InputError naming `key` otherwise.
Scenario ParseScenario(const std::string& name, const std::string& key);
std::string ScenarioName(Scenario scenario);

// A person walking back and forth between two floor points (ping-pong), or seated.
struct PersonPath {
  Eigen::Vector2d from{0, 0};   // metres, floor position (x, y) at the start
  Eigen::Vector2d to{0, 0};     // metres, turning point
  double speed_mps = 1.0;       // metres per second along the path (0: stands at `from`)
  double start_offset_s = 0.0;  // seconds already walked at time 0
  bool seated = false;          // seated: sways about the hips instead of walking
  double facing_rad = 0.0;      // seated only: heading (0 faces +y, pi faces the camera)
};

// One person: body dimensions, textures and path.
struct MovingPerson {
  int object_id = 1;      // > 0, written into the renderer's object buffer
  double height_m = 1.7;  // metres, top of head when standing
  double width_m = 0.5;   // metres, shoulder width including arms
  PersonPath path;
  std::vector<TexturedQuad> parts;  // body quads in the body frame at rest (see .cc)
};

// A textured person model (body frame: x right, y forward, z up, feet at z = 0).
MovingPerson MakePerson(int object_id, double height_m, std::uint32_t seed);

// The quads of a person in the world at `seconds`: walking legs and arms swing, the body
// faces its walking direction.
std::vector<TexturedQuad> PersonQuadsAt(const MovingPerson& person, double seconds);

// The floor position and heading (radians, 0 = +y) of the person at `seconds`.
void PersonPlacement(const MovingPerson& person, double seconds, Eigen::Vector2d* position, double* heading_rad);

// The people of a scenario in the synthetic room, deterministic from the seed.
std::vector<MovingPerson> MakeScenarioPeople(Scenario scenario, std::uint32_t seed);

}  // namespace dynvo
