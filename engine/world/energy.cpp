#include "tire/world/energy.h"

#include "tire/world/world.h"

namespace tire {

Energy tire_energy(const Tire& t, Vec2 gravity) {
  Energy e;
  const double m = t.particle_mass();
  const Particles& p = t.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    e.kinetic += 0.5 * m * length_squared(p.v[i]);
    e.gravitational -= m * dot(gravity, p.x[i]);
  }
  for (const DistanceConstraint& c : t.distance.constraints()) {
    if (!(c.compliance > 0.0)) continue;
    const double stretch = length(p.x[c.b] - p.x[c.a]) - c.rest_length;
    e.elastic += 0.5 * stretch * stretch / c.compliance;
  }
  e.elastic += t.area_constraint.energy(t.area());
  const AreaConstraint& rim = t.rim_area_constraint;
  e.elastic += rim.energy(polygon_area(p.x.data() + rim.first, rim.count));
  return e;
}

Energy world_energy(const World& world) {
  Energy e;
  for (const Tire& t : world.tires()) e += tire_energy(t, world.gravity());
  const RigidWorld& rigid = world.rigid();
  for (std::uint32_t i = 0; i < rigid.props().size(); ++i) {
    const Prop& prop = rigid.props()[i];
    if (!prop.alive || prop.spec.type != PropType::dynamic_body) continue;
    const PropState s = rigid.prop_state(i);
    e.kinetic +=
        0.5 * s.mass * length_squared(s.velocity) + 0.5 * s.inertia * s.angular_velocity * s.angular_velocity;
    e.gravitational -= s.mass * dot(world.gravity(), s.center);
  }
  const VehicleJoints& vehicles = world.vehicles();
  for (std::uint32_t v = 0; v < vehicles.count(); ++v) {
    const std::uint32_t chassis = vehicles.chassis(v);
    if (!rigid.props()[chassis].alive) continue;
    const Pose pose = rigid.prop_state(chassis).pose;
    for (std::size_t w = 0; w < vehicles.wheel_count(v); ++w) {
      const AxleSpec& axle = vehicles.axle(v, w);
      if (!(axle.stiffness > 0.0)) continue;
      const Tire& t = world.tires()[vehicles.wheel_tire(v, w)];
      const double c = vehicle_rows::stroke(t.particles, t.n, pose, axle);
      e.elastic += 0.5 * axle.stiffness * c * c;
    }
  }
  return e;
}

}  // namespace tire
