#include "synth/person_cutout.h"

#include <algorithm>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "synth/procedural_texture.h"

namespace dynvo {

PersonCutout CutoutFromMask(const cv::Mat& bgr, const cv::Mat& mask, const std::string& source) {
  if (bgr.empty() || bgr.type() != CV_8UC3) throw InputError(source + ": person image must be 8-bit BGR");
  if (mask.size() != bgr.size() || mask.type() != CV_8U)
    throw InputError(source + ": person mask must be 8-bit 1-channel and the size of the image (" +
                     std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) + ")");
  const cv::Rect box = cv::boundingRect(mask);
  if (box.area() == 0) throw InputError(source + ": person mask is empty");
  const cv::Mat alpha = mask(box) > 0;
  const cv::Scalar mean = cv::mean(bgr(box), alpha);
  cv::Mat fill(box.size(), CV_8UC3, mean);
  bgr(box).copyTo(fill, alpha);
  PersonCutout cutout;
  std::vector<cv::Mat> split;
  cv::split(fill, split);
  split.push_back(alpha);
  cv::merge(split, cutout.bgra);
  return cutout;
}

PersonCutout LoadPersonCutout(const std::string& image_path, const std::string& mask_path) {
  const cv::Mat bgr = cv::imread(image_path, cv::IMREAD_COLOR);
  if (bgr.empty()) throw InputError(image_path + ": cannot read the person image");
  const cv::Mat mask = cv::imread(mask_path, cv::IMREAD_GRAYSCALE);
  if (mask.empty()) throw InputError(mask_path + ": cannot read the person mask");
  return CutoutFromMask(bgr, mask, mask_path);
}

namespace {

// TUM's depth PNGs: 5000 units per metre.
constexpr double kTumDepthFactor = 5000;

void CheckPersonBox(const cv::Mat& bgr, const cv::Rect& box, const std::string& source) {
  if (bgr.empty() || bgr.type() != CV_8UC3) throw InputError(source + ": person image must be 8-bit BGR");
  if (box.width < 8 || box.height < 8 || (box & cv::Rect(0, 0, bgr.cols, bgr.rows)) != box)
    throw InputError(source + ": person box must lie inside the image and be at least 8x8 pixels");
}

// The largest 8-connected part of `mask`: the person, not stray background specks. Throws
// InputError(`error`) when the mask is empty.
cv::Mat LargestPart(const cv::Mat& mask, const std::string& error) {
  cv::Mat components, stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, components, stats, centroids, 8);
  int best = 0, best_area = 0;
  for (int i = 1; i < count; ++i)
    if (stats.at<int>(i, cv::CC_STAT_AREA) > best_area) {
      best_area = stats.at<int>(i, cv::CC_STAT_AREA);
      best = i;
    }
  if (best == 0) throw InputError(error);
  return components == best;
}

}  // namespace

PersonCutout CutoutWithGrabCut(const cv::Mat& bgr, const cv::Rect& box, int iterations, std::uint32_t seed,
                               const std::string& source) {
  CheckPersonBox(bgr, box, source);
  if (iterations < 1) throw InputError(source + ": GrabCut iterations must be >= 1");
  // Outside the box: background; inside: probably the person, and surely so along a stroke
  // down the box's middle (head, torso and the legs' gap of an upright person), which keeps
  // GrabCut from dropping a small person's head or legs into the background.
  cv::Mat labels(bgr.size(), CV_8U, cv::Scalar(cv::GC_BGD)), bgd, fgd;
  labels(box).setTo(cv::GC_PR_FGD);
  const int middle = box.x + box.width / 2;
  labels(cv::Range(box.y + box.height * 5 / 100, box.y + box.height * 97 / 100), cv::Range(middle - 1, middle + 1))
      .setTo(cv::GC_FGD);
  // GrabCut initialises its colour models with k-means on OpenCV's thread RNG.
  cv::theRNG().state = 0x5DEECE66DULL ^ seed;
  cv::grabCut(bgr, labels, box, bgd, fgd, iterations, cv::GC_INIT_WITH_MASK);
  const cv::Mat mask = (labels == cv::GC_FGD) | (labels == cv::GC_PR_FGD);
  return CutoutFromMask(bgr, LargestPart(mask, source + ": GrabCut found no person inside the box"), source);
}

PersonCutout CutoutWithDepth(const cv::Mat& bgr, const cv::Mat& depth, const cv::Rect& box,
                             const std::string& source) {
  CheckPersonBox(bgr, box, source);
  if (depth.size() != bgr.size() || depth.type() != CV_16U)
    throw InputError(source + ": person depth must be 16-bit 1-channel and the size of the image (" +
                     std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) + ")");
  const cv::Mat inside = depth(box);
  std::vector<std::uint16_t> valid;
  for (int r = 0; r < inside.rows; ++r)
    for (int c = 0; c < inside.cols; ++c)
      if (const std::uint16_t d = inside.at<std::uint16_t>(r, c); d > 0) valid.push_back(d);
  if (valid.empty()) throw InputError(source + ": person depth has no valid reading inside the box");
  const auto fifth = valid.begin() + static_cast<std::ptrdiff_t>(valid.size() / 5);
  std::nth_element(valid.begin(), fifth, valid.end());
  const double far = *fifth + kPersonDepthLayerM * kTumDepthFactor;
  cv::Mat layer = (inside > 0) & (inside <= far);
  cv::morphologyEx(layer, layer, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, {7, 7}));
  cv::Mat mask(bgr.size(), CV_8U, cv::Scalar(0));
  layer.copyTo(mask(box));
  return CutoutFromMask(bgr, LargestPart(mask, source + ": no person found in the depth inside the box"), source);
}

std::vector<PersonCutout> DefaultPersonCutouts() {
  const cv::Mat photo = cv::imread(kDefaultPeoplePhoto, cv::IMREAD_COLOR);
  if (photo.empty())
    throw InputError(std::string(kDefaultPeoplePhoto) +
                     ": the default people's photo is missing: install Debian's opencv-doc "
                     "(apt-get install opencv-doc), or give --person with --person-box or --person-mask");
  // Two men standing upright: on the right in a red shirt, seen from behind; on the left in a
  // red shirt and grey shorts, seen from the side.
  return {CutoutWithGrabCut(photo, kDefaultPersonBoxes[0], 5, 1, kDefaultPeoplePhoto),
          CutoutWithGrabCut(photo, kDefaultPersonBoxes[1], 5, 1, kDefaultPeoplePhoto)};
}

PersonCutout MakeSyntheticPersonCutout(std::uint32_t seed) {
  const int w = 200, h = 600;
  const cv::Mat shirt = MakeTextureImage(TextureKind::kClothes, w, h, seed * 11 + 1);
  const cv::Mat trousers = MakeTextureImage(TextureKind::kDenim, w, h, seed * 11 + 2);
  const cv::Mat skin = MakeTextureImage(TextureKind::kSkin, w, h, seed * 11 + 3);
  cv::Mat mask_shirt(h, w, CV_8U, cv::Scalar(0)), mask_legs = mask_shirt.clone(), mask_skin = mask_shirt.clone();
  // Head and hands.
  cv::ellipse(mask_skin, {100, 45}, {30, 40}, 0, 0, 360, 255, -1, cv::LINE_AA);
  cv::circle(mask_skin, {28, 330}, 14, 255, -1, cv::LINE_AA);
  cv::circle(mask_skin, {172, 330}, 14, 255, -1, cv::LINE_AA);
  // Torso and arms.
  cv::rectangle(mask_shirt, cv::Rect(91, 80, 18, 15), 255, -1);
  const std::vector<cv::Point> torso = {{48, 100}, {152, 100}, {145, 320}, {55, 320}};
  cv::fillConvexPoly(mask_shirt, torso, 255, cv::LINE_AA);
  const std::vector<cv::Point> left_arm = {{48, 100}, {60, 110}, {40, 320}, {16, 318}};
  const std::vector<cv::Point> right_arm = {{152, 100}, {140, 110}, {160, 320}, {184, 318}};
  cv::fillConvexPoly(mask_shirt, left_arm, 255, cv::LINE_AA);
  cv::fillConvexPoly(mask_shirt, right_arm, 255, cv::LINE_AA);
  // Legs and shoes.
  const std::vector<cv::Point> left_leg = {{55, 315}, {99, 315}, {95, 585}, {62, 585}};
  const std::vector<cv::Point> right_leg = {{101, 315}, {145, 315}, {138, 585}, {105, 585}};
  cv::fillConvexPoly(mask_legs, left_leg, 255, cv::LINE_AA);
  cv::fillConvexPoly(mask_legs, right_leg, 255, cv::LINE_AA);
  cv::Mat bgr(h, w, CV_8UC3, cv::Scalar(0, 0, 0));
  trousers.copyTo(bgr, mask_legs > 127);
  shirt.copyTo(bgr, mask_shirt > 127);
  skin.copyTo(bgr, mask_skin > 127);
  cv::Mat mask = (mask_legs > 127) | (mask_shirt > 127) | (mask_skin > 127);
  cv::rectangle(bgr, cv::Rect(58, 585, 42, 15), cv::Scalar(20, 20, 25), -1);
  cv::rectangle(bgr, cv::Rect(102, 585, 42, 15), cv::Scalar(20, 20, 25), -1);
  cv::rectangle(mask, cv::Rect(58, 585, 42, 15), 255, -1);
  cv::rectangle(mask, cv::Rect(102, 585, 42, 15), 255, -1);
  return CutoutFromMask(bgr, mask, "synthetic person");
}

}  // namespace dynvo
