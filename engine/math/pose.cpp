#include "tire/math/geometry.h"
#include "tire/math/trig.h"

namespace tire {

Pose Pose::make(Vec2 position, double angle) {
  const CosSin cs = cos_sin(angle);
  return {position, angle, cs.cos, cs.sin};
}

}  // namespace tire
