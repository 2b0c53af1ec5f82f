#include "detection/person_mask.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace dynvo {
namespace {

// A wall at 4 m, a person (head and body, arms apart) at 2 m in front of it, a small box on
// the floor at 1.5 m inside the person's detection box, and depth holes along the person's left
// edge, as Kinect leaves them. The person's pixels are known.
struct Scene {
  cv::Mat depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(4.0f));
  cv::Mat person = cv::Mat::zeros(480, 640, CV_8UC1);
  cv::Rect2d box{250, 80, 140, 360};
};

Scene MakeScene() {
  Scene s;
  cv::circle(s.person, {320, 120}, 30, 255, cv::FILLED);                  // head
  cv::rectangle(s.person, cv::Rect(285, 150, 70, 150), 255, cv::FILLED);  // body
  cv::rectangle(s.person, cv::Rect(262, 155, 18, 120), 255, cv::FILLED);  // arm, apart from the body
  cv::rectangle(s.person, cv::Rect(290, 300, 25, 135), 255, cv::FILLED);  // legs with a gap between
  cv::rectangle(s.person, cv::Rect(325, 300, 25, 135), 255, cv::FILLED);
  s.depth.setTo(2.0f, s.person);
  s.depth(cv::Rect(360, 400, 25, 30)).setTo(1.5f);  // the small box on the floor
  s.depth(cv::Rect(285, 180, 3, 100)).setTo(0.0f);  // holes at the body's edge
  return s;
}

TEST(PersonMask, TheNearDominantModeIsThePerson) {
  const Scene s = MakeScene();
  EXPECT_NEAR(PersonDepth(s.depth, cv::Rect(s.box)), 2.0, 2.0 * 0.04);  // one histogram bin
}

TEST(PersonMask, CoversThePersonAndLeavesTheBackgroundInTheBox) {
  const Scene s = MakeScene();
  const PersonMaskOptions options;
  const cv::Mat mask = PersonMaskFromBox(s.depth, s.box, options);
  const double person = cv::countNonZero(s.person);
  const double covered = cv::countNonZero(mask & s.person);
  EXPECT_GT(covered / person, 0.99);
  // Background inside the box: masked only within grow_px of the silhouette (and the holes).
  cv::Mat near_person;
  const int reach = 2 * options.grow_px + 1;
  cv::dilate(s.person, near_person,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * reach + 1, 2 * reach + 1)));
  cv::Mat background_in_box = cv::Mat::zeros(mask.size(), CV_8UC1);
  background_in_box(cv::Rect(s.box)).setTo(255);
  background_in_box &= ~s.person;
  const double far_background = cv::countNonZero(background_in_box & ~near_person);
  EXPECT_EQ(cv::countNonZero(mask & background_in_box & ~near_person), 0);
  EXPECT_GT(far_background, 0.3 * cv::countNonZero(background_in_box));  // a real test: there is such background
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(362, 405, 20, 20))), 0);      // the nearer small box is not the person
}

TEST(PersonMask, ADeskInFrontOfTheLegsIsNotThePerson) {
  // A desk at 1.2 m covers the box below the person's waist, more of the box than the person.
  Scene s = MakeScene();
  s.depth(cv::Rect(200, 260, 240, 220)).setTo(1.2f);
  EXPECT_NEAR(PersonDepth(s.depth, cv::Rect(s.box)), 2.0, 2.0 * 0.04);
  const cv::Mat mask = PersonMaskFromBox(s.depth, s.box);
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(200, 300, 240, 180))), 0);  // the desk below the waist
  EXPECT_GT(cv::countNonZero(mask & s.person), 0.99 * cv::countNonZero(s.person(cv::Rect(0, 0, 640, 260))));
}

// A person walking across the view with an arm held out: the detector boxed the body only. The
// arm, at the body's depth, is parted from the shoulder by a depth shadow 5 px wide and reaches
// half the box's width beyond its side, down to below the waist. The floor at the feet's depth
// runs across the image under the box's lowest rows.
struct ArmScene {
  cv::Mat depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(4.0f));
  cv::Mat arm = cv::Mat::zeros(480, 640, CV_8UC1);
  cv::Rect2d box{250, 80, 140, 380};
};

ArmScene MakeArmScene() {
  ArmScene s;
  s.depth(cv::Rect(280, 80, 80, 380)).setTo(2.0f);  // head, body and legs
  cv::line(s.arm, {370, 160}, {440, 330}, 255, 10);  // 5 px beyond the body
  s.depth.setTo(2.05f, s.arm);
  s.depth(cv::Rect(0, 450, 640, 30)).setTo(2.1f);  // the floor beside the feet, as near as the person
  return s;
}

TEST(PersonMask, AnArmHeldOutBesideTheBoxIsThePerson) {
  const ArmScene s = MakeArmScene();
  const cv::Mat mask = PersonMaskFromBox(s.depth, s.box, ArmsBesideTheBox());
  EXPECT_GT(cv::countNonZero(mask & s.arm), 0.99 * cv::countNonZero(s.arm));
  // The floor beside the feet stays out beyond the box's margin, though it touches the feet.
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(0, 462, 200, 18))), 0);
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(440, 462, 200, 18))), 0);
  // Only the box's margin and no bridge (the defaults): the arm is lost.
  const cv::Mat boxed_mask = PersonMaskFromBox(s.depth, s.box, PersonMaskOptions());
  EXPECT_LT(cv::countNonZero(boxed_mask & s.arm), 0.5 * cv::countNonZero(s.arm));
}

TEST(PersonMask, SomethingAsNearBesideThePersonButApartIsNot) {
  // A pillar at the person's depth, 20 px beside the arm and within the side reach.
  ArmScene s = MakeArmScene();
  s.depth(cv::Rect(470, 100, 30, 300)).setTo(2.0f);
  const cv::Mat mask = PersonMaskFromBox(s.depth, s.box, ArmsBesideTheBox());
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(470 + PersonMaskOptions().grow_px + 1, 100, 20, 300))), 0);
  EXPECT_GT(cv::countNonZero(mask & s.arm), 0.99 * cv::countNonZero(s.arm));
}

TEST(PersonMask, MoreThanALimbBesideTheBoxIsBackground) {
  // A desk top at the person's depth, touching the arm and reaching across beside the box: far
  // more than a limb. The silhouette is cut back to the box's margin; what the box holds stays.
  ArmScene s = MakeArmScene();
  s.depth(cv::Rect(360, 300, 280, 60)).setTo(2.1f);
  const PersonMaskOptions options = ArmsBesideTheBox();
  const cv::Mat mask = PersonMaskFromBox(s.depth, s.box, options);
  const int margin = static_cast<int>(std::ceil(options.box_margin * s.box.width)) + options.grow_px + 1;
  const int beyond = static_cast<int>(s.box.br().x) + margin;
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(beyond, 0, 640 - beyond, 480))), 0);
  EXPECT_GT(cv::countNonZero(mask(cv::Rect(280, 80, 80, 380))), 0.99 * 80 * 380);  // the body
}

TEST(PersonMask, WithoutDepthTheBoxIsTheMask) {
  const cv::Mat depth = cv::Mat::zeros(480, 640, CV_32FC1);
  const cv::Mat mask = PersonMaskFromBox(depth, cv::Rect2d(100.4, 50.2, 80, 200));
  EXPECT_EQ(cv::countNonZero(mask), 81 * 201);  // the box's pixels, rounded outwards
  EXPECT_EQ(cv::countNonZero(PersonMaskFromBox(depth, cv::Rect2d(700, 50, 80, 200))), 0);  // outside the image
}

TEST(PersonMask, ThePersonsCentreIsNotPulledByTheBackgroundItsSilhouetteTakesIn) {
  const Scene s = MakeScene();
  const Camera camera;  // 525 px, centre (319.5, 239.5)
  // The person's own pixels: centred on x about 320 at 2 m.
  const std::optional<Eigen::Vector3d> own = PersonCentre(s.person, s.depth, camera);
  ASSERT_TRUE(own.has_value());
  EXPECT_NEAR(own->z(), 2.0, 1e-9);
  EXPECT_NEAR(own->x(), 0.0, 0.05);
  // A silhouette that also took in a strip of the wall at 4 m beside the person (a quarter of
  // its pixels, as when a box widens): the centre stays on the person, its depth exact, sideways
  // a few ranks of the person's own columns. The mean of the pixels would move 0.5 m back and
  // 0.15 m sideways: a walk's speed over the 0.15 s the speed is measured on.
  cv::Mat widened = s.person.clone();
  const int wall = cv::countNonZero(s.person) / 3;
  widened(cv::Rect(400, 80, wall / 360, 360)).setTo(255);
  const std::optional<Eigen::Vector3d> centre = PersonCentre(widened, s.depth, camera);
  ASSERT_TRUE(centre.has_value());
  EXPECT_NEAR(centre->z(), 2.0, 1e-9);
  EXPECT_NEAR(centre->x(), own->x(), 0.08);
  EXPECT_FALSE(PersonCentre(s.person, cv::Mat::zeros(480, 640, CV_32FC1), camera).has_value());  // no depth
}

TEST(PersonMask, ThePersonsEndsAreTheirHeadAndFeet) {
  const Scene s = MakeScene();
  const Camera camera;  // 525 px, centre (319.5, 239.5); at 2 m a row is 3.8 mm
  const auto height_of_row = [](double row) { return (row - 239.5) * 2.0 / 525.0; };
  const std::optional<Eigen::Vector3d> centre = PersonCentre(s.person, s.depth, camera);
  const std::optional<Eigen::Vector3d> top = PersonEnd(s.person, s.depth, camera, PersonEndSide::kTop);
  const std::optional<Eigen::Vector3d> bottom = PersonEnd(s.person, s.depth, camera, PersonEndSide::kBottom);
  ASSERT_TRUE(centre && top && bottom);
  // The head's top is row 90, the feet's row 434; sampled every 4th row, the 6th point from
  // either end lies within two sample rows of it (the head is 15 samples wide at its widest).
  EXPECT_NEAR(top->y(), height_of_row(90), 3 * 4 * 2.0 / 525.0);
  EXPECT_NEAR(bottom->y(), height_of_row(434), 3 * 4 * 2.0 / 525.0);
  EXPECT_EQ(top->x(), centre->x());  // across and in depth, the centre
  EXPECT_EQ(bottom->z(), centre->z());

  // The silhouette grown by 8 px into the wall at 4 m, whose points above the head lie twice as
  // high in the camera, and cut at row 300 (the image's bottom edge below the waist): the top
  // end stays on the head.
  cv::Mat grown;
  cv::dilate(s.person, grown, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(17, 17)));
  grown.rowRange(300, grown.rows).setTo(0);
  const std::optional<Eigen::Vector3d> cut_top = PersonEnd(grown, s.depth, camera, PersonEndSide::kTop);
  ASSERT_TRUE(cut_top.has_value());
  EXPECT_NEAR(cut_top->y(), top->y(), 1e-9);
  EXPECT_FALSE(PersonEnd(s.person, cv::Mat::zeros(480, 640, CV_32FC1), camera, PersonEndSide::kTop).has_value());
}

}  // namespace
}  // namespace dynvo
