#include "loop/keyframe_database.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <random>

#include "core/error.h"

namespace dynvo {

void KeyframeDatabaseOptions::Check() const {
  RequireOption(tables >= 1 && tables <= 32, "loop.database", "tables", "in 1..32", tables);
  RequireOption(key_bits >= 1 && key_bits <= 32, "loop.database", "key_bits", "in 1..32", key_bits);
  RequireOption(max_distance >= 0 && max_distance <= 256, "loop.database", "max_distance", "in 0..256", max_distance);
}

namespace {

constexpr int kDescriptorBytes = 32;

void RequireDescriptors(const cv::Mat& descriptors, const char* what) {
  if (!descriptors.empty() && (descriptors.type() != CV_8UC1 || descriptors.cols != kDescriptorBytes))
    throw InputError(std::string(what) + ": descriptors must be N x 32 CV_8UC1 (ORB or LBD)");
}

std::array<uint64_t, 4> ToWords(const unsigned char* row) {
  std::array<uint64_t, 4> words;
  std::memcpy(words.data(), row, kDescriptorBytes);
  return words;
}

int Distance(const std::array<uint64_t, 4>& a, const std::array<uint64_t, 4>& b) {
  int d = 0;
  for (int i = 0; i < 4; ++i) d += __builtin_popcountll(a[i] ^ b[i]);
  return d;
}

}  // namespace

KeyframeDatabase::KeyframeDatabase(const KeyframeDatabaseOptions& options)
    : options_(options), buckets_(static_cast<size_t>(std::max(options.tables, 0))) {
  options_.Check();
  std::mt19937 rng(options_.seed);
  std::vector<int> bits(kDescriptorBytes * 8);
  std::iota(bits.begin(), bits.end(), 0);
  for (int t = 0; t < options_.tables; ++t) {
    std::shuffle(bits.begin(), bits.end(), rng);
    key_bit_positions_.emplace_back(bits.begin(), bits.begin() + options_.key_bits);
  }
}

uint32_t KeyframeDatabase::Key(const Descriptor& descriptor, size_t table) const {
  uint32_t key = 0;
  for (int bit : key_bit_positions_[table]) key = (key << 1) | ((descriptor[bit / 64] >> (bit % 64)) & 1u);
  return key;
}

void KeyframeDatabase::Add(const cv::Mat& descriptors) {
  RequireDescriptors(descriptors, "KeyframeDatabase::Add");
  const uint32_t keyframe = static_cast<uint32_t>(keyframe_sizes_.size());
  for (int r = 0; r < descriptors.rows; ++r) {
    const uint32_t index = static_cast<uint32_t>(descriptors_.size());
    descriptors_.push_back(ToWords(descriptors.ptr<unsigned char>(r)));
    descriptor_keyframe_.push_back(keyframe);
    for (size_t t = 0; t < buckets_.size(); ++t) buckets_[t][Key(descriptors_.back(), t)].push_back(index);
  }
  keyframe_sizes_.push_back(static_cast<size_t>(descriptors.rows));
}

std::vector<int> KeyframeDatabase::Votes(const cv::Mat& descriptors, size_t before) const {
  RequireDescriptors(descriptors, "KeyframeDatabase::Votes");
  std::vector<int> votes(std::min(before, size()), 0);
  if (votes.empty()) return votes;
  for (int r = 0; r < descriptors.rows; ++r) {
    const Descriptor query = ToWords(descriptors.ptr<unsigned char>(r));
    int best_distance = options_.max_distance + 1;
    uint32_t best = 0;
    for (size_t t = 0; t < buckets_.size(); ++t) {
      const auto bucket = buckets_[t].find(Key(query, t));
      if (bucket == buckets_[t].end()) continue;
      for (uint32_t index : bucket->second) {
        if (descriptor_keyframe_[index] >= votes.size()) break;  // stored in order: the rest are newer
        const int d = Distance(query, descriptors_[index]);
        if (d < best_distance || (d == best_distance && index < best)) {
          best_distance = d;
          best = index;
        }
      }
    }
    if (best_distance <= options_.max_distance) ++votes[descriptor_keyframe_[best]];
  }
  return votes;
}

}  // namespace dynvo
