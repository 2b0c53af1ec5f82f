#include "pipeline/mask_source.h"

namespace dynvo {

MaskPacket NoMaskSource::Compute(const MaskSourceInput& input) {
  MaskPacket packet;
  packet.frame = input.frame.index;
  return packet;
}

}  // namespace dynvo
