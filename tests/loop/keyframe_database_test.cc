#include "loop/keyframe_database.h"

#include <random>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

cv::Mat RandomDescriptors(int rows, std::mt19937* rng) {
  std::uniform_int_distribution<int> byte(0, 255);
  cv::Mat d(rows, 32, CV_8UC1);
  for (int r = 0; r < rows; ++r)
    for (int b = 0; b < 32; ++b) d.at<unsigned char>(r, b) = static_cast<unsigned char>(byte(*rng));
  return d;
}

// Each descriptor with `flips` distinct bits flipped: another view of the same corners.
cv::Mat Flipped(const cv::Mat& descriptors, int flips, std::mt19937* rng) {
  cv::Mat d = descriptors.clone();
  for (int r = 0; r < d.rows; ++r) {
    std::vector<int> bits(256);
    for (int b = 0; b < 256; ++b) bits[b] = b;
    std::shuffle(bits.begin(), bits.end(), *rng);
    for (int f = 0; f < flips; ++f)
      d.at<unsigned char>(r, bits[f] / 8) ^= static_cast<unsigned char>(1 << (bits[f] % 8));
  }
  return d;
}

TEST(KeyframeDatabase, AnotherViewVotesForItsKeyframe) {
  std::mt19937 rng(3);
  KeyframeDatabase database;
  std::vector<cv::Mat> keyframes;
  for (int k = 0; k < 6; ++k) {
    keyframes.push_back(RandomDescriptors(500, &rng));
    database.Add(keyframes.back());
  }
  ASSERT_EQ(database.size(), 6u);
  // 20 of 256 bits changed: a 16-bit key survives with probability (236/256)^16 = 0.27, in at
  // least one of 8 tables 0.92; unrelated descriptors (128 bits apart) never pass 50.
  const std::vector<int> votes = database.Votes(Flipped(keyframes[3], 20, &rng), 6);
  ASSERT_EQ(votes.size(), 6u);
  EXPECT_GT(votes[3], 425);
  for (int k : {0, 1, 2, 4, 5}) EXPECT_LE(votes[k], 2) << k;
  // Keyframes from `before` on do not vote.
  const std::vector<int> earlier = database.Votes(Flipped(keyframes[3], 20, &rng), 3);
  ASSERT_EQ(earlier.size(), 3u);
  for (int v : earlier) EXPECT_LE(v, 2);
  // Deterministic.
  const cv::Mat query = Flipped(keyframes[1], 25, &rng);
  EXPECT_EQ(database.Votes(query, 6), database.Votes(query, 6));
  EXPECT_TRUE(database.Votes(query, 0).empty());
}

TEST(KeyframeDatabase, TooDifferentDescriptorsFindNothing) {
  std::mt19937 rng(5);
  KeyframeDatabaseOptions options;
  options.max_distance = 30;
  KeyframeDatabase database(options);
  const cv::Mat stored = RandomDescriptors(300, &rng);
  database.Add(stored);
  database.Add(cv::Mat());  // a keyframe without descriptors is allowed
  EXPECT_GT(database.Votes(Flipped(stored, 10, &rng), 2)[0], 250);
  EXPECT_EQ(database.Votes(Flipped(stored, 40, &rng), 2)[0], 0) << "beyond max_distance";
}

TEST(KeyframeDatabase, BadDescriptorsAndOptionsAreErrors) {
  KeyframeDatabase database;
  EXPECT_THROW(database.Add(cv::Mat(3, 16, CV_8UC1)), InputError);
  EXPECT_THROW(database.Votes(cv::Mat(3, 32, CV_32FC1), 0), InputError);
  KeyframeDatabaseOptions options;
  options.key_bits = 33;
  EXPECT_THROW(KeyframeDatabase{options}, InputError);
}

}  // namespace
}  // namespace dynvo
