#pragma once
// A person detector for the stage tests: finds one fixed box (by default x 300, y 100, 80 x 200
// px), counts its calls, and throws on the calls listed.

#include <algorithm>
#include <utility>
#include <vector>

#include "core/error.h"
#include "detection/person_detector.h"

namespace dynvo::test {

class ScriptedDetector : public PersonDetector {
 public:
  ScriptedDetector(int* calls, std::vector<int> failing, const cv::Rect2d& box = cv::Rect2d(300, 100, 80, 200))
      : calls_(calls), failing_(std::move(failing)), box_(box) {}
  std::vector<Detection> Detect(const cv::Mat& /*bgr*/) override {
    const int call = (*calls_)++;
    if (std::find(failing_.begin(), failing_.end(), call) != failing_.end()) throw InputError("scripted failure");
    return {{box_, 0.9, 0}};
  }

 private:
  int* calls_;
  std::vector<int> failing_;
  cv::Rect2d box_;
};

}  // namespace dynvo::test
