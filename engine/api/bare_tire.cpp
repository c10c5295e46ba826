#include "tire/engine.h"
#include "tire/rigid/rigid_world.h"
#include "tire/tire/global_solver.h"
#include "tire/tire/tire.h"
#include "tire/tire/tire_solver.h"

namespace tire {

struct BareTire::Parts {
  Parts(const SolverConfig& c, Vec2 g, const TireSpec& spec)
      : config(c), gravity(g), rigid(g), tire(0, spec) {}
  SolverConfig config;
  Vec2 gravity;
  RigidWorld rigid;
  Tire tire;
  GlobalSolverPool global;  // the global method's solver, lent to the substep
};

BareTire::BareTire(const SolverConfig& config, Vec2 gravity, const TireSpec& spec, const Obstacle& ground)
    : parts_(std::make_unique<Parts>(config, gravity, spec)) {
  parts_->rigid.add_obstacle(ground);
  parts_->global.reserve(1, spec.segments);
}

BareTire::~BareTire() = default;
BareTire::BareTire(BareTire&&) noexcept = default;
BareTire& BareTire::operator=(BareTire&&) noexcept = default;

void BareTire::step(const TickInput& input) {
  Parts& p = *parts_;
  p.tire.control = {input.steer, input.jump};
  begin_tick(p.tire, p.config, p.rigid);
  const double h = p.config.dt / p.config.substeps;
  SubstepContext ctx{h, 0.0, p.gravity, &p.config, &p.rigid, false, &p.global};
  for (int s = 0; s < p.config.substeps; ++s) {
    ctx.time = s * h;
    substep(p.tire, ctx, p.rigid);
  }
}

const SolverConfig& BareTire::config() const { return parts_->config; }
std::uint32_t BareTire::segments() const { return parts_->tire.segments(); }
std::size_t BareTire::particle_count() const { return parts_->tire.particle_count(); }
std::size_t BareTire::touching_particles() const { return parts_->tire.touching_particles(); }
bool BareTire::asleep() const { return parts_->tire.asleep; }

}  // namespace tire
