#pragma once
// Person cut-outs for insertion into real sequences: a BGRA image (alpha = person) from a
// photo and its mask, from a photo and a box (GrabCut, or the nearest depth layer of a registered
// depth image), or drawn procedurally.

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

struct PersonCutout {
  cv::Mat bgra;  // CV_8UC4, cropped to the person; alpha 255 on the person, 0 elsewhere
};

// The cut-out of `bgr` where `mask` (CV_8U, same size) is non-zero. Transparent pixels take
// the person's mean colour so that filtering does not bleed the background in.
// Throws InputError naming `source` when sizes differ or the mask is empty.
PersonCutout CutoutFromMask(const cv::Mat& bgr, const cv::Mat& mask, const std::string& source);

// Reads an image and a mask PNG (non-zero = person); throws InputError naming the file.
PersonCutout LoadPersonCutout(const std::string& image_path, const std::string& mask_path);

// Segments the upright person inside `box` with GrabCut (`iterations` rounds, deterministic from
// `seed`; the box's middle column is taken as surely the person). Throws InputError naming `source` when the box is not
// inside the image or nothing is segmented.
PersonCutout CutoutWithGrabCut(const cv::Mat& bgr, const cv::Rect& box, int iterations, std::uint32_t seed,
                               const std::string& source);

// Cuts the person inside `box` by depth: the valid pixels of `depth` (CV_16U, TUM's 1/5000 m,
// registered to `bgr`) at most kPersonDepthLayerM behind the box's 20th percentile of depth,
// small holes closed, the largest connected part. For a person standing in front of a farther
// background, as in a frame of a real RGB-D sequence. Throws InputError naming `source` when the
// box is not inside the image, the sizes or types differ, or the box has no valid depth.
PersonCutout CutoutWithDepth(const cv::Mat& bgr, const cv::Mat& depth, const cv::Rect& box,
                             const std::string& source);

// Metres behind the nearest fifth of a box's depths that still count as the person (a body's
// depth plus Kinect noise at 1-3 m).
constexpr double kPersonDepthLayerM = 0.5;

// The photo the default people are cut from: a Debian package's file (opencv-doc).
constexpr const char* kDefaultPeoplePhoto = "/usr/share/doc/opencv-doc/opencv4/html/person_multi_det.jpg";

// Boxes (x, y, width, height) of two people standing upright in kDefaultPeoplePhoto.
inline const cv::Rect kDefaultPersonBoxes[2] = {{343, 170, 40, 178}, {18, 186, 24, 118}};

// The two people of kDefaultPersonBoxes, segmented by GrabCut in fixed boxes. Throws
// InputError saying how to install the photo (or to give one) when it is missing.
std::vector<PersonCutout> DefaultPersonCutouts();

// A textured standing-person silhouette (head, torso, arms, legs; clothes patterns),
// 200 x 600 pixels, deterministic from the seed: the default when no photo is given.
PersonCutout MakeSyntheticPersonCutout(std::uint32_t seed);

}  // namespace dynvo
