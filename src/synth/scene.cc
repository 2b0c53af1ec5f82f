#include "synth/scene.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "core/error.h"

namespace dynvo {

TexturedQuad TransformQuad(const Pose& to_from_from, const TexturedQuad& quad) {
  TexturedQuad out = quad;
  out.origin = to_from_from * quad.origin;
  out.edge_u = to_from_from.linear() * quad.edge_u;
  out.edge_v = to_from_from.linear() * quad.edge_v;
  return out;
}

float LambertShade(const Eigen::Vector3d& normal) {
  static const Eigen::Vector3d light = Eigen::Vector3d(0.35, -0.5, 0.8).normalized();
  const double n = normal.norm();
  if (n <= 0) return 1.0f;
  return static_cast<float>(0.62 + 0.38 * std::abs(normal.dot(light) / n));
}

namespace {

constexpr double kWallpaperPanelM = 1.6;  // RoomOptions::repeated_walls

int Texels(double metres, double texel) { return std::clamp(static_cast<int>(std::lround(metres / texel)), 8, 4096); }

TexturedQuad Face(const Eigen::Vector3d& origin, const Eigen::Vector3d& u, const Eigen::Vector3d& v, TextureKind kind,
                  double texel, std::uint32_t seed, int object_id) {
  TexturedQuad quad;
  quad.origin = origin;
  quad.edge_u = u;
  quad.edge_v = v;
  // Cap texture memory: coarser texels for very large faces.
  double t = texel;
  while (Texels(u.norm(), t) * static_cast<double>(Texels(v.norm(), t)) > 2.5e6) t *= 1.25;
  quad.texture = MakeTexture(MakeTextureImage(kind, Texels(u.norm(), t), Texels(v.norm(), t), seed), t);
  quad.shade = LambertShade(u.cross(v));
  quad.object_id = object_id;
  return quad;
}

}  // namespace

void AddBox(const Eigen::Vector3d& mn, const Eigen::Vector3d& mx, const Pose& world_from_box, TextureKind kind,
            double texel, std::uint32_t seed, int object_id, std::vector<TexturedQuad>* quads) {
  const Eigen::Vector3d d = mx - mn;
  const Eigen::Vector3d ex(d.x(), 0, 0), ey(0, d.y(), 0), ez(0, 0, d.z());
  // Texture rows run downwards (v along -z) on vertical faces so prints stand upright.
  const Eigen::Vector3d top(0, 0, d.z());
  const TexturedQuad faces[6] = {
      Face(mn + top, ex, -ez, kind, texel, seed * 7 + 1, object_id),             // front (y min)
      Face(mn + ey + ex + top, -ex, -ez, kind, texel, seed * 7 + 2, object_id),  // back (y max)
      Face(mn + ey + top, -ey, -ez, kind, texel, seed * 7 + 3, object_id),       // left (x min)
      Face(mn + ex + top, ey, -ez, kind, texel, seed * 7 + 4, object_id),        // right (x max)
      Face(mn + top, ex, ey, kind, texel, seed * 7 + 5, object_id),              // top
      Face(mn, ex, ey, kind, texel, seed * 7 + 6, object_id),                    // bottom
  };
  for (const TexturedQuad& f : faces) {
    TexturedQuad w = TransformQuad(world_from_box, f);
    w.shade = LambertShade(w.edge_u.cross(w.edge_v));
    quads->push_back(w);
  }
}

void RoomOptions::Check() const {
  RequireOption(width_m > 2.0, "room", "width_m", "> 2", width_m);
  RequireOption(depth_m > 3.0, "room", "depth_m", "> 3", depth_m);
  RequireOption(height_m > 2.0, "room", "height_m", "> 2", height_m);
  RequireOption(texel_size_m >= 0.001 && texel_size_m <= 0.05, "room", "texel_size_m", "in [0.001, 0.05]",
                texel_size_m);
  RequireOption(furniture >= 0, "room", "furniture", ">= 0", furniture);
}

std::vector<TexturedQuad> MakeRoomScene(const RoomOptions& o, std::uint32_t seed) {
  o.Check();
  std::vector<TexturedQuad> quads;
  const double x0 = -o.width_m / 2, x1 = o.width_m / 2, y0 = -1.5, y1 = y0 + o.depth_m, h = o.height_m;
  const double t = o.texel_size_m;
  const auto kind = [&](TextureKind k) { return o.plain ? TextureKind::kPaint : k; };
  // Shell: walls seen from inside, texture rows downwards.
  const auto wall = [&](const Eigen::Vector3d& top_left, const Eigen::Vector3d& along, std::uint32_t wall_seed) {
    if (!o.repeated_walls) {
      quads.push_back(Face(top_left, along, {0, 0, -h}, kind(TextureKind::kWall), t, wall_seed, 0));
      return;
    }
    // Panels of one size and seed have one texture; the remainder is a panel of its own.
    const double length = along.norm();
    const Eigen::Vector3d panel = along * (kWallpaperPanelM / length);
    const int full = static_cast<int>(length / kWallpaperPanelM + 1e-9);
    for (int i = 0; i < full; ++i)
      quads.push_back(Face(top_left + i * panel, panel, {0, 0, -h}, kind(TextureKind::kWall), t, seed + 11, 0));
    const double rest = length - full * kWallpaperPanelM;
    if (rest > 1e-6)
      quads.push_back(Face(top_left + full * panel, along * (rest / length), {0, 0, -h}, kind(TextureKind::kWall), t,
                           seed + 17, 0));
  };
  wall({x0, y1, h}, {o.width_m, 0, 0}, seed + 11);   // front
  wall({x1, y0, h}, {-o.width_m, 0, 0}, seed + 12);  // back
  wall({x0, y0, h}, {0, o.depth_m, 0}, seed + 13);   // left
  wall({x1, y1, h}, {0, -o.depth_m, 0}, seed + 14);  // right
  quads.push_back(Face({x0, y0, 0}, {o.width_m, 0, 0}, {0, o.depth_m, 0}, kind(TextureKind::kFloor), t, seed + 15, 0));
  quads.push_back(
      Face({x0, y0, h}, {o.width_m, 0, 0}, {0, o.depth_m, 0}, kind(TextureKind::kWall), 2 * t, seed + 16, 0));

  const Pose identity = Pose::Identity();
  const double fine = std::min(t, 0.003);
  // Two desks (top slab + legs), a cabinet, a shelf with boxes along the front wall.
  auto desk = [&](double xa, double xb, double ya, double yb, std::uint32_t s) {
    AddBox({xa, ya, 0.72}, {xb, yb, 0.76}, identity, kind(TextureKind::kWood), fine, s, 0, &quads);
    AddBox({xa + 0.03, ya + 0.03, 0}, {xa + 0.08, ya + 0.08, 0.72}, identity, kind(TextureKind::kWood), t, s + 1, 0,
           &quads);
    AddBox({xb - 0.08, ya + 0.03, 0}, {xb - 0.03, ya + 0.08, 0.72}, identity, kind(TextureKind::kWood), t, s + 2, 0,
           &quads);
    AddBox({xa + 0.03, yb - 0.08, 0}, {xa + 0.08, yb - 0.03, 0.72}, identity, kind(TextureKind::kWood), t, s + 3, 0,
           &quads);
    AddBox({xb - 0.08, yb - 0.08, 0}, {xb - 0.03, yb - 0.03, 0.72}, identity, kind(TextureKind::kWood), t, s + 4, 0,
           &quads);
  };
  desk(-2.6, -1.0, 3.2, 4.0, seed + 100);
  desk(0.9, 2.5, 3.6, 4.4, seed + 200);
  AddBox({x0, 0.2, 0}, {x0 + 0.45, 1.4, 1.25}, identity, kind(TextureKind::kWood), t, seed + 300, 0,
         &quads);  // cabinet
  AddBox({-1.0, y1 - 0.35, 1.3}, {1.2, y1 - 0.02, 1.34}, identity, kind(TextureKind::kWood), t, seed + 310, 0,
         &quads);  // shelf
  AddBox({x1 - 0.5, 0.0, 0}, {x1 - 0.02, 1.0, 0.9}, identity, kind(TextureKind::kCarton), t, seed + 320, 0,
         &quads);  // crate

  std::mt19937 rng(seed + 400);
  auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  // Spots for extra boxes: on desks, on the shelf, on the floor along the walls.
  struct Spot {
    double xa, xb, ya, yb, z;
  };
  const Spot spots[] = {{-2.5, -1.3, 3.3, 3.8, 0.76},           {1.0, 2.2, 3.7, 4.2, 0.76},
                        {-0.9, 1.0, y1 - 0.33, y1 - 0.1, 1.34}, {x0 + 0.1, x0 + 1.2, 4.3, y1 - 0.4, 0.0},
                        {x1 - 1.2, x1 - 0.2, 1.2, 3.0, 0.0},    {x0 + 0.6, x0 + 1.4, -0.5, 1.2, 0.0}};
  for (int i = 0; i < o.furniture; ++i) {
    const Spot& s = spots[i % 6];
    const double sx = uni(0.12, 0.45), sy = uni(0.12, 0.4), sz = uni(0.08, s.z > 0 ? 0.35 : 0.6);
    const double cx = uni(s.xa, std::max(s.xa + 0.01, s.xb - sx)), cy = uni(s.ya, std::max(s.ya + 0.01, s.yb - sy));
    const Pose world_from_box =
        Pose(Eigen::Translation3d(cx, cy, s.z) * Eigen::AngleAxisd(uni(-0.5, 0.5), Eigen::Vector3d::UnitZ()));
    AddBox({0, 0, 0}, {sx, sy, sz}, world_from_box, kind(TextureKind::kCarton), fine,
           seed + 500 + static_cast<std::uint32_t>(i) * 13, 0, &quads);
  }
  return quads;
}

}  // namespace dynvo
