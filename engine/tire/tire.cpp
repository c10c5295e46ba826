#include "tire/tire/tire.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>

#include "tire/math/check.h"
#include "tire/math/trig.h"

namespace tire {

Tire::Tire(TireId id_, const TireSpec& spec_, std::shared_ptr<const TireTopology> topology_)
    : id(id_),
      spec(spec_),
      spawn_mass(spec_.mass),
      n(static_cast<std::uint32_t>(spec_.segments)),
      segment_length(2.0 * spec_.outer_radius * cos_sin(std::numbers::pi / spec_.segments).sin) {
  TIRE_ASSERT(spec.segments >= 3, "a tire ring of fewer than three segments");
  TIRE_ASSERT(spec.mass > 0.0 && std::isfinite(spec.mass), "a tire's mass is not positive and finite");
  TIRE_ASSERT(spec.inner_radius > 0.0 && spec.inner_radius < spec.outer_radius,
              "a tire's rim is not inside its tread");
  topology = topology_ ? std::move(topology_) : std::make_shared<const TireTopology>(TireShape::of(spec));
  TIRE_ASSERT(topology->shape() == TireShape::of(spec), "a tire built on the topology of another shape");
  // Every array of a fixed size in one block: first what every iteration streams through (the
  // particles, the distance lanes), last the contact records (touched only near a surface).
  const std::size_t count = 2 * n;
  BlockLayout layout;
  const Particles::Slots particle_slots = Particles::plan(layout, count);
  const DistanceConstraintSet::Slots distance_slots =
      DistanceConstraintSet::plan(layout, *topology->distance());
  const BlockSlot<std::uint8_t> grounded_slot = layout.add<std::uint8_t>(count);
  const BlockSlot<std::uint8_t> on_tire_slot = layout.add<std::uint8_t>(count);
  const BlockSlot<Vec2> friction_anchor_slot = layout.add<Vec2>(count);
  const BlockSlot<std::int32_t> anchor_on_slot = layout.add<std::int32_t>(count);
  const BlockSlot<Vec2> still_shape_slot = layout.add<Vec2>(count);
  const BlockSlot<double> soft_lambda_slot = layout.add<double>(n);
  const BlockSlot<std::uint64_t> contact_mask_slot = layout.add<std::uint64_t>((count + 63) / 64);
  const BlockSlot<std::uint64_t> held_mask_slot = layout.add<std::uint64_t>((count + 63) / 64);
  const BlockSlot<ContactRecord> contacts_slot = layout.add<ContactRecord>(count);
  arrays = ArrayBlock(layout);
  particles = Particles(arrays, particle_slots);
  grounded_flags = arrays.construct(grounded_slot);
  on_tire = arrays.construct(on_tire_slot);
  friction_anchor = arrays.construct(friction_anchor_slot);
  anchor_on = arrays.construct(anchor_on_slot);
  still_shape = arrays.construct(still_shape_slot);
  soft_lambda = arrays.construct(soft_lambda_slot);
  contact_mask = arrays.construct(contact_mask_slot);
  held_mask = arrays.construct(held_mask_slot);
  contacts = arrays.construct(contacts_slot);
  // The broad-phase lists, for a usual scene (see tire.h).
  candidates.reserve(16);
  prop_candidates.reserve(16);
  prop_frames.reserve(16);
  prop_impulses.reserve(64);
  pairs.reserve(4 * n);

  area_constraint = {0, n, 0.0, spec.pressure, spec.compliance.pressure};
  // The rim's area is as stiff as its ring: α_area = α_inner·r² (m³/N) matches the ring's own
  // resistance to a change of radius, so a metal rim is nearly rigid and a rubber one is not.
  rim_area_constraint = {n, n, 0.0, 1.0, spec.compliance.inner * spec.inner_radius * spec.inner_radius};
  reset();
  // Rest lengths and rest area are those of the tire as built, so it starts in equilibrium.
  const double compliance[TireTopology::group_count] = {spec.compliance.outer, spec.compliance.inner,
                                                        spec.compliance.spoke};
  distance = DistanceConstraintSet(topology->distance(), particles.x, compliance, arrays, distance_slots);
  area_constraint.rest_area = polygon_area(particles.x.data(), n);
  rim_area_constraint.rest_area = polygon_area(particles.x.data() + n, n);
  TIRE_ASSERT(distance.size() == (spec.spokes == SpokePattern::cross ? 5u : 3u) * n,
              "a ring or a spoke is missing");
  TIRE_ASSERT(sizes_consistent(), "a tire built with arrays of the wrong size");
  TIRE_ASSERT(area_constraint.rest_area > 0.0 && rim_area_constraint.rest_area > 0.0,
              "a tire built clockwise");
}

void Tire::reset() {
  const double w = 2.0 * n / spec.mass;
  for (std::uint32_t i = 0; i < n; ++i) {
    // At angle 0 the segment between particles n−1 and 0 lies flat at the bottom: a polygon resting
    // on a vertex is balanced on a knife edge and would tip over, on an edge it is at rest.
    const double theta = spec.angle - std::numbers::pi / 2 + std::numbers::pi * (2.0 * i + 1.0) / n;
    const CosSin cs = cos_sin(theta);
    const Vec2 dir{cs.cos, cs.sin};
    const Vec2 r_out = dir * spec.outer_radius;
    const Vec2 r_in = dir * spec.inner_radius;
    particles.x[i] = spec.position + r_out;
    particles.x[n + i] = spec.position + r_in;
    particles.v[i] = spec.velocity + perp(r_out) * spec.angular_velocity;
    particles.v[n + i] = spec.velocity + perp(r_in) * spec.angular_velocity;
  }
  std::copy(particles.x.begin(), particles.x.end(), particles.x_prev.begin());
  std::fill(particles.w.begin(), particles.w.end(), w);
  std::fill(contacts.begin(), contacts.end(), ContactRecord{});
  std::fill(contact_mask.begin(), contact_mask.end(), std::uint64_t{0});
  std::fill(held_mask.begin(), held_mask.end(), std::uint64_t{0});
  std::fill(grounded_flags.begin(), grounded_flags.end(), std::uint8_t{0});
  std::fill(anchor_on.begin(), anchor_on.end(), kNoAnchor);
  air_time = std::numeric_limits<double>::infinity();
  spin_as_built = spec.angular_velocity != 0.0;
  rolling_held = false;
  late_push = {};
  predicted_push = {};
  distance.reset_lambda();
  area_lambda = 0.0;
  rim_area_lambda = 0.0;
  control = {};
  tick_contacts = {};
}

void Tire::set_compliance(const TireCompliance& c) {
  TIRE_ASSERT(c.outer >= 0.0 && c.inner >= 0.0 && c.spoke >= 0.0 && c.pressure >= 0.0,
              "a negative compliance");
  spec.compliance = c;
  distance.set_group_compliance(TireTopology::outer_ring, c.outer);
  distance.set_group_compliance(TireTopology::inner_ring, c.inner);
  distance.set_group_compliance(TireTopology::spoke, c.spoke);
  area_constraint.compliance = c.pressure;
  rim_area_constraint.compliance = c.inner * spec.inner_radius * spec.inner_radius;
}

void Tire::set_mass(double mass) {
  TIRE_ASSERT(mass > 0.0 && std::isfinite(mass), "a tire's mass is not positive and finite");
  spec.mass = mass;
  std::fill(particles.w.begin(), particles.w.end(), 2.0 * n / mass);
}

Vec2 Tire::centroid() const { return mean(particles.x); }

Vec2 Tire::velocity() const { return mean(particles.v); }

RigidMotion Tire::substep_motion(double h) const {
  RigidMotion m;
  const double count = static_cast<double>(particles.size());
  for (std::size_t k = 0; k < particles.size(); ++k) {
    m.centroid += particles.x[k];
    m.velocity += particles.x[k] - particles.x_prev[k];
  }
  m.centroid = m.centroid / count;
  m.velocity = m.velocity / (count * h);
  double momentum = 0.0, r2 = 0.0;  // per unit particle mass: every particle weighs the same
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const Vec2 r = particles.x[k] - m.centroid;
    momentum += cross(r, (particles.x[k] - particles.x_prev[k]) / h - m.velocity);
    r2 += length_squared(r);
  }
  m.omega = r2 > 0.0 ? momentum / r2 : 0.0;
  m.inertia = particle_mass() * r2;
  return m;
}

RigidMotion Tire::rigid_motion() const {
  // centroid() and velocity() in one pass (each sum in the same order: the same bits).
  Vec2 x_sum, v_sum;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    x_sum += particles.x[i];
    v_sum += particles.v[i];
  }
  const double count = static_cast<double>(particles.size());
  RigidMotion m{x_sum / count, v_sum / count, 0.0, 0.0};
  double momentum = 0.0;  // L and I per unit particle mass
  double inertia = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Vec2 r = particles.x[i] - m.centroid;
    momentum += cross(r, particles.v[i] - m.velocity);
    inertia += length_squared(r);
  }
  m.omega = inertia > 0.0 ? momentum / inertia : 0.0;
  m.inertia = inertia * particle_mass();
  return m;
}

double Tire::area() const { return polygon_area(particles.x.data(), n); }

bool Tire::grounded() const {
  return std::any_of(grounded_flags.begin(), grounded_flags.begin() + n,
                     [](std::uint8_t g) { return g != 0; });
}

void Tire::clear_contacts() {
  // An anchor outlives the substep only with its contact: held, stuck, on the same surface.
  for (std::uint32_t i = 0; i < particle_count(); ++i) {
    if (anchor_on[i] == kNoAnchor) continue;
    const ContactRecord& rec = contacts[i];
    const bool in_mask = (contact_mask[i >> 6] >> (i & 63)) & 1u;
    if (!in_mask || !rec.active || !rec.stuck || anchor_code(rec.prop, rec.tire) != anchor_on[i])
      anchor_on[i] = kNoAnchor;
  }
  for_each_contact([this](std::uint32_t i) { contacts[i] = ContactRecord{}; });
  std::copy(contact_mask.begin(), contact_mask.end(), held_mask.begin());
  std::fill(contact_mask.begin(), contact_mask.end(), std::uint64_t{0});
}

void Tire::prefetch() const {
  distance.prefetch();
  tire::prefetch(particles.x);
  tire::prefetch(particles.x_prev);
  tire::prefetch(particles.v);
  tire::prefetch(particles.w);
  tire::prefetch(grounded_flags);
  tire::prefetch(on_tire);
  tire::prefetch(soft_lambda);
}

std::size_t Tire::touching_particles() const {
  std::size_t count = 0;
  for (std::uint32_t i = 0; i < particle_count(); ++i)
    count += contacts[i].active || on_tire[i] != 0 || (i < n && soft_lambda[i] > 0.0);
  return count;
}

bool Tire::sizes_consistent() const {
  const std::size_t count = particle_count();
  if (particles.x.size() != count || particles.x_prev.size() != count || particles.v.size() != count ||
      particles.w.size() != count || contacts.size() != count || contact_mask.size() != (count + 63) / 64 ||
      held_mask.size() != contact_mask.size() || grounded_flags.size() != count || on_tire.size() != count ||
      friction_anchor.size() != count || anchor_on.size() != count || still_shape.size() != count ||
      soft_lambda.size() != n)
    return false;
  for (const DistanceConstraint& c : distance.constraints())
    if (c.a >= count || c.b >= count) return false;
  return area_constraint.first + area_constraint.count <= count &&
         rim_area_constraint.first + rim_area_constraint.count <= count && grab_particle < count;
}

bool Tire::is_finite() const {
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (!tire::is_finite(particles.x[i]) || !tire::is_finite(particles.v[i])) return false;
  return true;
}

double Tire::max_abs_coordinate() const {
  double m = 0.0;
  for (const Vec2& x : particles.x) m = std::max({m, std::abs(x.x), std::abs(x.y)});
  return m;
}

}  // namespace tire
