// How far tires are inside each other: the deepest tread particle of one tire inside another's tread
// polygon. A contact holds one tire's particle on the other's edge, so what is left at rest is the
// solver's, plus up to the chord's sagitta R (1 − cos(π/n)) of the polygons (docs/at-rest.md, "Block
// Gauss–Seidel leaves tires inside each other under load"). Between ticks; reported by tirectl run.
#pragma once

#include "tire/tire/tire_spec.h"

namespace tire {

class World;

struct TireOverlap {
  double depth = 0.0;  // how far the particle is from the other's tread, inside it (m); 0 for none
  TireId tire = 0;     // the tire whose particle it is
  TireId inside = 0;   // the tire it is inside
};

// Over every two tires whose bounds meet (a sort and sweep on x), asleep or not.
TireOverlap deepest_tire_overlap(const World& world);

}  // namespace tire
