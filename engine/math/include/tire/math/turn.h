// The turn of a set of equal-weight points: the least-squares rotation that lays them, each about
// its set's centroid, onto where they moved. What a deformable body has turned through, its
// deformation left out (the rotation of the polar decomposition, in 2D a single angle).
#pragma once

#include <span>

#include "tire/math/geometry.h"

namespace tire {

// θ with tan θ = Σ rᵢ × r′ᵢ / Σ rᵢ · r′ᵢ, rᵢ = fromᵢ − centroid(from), r′ᵢ = toᵢ − centroid(to):
// the angle that best lays `from` onto `to` (the sets of equal size). 0 for coincident points.
double turn_between(std::span<const Vec2> from, std::span<const Vec2> to);

// ∂θ/∂toᵢ at to = from: perp(rᵢ) / Σ |rⱼ|² (the translation drops out, as Σ rᵢ = 0). The first
// order of turn_between: θ(from + δ) = Σ gᵢ · δᵢ + O(|δ|²). Writes one entry a point into `out`;
// false, and nothing written, when the points coincide.
bool turn_gradient(std::span<const Vec2> from, std::span<Vec2> out);

}  // namespace tire
