#include "synth/moving_object.h"

#include <cmath>

#include "core/error.h"

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Parts are stored in `parts` in this order; each part is 6 quads (a box).
enum Part { kLeftLeg, kRightLeg, kTorso, kLeftArm, kRightArm, kHead, kNumParts };

struct PartGeometry {
  Eigen::Vector3d min, max;  // box in the part frame
  Eigen::Vector3d joint;     // joint position in the body frame (part frame origin)
};

// Body proportions scaled to the height; the part frames hang from their joints.
PartGeometry Geometry(Part part, double h) {
  const double s = h / 1.7;
  switch (part) {
    case kLeftLeg:
      return {{-0.08 * s, -0.08 * s, -0.86 * s}, {0.08 * s, 0.08 * s, 0}, {-0.1 * s, 0, 0.86 * s}};
    case kRightLeg:
      return {{-0.08 * s, -0.08 * s, -0.86 * s}, {0.08 * s, 0.08 * s, 0}, {0.1 * s, 0, 0.86 * s}};
    case kTorso:
      return {{-0.19 * s, -0.12 * s, 0}, {0.19 * s, 0.12 * s, 0.58 * s}, {0, 0, 0.86 * s}};
    case kLeftArm:
      return {{-0.055 * s, -0.06 * s, -0.6 * s}, {0.055 * s, 0.06 * s, 0}, {-0.25 * s, 0, 1.42 * s}};
    case kRightArm:
      return {{-0.055 * s, -0.06 * s, -0.6 * s}, {0.055 * s, 0.06 * s, 0}, {0.25 * s, 0, 1.42 * s}};
    case kHead:
      return {{-0.1 * s, -0.11 * s, 0.02 * s}, {0.1 * s, 0.11 * s, 0.26 * s}, {0, 0, 1.44 * s}};
    default:
      return {};
  }
}

}  // namespace

Scenario ParseScenario(const std::string& name, const std::string& key) {
  if (name == "none") return Scenario::kNone;
  if (name == "walking_across") return Scenario::kWalkingAcross;
  if (name == "walking_toward") return Scenario::kWalkingToward;
  if (name == "two_crossing") return Scenario::kTwoCrossing;
  if (name == "sitting_sway") return Scenario::kSittingSway;
  if (name == "tum_walking") return Scenario::kTumWalking;
  if (name == "tum_toward") return Scenario::kTumToward;
  if (name == "tum_away") return Scenario::kTumAway;
  if (name == "tum_sitting") return Scenario::kTumSitting;
  throw InputError(key +
                   " must be one of none, walking_across, walking_toward, two_crossing, "
                   "sitting_sway, tum_walking, tum_toward, tum_away, tum_sitting, got '" +
                   name + "'");
}

bool IsTumScenario(Scenario scenario) {
  return scenario == Scenario::kTumWalking || scenario == Scenario::kTumToward || scenario == Scenario::kTumAway ||
         scenario == Scenario::kTumSitting;
}

std::string ScenarioName(Scenario scenario) {
  switch (scenario) {
    case Scenario::kNone:
      return "none";
    case Scenario::kWalkingAcross:
      return "walking_across";
    case Scenario::kWalkingToward:
      return "walking_toward";
    case Scenario::kTwoCrossing:
      return "two_crossing";
    case Scenario::kSittingSway:
      return "sitting_sway";
    case Scenario::kTumWalking:
      return "tum_walking";
    case Scenario::kTumToward:
      return "tum_toward";
    case Scenario::kTumAway:
      return "tum_away";
    case Scenario::kTumSitting:
      return "tum_sitting";
  }
  return "none";
}

MovingPerson MakePerson(int object_id, double height_m, std::uint32_t seed) {
  if (object_id <= 0) throw InputError("person object_id must be > 0, got " + std::to_string(object_id));
  MovingPerson person;
  person.object_id = object_id;
  person.height_m = height_m;
  person.width_m = 0.5 * height_m / 1.7;
  const double texel = 0.004;
  for (int p = 0; p < kNumParts; ++p) {
    const PartGeometry g = Geometry(static_cast<Part>(p), height_m);
    TextureKind kind = TextureKind::kClothes;
    std::uint32_t tex_seed = seed * 31 + 7;  // shirt shared by torso and arms
    if (p == kLeftLeg || p == kRightLeg) {
      kind = TextureKind::kDenim;
      tex_seed = seed * 31 + 3;
    }
    if (p == kHead) {
      kind = TextureKind::kSkin;
      tex_seed = seed * 31 + 5;
    }
    AddBox(g.min, g.max, Pose::Identity(), kind, texel, tex_seed + static_cast<std::uint32_t>(p), object_id,
           &person.parts);
  }
  return person;
}

void PersonPlacement(const MovingPerson& person, double seconds, Eigen::Vector2d* position, double* heading_rad) {
  const PersonPath& path = person.path;
  const Eigen::Vector2d d = path.to - path.from;
  const double length = d.norm();
  if (path.seated || path.speed_mps <= 0 || length < 1e-9) {
    *position = path.from;
    *heading_rad = path.facing_rad;
    return;
  }
  const double walked = path.start_offset_s * path.speed_mps + seconds * path.speed_mps;
  const double period = 2.0 * length;
  double along = std::fmod(walked, period);
  if (along < 0) along += period;
  const bool going = along <= length;
  const double x = going ? along : period - along;
  *position = path.from + d * (x / length);
  const Eigen::Vector2d dir = going ? d : Eigen::Vector2d(-d);
  *heading_rad = std::atan2(-dir.x(), dir.y());  // 0 faces +y, positive turns left (to -x)
}

std::vector<TexturedQuad> PersonQuadsAt(const MovingPerson& person, double seconds) {
  Eigen::Vector2d position;
  double heading = 0;
  PersonPlacement(person, seconds, &position, &heading);
  const PersonPath& path = person.path;
  double swing = 0, sway_x = 0, sway_y = 0, head_turn = 0, bob = 0;
  if (path.seated) {
    sway_x = 0.09 * std::sin(2 * kPi * seconds / 3.3);  // radians, sideways lean
    sway_y = 0.06 * std::sin(2 * kPi * seconds / 4.7);  // radians, forward lean
    head_turn = 0.35 * std::sin(2 * kPi * seconds / 5.9);
  } else if (path.speed_mps > 0) {
    const double stride = 0.7;  // metres per step pair / 2
    const double phase = 2 * kPi * (path.start_offset_s + seconds) * path.speed_mps / (2 * stride);
    swing = 0.45 * std::sin(phase);
    bob = 0.02 * std::abs(std::cos(phase));
  }
  const Pose world_from_body(Eigen::Translation3d(position.x(), position.y(), bob) *
                             Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()));
  const double s = person.height_m / 1.7;
  std::vector<TexturedQuad> quads;
  quads.reserve(person.parts.size());
  for (int p = 0; p < kNumParts; ++p) {
    const PartGeometry g = Geometry(static_cast<Part>(p), person.height_m);
    Pose body_from_part = Pose::Identity();
    body_from_part.translation() = g.joint;
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    if (path.seated) {
      if (p == kLeftLeg || p == kRightLeg) {
        // Thighs forward, the box stands in for the whole bent leg; hips at seat height.
        body_from_part.translation() = Eigen::Vector3d(g.joint.x(), 0, 0.47 * s);
        r = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
      } else {
        // Upper body pivots about the hips, lowered by the seat.
        const Eigen::Matrix3d lean =
            (Eigen::AngleAxisd(sway_x, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(sway_y, Eigen::Vector3d::UnitX()))
                .toRotationMatrix();
        const Eigen::Vector3d hip(0, 0, 0.47 * s);
        const Eigen::Vector3d joint_seated = g.joint - Eigen::Vector3d(0, 0, 0.86 * s - 0.47 * s);
        body_from_part.translation() = hip + lean * (joint_seated - hip);
        r = lean;
        if (p == kHead) r = lean * Eigen::AngleAxisd(head_turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        if (p == kLeftArm || p == kRightArm)
          r = lean * Eigen::AngleAxisd(kPi / 3, Eigen::Vector3d::UnitX()).toRotationMatrix();
      }
    } else {
      if (p == kLeftLeg) r = Eigen::AngleAxisd(swing, Eigen::Vector3d::UnitX()).toRotationMatrix();
      if (p == kRightLeg) r = Eigen::AngleAxisd(-swing, Eigen::Vector3d::UnitX()).toRotationMatrix();
      if (p == kLeftArm) r = Eigen::AngleAxisd(-0.8 * swing, Eigen::Vector3d::UnitX()).toRotationMatrix();
      if (p == kRightArm) r = Eigen::AngleAxisd(0.8 * swing, Eigen::Vector3d::UnitX()).toRotationMatrix();
    }
    body_from_part.linear() = r;
    const Pose world_from_part = world_from_body * body_from_part;
    for (int f = 0; f < 6; ++f) {
      TexturedQuad q = TransformQuad(world_from_part, person.parts[static_cast<size_t>(p * 6 + f)]);
      q.shade = LambertShade(q.edge_u.cross(q.edge_v));
      quads.push_back(q);
    }
  }
  return quads;
}

std::vector<MovingPerson> MakeScenarioPeople(Scenario scenario, std::uint32_t seed) {
  std::vector<MovingPerson> people;
  switch (scenario) {
    case Scenario::kNone:
      break;
    case Scenario::kWalkingAcross: {
      MovingPerson p = MakePerson(1, 1.72, seed + 1);
      p.path.from = {-3.0, 2.3};
      p.path.to = {3.0, 2.3};
      p.path.speed_mps = 1.0;
      p.path.start_offset_s = 0.8;  // enters the view after about 1.5 s
      people.push_back(p);
      break;
    }
    case Scenario::kWalkingToward: {
      MovingPerson p = MakePerson(1, 1.75, seed + 1);
      p.path.from = {0.15, 5.0};
      p.path.to = {0.1, 1.1};
      p.path.speed_mps = 0.9;
      people.push_back(p);
      break;
    }
    case Scenario::kTwoCrossing: {
      MovingPerson a = MakePerson(1, 1.70, seed + 1);
      a.path.from = {-3.0, 2.0};
      a.path.to = {3.0, 2.0};
      a.path.speed_mps = 1.0;
      a.path.start_offset_s = 1.2;
      MovingPerson b = MakePerson(2, 1.78, seed + 2);
      b.path.from = {3.0, 2.8};
      b.path.to = {-3.0, 2.8};
      b.path.speed_mps = 1.1;
      b.path.start_offset_s = 0.9;
      people.push_back(a);
      people.push_back(b);
      break;
    }
    case Scenario::kSittingSway: {
      MovingPerson p = MakePerson(1, 1.72, seed + 1);
      p.path.from = {1.5, 4.75};
      p.path.seated = true;
      p.path.facing_rad = kPi;  // faces the camera across the desk
      p.path.speed_mps = 0;
      people.push_back(p);
      break;
    }
    default:
      break;  // the TUM scenarios' people are articulated photos (synth/stage_people.h)
  }
  return people;
}

}  // namespace dynvo
