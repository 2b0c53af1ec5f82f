#include "ego_motion/homography.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "core/config_registry.h"
#include "core/error.h"
#include "estimators/ransac.h"

namespace dynvo {
namespace {

using Vec2 = Eigen::Vector2d;
using Mat3 = Eigen::Matrix3d;
using Vec8 = Eigen::Matrix<double, 8, 1>;

void Require(bool condition, const std::string& message) {
  if (!condition) throw InputError(message);
}

// Similarity that moves the centroid to the origin and the mean distance to sqrt(2) (Hartley).
struct Normalisation {
  Vec2 centre = Vec2::Zero();
  double scale = 1.0;
  Mat3 Matrix() const {
    Mat3 t;
    t << scale, 0, -scale * centre.x(), 0, scale, -scale * centre.y(), 0, 0, 1;
    return t;
  }
};

Normalisation NormalisationOf(const std::vector<cv::Point2f>& points) {
  Normalisation n;
  if (points.empty()) return n;
  for (const auto& p : points) n.centre += Vec2(p.x, p.y);
  n.centre /= static_cast<double>(points.size());
  double mean_distance = 0.0;
  for (const auto& p : points) mean_distance += (Vec2(p.x, p.y) - n.centre).norm();
  mean_distance /= static_cast<double>(points.size());
  n.scale = mean_distance > 1e-12 ? std::sqrt(2.0) / mean_distance : 1.0;
  return n;
}

std::vector<Vec2> Apply(const Normalisation& n, const std::vector<cv::Point2f>& points) {
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(n.scale * (Vec2(p.x, p.y) - n.centre));
  return out;
}

// Squared transfer error of one correspondence, infinite when the point maps through infinity.
inline double TransferErrorSq(const Mat3& h, const Vec2& from, const Vec2& to) {
  const double w = h(2, 0) * from.x() + h(2, 1) * from.y() + h(2, 2);
  if (!(w > 1e-12)) return std::numeric_limits<double>::infinity();
  const double u = (h(0, 0) * from.x() + h(0, 1) * from.y() + h(0, 2)) / w;
  const double v = (h(1, 0) * from.x() + h(1, 1) * from.y() + h(1, 2)) / w;
  const double du = u - to.x(), dv = v - to.y();
  return du * du + dv * dv;
}

double Cross(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Minimal 4-point homography in normalised coordinates; false for collinear triples or a sample
// whose orientation flips between the images (impossible for a real camera motion).
bool MinimalHomography(const std::array<Vec2, 4>& from, const std::array<Vec2, 4>& to, Mat3* h) {
  static constexpr int kTriples[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  constexpr double kMinArea = 1e-3;  // normalised units: a few px^2 at 640x480
  for (const auto& t : kTriples) {
    const double a = Cross(from[t[0]], from[t[1]], from[t[2]]);
    const double b = Cross(to[t[0]], to[t[1]], to[t[2]]);
    if (std::abs(a) < kMinArea || std::abs(b) < kMinArea || (a > 0) != (b > 0)) return false;
  }
  Eigen::Matrix<double, 8, 8> a;
  Vec8 rhs;
  for (int i = 0; i < 4; ++i) {
    const double x = from[i].x(), y = from[i].y(), u = to[i].x(), v = to[i].y();
    a.row(2 * i) << x, y, 1, 0, 0, 0, -u * x, -u * y;
    a.row(2 * i + 1) << 0, 0, 0, x, y, 1, -v * x, -v * y;
    rhs(2 * i) = u;
    rhs(2 * i + 1) = v;
  }
  const Eigen::FullPivLU<Eigen::Matrix<double, 8, 8>> lu(a);
  if (!lu.isInvertible()) return false;
  const Vec8 p = lu.solve(rhs);
  if (!p.allFinite()) return false;
  *h << p(0), p(1), p(2), p(3), p(4), p(5), p(6), p(7), 1.0;
  return true;
}

// Normalised DLT over the given correspondences (normalised coordinates); H(2,2) = 1.
bool DltNormalised(const std::vector<Vec2>& from, const std::vector<Vec2>& to, const std::vector<int>& use, Mat3* h) {
  if (use.size() < 4) return false;
  Eigen::Matrix<double, 9, 9> ata = Eigen::Matrix<double, 9, 9>::Zero();
  Eigen::Matrix<double, 9, 1> r1, r2;
  for (int i : use) {
    const double x = from[i].x(), y = from[i].y(), u = to[i].x(), v = to[i].y();
    r1 << x, y, 1, 0, 0, 0, -u * x, -u * y, -u;
    r2 << 0, 0, 0, x, y, 1, -v * x, -v * y, -v;
    ata.noalias() += r1 * r1.transpose() + r2 * r2.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> solver(ata);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::VectorXd& values = solver.eigenvalues();
  // A second (near) null vector means the points do not pin H down.
  if (values(1) <= 1e-12 * std::max(values(8), 1e-300)) return false;
  const Eigen::Matrix<double, 9, 1> p = solver.eigenvectors().col(0);
  if (std::abs(p(8)) < 1e-12) return false;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) (*h)(r, c) = p(3 * r + c) / p(8);
  return h->allFinite();
}

double CostNormalised(const std::vector<Vec2>& from, const std::vector<Vec2>& to, const std::vector<int>& use,
                      const Mat3& h) {
  double cost = 0.0;
  for (int i : use) cost += TransferErrorSq(h, from[i], to[i]);
  return cost;
}

// LM on the 8 free entries of a normalised H (H(2,2) = 1), eq. 4. Returns the final cost.
double RefineNormalised(const std::vector<Vec2>& from, const std::vector<Vec2>& to, const std::vector<int>& use,
                        int max_iterations, Mat3* h) {
  double cost = CostNormalised(from, to, use, *h);
  if (!std::isfinite(cost) || use.size() < 4) return cost;
  double lambda = 1e-3;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    Eigen::Matrix<double, 8, 8> jtj = Eigen::Matrix<double, 8, 8>::Zero();
    Vec8 jtr = Vec8::Zero();
    Vec8 jx, jy;
    const Mat3& m = *h;
    for (int i : use) {
      const double x = from[i].x(), y = from[i].y();
      const double w = m(2, 0) * x + m(2, 1) * y + 1.0;
      const double px = (m(0, 0) * x + m(0, 1) * y + m(0, 2)) / w;
      const double py = (m(1, 0) * x + m(1, 1) * y + m(1, 2)) / w;
      const double rx = px - to[i].x(), ry = py - to[i].y();
      const double iw = 1.0 / w;
      jx << x * iw, y * iw, iw, 0, 0, 0, -px * x * iw, -px * y * iw;
      jy << 0, 0, 0, x * iw, y * iw, iw, -py * x * iw, -py * y * iw;
      jtj.noalias() += jx * jx.transpose() + jy * jy.transpose();
      jtr.noalias() += jx * rx + jy * ry;
    }
    bool improved = false;
    while (lambda < 1e16) {
      Eigen::Matrix<double, 8, 8> damped = jtj;
      damped.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-12);
      const Vec8 step = damped.ldlt().solve(-jtr);
      Mat3 candidate = m;
      for (int k = 0; k < 8; ++k) candidate(k / 3, k % 3) += step(k);
      const double candidate_cost = CostNormalised(from, to, use, candidate);
      if (step.allFinite() && candidate_cost < cost) {
        const double decrease = cost - candidate_cost;
        *h = candidate;
        cost = candidate_cost;
        lambda = std::max(lambda * 0.3, 1e-12);
        improved = decrease > 1e-14 * std::max(cost, 1e-30);
        break;
      }
      lambda *= 10.0;
    }
    if (!improved) break;
  }
  return cost;
}

// H in pixels from a normalised one, scaled so that H(2,2) = 1; false when that is impossible.
bool Denormalise(const Mat3& normalised, const Normalisation& from, const Normalisation& to, Mat3* h) {
  Mat3 pixel = to.Matrix().inverse() * normalised * from.Matrix();
  if (!pixel.allFinite() || std::abs(pixel(2, 2)) < 1e-12) return false;
  *h = pixel / pixel(2, 2);
  return true;
}

// A real frame-to-frame motion keeps the points' bounding box in front (w > 0), convex and
// with its orientation.
bool PlausibleHomography(const Mat3& h, const std::vector<cv::Point2f>& points, const std::vector<int>& use) {
  if (!h.allFinite()) return false;
  double min_x = std::numeric_limits<double>::max(), min_y = min_x, max_x = -min_x, max_y = -min_x;
  for (int i : use) {
    min_x = std::min(min_x, static_cast<double>(points[i].x));
    max_x = std::max(max_x, static_cast<double>(points[i].x));
    min_y = std::min(min_y, static_cast<double>(points[i].y));
    max_y = std::max(max_y, static_cast<double>(points[i].y));
  }
  const std::array<Vec2, 4> corners = {Vec2(min_x, min_y), Vec2(max_x, min_y), Vec2(max_x, max_y), Vec2(min_x, max_y)};
  std::array<Vec2, 4> mapped;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d q = h * corners[k].homogeneous();
    if (!(q.z() > 1e-9)) return false;
    mapped[k] = q.hnormalized();
  }
  for (int k = 0; k < 4; ++k) {
    const double turn = Cross(mapped[k], mapped[(k + 1) % 4], mapped[(k + 2) % 4]);
    if (!(turn > 0.0)) return false;  // the identity gives positive turns for this corner order
  }
  return true;
}

std::vector<int> AllIndices(size_t n) {
  std::vector<int> all(n);
  for (size_t i = 0; i < n; ++i) all[i] = static_cast<int>(i);
  return all;
}

// The homography as a RANSAC estimator (estimators/ransac.h), in normalised coordinates: the
// minimal 4-point solution; no refit inside the loop (the caller refits and refines the best).
struct NormalisedHomographyEstimator {
  using Model = Mat3;
  static constexpr int kMinSamples = 4;
  std::vector<Vec2> from, to;

  bool Estimate(const std::vector<int>& sample, Mat3* h) const {
    std::array<Vec2, 4> a, b;
    for (int k = 0; k < 4; ++k) {
      a[k] = from[sample[k]];
      b[k] = to[sample[k]];
    }
    return MinimalHomography(a, b, h);
  }
  void Residuals(const Mat3& h, std::vector<double>* squared) const {
    squared->resize(from.size());
    for (size_t i = 0; i < from.size(); ++i) (*squared)[i] = TransferErrorSq(h, from[i], to[i]);
  }
  bool Refit(const std::vector<int>&, Mat3*) const { return false; }
  std::vector<int> InliersOf(const Mat3& h, double threshold) const {
    std::vector<int> inliers;
    for (size_t i = 0; i < from.size(); ++i)
      if (TransferErrorSq(h, from[i], to[i]) < threshold * threshold) inliers.push_back(static_cast<int>(i));
    return inliers;
  }
};

// The RANSAC model re-fitted on all its inliers (algebraic; kept when it has as many), then
// refined on the reprojection error (eq. 4). Returns the inliers of the final `*h`.
std::vector<int> PolishOnInliers(const NormalisedHomographyEstimator& e, double threshold,
                                 const HomographyOptions& options, Mat3* h) {
  std::vector<int> inliers = e.InliersOf(*h, threshold);
  Mat3 fitted;
  if (DltNormalised(e.from, e.to, inliers, &fitted)) {
    std::vector<int> refit_inliers = e.InliersOf(fitted, threshold);
    if (refit_inliers.size() >= inliers.size()) {
      *h = fitted;
      inliers.swap(refit_inliers);
    }
  }
  if (options.refine && options.refine_iterations > 0) {
    RefineNormalised(e.from, e.to, inliers, options.refine_iterations, h);
    inliers = e.InliersOf(*h, threshold);
  }
  return inliers;
}

}  // namespace

void HomographyOptions::Check() const {
  Require(ransac_threshold_px > 0.0,
          "homography.ransac_threshold_px must be > 0, got " + std::to_string(ransac_threshold_px));
  Require(ransac_iterations >= 1,
          "homography.ransac_iterations must be >= 1, got " + std::to_string(ransac_iterations));
  Require(ransac_confidence > 0.0 && ransac_confidence <= 1.0,
          "homography.ransac_confidence must be in (0, 1], got " + std::to_string(ransac_confidence));
  Require(min_inliers >= 4, "homography.min_inliers must be >= 4, got " + std::to_string(min_inliers));
  Require(refine_iterations >= 0,
          "homography.refine_iterations must be >= 0, got " + std::to_string(refine_iterations));
}

double HomographyRmsError(const std::vector<cv::Point2f>& previous, const std::vector<cv::Point2f>& current,
                          const Eigen::Matrix3d& current_from_previous) {
  Require(previous.size() == current.size(), "HomographyRmsError: point lists differ in length");
  if (previous.empty()) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < previous.size(); ++i)
    sum += TransferErrorSq(current_from_previous, Vec2(previous[i].x, previous[i].y), Vec2(current[i].x, current[i].y));
  return std::sqrt(sum / static_cast<double>(previous.size()));
}

bool FitHomographyDlt(const std::vector<cv::Point2f>& previous, const std::vector<cv::Point2f>& current,
                      Eigen::Matrix3d* current_from_previous) {
  Require(previous.size() == current.size(), "FitHomographyDlt: point lists differ in length");
  if (previous.size() < 4) return false;
  const Normalisation np = NormalisationOf(previous), nc = NormalisationOf(current);
  Mat3 normalised;
  if (!DltNormalised(Apply(np, previous), Apply(nc, current), AllIndices(previous.size()), &normalised)) return false;
  return Denormalise(normalised, np, nc, current_from_previous);
}

double RefineHomography(const std::vector<cv::Point2f>& previous, const std::vector<cv::Point2f>& current,
                        int max_iterations, Eigen::Matrix3d* current_from_previous) {
  Require(previous.size() == current.size(), "RefineHomography: point lists differ in length");
  const Normalisation np = NormalisationOf(previous), nc = NormalisationOf(current);
  Mat3 normalised = nc.Matrix() * (*current_from_previous) * np.Matrix().inverse();
  if (std::abs(normalised(2, 2)) > 1e-12) {
    normalised /= normalised(2, 2);
    RefineNormalised(Apply(np, previous), Apply(nc, current), AllIndices(previous.size()), max_iterations, &normalised);
    Mat3 refined;
    if (Denormalise(normalised, np, nc, &refined) &&
        HomographyRmsError(previous, current, refined) <= HomographyRmsError(previous, current, *current_from_previous))
      *current_from_previous = refined;
  }
  return HomographyRmsError(previous, current, *current_from_previous);
}

HomographyEstimate EstimateHomography(const std::vector<cv::Point2f>& previous, const std::vector<cv::Point2f>& current,
                                      const HomographyOptions& options) {
  options.Check();
  Require(previous.size() == current.size(), "EstimateHomography: " + std::to_string(previous.size()) +
                                                 " previous points but " + std::to_string(current.size()) +
                                                 " current points");
  HomographyEstimate estimate;
  const int n = static_cast<int>(previous.size());
  estimate.inliers.assign(previous.size(), 0);
  if (n < options.min_inliers || n < 4) {
    estimate.failure = "too few tracks (" + std::to_string(n) + " < " + std::to_string(options.min_inliers) + ")";
    return estimate;
  }
  const Normalisation np = NormalisationOf(previous), nc = NormalisationOf(current);
  const NormalisedHomographyEstimator estimator{Apply(np, previous), Apply(nc, current)};
  RansacOptions ransac;
  ransac.max_error = options.ransac_threshold_px * nc.scale;  // errors are in normalised units
  ransac.confidence = options.ransac_confidence;
  ransac.max_iterations = options.ransac_iterations;
  ransac.seed = options.seed;
  const RansacResult<Mat3> found = RunRansac(estimator, n, ransac);
  if (!found.found) {
    estimate.failure = "degenerate point configuration (no non-collinear sample)";
    return estimate;
  }
  if (found.num_inliers < options.min_inliers) {
    estimate.failure =
        "too few inliers (" + std::to_string(found.num_inliers) + " < " + std::to_string(options.min_inliers) + ")";
    return estimate;
  }
  Mat3 best = found.model;
  const std::vector<int> inliers = PolishOnInliers(estimator, ransac.max_error, options, &best);
  Mat3 h_pixel;
  if (!Denormalise(best, np, nc, &h_pixel) || !PlausibleHomography(h_pixel, previous, inliers)) {
    estimate.failure = "degenerate homography";
    return estimate;
  }
  if (static_cast<int>(inliers.size()) < options.min_inliers) {
    estimate.failure =
        "too few inliers (" + std::to_string(inliers.size()) + " < " + std::to_string(options.min_inliers) + ")";
    return estimate;
  }
  estimate.ok = true;
  estimate.current_from_previous = h_pixel;
  estimate.num_inliers = static_cast<int>(inliers.size());
  double sum = 0.0;
  for (int i : inliers) {
    estimate.inliers[i] = 1;
    sum += TransferErrorSq(h_pixel, Vec2(previous[i].x, previous[i].y), Vec2(current[i].x, current[i].y));
  }
  estimate.rms_error_px = std::sqrt(sum / std::max<size_t>(inliers.size(), 1));
  return estimate;
}

void BindConfigKeys(const std::string& prefix, HomographyOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".seed", &o->seed, "homography RANSAC random seed");
}

}  // namespace dynvo
