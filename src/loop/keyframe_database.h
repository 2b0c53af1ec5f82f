#pragma once
// Place recognition without a vocabulary: every keyframe's ORB (or LBD) descriptors in a locality-
// sensitive hash index built online (bit sampling: each table keys a descriptor by a fixed
// random choice of its bits), so that a new keyframe finds the earlier keyframes that share
// its descriptors without a vocabulary trained beforehand.

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

struct KeyframeDatabaseOptions {
  // Two views of one ORB corner differ in about 10-30 of 256 bits: a 16-bit key then agrees in
  // 20-50% of the tables, so 8 tables find most of them, and 2^16 buckets keep each one short.
  int tables = 8;         // hash tables (1..32)
  int key_bits = 16;      // bits per key (1..32)
  int max_distance = 50;  // a stored descriptor farther than this (bits) is no match (0..256)
  unsigned seed = 11;     // which bits each table samples
  // Throws InputError naming the key ("loop.database.<field> ...") when out of range.
  void Check() const;
};

class KeyframeDatabase {
 public:
  // Throws InputError when the options are out of range.
  explicit KeyframeDatabase(const KeyframeDatabaseOptions& options = {});

  // Stores a keyframe's descriptors (N x 32, CV_8UC1; empty is allowed) as keyframe number
  // size() (0 for the first). Throws InputError on another type or width.
  void Add(const cv::Mat& descriptors);
  size_t size() const { return keyframe_sizes_.size(); }

  // Votes for the keyframes numbered below `before`: each query descriptor (N x 32, CV_8UC1)
  // gives one vote to the keyframe of its nearest stored descriptor that shares a key with it,
  // if that one is within max_distance. Returns the votes per keyframe (size min(before,
  // size())). Deterministic: ties go to the earlier stored descriptor.
  std::vector<int> Votes(const cv::Mat& descriptors, size_t before) const;

 private:
  using Descriptor = std::array<uint64_t, 4>;
  uint32_t Key(const Descriptor& descriptor, size_t table) const;

  KeyframeDatabaseOptions options_;
  std::vector<std::vector<int>> key_bit_positions_;                           // per table, the bits its key samples
  std::vector<Descriptor> descriptors_;                                       // all stored, in order
  std::vector<uint32_t> descriptor_keyframe_;                                 // keyframe number of each
  std::vector<size_t> keyframe_sizes_;                                        // descriptors per keyframe
  std::vector<std::unordered_map<uint32_t, std::vector<uint32_t>>> buckets_;  // per table: key -> descriptors
};

}  // namespace dynvo
