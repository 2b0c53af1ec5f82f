#pragma once
// Spreading detected corners over an image region so that features cover the whole frame.

#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

// Indices of at most `wanted` keypoints spread by an ORB-SLAM style quadtree over `region`:
// nodes holding more than one keypoint are split into four (largest nodes first in the last
// round) until there are `wanted` nodes or no node can be split (or nodes reach 1 pixel);
// the strongest response of each node is kept. Keypoints outside `region` are ignored.
std::vector<int> DistributeQuadtree(const std::vector<cv::KeyPoint>& keypoints, const cv::Rect2f& region, int wanted);

// Indices of at most `wanted` keypoints: the strongest of each cell of a regular grid of about
// `wanted` cells over `region`, topped up with the strongest remaining ones.
std::vector<int> DistributeGrid(const std::vector<cv::KeyPoint>& keypoints, const cv::Rect2f& region, int wanted);

// Indices of the `wanted` strongest keypoints (ties broken by index).
std::vector<int> StrongestKeypoints(const std::vector<cv::KeyPoint>& keypoints, int wanted);

}  // namespace dynvo
