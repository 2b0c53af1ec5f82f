#include "synth/procedural_texture.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

using Rng = std::mt19937;

double Uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
int UniformInt(Rng& rng, int lo, int hi) {  // inclusive; lo when the range is empty
  return std::uniform_int_distribution<int>(lo, std::max(lo, hi))(rng);
}

cv::Scalar RandomColor(Rng& rng, double lo = 20, double hi = 235) {
  return cv::Scalar(Uniform(rng, lo, hi), Uniform(rng, lo, hi), Uniform(rng, lo, hi));
}

// Sum of value noise at octaves from `coarsest` texels down to 2 texels, in [-1, 1] roughly.
cv::Mat FractalNoise(int width, int height, double coarsest, Rng& rng) {
  cv::Mat sum(height, width, CV_32F, cv::Scalar(0));
  double amplitude = 1.0, total = 0.0;
  for (double cell = coarsest; cell >= 2.0; cell /= 2.0) {
    const int gw = std::max(2, static_cast<int>(width / cell) + 2);
    const int gh = std::max(2, static_cast<int>(height / cell) + 2);
    cv::Mat grid(gh, gw, CV_32F);
    for (int y = 0; y < gh; ++y)
      for (int x = 0; x < gw; ++x) grid.at<float>(y, x) = static_cast<float>(Uniform(rng, -1, 1));
    cv::Mat up;
    cv::resize(grid, up, cv::Size(width, height), 0, 0, cv::INTER_CUBIC);
    sum += up * amplitude;
    total += amplitude;
    amplitude *= 0.6;
  }
  return sum / total;
}

// Adds signed noise (scaled by `strength` grey levels) to every channel.
void AddNoise(cv::Mat& image, const cv::Mat& noise, double strength) {
  cv::Mat n3;
  cv::Mat channels[3] = {noise, noise, noise};
  cv::merge(channels, 3, n3);
  cv::Mat f;
  image.convertTo(f, CV_32FC3);
  f += n3 * strength;
  f.convertTo(image, CV_8UC3);
}

void RandomText(cv::Mat& image, Rng& rng, int count, double scale_lo, double scale_hi) {
  static const char* kWords[] = {"DYNVO", "EXIT",     "LAB 3", "TUM",  "RGB-D", "FRAGILE", "42",
                                 "NO 7",  "KEEP DRY", "A-113", "BOOK", "MAP",   "2012",    "XYZ"};
  for (int i = 0; i < count; ++i) {
    const std::string word = kWords[UniformInt(rng, 0, 13)];
    const cv::Point at(UniformInt(rng, 0, std::max(1, image.cols - 20)),
                       UniformInt(rng, 10, std::max(11, image.rows - 2)));
    const double scale = Uniform(rng, scale_lo, scale_hi);
    cv::putText(image, word, at, cv::FONT_HERSHEY_SIMPLEX, scale, RandomColor(rng, 0, 255),
                std::max(1, static_cast<int>(scale * 2)), cv::LINE_AA);
  }
}

// A framed picture or poster: nested rectangles, circles and lines at mixed scales.
void Poster(cv::Mat& image, cv::Rect box, Rng& rng) {
  box &= cv::Rect(0, 0, image.cols, image.rows);
  if (box.width < 8 || box.height < 8) return;
  cv::Mat roi = image(box);
  roi.setTo(RandomColor(rng));
  const int shapes = UniformInt(rng, 6, 18);
  for (int i = 0; i < shapes; ++i) {
    const cv::Point c(UniformInt(rng, 0, box.width - 1), UniformInt(rng, 0, box.height - 1));
    const int r = UniformInt(rng, 3, std::max(4, std::min(box.width, box.height) / 3));
    switch (UniformInt(rng, 0, 2)) {
      case 0:
        cv::circle(roi, c, r, RandomColor(rng), -1, cv::LINE_AA);
        break;
      case 1:
        cv::rectangle(roi, cv::Rect(c.x - r, c.y - r / 2, 2 * r, r), RandomColor(rng), -1);
        break;
      default: {
        const cv::Point d(UniformInt(rng, 0, box.width - 1), UniformInt(rng, 0, box.height - 1));
        cv::line(roi, c, d, RandomColor(rng), UniformInt(rng, 1, 4), cv::LINE_AA);
      }
    }
  }
  RandomText(roi, rng, UniformInt(rng, 0, 2), 0.4, 1.2);
  cv::rectangle(image, box, cv::Scalar(30, 30, 30), std::max(2, box.width / 40));
}

cv::Mat Wall(int w, int h, Rng& rng) {
  cv::Mat image(h, w, CV_8UC3, RandomColor(rng, 150, 225));
  AddNoise(image, FractalNoise(w, h, 256, rng), 14);
  // Posters and pictures of several sizes.
  const int posters = std::max(3, w * h / 60000);
  for (int i = 0; i < posters; ++i) {
    const int pw = UniformInt(rng, 30, std::max(31, w / 4));
    const int ph = UniformInt(rng, 30, std::max(31, h / 3));
    Poster(image, cv::Rect(UniformInt(rng, 0, w - 1), UniformInt(rng, 0, h - 1), pw, ph), rng);
  }
  // Cables, skirting and outlet-like small items.
  cv::rectangle(image, cv::Rect(0, h - h / 25, w, h / 25), RandomColor(rng, 40, 120), -1);
  for (int i = 0; i < w / 60; ++i) {
    const cv::Point p(UniformInt(rng, 0, w), UniformInt(rng, h / 2, h));
    cv::rectangle(image, cv::Rect(p.x, p.y, 14, 20), cv::Scalar(235, 235, 235), -1);
    cv::rectangle(image, cv::Rect(p.x, p.y, 14, 20), cv::Scalar(60, 60, 60), 1);
  }
  AddNoise(image, FractalNoise(w, h, 8, rng), 6);
  return image;
}

// One colour with soft large-scale shading and faint grain: what a corner detector hardly
// finds anything in, away from the surface's edges.
cv::Mat Paint(int w, int h, Rng& rng) {
  cv::Mat image(h, w, CV_8UC3, RandomColor(rng, 60, 225));
  AddNoise(image, FractalNoise(w, h, 256, rng), 6);
  AddNoise(image, FractalNoise(w, h, 4, rng), 1.5);
  return image;
}

cv::Mat Floor(int w, int h, Rng& rng) {
  cv::Mat image(h, w, CV_8UC3);
  const bool tiles = UniformInt(rng, 0, 1) == 0;
  const cv::Scalar base = RandomColor(rng, 70, 170);
  if (tiles) {
    const int tile = UniformInt(rng, 50, 90);
    for (int y = 0; y < h; y += tile)
      for (int x = 0; x < w; x += tile) {
        cv::Scalar c = base + cv::Scalar::all(Uniform(rng, -35, 35));
        cv::rectangle(image, cv::Rect(x, y, tile, tile), c, -1);
        cv::rectangle(image, cv::Rect(x, y, tile, tile), base * 0.5, 2);
      }
  } else {
    const int plank = UniformInt(rng, 30, 45);
    for (int y = 0; y < h; y += plank) {
      int x = -UniformInt(rng, 0, 300);
      while (x < w) {
        const int len = UniformInt(rng, 150, 400);
        cv::rectangle(image, cv::Rect(x, y, len, plank), base + cv::Scalar::all(Uniform(rng, -30, 30)), -1);
        cv::line(image, {x, y}, {x, y + plank}, base * 0.4, 2);
        x += len;
      }
      cv::line(image, {0, y}, {w, y}, base * 0.4, 2);
    }
  }
  AddNoise(image, FractalNoise(w, h, 128, rng), 18);
  // Rugs, stains and scattered papers.
  for (int i = 0; i < std::max(4, w * h / 150000); ++i) {
    const cv::Point c(UniformInt(rng, 0, w), UniformInt(rng, 0, h));
    if (UniformInt(rng, 0, 2) == 0) {
      cv::ellipse(image, c, cv::Size(UniformInt(rng, 10, 60), UniformInt(rng, 10, 40)), Uniform(rng, 0, 180), 0, 360,
                  base * Uniform(rng, 0.5, 0.9), -1, cv::LINE_AA);
    } else {
      const cv::RotatedRect paper(c, cv::Size2f(UniformInt(rng, 40, 70), UniformInt(rng, 55, 90)),
                                  static_cast<float>(Uniform(rng, 0, 180)));
      cv::Point2f pts[4];
      paper.points(pts);
      std::vector<cv::Point> poly(pts, pts + 4);
      cv::fillConvexPoly(image, poly, cv::Scalar(240, 240, 235), cv::LINE_AA);
    }
  }
  AddNoise(image, FractalNoise(w, h, 4, rng), 8);
  return image;
}

cv::Mat Wood(int w, int h, Rng& rng) {
  const cv::Scalar base = cv::Scalar(Uniform(rng, 40, 90), Uniform(rng, 80, 140), Uniform(rng, 120, 190));
  cv::Mat grain = FractalNoise(w, h, 64, rng);
  cv::Mat image(h, w, CV_8UC3);
  const double rings = Uniform(rng, 0.05, 0.12);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double v = std::sin((y + 40.0 * grain.at<float>(y, x)) * rings * 2.0 * CV_PI);
      const double f = 0.8 + 0.2 * v;
      image.at<cv::Vec3b>(y, x) =
          cv::Vec3b(cv::saturate_cast<uchar>(base[0] * f), cv::saturate_cast<uchar>(base[1] * f),
                    cv::saturate_cast<uchar>(base[2] * f));
    }
  // Things lying on the desk: papers, books, a keyboard-like grid, cups.
  for (int i = 0; i < std::max(3, w * h / 40000); ++i) {
    const int pw = UniformInt(rng, 30, std::max(31, w / 3)), ph = UniformInt(rng, 30, std::max(31, h / 2));
    const cv::Rect r(UniformInt(rng, 0, w - 10), UniformInt(rng, 0, h - 10), pw, ph);
    switch (UniformInt(rng, 0, 3)) {
      case 0: {
        cv::rectangle(image, r, cv::Scalar(245, 245, 245), -1);
        for (int yy = r.y + 8; yy < r.y + r.height - 4; yy += 7)
          cv::line(image, {r.x + 5, yy}, {r.x + r.width - UniformInt(rng, 5, 25), yy}, cv::Scalar(60, 60, 60), 1);
        break;
      }
      case 1:
        Poster(image, r, rng);
        break;
      case 2: {
        cv::rectangle(image, r, cv::Scalar(40, 40, 40), -1);
        for (int yy = r.y + 3; yy < r.y + r.height - 6; yy += 9)
          for (int xx = r.x + 3; xx < r.x + r.width - 6; xx += 9)
            cv::rectangle(image, cv::Rect(xx, yy, 7, 7), cv::Scalar(200, 200, 200), -1);
        break;
      }
      default:
        cv::circle(image, r.tl(), UniformInt(rng, 12, 25), RandomColor(rng), -1, cv::LINE_AA);
        cv::circle(image, r.tl(), UniformInt(rng, 5, 10), cv::Scalar(30, 50, 70), -1, cv::LINE_AA);
    }
  }
  AddNoise(image, FractalNoise(w, h, 4, rng), 6);
  return image;
}

cv::Mat Carton(int w, int h, Rng& rng) {
  cv::Mat image(h, w, CV_8UC3, cv::Scalar(Uniform(rng, 60, 110), Uniform(rng, 120, 160), Uniform(rng, 170, 210)));
  if (UniformInt(rng, 0, 2) == 0) image.setTo(RandomColor(rng));
  AddNoise(image, FractalNoise(w, h, 32, rng), 12);
  cv::line(image, {0, h / 2}, {w, h / 2}, cv::Scalar(150, 190, 200), std::max(2, h / 12));
  Poster(image, cv::Rect(w / 8, h / 8, w / 3, h / 3), rng);
  RandomText(image, rng, UniformInt(rng, 2, 5), 0.5, 1.6);
  const cv::Point arrow(UniformInt(rng, w / 2, w - 20), UniformInt(rng, h / 2, h - 20));
  cv::arrowedLine(image, arrow, arrow - cv::Point(0, 30), cv::Scalar(20, 20, 20), 3);
  AddNoise(image, FractalNoise(w, h, 4, rng), 7);
  return image;
}

cv::Mat Clothes(int w, int h, Rng& rng) {
  cv::Mat image(h, w, CV_8UC3, RandomColor(rng, 30, 220));
  const cv::Scalar second = RandomColor(rng, 20, 240);
  const int pattern = UniformInt(rng, 0, 3);
  const int period = UniformInt(rng, 10, 28);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool on = false;
      switch (pattern) {
        case 0:
          on = (y / period) % 2 == 0;
          break;  // stripes
        case 1:
          on = ((x / period) + (y / period)) % 2 == 0;
          break;  // checks
        case 2:
          on = (x % period < 3) || (y % period < 3);
          break;  // tartan lines
        default:
          on = ((x + y) / period) % 3 == 0;
          break;  // diagonal
      }
      if (on) image.at<cv::Vec3b>(y, x) = cv::Vec3b(second[0], second[1], second[2]);
    }
  Poster(image, cv::Rect(w / 3, h / 5, w / 3, h / 4), rng);  // a print on the shirt
  AddNoise(image, FractalNoise(w, h, 16, rng), 14);
  return image;
}

cv::Mat Denim(int w, int h, Rng& rng) {
  cv::Mat image(h, w, CV_8UC3, cv::Scalar(Uniform(rng, 90, 140), Uniform(rng, 50, 80), Uniform(rng, 20, 50)));
  AddNoise(image, FractalNoise(w, h, 8, rng), 18);
  for (int x = 0; x < w; x += UniformInt(rng, 20, 40))
    cv::line(image, {x, 0}, {x, h}, cv::Scalar(60, 110, 170), 1);  // seams
  return image;
}

cv::Mat Skin(int w, int h, Rng& rng) {
  cv::Mat image(h, w, CV_8UC3, cv::Scalar(Uniform(rng, 90, 150), Uniform(rng, 130, 175), Uniform(rng, 180, 225)));
  AddNoise(image, FractalNoise(w, h, 16, rng), 10);
  // Hair band at the top and a face-like pattern in the middle.
  cv::rectangle(image, cv::Rect(0, 0, w, h / 4), cv::Scalar(20, 30, 50 + Uniform(rng, 0, 60)), -1);
  cv::circle(image, {w / 3, h / 2}, std::max(2, w / 14), cv::Scalar(40, 30, 30), -1);
  cv::circle(image, {2 * w / 3, h / 2}, std::max(2, w / 14), cv::Scalar(40, 30, 30), -1);
  cv::ellipse(image, {w / 2, 3 * h / 4}, cv::Size(w / 6, h / 20), 0, 0, 180, cv::Scalar(60, 60, 140), 2);
  return image;
}

}  // namespace

cv::Mat MakeTextureImage(TextureKind kind, int width, int height, std::uint32_t seed) {
  if (width < 8 || height < 8)
    throw InputError("texture size must be at least 8x8 texels, got " + std::to_string(width) + "x" +
                     std::to_string(height));
  Rng rng(seed);
  switch (kind) {
    case TextureKind::kWall:
      return Wall(width, height, rng);
    case TextureKind::kFloor:
      return Floor(width, height, rng);
    case TextureKind::kWood:
      return Wood(width, height, rng);
    case TextureKind::kCarton:
      return Carton(width, height, rng);
    case TextureKind::kClothes:
      return Clothes(width, height, rng);
    case TextureKind::kDenim:
      return Denim(width, height, rng);
    case TextureKind::kSkin:
      return Skin(width, height, rng);
    case TextureKind::kPaint:
      return Paint(width, height, rng);
  }
  return Wall(width, height, rng);
}

std::shared_ptr<const Texture> MakeTexture(const cv::Mat& image, double texel_size_m) {
  if (image.empty() || (image.type() != CV_8UC3 && image.type() != CV_8UC4))
    throw InputError("texture image must be a non-empty 8-bit BGR or BGRA image");
  if (!(texel_size_m > 0)) throw InputError("texture texel size must be positive");
  auto texture = std::make_shared<Texture>();
  texture->texel_size_m = texel_size_m;
  texture->levels.push_back(image.clone());
  while (texture->levels.back().cols >= 16 && texture->levels.back().rows >= 16 && texture->levels.size() < 8) {
    cv::Mat down;
    cv::pyrDown(texture->levels.back(), down);
    texture->levels.push_back(down);
  }
  return texture;
}

}  // namespace dynvo
