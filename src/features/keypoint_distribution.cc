#include "features/keypoint_distribution.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace dynvo {

namespace {

struct Node {
  float x0, y0, x1, y1;  // bounds, [x0, x1) x [y0, y1)
  std::vector<int> members;
};

// Index of the strongest member (lowest index on ties).
int Strongest(const std::vector<cv::KeyPoint>& keypoints, const std::vector<int>& members) {
  int best = members.front();
  for (int i : members)
    if (keypoints[i].response > keypoints[best].response) best = i;
  return best;
}

// Appends the non-empty children of `node` to `out`.
void Split(const std::vector<cv::KeyPoint>& keypoints, const Node& node, std::vector<Node>* out) {
  const float xm = 0.5f * (node.x0 + node.x1);
  const float ym = 0.5f * (node.y0 + node.y1);
  Node children[4] = {{node.x0, node.y0, xm, ym, {}},
                      {xm, node.y0, node.x1, ym, {}},
                      {node.x0, ym, xm, node.y1, {}},
                      {xm, ym, node.x1, node.y1, {}}};
  for (int i : node.members) {
    const cv::Point2f& p = keypoints[i].pt;
    children[(p.x >= xm ? 1 : 0) + (p.y >= ym ? 2 : 0)].members.push_back(i);
  }
  for (Node& child : children)
    if (!child.members.empty()) out->push_back(std::move(child));
}

bool Splittable(const Node& node) {
  return node.members.size() > 1 && node.x1 - node.x0 > 1.0f && node.y1 - node.y0 > 1.0f;
}

bool Inside(const cv::Point2f& p, const cv::Rect2f& r) {
  return p.x >= r.x && p.y >= r.y && p.x < r.x + r.width && p.y < r.y + r.height;
}

// Keeps the `wanted` strongest of `indices` (ties by index), sorted by index.
void KeepStrongest(const std::vector<cv::KeyPoint>& keypoints, int wanted, std::vector<int>* indices) {
  if (static_cast<int>(indices->size()) > wanted) {
    std::nth_element(indices->begin(), indices->begin() + wanted, indices->end(), [&](int a, int b) {
      return keypoints[a].response != keypoints[b].response ? keypoints[a].response > keypoints[b].response : a < b;
    });
    indices->resize(wanted);
  }
  std::sort(indices->begin(), indices->end());
}

}  // namespace

std::vector<int> DistributeQuadtree(const std::vector<cv::KeyPoint>& keypoints, const cv::Rect2f& region, int wanted) {
  std::vector<int> kept;
  if (wanted <= 0 || region.width <= 0 || region.height <= 0) return kept;

  // Roots: square-ish nodes side by side along the longer axis (one for a 4:3 image).
  const int roots_x = std::max(1, static_cast<int>(std::lround(region.width / region.height)));
  const int roots_y = std::max(1, static_cast<int>(std::lround(region.height / region.width)));
  const float root_w = region.width / roots_x, root_h = region.height / roots_y;
  std::vector<Node> nodes(static_cast<size_t>(roots_x * roots_y));
  for (int ry = 0; ry < roots_y; ++ry)
    for (int rx = 0; rx < roots_x; ++rx) {
      Node& n = nodes[ry * roots_x + rx];
      n.x0 = region.x + rx * root_w;
      n.y0 = region.y + ry * root_h;
      n.x1 = rx + 1 == roots_x ? region.x + region.width : n.x0 + root_w;
      n.y1 = ry + 1 == roots_y ? region.y + region.height : n.y0 + root_h;
    }
  for (int i = 0; i < static_cast<int>(keypoints.size()); ++i) {
    const cv::Point2f& p = keypoints[i].pt;
    if (!Inside(p, region)) continue;
    const int rx = std::min(roots_x - 1, static_cast<int>((p.x - region.x) / root_w));
    const int ry = std::min(roots_y - 1, static_cast<int>((p.y - region.y) / root_h));
    nodes[ry * roots_x + rx].members.push_back(i);
  }
  nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [](const Node& n) { return n.members.empty(); }), nodes.end());

  std::vector<Node> next;
  while (static_cast<int>(nodes.size()) < wanted) {
    std::vector<size_t> splittable;
    for (size_t k = 0; k < nodes.size(); ++k)
      if (Splittable(nodes[k])) splittable.push_back(k);
    if (splittable.empty()) break;
    // A full round adds up to three nodes per split. When it would overshoot, split the most
    // populated nodes first and stop as soon as there are enough.
    const bool last_round = static_cast<int>(nodes.size() + 3 * splittable.size()) >= wanted;
    if (last_round)
      std::stable_sort(splittable.begin(), splittable.end(),
                       [&](size_t a, size_t b) { return nodes[a].members.size() > nodes[b].members.size(); });
    next.clear();
    std::vector<uint8_t> split_done(nodes.size(), 0);
    int count = static_cast<int>(nodes.size());
    for (size_t k : splittable) {
      if (last_round && count >= wanted) break;
      const size_t before = next.size();
      Split(keypoints, nodes[k], &next);
      count += static_cast<int>(next.size() - before) - 1;
      split_done[k] = 1;
    }
    for (size_t k = 0; k < nodes.size(); ++k)
      if (!split_done[k]) next.push_back(std::move(nodes[k]));
    nodes.swap(next);
  }

  kept.reserve(nodes.size());
  for (const Node& n : nodes) kept.push_back(Strongest(keypoints, n.members));
  KeepStrongest(keypoints, wanted, &kept);
  return kept;
}

std::vector<int> DistributeGrid(const std::vector<cv::KeyPoint>& keypoints, const cv::Rect2f& region, int wanted) {
  std::vector<int> kept;
  if (wanted <= 0 || region.width <= 0 || region.height <= 0) return kept;
  const double cell = std::sqrt(static_cast<double>(region.width) * region.height / wanted);
  const int cols = std::max(1, static_cast<int>(std::lround(region.width / cell)));
  const int rows = std::max(1, static_cast<int>(std::lround(region.height / cell)));
  std::vector<int> best(static_cast<size_t>(cols * rows), -1);
  std::vector<int> inside;
  for (int i = 0; i < static_cast<int>(keypoints.size()); ++i) {
    const cv::Point2f& p = keypoints[i].pt;
    if (!Inside(p, region)) continue;
    inside.push_back(i);
    const int cx = std::min(cols - 1, static_cast<int>((p.x - region.x) * cols / region.width));
    const int cy = std::min(rows - 1, static_cast<int>((p.y - region.y) * rows / region.height));
    int& b = best[cy * cols + cx];
    if (b < 0 || keypoints[i].response > keypoints[b].response) b = i;
  }
  std::vector<uint8_t> taken(keypoints.size(), 0);
  for (int b : best)
    if (b >= 0) {
      kept.push_back(b);
      taken[b] = 1;
    }
  KeepStrongest(keypoints, wanted, &kept);
  if (static_cast<int>(kept.size()) < wanted) {
    std::vector<int> rest;
    for (int i : inside)
      if (!taken[i]) rest.push_back(i);
    KeepStrongest(keypoints, wanted - static_cast<int>(kept.size()), &rest);
    kept.insert(kept.end(), rest.begin(), rest.end());
    std::sort(kept.begin(), kept.end());
  }
  return kept;
}

std::vector<int> StrongestKeypoints(const std::vector<cv::KeyPoint>& keypoints, int wanted) {
  std::vector<int> kept(keypoints.size());
  std::iota(kept.begin(), kept.end(), 0);
  KeepStrongest(keypoints, std::max(0, wanted), &kept);
  return kept;
}

}  // namespace dynvo
