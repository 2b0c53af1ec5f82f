#include "synth/rolling_shutter.h"

#include <algorithm>

namespace dynvo {

std::vector<ShutterBand> RollingShutterBands(int height, double readout_s, int bands) {
  bands = std::clamp(bands, 1, std::max(1, height));
  std::vector<ShutterBand> out;
  for (int k = 0; k < bands; ++k) {
    ShutterBand band;
    band.row_begin = static_cast<int>(static_cast<long long>(height) * k / bands);
    band.row_end = static_cast<int>(static_cast<long long>(height) * (k + 1) / bands);
    band.offset_s = RowExposureOffset(0.5 * (band.row_begin + band.row_end - 1), height, readout_s);
    out.push_back(band);
  }
  return out;
}

RenderResult RenderRollingShutter(const Renderer& renderer,
                                  const std::function<std::vector<TexturedQuad>(double)>& quads_at,
                                  const std::function<Pose(double)>& camera_from_world_at, double seconds,
                                  double readout_s, int bands) {
  if (readout_s == 0.0) return renderer.Render(quads_at(seconds), camera_from_world_at(seconds));
  RenderResult result;
  for (const ShutterBand& band : RollingShutterBands(renderer.camera().height, readout_s, bands)) {
    const double s = seconds + band.offset_s;
    renderer.RenderRows(quads_at(s), camera_from_world_at(s), band.row_begin, band.row_end, &result);
  }
  return result;
}

}  // namespace dynvo
