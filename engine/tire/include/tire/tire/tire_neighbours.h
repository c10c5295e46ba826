// The contacts between tires as the global method solves them (issue 13, item 2): block
// Gauss–Seidel between tires, each tire exact inside. A tire's tread particles that enter a
// neighbour's tread are rows of the tire's own system (GlobalSolver), against the neighbour's
// tread edge as it stood when the iteration began: a plane. The neighbour answers as the stiff body
// it is: the row's compliance holds its give as a rigid body at the contact point,
// w = 1/M + (r × n)²/I (Müller et al. 2020, eq. 2), and its reaction −μ n is a rigid displacement
// of the whole neighbour, Δx_j = −(μ n/M + perp(r_j) (r × μ n)/I), which keeps linear and angular
// momentum. (Giving the reaction to the edge's two particles alone, as the Gauss–Seidel contact of
// soft_contact.h does, dents a stiff tire by centimetres a substep under a pile's weight and
// throws it apart at two substeps.) The reactions wait here and go to the neighbours after every
// tire has been solved, in tire order, so the result does not depend on which thread solved what.
// The neighbour's own dent comes from its own contacts, in its own solve.
//
// Leaving these contacts outside the tires' systems, as a projection after them, does not hold a
// pile: each stiff tire undoes the local dent a neighbour's push makes, and a column of six tires at
// two substeps lost a third of its area and let a tire through (see the README, "The global method").
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tire/math/vec2.h"
#include "tire/tire/soft_contact.h"
#include "tire/tire/tire.h"

namespace tire {

// A neighbour's tread as one iteration sees it: where its particles are (x) and how far each moved
// over the substep (motion), with its hub and the radius of the circle around them.
struct TreadView {
  const Vec2* x = nullptr;
  const Vec2* motion = nullptr;
  const Tire* tire = nullptr;  // for its friction (not written during a sweep)
  std::uint32_t n = 0;
  Vec2 hub;
  double reach = 0.0;
  Vec2 centroid;  // of the whole tire, and its rigid body's inverse mass and inertia
  double inverse_mass = 0.0;
  double inverse_inertia = 0.0;
  // What the neighbour gives way at `point` along unit `d`: 1/M + (r × d)²/I.
  double give(Vec2 point, Vec2 d) const {
    const double rd = cross(point - centroid, d);
    return inverse_mass + rd * rd * inverse_inertia;
  }
};

// The push a tire's contact gives a neighbour at a point of its tread edge (edge, edge + 1):
// push = μ_n n + μ_t t (kg·m), taken by the neighbour as a rigid body.
struct TireReaction {
  std::uint32_t tire;  // the neighbour, an index into the world's tires
  std::uint32_t edge;
  Vec2 point;
  Vec2 push;
  bool carried;  // the neighbour rests on the pushing tire (the edge faces down)
};

class TireNeighbours {
 public:
  // Room for these tires and `pairs` pairs, so that a step never allocates (World::add_tire calls
  // it).
  void reserve(const std::vector<Tire>& tires, std::size_t pairs);
  // This tick's candidate pairs, as a list of neighbours per tire.
  void set_pairs(std::size_t tire_count, const std::vector<TirePair>& pairs);
  // The treads as the next iteration sees them. `extrapolate`: at the start of a substep, before
  // its prediction, each particle carried on by its last substep's motion, x + (x − xₙ), which
  // both step schedules have at that point; otherwise where they are now.
  void capture(const std::vector<Tire>& tires, bool extrapolate);
  // The index in the world's tires of `tire`, one of the tires captured.
  std::uint32_t index_of(const Tire& tire) const { return static_cast<std::uint32_t>(&tire - first_); }
  std::span<const std::uint32_t> neighbours(std::uint32_t tire) const {
    return {adjacency_.data() + adjacency_begin_[tire], adjacency_.data() + adjacency_begin_[tire + 1]};
  }
  TreadView tread(std::uint32_t tire) const;
  // Where tire `tire`'s solve leaves the pushes it owes its neighbours (its own list: tires solved
  // in parallel never share one).
  std::vector<TireReaction>& reactions(std::uint32_t tire) const { return reactions_[tire]; }
  // Hands every owed push to its tire, in tire order, and forgets them; marks the particles that
  // carry another tire (on_tire), as the Gauss–Seidel contact does.
  void apply_reactions(std::vector<Tire>& tires) const;

 private:
  const Tire* first_ = nullptr;
  std::vector<std::uint32_t> adjacency_begin_;
  std::vector<std::uint32_t> adjacency_;
  std::vector<std::uint32_t> offset_;  // per tire: its first tread particle in x_ and motion_
  std::vector<Vec2> x_;
  std::vector<Vec2> motion_;
  std::vector<Vec2> hub_;
  std::vector<double> reach_;
  struct Body {
    Vec2 centroid;
    double inverse_mass = 0.0;
    double inverse_inertia = 0.0;
  };
  std::vector<Body> body_;
  // apply_reactions' sums per tire: the linear and angular push, and whether any came.
  mutable std::vector<Vec2> linear_;
  mutable std::vector<double> angular_;
  mutable std::vector<std::vector<TireReaction>> reactions_;
};

}  // namespace tire
