// Area ("pressure") constraint on a closed polygon: C(x) = A(x) − p·A0, with A the shoelace area
// (positive for counter-clockwise order) and p the pressure factor: p > 1 inflates, p < 1 deflates.
// The 2D analogue of the volume constraint of Müller et al. 2007 ("PBD", Sec. 4.4) and of the
// overpressure factor in Macklin et al. 2016.
#pragma once

#include <cstdint>

#include "tire/math/geometry.h"

namespace tire {

struct AreaConstraint {
  std::uint32_t first = 0;  // polygon vertices are particles [first, first + count), CCW
  std::uint32_t count = 0;
  double rest_area = 0.0;   // A0 (m²)
  double pressure = 1.0;    // p: target area is p·A0
  double compliance = 0.0;  // α (m²/N in 2D: 1 / (N/m per m² of area change))
  // The energy it holds at `area`, U = ½ C²/α with C = A − p A0 (Macklin et al. 2016, eq. 2–4);
  // none when rigid.
  double energy(double area) const {
    if (!(compliance > 0.0)) return 0.0;
    const double c = area - pressure * rest_area;
    return 0.5 * c * c / compliance;
  }
};

// A = ½ Σ (x_i y_{i+1} − x_{i+1} y_i)
double polygon_area(const Vec2* x, std::uint32_t count);

// ∇_{x_i}A = ½ (y_{i+1} − y_{i−1}, x_{i−1} − x_{i+1}), written into grad[0..count).
void polygon_area_gradient(const Vec2* x, std::uint32_t count, Vec2* grad);

// One XPBD projection of the constraint; `lambda` is its accumulated multiplier for the substep.
void solve_area_constraint(const AreaConstraint& c, double& lambda, Vec2* x, const double* w, double inv_h2);

// Kelvin–Voigt damping of the area's rate of change dA/dt = Σ ∇_i A · v_i, as for distance
// constraints (see damp_distance_constraints): a dashpot c = τ/α, integrated implicitly.
void damp_area_constraint(const AreaConstraint& c, const Vec2* x, Vec2* v, const double* w, double tau,
                          double h);

}  // namespace tire
