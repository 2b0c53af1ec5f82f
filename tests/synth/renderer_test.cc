#include "synth/renderer.h"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "core/pose.h"
#include "synth/procedural_texture.h"
#include "synth/scene.h"

namespace dynvo {
namespace {

// Texture whose colour encodes the texture coordinate: B = 255 a, G = 255 b.
std::shared_ptr<const Texture> GradientTexture(int size, double texel) {
  cv::Mat image(size, size, CV_8UC3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      image.at<cv::Vec3b>(y, x) = cv::Vec3b(cv::saturate_cast<uchar>(255.0 * (x + 0.5) / size),
                                            cv::saturate_cast<uchar>(255.0 * (y + 0.5) / size), 128);
  return MakeTexture(image, texel);
}

Camera SmallCamera() {
  Camera c;
  c.width = 160;
  c.height = 120;
  c.fx = 130.0;
  c.fy = 128.0;
  c.cx = 79.3;
  c.cy = 60.8;
  return c;
}

TEST(Renderer, KnownPointLandsOnPredictedPixelWithPredictedDepth) {
  const Camera camera = SmallCamera();
  const Renderer renderer(camera);
  const Pose world_from_camera = PoseFromAxisAngle({0.1, -0.3, 0.05}, {0.4, -0.2, 1.1});
  // A point behind pixel (97, 41) at depth 2.3 m, on a tilted quad at texture coordinate (0.3, 0.6).
  const Eigen::Vector2d pixel(97, 41);
  const double depth = 2.3;
  const Eigen::Vector3d point_in_world = world_from_camera * camera.Backproject(pixel, depth);
  TexturedQuad quad;
  quad.edge_u = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.3, 1, 0.2).normalized()) * Eigen::Vector3d(1.2, 0, 0);
  quad.edge_v = Eigen::AngleAxisd(-0.3, Eigen::Vector3d(1, 0.1, 0).normalized()) * Eigen::Vector3d(0, 0.9, 0.3);
  quad.origin = point_in_world - 0.3 * quad.edge_u - 0.6 * quad.edge_v;
  quad.texture = GradientTexture(256, 0.004);  // about 0.07 texels per pixel: level 0
  quad.object_id = 3;
  const RenderResult r = renderer.Render({quad}, world_from_camera.inverse());
  const int u = static_cast<int>(pixel.x()), v = static_cast<int>(pixel.y());
  EXPECT_NEAR(r.depth.at<float>(v, u), depth, 1e-4);  // float arithmetic
  EXPECT_EQ(r.object_id.at<std::uint16_t>(v, u), 3);
  const cv::Vec3b colour = r.bgr.at<cv::Vec3b>(v, u);
  // Bilinear lookup at (0.3, 0.6) gives 255 * (0.3, 0.6) up to rounding; shade is 1.
  EXPECT_NEAR(colour[0], 255 * 0.3, 1.5);
  EXPECT_NEAR(colour[1], 255 * 0.6, 1.5);
}

TEST(Renderer, DistortedCameraAgreesWithOpenCvProjection) {
  Camera camera;  // TUM fr1: strong radial distortion
  camera.fx = 517.3;
  camera.fy = 516.5;
  camera.cx = 318.6;
  camera.cy = 255.3;
  camera.distortion = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};
  const Renderer renderer(camera);
  // A fronto-parallel square at 1.5 m near the image corner, where distortion is largest.
  TexturedQuad quad;
  quad.origin = {-0.75, -0.55, 1.5};
  quad.edge_u = {0.2, 0, 0};
  quad.edge_v = {0, 0.2, 0};
  quad.texture = GradientTexture(64, 0.2 / 64);
  quad.object_id = 1;
  const RenderResult r = renderer.Render({quad}, Pose::Identity());
  std::vector<cv::Point3d> corners = {
      {-0.75, -0.55, 1.5}, {-0.55, -0.55, 1.5}, {-0.55, -0.35, 1.5}, {-0.75, -0.35, 1.5}, {-0.65, -0.45, 1.5}};
  std::vector<cv::Point2d> pixels;
  cv::projectPoints(corners, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera.K(), camera.DistCoeffs(), pixels);
  // The centre is covered at exactly 1.5 m; 2 pixels outside each corner (away from the
  // centre) nothing is drawn; 2 pixels inside each corner the quad is.
  const cv::Point2d centre = pixels[4];
  EXPECT_NEAR(r.depth.at<float>(cvRound(centre.y), cvRound(centre.x)), 1.5, 1e-5);
  for (int i = 0; i < 4; ++i) {
    const cv::Point2d dir = (pixels[i] - centre) / cv::norm(pixels[i] - centre);
    const cv::Point2d outside = pixels[i] + 2.5 * dir, inside = pixels[i] - 2.5 * dir;
    ASSERT_TRUE(outside.x >= 0 && outside.y >= 0) << "corner " << i << " must stay in the image";
    EXPECT_EQ(r.object_id.at<std::uint16_t>(cvRound(outside.y), cvRound(outside.x)), 0) << "corner " << i;
    EXPECT_EQ(r.object_id.at<std::uint16_t>(cvRound(inside.y), cvRound(inside.x)), 1) << "corner " << i;
  }
  // ProjectPoint implements the same model as cv::projectPoints.
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2d p = renderer.ProjectPoint({corners[i].x, corners[i].y, corners[i].z});
    EXPECT_NEAR(p.x(), pixels[i].x, 1e-9);
    EXPECT_NEAR(p.y(), pixels[i].y, 1e-9);
  }
}

TEST(Renderer, NearerQuadWinsWhateverTheOrder) {
  const Camera camera = SmallCamera();
  const Renderer renderer(camera);
  TexturedQuad far_quad, near_quad;
  far_quad.origin = {-2, -2, 3.0};
  far_quad.edge_u = {4, 0, 0};
  far_quad.edge_v = {0, 4, 0};
  far_quad.texture = GradientTexture(64, 0.05);
  far_quad.object_id = 0;
  near_quad = far_quad;
  near_quad.origin = {-0.2, -0.2, 1.0};
  near_quad.edge_u = {0.4, 0, 0};
  near_quad.edge_v = {0, 0.4, 0};
  near_quad.object_id = 7;
  for (const auto& quads :
       {std::vector<TexturedQuad>{far_quad, near_quad}, std::vector<TexturedQuad>{near_quad, far_quad}}) {
    const RenderResult r = renderer.Render(quads, Pose::Identity());
    EXPECT_NEAR(r.depth.at<float>(60, 79), 1.0, 1e-5);
    EXPECT_EQ(r.object_id.at<std::uint16_t>(60, 79), 7);
    EXPECT_NEAR(r.depth.at<float>(5, 5), 3.0, 1e-5);
    EXPECT_EQ(r.object_id.at<std::uint16_t>(5, 5), 0);
    // The near square spans 0.4 m at 1 m: 52 x 51.2 pixels.
    const int covered = cv::countNonZero(r.object_id == 7);
    EXPECT_NEAR(covered, 130.0 * 0.4 * 128.0 * 0.4, 110.0);
  }
}

TEST(Renderer, QuadBehindCameraIsNotDrawnAndCrossingQuadIsClipped) {
  const Camera camera = SmallCamera();
  const Renderer renderer(camera);
  TexturedQuad behind;
  behind.origin = {-1, -1, -2};
  behind.edge_u = {2, 0, 0};
  behind.edge_v = {0, 2, 0};
  behind.texture = GradientTexture(32, 0.06);
  EXPECT_EQ(cv::countNonZero(renderer.Render({behind}, Pose::Identity()).depth), 0);
  // A floor quad y = 1 m below the camera running from behind it to 10 m ahead.
  TexturedQuad floor = behind;
  floor.origin = {-5, 1, -3};
  floor.edge_u = {10, 0, 0};
  floor.edge_v = {0, 0, 13};
  const RenderResult r = renderer.Render({floor}, Pose::Identity());
  // Row v sees the floor at depth fy * 1 / (v - cy) for v > cy, nothing above the horizon
  // (rows 61-73 see beyond the far end at 10 m).
  for (int v : {80, 100, 119}) EXPECT_NEAR(r.depth.at<float>(v, 80), 128.0 / (v - 60.8), 1e-3) << v;
  EXPECT_EQ(r.depth.at<float>(40, 80), 0.0f);
}

TEST(Renderer, AlphaTexturesAreCutOut) {
  const Camera camera = SmallCamera();
  const Renderer renderer(camera);
  cv::Mat bgra(40, 40, CV_8UC4, cv::Scalar(10, 200, 30, 255));
  bgra(cv::Rect(0, 0, 20, 40)).setTo(cv::Scalar(0, 0, 0, 0));  // left half transparent
  TexturedQuad quad;
  quad.origin = {-0.5, -0.5, 1.0};
  quad.edge_u = {1, 0, 0};
  quad.edge_v = {0, 1, 0};
  quad.texture = MakeTexture(bgra, 1.0 / 40);
  quad.object_id = 1;
  const RenderResult r = renderer.Render({quad}, Pose::Identity());
  EXPECT_EQ(r.object_id.at<std::uint16_t>(60, 60), 0);   // x = -0.15 m: transparent half
  EXPECT_EQ(r.object_id.at<std::uint16_t>(60, 100), 1);  // x = +0.16 m: opaque half
}

// The number of pixels where two renders differ in colour, depth or object id.
int DifferingPixels(const RenderResult& a, const RenderResult& b) {
  cv::Mat colour;
  cv::absdiff(a.bgr, b.bgr, colour);
  std::vector<cv::Mat> channels;
  cv::split(colour, channels);
  return cv::countNonZero((channels[0] | channels[1] | channels[2]) | (a.depth != b.depth) |
                          (a.object_id != b.object_id));
}

TEST(Renderer, RowBandsAssembleTheFullRenderByteForByte) {
  Camera camera = SmallCamera();
  camera.distortion = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};  // TUM fr1: wider screen-box margins
  const Renderer renderer(camera);
  RoomOptions room;
  room.furniture = 4;
  room.texel_size_m = 0.02;
  const std::vector<TexturedQuad> quads = MakeRoomScene(room, 3);
  // Looking along the room's y axis (forward), tilted a little, from 1.3 m up.
  const Pose camera_from_world = PoseFromAxisAngle({-1.5, 0.1, 0.05}, {0.2, 0.3, 1.3}).inverse();
  const RenderResult full = renderer.Render(quads, camera_from_world);
  ASSERT_GT(cv::countNonZero(full.depth), 0.9 * full.depth.total());  // the room fills the view
  for (int bands : {2, 7, 16, camera.height}) {
    RenderResult assembled;
    for (int k = 0; k < bands; ++k)
      renderer.RenderRows(quads, camera_from_world, camera.height * k / bands, camera.height * (k + 1) / bands,
                          &assembled);
    EXPECT_EQ(DifferingPixels(assembled, full), 0) << bands << " bands";
  }
}

// The plain room is low texture: from the same place, FAST finds under a quarter of the
// textured room's corners, while its depth (the same geometry) is the same.
TEST(Renderer, ThePlainRoomHasFewCornersAndTheSameGeometry) {
  Camera camera;  // 640 x 480, where a tracker sees it
  const Renderer renderer(camera);
  const Pose camera_from_world = PoseFromAxisAngle({-1.5, 0.1, 0.05}, {0.2, 0.3, 1.3}).inverse();
  RoomOptions room;
  std::vector<cv::KeyPoint> corners[2];
  cv::Mat depth[2];
  for (int plain = 0; plain < 2; ++plain) {
    room.plain = plain == 1;
    const RenderResult render = renderer.Render(MakeRoomScene(room, 3), camera_from_world);
    cv::Mat grey;
    cv::cvtColor(render.bgr, grey, cv::COLOR_BGR2GRAY);
    cv::FAST(grey, corners[plain], 20);
    depth[plain] = render.depth;
  }
  EXPECT_GT(corners[0].size(), 1000u) << corners[1].size();
  EXPECT_LT(corners[1].size(), corners[0].size() / 4) << corners[1].size() << " against " << corners[0].size();
  EXPECT_EQ(cv::countNonZero(depth[0] != depth[1]), 0);
}

// Repeated walls: every full panel of every wall carries the same texture, so stretches of
// different walls look alike (false loop candidates); the usual walls all differ.
TEST(Renderer, RepeatedWallsArePaperedWithOnePanel) {
  const auto wall_textures = [](bool repeated) {
    RoomOptions room;
    room.repeated_walls = repeated;
    std::vector<cv::Mat> textures;
    for (const TexturedQuad& q : MakeRoomScene(room, 3))
      if (std::abs(q.edge_v.z() + room.height_m) < 1e-9 && std::abs(q.edge_u.z()) < 1e-9 &&
          std::abs(q.edge_u.norm() - (repeated ? 1.6 : q.edge_u.norm())) < 1e-9)
        textures.push_back(q.texture->levels[0]);
    return textures;
  };
  const std::vector<cv::Mat> panels = wall_textures(true);
  ASSERT_EQ(panels.size(), 16u);  // 4 panels on each of the 6.4 m and 7.0 m walls
  for (const cv::Mat& panel : panels) EXPECT_EQ(cv::norm(panel, panels[0], cv::NORM_INF), 0.0);
  const std::vector<cv::Mat> walls = wall_textures(false);
  ASSERT_EQ(walls.size(), 4u);
  EXPECT_GT(cv::norm(walls[0].colRange(0, 300), walls[2].colRange(0, 300), cv::NORM_L1), 0.0);
}

TEST(Renderer, RenderRowsWritesOnlyItsRowsAndRejectsBadRanges) {
  const Camera camera = SmallCamera();
  const Renderer renderer(camera);
  TexturedQuad wall;
  wall.origin = {-5, -5, 2.0};
  wall.edge_u = {10, 0, 0};
  wall.edge_v = {0, 10, 0};
  wall.texture = GradientTexture(64, 0.2);
  wall.object_id = 2;
  RenderResult result;
  renderer.RenderRows({wall}, Pose::Identity(), 30, 50, &result);
  ASSERT_EQ(result.depth.size(), cv::Size(camera.width, camera.height));
  EXPECT_EQ(cv::countNonZero(result.object_id == 2), 20 * camera.width);
  EXPECT_EQ(cv::countNonZero(result.object_id.rowRange(30, 50) == 2), 20 * camera.width);
  // Rows already drawn stay; the band drawn again shows the new scene (nothing here).
  renderer.RenderRows({}, Pose::Identity(), 40, 45, &result);
  EXPECT_EQ(cv::countNonZero(result.object_id == 2), 15 * camera.width);
  EXPECT_EQ(cv::countNonZero(result.depth.rowRange(40, 45)), 0);
  EXPECT_THROW(renderer.RenderRows({wall}, Pose::Identity(), -1, 10, &result), InputError);
  EXPECT_THROW(renderer.RenderRows({wall}, Pose::Identity(), 10, 10, &result), InputError);
  EXPECT_THROW(renderer.RenderRows({wall}, Pose::Identity(), 100, camera.height + 1, &result), InputError);
}

}  // namespace
}  // namespace dynvo
