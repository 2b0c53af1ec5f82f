#pragma once
// A rolling shutter rendered (core/rolling_shutter.h: row r of an image stamped t is exposed at
// t + RowExposureOffset): in horizontal bands, each at its centre row's time, so the cost stays
// close to one full render per image.

#include <functional>
#include <vector>

#include "core/pose.h"
#include "core/rolling_shutter.h"
#include "synth/renderer.h"
#include "synth/scene.h"

namespace dynvo {

// One horizontal band of an image, rendered at one time.
struct ShutterBand {
  int row_begin = 0;    // first row
  int row_end = 0;      // one past the last row
  double offset_s = 0;  // seconds from the image stamp: its centre row's exposure offset
};

// `bands` bands (clamped to [1, height]) splitting `height` rows as evenly as integers allow,
// top to bottom, covering every row once.
std::vector<ShutterBand> RollingShutterBands(int height, double readout_s, int bands);

// The scene at time `seconds` through a rolling shutter read out over `readout_s` in `bands`
// bands: rows of band k as Render(quads_at(s), camera_from_world_at(s)) at s = seconds +
// band k's offset. A readout of 0 is Render at `seconds`, byte-identical.
RenderResult RenderRollingShutter(const Renderer& renderer,
                                  const std::function<std::vector<TexturedQuad>(double)>& quads_at,
                                  const std::function<Pose(double)>& camera_from_world_at, double seconds,
                                  double readout_s, int bands);

}  // namespace dynvo
