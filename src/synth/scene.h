#pragma once
// Scene geometry for the synthetic generator: textured planar quads, boxes made of quads,
// and the default indoor room (walls, floor, ceiling, desks, boxes, shelves).
// World frame of the synthetic room: x right, y forward (away from the start camera),
// z up; metres.

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/pose.h"
#include "synth/procedural_texture.h"

namespace dynvo {

// A parallelogram origin + a*edge_u + b*edge_v, (a, b) in [0, 1]^2, carrying a texture:
// texel (a * width, b * height) of the texture's level 0.
struct TexturedQuad {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();   // metres
  Eigen::Vector3d edge_u = Eigen::Vector3d::UnitX();  // metres, texture columns run along it
  Eigen::Vector3d edge_v = Eigen::Vector3d::UnitY();  // metres, texture rows run along it
  std::shared_ptr<const Texture> texture;             // required for rendering
  float shade = 1.0f;                                 // brightness factor in (0, 2]
  int object_id = 0;                                  // 0: static scene; > 0: moving object
  double relief_m = 0;                                // metres: depth pulled toward the camera by
                                                      // relief_m * texture->relief (rounded bodies)
};

// The quad moved by a rigid transform (`to_from_from` applied to its points).
TexturedQuad TransformQuad(const Pose& to_from_from, const TexturedQuad& quad);

// A brightness factor for a surface with the given normal under the fixed room light.
float LambertShade(const Eigen::Vector3d& normal);

// Appends the six faces of an axis-aligned box [min, max] (in the frame of `world_from_box`)
// with one texture per face generated from `kind` and `seed`; texel_size_m sets texture
// resolution. Faces get Lambert shading and `object_id`.
void AddBox(const Eigen::Vector3d& min, const Eigen::Vector3d& max, const Pose& world_from_box, TextureKind kind,
            double texel_size_m, std::uint32_t seed, int object_id, std::vector<TexturedQuad>* quads);

struct RoomOptions {
  double width_m = 6.4;         // metres along x, centred on x = 0
  double depth_m = 7.0;         // metres along y, from y = -1.5
  double height_m = 2.8;        // metres along z, floor at z = 0
  double texel_size_m = 0.005;  // metres per texel of walls and floor
  int furniture = 10;           // number of extra boxes on floor and desks (0 or more)
  bool plain = false;           // every surface plain paint (TextureKind::kPaint): low texture, where
                                // the edges of walls and furniture are what a tracker can hold on to
  bool repeated_walls = false;  // the walls papered with one 1.6 m wide panel over and over: any
                                // stretch of wall looks like any other (false loop candidates)

  // Throws InputError naming the key ("room.width_m must be > 2, got 1").
  void Check() const;
};

// The static indoor scene: room shell, two desks with things on them, a cabinet, shelves,
// boxes, textured or (plain) painted; deterministic from the seed. A lane y in [1.6, 2.9] and x in [-0.6, 0.6] for all
// y are kept free for walking people.
std::vector<TexturedQuad> MakeRoomScene(const RoomOptions& options, std::uint32_t seed);

}  // namespace dynvo
