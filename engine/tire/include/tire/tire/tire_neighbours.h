// The contacts between tires as the global method solves them (issue 13, item 2): block
// Gauss–Seidel between tires, each tire exact inside. A tire's tread particles that enter a
// neighbour's tread are rows of the tire's own system (GlobalSolver), against the neighbour's
// tread edge as it stood when the tire's turn came: a plane. The neighbour answers as the stiff body
// it is: the row's compliance holds its give as a rigid body at the contact point,
// w = 1/M + (r × n)²/I (Müller et al. 2020, eq. 2), and its reaction −μ n is a rigid displacement
// of the whole neighbour, Δx_j = −(μ n/M + perp(r_j) (r × μ n)/I), which keeps linear and angular
// momentum. (Giving the reaction to the edge's two particles alone, as the Gauss–Seidel contact of
// soft_contact.h does, dents a stiff tire by centimetres a substep under a pile's weight and
// throws it apart at two substeps.) The neighbour's own dent comes from its own contacts, in its
// own solve.
//
// The push is an impulse: it moves the neighbour's velocities with its positions, so that the
// neighbour's own solve later in the substep, which pulls each particle towards its inertial target
// x̃ = xₙ + h v, does not undo it. (Moving the positions alone lost a head-on collision's momentum and
// let a column of tires sag with more substeps: 0.994 m between hubs at 2, 0.971 m at 32.)
//
// Two guards, for what one colour's pushes do to a tire:
// - Mass splitting (Tonge, Benevolenskiy and Voroshilov 2012, "Mass splitting for jitter-free
//   parallel rigid body simulation"): a tire touching k others may be pushed by several of them in
//   one colour, each solving as if it alone moved it; each sees it k times lighter,
//   w = k (1/M + (r × n)²/I), so that together they move it about as much as one would. (Level 08
//   at 2 × 1: least area 1.000 with it, 0.995 without.)
// - The anti-tunnelling clamp (SolverConfig::tunnel_clamp) on the pushes as on the velocities: one
//   hand-over moves no particle of a tire further than tunnel_clamp rest segments, the push scaled
//   down whole. Level 08 holds without it too (least area 1.000 either way at 2 × 1); it bounds
//   what one hand-over can do, as the velocity clamp bounds what one substep can.
//
// The tires take turns by colour: no two neighbours share one, so a colour's tires are solved in
// parallel, each against its neighbours as the colours before left them, and the reactions a
// colour owes go to its neighbours after it, in tire order, so the result does not depend on which
// thread solved what. (Solving every tire at once against the others as they were, Jacobi between
// tires, let level 08's rain of 300 tires diverge; that was measured before the impulse fix above.)
//
// Leaving these contacts outside the tires' systems, as a projection after them, does not hold a
// pile: each stiff tire undoes the local dent a neighbour's push makes, and a column of six tires at
// two substeps lost a third of its area and let a tire through (docs/physics.md, "The global method").
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tire/math/geometry.h"
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
  double split = 1.0;  // the neighbours it has this tick (mass splitting), at least 1
  // What the neighbour gives way at `point` along unit `d`: k (1/M + (r × d)²/I).
  double give(Vec2 point, Vec2 d) const {
    const double rd = cross(point - centroid, d);
    return split * (inverse_mass + rd * rd * inverse_inertia);
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
  // This tick's candidate pairs, as a list of neighbours per tire, and the tires' colours: greedy
  // in tire order, each tire the lowest colour none of its neighbours before it took.
  // Only the `members` (the awake tires, in tire order) are coloured, captured and pushed: a pair's
  // tires are both among them.
  void set_pairs(std::size_t tire_count, std::span<const std::uint32_t> members,
                 const std::vector<TirePair>& pairs);
  std::size_t colours() const { return colour_begin_.empty() ? 0 : colour_begin_.size() - 1; }
  // The tires of colour c, in tire order.
  std::span<const std::uint32_t> tires_of_colour(std::size_t c) const {
    return {by_colour_.data() + colour_begin_[c], by_colour_.data() + colour_begin_[c + 1]};
  }
  // The treads where they are now, as the next colour's tires see them: every member, at the start
  // of an iteration. `h`: the substep.
  void capture(const std::vector<Tire>& tires, double h);
  // capture() in parts, for a caller that spreads the tires over threads: begin_capture once, then
  // capture_tire for each member (any order, any thread: each writes only its own tire's slots).
  // A tire of the colour being solved may be captured as soon as its own solve ends, as no tire of
  // its colour reads it; a tire moved by apply_reaction, once moved.
  void begin_capture(const std::vector<Tire>& tires, double h);
  void capture_tire(const Tire& t, std::size_t i);
  std::span<const std::uint32_t> members() const { return members_; }
  std::uint32_t colour_of(std::uint32_t tire) const { return colour_[tire]; }
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
  // carry another tire (on_tire), as the Gauss–Seidel contact does. `tunnel_clamp`: the most a
  // particle may move, in rest tread segments; h the substep; `colour` the colour just solved.
  // A tire of a later colour is moved now, before its own solve. A tire of this colour or an
  // earlier one has been solved this iteration: its push is kept as an impulse for the velocity
  // update (Tire::late_push), not a displacement now. Moved now, it would be driven into what holds
  // it (the floor, a wall) after its solve had held it there; the next substep would start inside
  // and its solve turn the way out into velocity: the energy that made piles creep (60 tires in a
  // 6 m box never slept at 2 × 1; docs/at-rest.md).
  void apply_reactions(std::vector<Tire>& tires, double tunnel_clamp, double h, std::size_t colour) const;
  // apply_reactions in parts: gather_reactions sums what each tire is owed (in tire order, so the
  // same on any thread count) and lists the tires owed something; apply_reaction then hands tire i
  // its push (distinct tires on any threads), true when it moved it (a later colour's tire).
  std::span<const std::uint32_t> gather_reactions(std::vector<Tire>& tires) const;
  bool apply_reaction(Tire& t, std::uint32_t i, double tunnel_clamp, double h, std::size_t colour) const;

 private:
  const Tire* first_ = nullptr;
  double h_ = 0.0;                      // the substep captured
  std::vector<std::uint32_t> members_;  // the tires set_pairs was given, in tire order
  std::vector<std::uint32_t> adjacency_begin_;
  std::vector<std::uint32_t> adjacency_;
  std::vector<std::uint32_t> colour_;        // per tire
  std::vector<std::uint32_t> colour_seen_;   // set_pairs' scratch: per colour, the last tire that saw it
  std::vector<std::uint32_t> colour_begin_;  // per colour: its first tire in by_colour_
  std::vector<std::uint32_t> by_colour_;     // the tires sorted by colour, in tire order within one
  std::vector<std::uint32_t> offset_;        // per tire: its first tread particle in x_ and motion_
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
  // gather_reactions' sums per tire: the linear and angular push.
  mutable std::vector<Vec2> linear_;
  mutable std::vector<double> angular_;
  mutable std::vector<std::vector<TireReaction>> reactions_;
  mutable std::vector<std::uint32_t> owed_;  // gather_reactions': the tires owed a push
};

}  // namespace tire
