// How far tires are inside each other: the deepest tread particle of one tire inside another's tread
// polygon. A contact holds one tire's particle on the other's edge, so what is left at rest is the
// solver's, plus up to the chord's sagitta R (1 − cos(π/n)) of the polygons (docs/at-rest.md, "Block
// Gauss–Seidel leaves tires inside each other under load"). Between ticks; reported by tirectl run.
#pragma once

#include "tire/world/views.h"

namespace tire {

class World;

// Over every two tires whose bounds meet (a sort and sweep on x), asleep or not.
TireOverlap deepest_tire_overlap(const World& world);

}  // namespace tire
