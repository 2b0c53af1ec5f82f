#include "detection/yolo_detector.h"

#include <algorithm>
#include <fstream>

#include "core/error.h"

namespace dynvo {
namespace {

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void RequireReadableFile(const std::string& path, const std::string& key) {
  if (path.empty()) throw InputError(key + ": no file given");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(key + " " + path + ": cannot open the file");
}

// The candidates as rows (N x (fields)), whatever the tensor's layout.
cv::Mat CandidateRows(const cv::Mat& output, YoloLayout layout) {
  if (layout == YoloLayout::kDarknetRegion && output.dims == 2) return output;
  if (output.dims != 3 || output.size[0] != 1)
    throw InputError("detector output: expected a 1 x A x B tensor, got " + std::to_string(output.dims) + " dims");
  const cv::Mat plane(output.size[1], output.size[2], CV_32F, const_cast<uchar*>(output.ptr()));
  if (layout == YoloLayout::kColumns) return plane.t();
  return plane;
}

}  // namespace

std::vector<Detection> DecodeYoloOutput(const cv::Mat& output, YoloLayout layout, cv::Size image, int input_size,
                                        const DetectorOptions& options) {
  if (output.type() != CV_32F) throw InputError("detector output: expected 32-bit floats");
  const cv::Mat rows = CandidateRows(output, layout);
  const int first_class = layout == YoloLayout::kColumns ? 4 : 5;
  if (rows.cols <= first_class) throw InputError("detector output: rows too short for boxes and class scores");
  // Box coordinates to image pixels: relative (Darknet) or in the square input's pixels.
  const double unit = layout == YoloLayout::kDarknetRegion ? 1.0 : static_cast<double>(input_size);
  const double sx = image.width / unit, sy = image.height / unit;
  const cv::Rect2d frame(0, 0, image.width, image.height);
  std::vector<Detection> found;
  for (int r = 0; r < rows.rows; ++r) {
    const float* row = rows.ptr<float>(r);
    const float* scores = row + first_class;
    const int best = static_cast<int>(std::max_element(scores, row + rows.cols) - scores);
    double score = scores[best];
    if (layout == YoloLayout::kRows) score *= row[4];
    if (score < options.confidence) continue;
    if (std::find(options.classes.begin(), options.classes.end(), best) == options.classes.end()) continue;
    const double w = row[2] * sx, h = row[3] * sy;
    const cv::Rect2d box = cv::Rect2d(row[0] * sx - w / 2, row[1] * sy - h / 2, w, h) & frame;
    if (box.area() <= 0.0) continue;
    found.push_back({box, score, best});
  }
  return found;
}

std::vector<Detection> SuppressOverlaps(const std::vector<Detection>& candidates, const DetectorOptions& options) {
  std::vector<Detection> result;
  for (const int class_id : options.classes) {  // NMS within each class
    std::vector<cv::Rect2d> boxes;
    std::vector<float> scores;
    std::vector<size_t> index;
    for (size_t i = 0; i < candidates.size(); ++i) {
      if (candidates[i].class_id != class_id) continue;
      boxes.push_back(candidates[i].box);
      scores.push_back(static_cast<float>(candidates[i].score));
      index.push_back(i);
    }
    std::vector<int> kept;
    cv::dnn::NMSBoxes(boxes, scores, 0.0f, static_cast<float>(options.nms_threshold), kept);
    for (const int k : kept) result.push_back(candidates[index[static_cast<size_t>(k)]]);
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const Detection& a, const Detection& b) { return a.score > b.score; });
  return result;
}

YoloDetector::YoloDetector(const DetectorOptions& options) : options_(options) {
  options_.Check();
  RequireReadableFile(options_.model, "detector.model");
  try {
    if (EndsWith(options_.model, ".onnx")) {
      net_ = cv::dnn::readNetFromONNX(options_.model);
      // YOLOv8 exports put the candidates in columns; YOLOv5 in rows (decided on the first output).
      layout_ = YoloLayout::kRows;
    } else if (EndsWith(options_.model, ".weights")) {
      RequireReadableFile(options_.config, "detector.config");
      net_ = cv::dnn::readNetFromDarknet(options_.config, options_.model);
      layout_ = YoloLayout::kDarknetRegion;
    } else {
      throw InputError("detector.model " + options_.model + ": expected a Darknet .weights or an .onnx file");
    }
  } catch (const cv::Exception& e) {
    throw InputError("detector.model " + options_.model + ": OpenCV cannot load it: " + e.err);
  }
  if (net_.empty()) throw InputError("detector.model " + options_.model + ": OpenCV loaded an empty network");
  net_.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net_.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  output_names_ = net_.getUnconnectedOutLayersNames();
}

std::vector<Detection> YoloDetector::Detect(const cv::Mat& bgr) {
  if (bgr.empty() || bgr.type() != CV_8UC3) throw InputError("detector: expected a CV_8UC3 BGR image");
  const cv::Mat blob = cv::dnn::blobFromImage(bgr, 1.0 / 255.0, cv::Size(options_.input_size, options_.input_size),
                                              cv::Scalar(), /*swapRB=*/true, /*crop=*/false);
  std::vector<cv::Mat> outputs;
  try {
    net_.setInput(blob);
    net_.forward(outputs, output_names_);
  } catch (const cv::Exception& e) {
    throw InputError("detector.model " + options_.model + ": inference failed: " + e.err);
  }
  std::vector<Detection> candidates;
  for (const cv::Mat& output : outputs) {
    YoloLayout layout = layout_;
    if (layout == YoloLayout::kRows && output.dims == 3 && output.size[1] < output.size[2])
      layout = YoloLayout::kColumns;
    const std::vector<Detection> found = DecodeYoloOutput(output, layout, bgr.size(), options_.input_size, options_);
    candidates.insert(candidates.end(), found.begin(), found.end());
  }
  return SuppressOverlaps(candidates, options_);
}

}  // namespace dynvo
