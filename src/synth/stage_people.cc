#include "synth/stage_people.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStrideM = 1.3;  // metres per stride (two steps) of an adult at walking pace

StagePerson Walker(std::vector<Eigen::Vector2d> route, bool loop, double speed, double start, int doll) {
  StagePerson p;
  p.route = std::move(route);
  p.loop = loop;
  p.speed_mps = speed;
  p.start_walked_m = start;
  p.doll = doll;
  return p;
}

StagePerson Seated(const Eigen::Vector2d& at, StageMotion motion, double phase, int doll) {
  StagePerson p;
  p.route = {at};
  p.motion = motion;
  p.phase_rad = phase;
  p.doll = doll;
  return p;
}

// A walker across the view at `depth` that turns where it is out of view (the old presets).
StagePerson Across(const StageGeometry& g, double depth, double direction, double speed, int doll) {
  const double half = std::max(depth * g.tan_half_fov + g.person_width_m + 0.3, 0.5 * speed * g.duration_s + 0.2);
  return Walker({{-direction * half, depth}, {direction * half, depth}}, false, speed, 0, doll);
}

std::vector<StagePerson> OldPresets(Scenario scenario, const StageGeometry& g) {
  const double d = g.distance_m, v = g.speed_mps;
  switch (scenario) {
    case Scenario::kWalkingAcross:
      return {Across(g, d, 1.0, v, 0)};
    case Scenario::kTwoCrossing:
      return {Across(g, d, 1.0, v, 0), Across(g, d + 1.2, -1.0, 1.15 * v, 1)};
    case Scenario::kWalkingToward:
      return {Walker({{0.15, d + 2.5}, {0.1, std::max(0.6, d - 1.2)}}, false, v, 0, 0)};
    case Scenario::kSittingSway:
      return {Seated({0.3, d}, StageMotion::kSit, 0, 0)};
    default:
      return {};
  }
}

// Route position after `walked` metres, and the walking direction there.
void AlongRoute(const StagePerson& p, double walked, Eigen::Vector2d* at, Eigen::Vector2d* direction) {
  std::vector<Eigen::Vector2d> path = p.route;
  if (p.loop) path.push_back(p.route.front());
  double length = 0;
  for (size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  *at = path.front();
  *direction = Eigen::Vector2d::Zero();
  if (length < 1e-9) return;
  const double period = p.loop ? length : 2 * length;
  double s = std::fmod(walked, period);
  if (s < 0) s += period;
  const bool back = s > length;
  if (back) s = period - s;
  for (size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d step = path[i] - path[i - 1];
    const double n = step.norm();
    if (s <= n || i + 1 == path.size()) {
      *at = path[i - 1] + step * std::min(1.0, s / n);
      *direction = (back ? -step : step) / n;
      return;
    }
    s -= n;
  }
}

// 0 seated, 1 standing: seated 40% of the cycle, rising over 15%, standing 25%, sitting down 15%.
double RiseAt(double seconds, double cycle) {
  double u = std::fmod(seconds, cycle) / cycle;
  if (u < 0) u += 1;
  auto smooth = [](double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3 - 2 * x);
  };
  if (u < 0.40) return 0;
  if (u < 0.55) return smooth((u - 0.40) / 0.15);
  if (u < 0.80) return 1;
  return 1 - smooth((u - 0.80) / 0.15);
}

}  // namespace

std::vector<StagePerson> PlanStagePeople(Scenario scenario, const StageGeometry& g) {
  // The TUM presets' layouts are drawn for people 2 m away and scaled with the distance, so
  // that they look alike from any distance.
  const double d = g.distance_m, s = d / 2.0, v = 0.8 * g.speed_mps;
  auto at = [&](double x, double y) { return Eigen::Vector2d(s * x, d + s * y); };
  switch (scenario) {
    case Scenario::kTumWalking: {
      // One walks around a desk-sized loop, the other back and forth across, both in view.
      StagePerson around = Walker({at(-0.7, -0.5), at(0.7, -0.5), at(0.7, 0.6), at(-0.7, 0.6)}, true, v, 0.3, 0);
      StagePerson across = Walker({at(-1.0, 0.3), at(1.0, 0.3)}, false, 0.9 * v, 1.4, 1);
      return {around, across};
    }
    case Scenario::kTumToward:
      return {Walker({at(0.1, 1.2), at(0.05, -1.0)}, false, 0.6 * g.speed_mps, 0, 0)};
    case Scenario::kTumAway:
      return {Walker({at(0.05, -1.0), at(0.1, 1.2)}, false, 0.6 * g.speed_mps, 0, 0)};
    case Scenario::kTumSitting:
      return {Seated(at(-0.45, -0.2), StageMotion::kSit, 0.0, 0),
              Seated(at(0.5, 0.3), StageMotion::kSitAndStand, 1.7, 1)};
    default:
      return OldPresets(scenario, g);
  }
}

CoverageRange DeclaredCoverage(Scenario scenario) {
  switch (scenario) {
    case Scenario::kTumWalking:
      return {0.10, 0.40};
    case Scenario::kTumToward:
    case Scenario::kTumAway:
      return {0.03, 0.30};
    case Scenario::kTumSitting:
      return {0.05, 0.30};
    default:
      return {};
  }
}

StagePlacement PlaceStagePerson(const StagePerson& person, double seconds) {
  StagePlacement out;
  if (person.motion == StageMotion::kWalk && person.speed_mps > 0) {
    const double walked = person.start_walked_m + person.speed_mps * seconds;
    AlongRoute(person, walked, &out.position, &out.direction);
    out.pose = WalkingPose(2 * kPi * walked / kStrideM);
    return out;
  }
  out.position = person.route.empty() ? Eigen::Vector2d::Zero() : person.route.front();
  const double rise = person.motion == StageMotion::kSitAndStand
                          ? RiseAt(seconds + person.phase_rad * person.cycle_s, person.cycle_s)
                          : (person.motion == StageMotion::kSit ? 0.0 : 1.0);
  out.pose = SittingPose(rise, seconds, person.phase_rad);
  return out;
}

namespace {

// One person's quads in the world at `seconds`, object id `object_id`.
std::vector<TexturedQuad> PersonQuadsAt(const StagePerson& person, const ArticulatedCutout& doll,
                                        const Pose& world_from_stage, double seconds, int object_id) {
  const StagePlacement at = PlaceStagePerson(person, seconds);
  // Limbs turn about the walking direction crossed with up; a seated person faces the
  // reference camera (forward is stage -y).
  const Eigen::Vector3d forward = at.direction.squaredNorm() > 0
                                      ? Eigen::Vector3d(at.direction.x(), at.direction.y(), 0)
                                      : Eigen::Vector3d(0, -1, 0);
  const Pose stage_from_doll(Eigen::Translation3d(at.position.x(), at.position.y(), 0));
  return PoseArticulatedCutout(doll, at.pose, world_from_stage * stage_from_doll,
                               forward.cross(Eigen::Vector3d::UnitZ()), object_id);
}

}  // namespace

std::vector<TexturedQuad> StagePeopleQuadsAt(const std::vector<StagePerson>& people,
                                             const std::vector<ArticulatedCutout>& dolls, const Pose& world_from_stage,
                                             double seconds) {
  std::vector<TexturedQuad> quads;
  for (size_t i = 0; i < people.size(); ++i) {
    const ArticulatedCutout& doll = dolls.at(static_cast<size_t>(people[i].doll) % dolls.size());
    for (TexturedQuad& q : PersonQuadsAt(people[i], doll, world_from_stage, seconds, static_cast<int>(i) + 1))
      quads.push_back(std::move(q));
  }
  return quads;
}

double StagePersonSpeed(const StagePerson& person, const ArticulatedCutout& doll, double seconds) {
  const double dt = 1.0 / 30.0;
  const auto now = PersonQuadsAt(person, doll, Pose::Identity(), seconds, 1);
  const auto before = PersonQuadsAt(person, doll, Pose::Identity(), seconds - dt, 1);
  double fastest = 0;
  for (size_t k = 0; k < std::min(now.size(), before.size()); ++k) {
    const TexturedQuad &a = now[k], &b = before[k];
    const Eigen::Vector3d moved[4] = {a.origin - b.origin, a.origin + a.edge_u - b.origin - b.edge_u,
                                      a.origin + a.edge_v - b.origin - b.edge_v,
                                      a.origin + a.edge_u + a.edge_v - b.origin - b.edge_u - b.edge_v};
    for (const Eigen::Vector3d& m : moved) fastest = std::max(fastest, m.norm() / dt);
  }
  return fastest;
}

}  // namespace dynvo
