#pragma once
// A person photo cut into body parts that turn at their joints (a paper doll): head, torso,
// upper arms, forearms, thighs and shins, each a textured quad in the doll's plane with a
// rounded relief (the body's depth is not a plane), posed by joint angles about one swing axis.
// Doll frame: x right, y away from the viewer the photo faces, z up; feet at z = 0, the
// silhouette's centre column at x = 0.

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/pose.h"
#include "synth/person_cutout.h"
#include "synth/scene.h"

namespace dynvo {

enum BodyPart {
  kTorso,
  kHead,
  kLeftUpperArm,
  kLeftForearm,
  kRightUpperArm,
  kRightForearm,
  kLeftThigh,
  kLeftShin,
  kRightThigh,
  kRightShin,
  kNumBodyParts
};

struct ArticulatedCutout {
  struct Part {
    std::shared_ptr<const Texture> texture;  // BGRA: the part's pixels of the photo, with relief
    Eigen::Vector2d top_left{0, 0};          // metres, doll (x, z) of the texture's top-left corner at rest
    Eigen::Vector2d size{0, 0};              // metres, texture width and height
    Eigen::Vector2d joint{0, 0};             // metres, doll (x, z) of the joint the part turns about
    double behind_m = 0;                     // metres along doll y: limbs sit just behind the torso
  };
  std::array<Part, kNumBodyParts> parts;  // a part without pixels has no texture
  double height_m = 1.7;                  // metres, head to feet
  double width_m = 0.5;                   // metres, the photo's silhouette width
  double relief_m = 0.12;                 // metres of relief where the texture's relief is 1
};

// Cuts `cutout` (BGRA, cropped to the person standing upright) into parts by body
// proportions and scales it to `height_m`. Every silhouette pixel belongs to exactly one
// part, so the doll at rest shows the photo unchanged. Throws InputError when the cut-out is
// not 8-bit BGRA or is under 40 pixels tall.
ArticulatedCutout MakeArticulatedCutout(const PersonCutout& cutout, double height_m);

// Joint angles in radians about the swing axis; a positive angle turns a limb forward (in the
// walking direction). The lowest foot is kept on the floor, then the body rises by lift_m.
struct BodyPose {
  double hip[2] = {0, 0};       // thighs, left and right
  double knee[2] = {0, 0};      // knee flexion (>= 0 turns the shin back from the thigh)
  double shoulder[2] = {0, 0};  // upper arms
  double elbow[2] = {0, 0};     // elbow flexion (>= 0 turns the forearm forward)
  double neck = 0;              // head tilt in the doll plane (about doll y)
  double lift_m = 0;            // metres above the planted foot (a walker's bob)
};

// The walking gait at `phase_rad` (2 pi per stride of two steps): thighs and arms swing in
// opposite phase, the knee bends while its leg swings forward, the body bobs twice a stride.
BodyPose WalkingPose(double phase_rad);

// Between seated (rise 0: thighs forward, shins upright) and standing (rise 1), with the small
// head and forearm motions of a seated person at `seconds` (phases shifted by `phase_rad`).
BodyPose SittingPose(double rise, double seconds, double phase_rad);

// The doll's quads in the world (object id `object_id`): `world_from_doll` places the doll
// frame and `swing_axis` (unit vector, doll frame) is the axis the limbs turn about; for a
// walker, the walking direction crossed with up.
std::vector<TexturedQuad> PoseArticulatedCutout(const ArticulatedCutout& doll, const BodyPose& pose,
                                                const Pose& world_from_doll, const Eigen::Vector3d& swing_axis,
                                                int object_id);

}  // namespace dynvo
