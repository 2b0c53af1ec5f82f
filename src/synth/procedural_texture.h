#pragma once
// Procedural textures for synthetic scenes: deterministic from a seed, with structure at
// several scales (blobs, patches, edges, corners, fine grain) so that corner and edge
// detectors find features at every pyramid level.

#include <cstdint>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

enum class TextureKind {
  kWall,     // painted plaster with posters, shelves, prints
  kFloor,    // tiles or wood planks with grain
  kWood,     // desk tops and cabinets
  kCarton,   // boxes: cardboard with prints and labels
  kClothes,  // stripes, checks or prints on fabric
  kDenim,    // trousers
  kSkin,     // face and hands
  kPaint,    // plain paint: one colour, soft shading and faint grain, no print (low texture)
};

// A texture and its mip pyramid (level 0 full size, each next level halved).
struct Texture {
  std::vector<cv::Mat> levels;  // CV_8UC3 (BGR) or CV_8UC4 (BGRA, alpha = coverage)
  double texel_size_m = 0.005;  // metres covered by one level-0 texel
  cv::Mat relief;               // CV_32F in [0, 1] of level 0's size, or empty: per-texel height
                                // toward the viewer, in units of the quad's relief_m
};

// A BGR image of the given kind, width x height texels, the same for the same seed.
cv::Mat MakeTextureImage(TextureKind kind, int width, int height, std::uint32_t seed);

// A texture with its pyramid built from `image` (CV_8UC3 or CV_8UC4).
std::shared_ptr<const Texture> MakeTexture(const cv::Mat& image, double texel_size_m);

}  // namespace dynvo
