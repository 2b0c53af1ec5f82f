#include "loop/static_map.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <tuple>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "core/output_file.h"

namespace dynvo {

void StaticMapOptions::Check() const {
  RequireOption(voxel_m > 0.0, "map", "voxel_m", "> 0", voxel_m);
  RequireOption(pixel_step >= 1, "map", "pixel_step", ">= 1", pixel_step);
  RequireOption(max_depth_m > 0.0, "map", "max_depth_m", "> 0", max_depth_m);
  RequireOption(mask_margin_px >= 0, "map", "mask_margin_px", ">= 0", mask_margin_px);
  RequireOption(min_observations >= 1, "map", "min_observations", ">= 1", min_observations);
}

KeyframeMapSample SampleKeyframe(const cv::Mat& bgr, const cv::Mat& depth, const cv::Mat& excluded,
                                 const Camera& camera, const StaticMapOptions& options) {
  options.Check();
  cv::Mat grown;
  if (!excluded.empty() && options.mask_margin_px > 0)
    cv::dilate(excluded, grown,
               cv::getStructuringElement(cv::MORPH_ELLIPSE,
                                         cv::Size(2 * options.mask_margin_px + 1, 2 * options.mask_margin_px + 1)));
  else
    grown = excluded;
  KeyframeMapSample sample;
  for (int v = options.pixel_step / 2; v < depth.rows; v += options.pixel_step)
    for (int u = options.pixel_step / 2; u < depth.cols; u += options.pixel_step) {
      const float z = depth.at<float>(v, u);
      if (!(z > 0.0f) || z > options.max_depth_m || (!grown.empty() && grown.at<uint8_t>(v, u) != 0)) continue;
      sample.points_in_camera.push_back(camera.Backproject(Eigen::Vector2d(u, v), z).cast<float>());
      sample.colours.push_back(bgr.at<cv::Vec3b>(v, u));
    }
  return sample;
}

namespace {

struct Voxel {
  Eigen::Vector3d position_sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d colour_sum = Eigen::Vector3d::Zero();
  int samples = 0;
  int observations = 0;
  int last_keyframe = -1;
};

}  // namespace

StaticMap BuildStaticMap(const std::vector<KeyframeMapSample>& samples, const std::vector<Pose>& world_from_camera,
                         const StaticMapOptions& options) {
  options.Check();
  if (samples.size() != world_from_camera.size())
    throw InputError("BuildStaticMap: " + std::to_string(samples.size()) + " samples but " +
                     std::to_string(world_from_camera.size()) + " poses");
  std::map<std::tuple<int, int, int>, Voxel> grid;  // ordered: the map comes out the same every time
  for (size_t k = 0; k < samples.size(); ++k) {
    const Eigen::Isometry3f pose = world_from_camera[k].cast<float>();
    for (size_t i = 0; i < samples[k].points_in_camera.size(); ++i) {
      const Eigen::Vector3f p = pose * samples[k].points_in_camera[i];
      const auto key = std::make_tuple(static_cast<int>(std::floor(p.x() / options.voxel_m)),
                                       static_cast<int>(std::floor(p.y() / options.voxel_m)),
                                       static_cast<int>(std::floor(p.z() / options.voxel_m)));
      Voxel& voxel = grid[key];
      voxel.position_sum += p.cast<double>();
      const cv::Vec3b& c = samples[k].colours[i];
      voxel.colour_sum += Eigen::Vector3d(c[0], c[1], c[2]);
      ++voxel.samples;
      if (voxel.last_keyframe != static_cast<int>(k)) {
        voxel.last_keyframe = static_cast<int>(k);
        ++voxel.observations;
      }
    }
  }
  StaticMap map;
  for (const auto& [key, voxel] : grid) {
    if (voxel.observations < options.min_observations) continue;
    map.points.push_back((voxel.position_sum / voxel.samples).cast<float>());
    const Eigen::Vector3d colour = voxel.colour_sum / voxel.samples;
    map.colours.emplace_back(cv::saturate_cast<uint8_t>(colour.x()), cv::saturate_cast<uint8_t>(colour.y()),
                             cv::saturate_cast<uint8_t>(colour.z()));
    map.observations.push_back(voxel.observations);
  }
  return map;
}

void WriteMapPly(const std::string& path, const StaticMap& map) {
  std::string data =
      "ply\nformat binary_little_endian 1.0\ncomment dynvo static map (world = first camera frame)\n"
      "element vertex " +
      std::to_string(map.points.size()) +
      "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
      "property uchar green\nproperty uchar blue\nproperty int observations\nend_header\n";
  const size_t header = data.size();
  constexpr size_t kVertexBytes = 3 * sizeof(float) + 3 + sizeof(int32_t);
  data.resize(header + kVertexBytes * map.points.size());
  char* out = data.data() + header;  // x86 and ARM Linux are little-endian, as the header says
  for (size_t i = 0; i < map.points.size(); ++i, out += kVertexBytes) {
    std::memcpy(out, map.points[i].data(), 3 * sizeof(float));
    const cv::Vec3b& bgr = map.colours[i];
    const uint8_t rgb[3] = {bgr[2], bgr[1], bgr[0]};
    std::memcpy(out + 12, rgb, 3);
    const int32_t observations = map.observations[i];
    std::memcpy(out + 15, &observations, sizeof(observations));
  }
  WriteFileAtomically(path, data);
}

StaticMap ReadMapPly(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file");
  std::string line;
  size_t vertices = 0;
  bool binary = false, ended = false;
  while (std::getline(in, line)) {
    if (line.rfind("element vertex ", 0) == 0) vertices = std::stoul(line.substr(15));
    binary = binary || line == "format binary_little_endian 1.0";
    if ((ended = line == "end_header")) break;
  }
  if (!ended || !binary) throw InputError(path + ": not a binary little-endian PLY written by dynvo");
  StaticMap map;
  char vertex[19];
  for (size_t i = 0; i < vertices && in.read(vertex, sizeof(vertex)); ++i) {
    Eigen::Vector3f p;
    std::memcpy(p.data(), vertex, 12);
    map.points.push_back(p);
    map.colours.emplace_back(static_cast<uint8_t>(vertex[14]), static_cast<uint8_t>(vertex[13]),
                             static_cast<uint8_t>(vertex[12]));
    int32_t observations;
    std::memcpy(&observations, vertex + 15, 4);
    map.observations.push_back(observations);
  }
  if (map.points.size() != vertices)
    throw InputError(path + ": " + std::to_string(vertices) + " points declared, " + std::to_string(map.points.size()) +
                     " found");
  return map;
}

void WriteMapTopView(const std::string& path, const StaticMap& map) {
  constexpr double kMetresPerPixel = 0.02;
  constexpr int kMaxSide = 2000;
  float min_x = 0, max_x = 0, min_z = 0, max_z = 0;
  for (size_t i = 0; i < map.points.size(); ++i) {
    const Eigen::Vector3f& p = map.points[i];
    min_x = i == 0 ? p.x() : std::min(min_x, p.x());
    max_x = i == 0 ? p.x() : std::max(max_x, p.x());
    min_z = i == 0 ? p.z() : std::min(min_z, p.z());
    max_z = i == 0 ? p.z() : std::max(max_z, p.z());
  }
  const double scale =
      std::max({kMetresPerPixel, (max_x - min_x) / (kMaxSide - 1.0), (max_z - min_z) / (kMaxSide - 1.0)});
  const int width = static_cast<int>((max_x - min_x) / scale) + 1,
            height = static_cast<int>((max_z - min_z) / scale) + 1;
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::Mat top(height, width, CV_32FC1, cv::Scalar(std::numeric_limits<float>::max()));
  for (size_t i = 0; i < map.points.size(); ++i) {
    const Eigen::Vector3f& p = map.points[i];
    const int col = static_cast<int>((p.x() - min_x) / scale),
              row = height - 1 - static_cast<int>((p.z() - min_z) / scale);
    if (p.y() >= top.at<float>(row, col)) continue;  // y points down: the smallest is the highest
    top.at<float>(row, col) = p.y();
    image.at<cv::Vec3b>(row, col) = map.colours[i];
  }
  std::vector<uchar> png;
  if (!cv::imencode(".png", image, png)) throw InputError(path + ": cannot encode the map's top view");
  WriteFileAtomically(path, std::string(png.begin(), png.end()));
}

}  // namespace dynvo
