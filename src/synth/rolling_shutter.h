#pragma once
// Rolling shutter: a CMOS sensor (the Kinect v1's colour and IR cameras) reads its rows out one
// after another, so under motion each row shows the scene at its own time. Row r of an image
// of H rows stamped t is exposed at t + readout * (r / (H - 1) - 0.5): the middle row at the
// stamp. Rendered in horizontal bands, each at its centre row's time, so the cost stays close
// to one full render per image.

#include <functional>
#include <vector>

#include "core/pose.h"
#include "synth/renderer.h"
#include "synth/scene.h"

namespace dynvo {

// Seconds from the image stamp at which (fractional) row `row` of `height` rows is exposed
// when the rows are read out over `readout_s`; 0 for the middle row or a readout of 0.
double RowExposureOffset(double row, int height, double readout_s);

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
