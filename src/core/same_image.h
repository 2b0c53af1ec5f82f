#pragma once
// Whether two image headers view the same pixels: how a stage recognises the frame its
// look-ahead already started on (one decoded frame handed to two calls).

#include <opencv2/core.hpp>

namespace dynvo {

// True when both headers view the same pixels (and neither is empty).
inline bool SameImage(const cv::Mat& a, const cv::Mat& b) {
  return !a.empty() && a.data == b.data && a.size() == b.size() && a.step == b.step && a.type() == b.type();
}

}  // namespace dynvo
