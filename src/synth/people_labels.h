#pragma once
// The ground truth about people that a generated sequence carries beside masks.txt:
//   people.txt  one line per person and colour image: `timestamp id state visible_pixels`,
//               state `moving` or `still`, visible_pixels the person's pixels in masks/;
//   stats.csv   one line per colour image: `timestamp,coverage,people_in_view,people_moving`,
//               coverage the share of the image masks/ marks.

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

class PeopleLabels {
 public:
  // `generator` names the program in people.txt's header.
  explicit PeopleLabels(const std::string& generator);

  // Adds the colour image at `stamp`: `person_id` (CV_16U) holds person k + 1's visible pixels,
  // `mask` (CV_8U) the image's dynamic pixels, `moving[k]` person k's state.
  void AddFrame(double stamp, const cv::Mat& person_id, const cv::Mat& mask, const std::vector<bool>& moving);

  // Writes people.txt and stats.csv into `folder`; throws InputError naming a file not written.
  void Write(const std::string& folder) const;

  const std::vector<double>& coverage() const { return coverage_; }  // per frame, in order

 private:
  std::string people_, stats_;
  std::vector<double> coverage_;
};

// 255 where `person_id` (CV_16U, person k + 1) shows a person k with !moving[k], else 0.
cv::Mat StillPeoplePixels(const cv::Mat& person_id, const std::vector<bool>& moving);

// `mask` (CV_8U, non-zero = dynamic) with kStillPersonLabel (dataset/tum_dataset.h) where `still`
// (CV_8U, same size) is non-zero: what a generated sequence writes into masks/.
cv::Mat LabelStillPeople(const cv::Mat& mask, const cv::Mat& still);

// The median of `values` (0 when empty).
double MedianOf(std::vector<double> values);

}  // namespace dynvo
