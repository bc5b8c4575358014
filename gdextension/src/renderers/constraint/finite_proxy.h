#pragma once

// The god-object / finite proxy (Zilles & Salisbury 1995; Ruspini, Kolarov & Khatib 1997)
// in the plane of the maze: a disc of radius r that follows the goal (the device position
// mapped into the maze) but never enters a wall. The renderer then pulls the hand toward it:
// F = k_c (proxy - device).
//
// One update, as CHAI3D's proxy does it, in at most p_max_iterations sweeps:
//   1. target = the point nearest the goal that satisfies every constraint found so far in
//      this update (none at first: the goal itself);
//   2. sweep the disc from the proxy to the target against the walls (continuous
//      collision, swept_disc.h), through the broad phase (constraint_geometry.h);
//   3. no hit: the proxy moves to the target, done. A hit: the proxy moves to the touch
//      point (backed off by a skin of 1e-6 r along the motion, so it rests just outside) and
//      the wall's tangent there becomes a new constraint, the half-plane n.p >= n.proxy;
//      go to 1.
// Step 1 is a tiny quadratic program, nearest point of a convex polygon: with no constraint
// the goal; with one, the goal projected onto the wall's tangent line (the proxy slides and
// keeps the tangential part of the motion); with two non-parallel ones, the corner where
// they meet (the proxy stops: 2D has no line left to slide along); with three or more (a
// dead end, an acute fan of walls), whichever single projection or pairwise corner is
// feasible and nearest. Candidates are enumerated, which is exact for a convex polygon and
// cheap for the handful of constraints one update collects.
//
// Constraints live for one update only; they are found again the next tick from the resting
// contact (a disc within the skin of a wall and moving into it hits at t = 0). Because the
// proxy never moves except along a swept, collision-free path, it cannot cross a wall however
// far the goal jumps in one tick. Deterministic: ties between walls hit at the same t are
// broken by the lower segment index, so the grid and the brute-force broad phase give
// bit-identical paths.
//
// No allocation: constraints are a fixed array; the broad phase needs no scratch.

#include "core/base/vec2.h"
#include "renderers/constraint/constraint.gen.h"
#include "renderers/constraint/constraint_geometry.h"

#include <cstdint>

namespace haptics {

// MAX_PROXY_ITERATIONS: constraint.schema.toml.
// Proxy skin (rest distance outside a wall) as a fraction of the radius.
inline constexpr double PROXY_SKIN = 1e-6;

// The half-plane normal . p >= offset.
struct ProxyConstraint {
	Vec2 normal;
	double offset = 0.0;
};

// Is a disc of p_radius at p_centre clear of every segment (distance >= p_radius)?
bool disc_fits(const ConstraintGeometry &p_geometry, const Vec2 &p_centre, double p_radius);

// The point nearest p_goal satisfying every constraint to within p_tolerance; p_fallback
// (which must satisfy them) when none of the candidates does (e.g. parallel walls closer
// than rounding). p_count <= MAX_PROXY_ITERATIONS.
Vec2 project_onto_constraints(const Vec2 &p_goal, const ProxyConstraint *p_constraints, uint32_t p_count,
		const Vec2 &p_fallback, double p_tolerance);

class FiniteProxy {
public:
	// Forgets the position: the next update places the proxy at the goal as soon as the
	// disc fits there (a device that starts inside a wall renders no force until it leaves).
	void reset();
	// Places the proxy at p_point if the disc fits there; returns whether it did.
	bool try_place(const ConstraintGeometry &p_geometry, const Vec2 &p_point, double p_radius);
	// One update toward p_goal (finite); p_radius > 0, p_max_iterations in
	// [1, MAX_PROXY_ITERATIONS]. Places the proxy instead when it is not placed.
	void update(const ConstraintGeometry &p_geometry, const Vec2 &p_goal, double p_radius, uint32_t p_max_iterations);

	bool placed() const { return placed_; }
	// Maze units; meaningless while !placed().
	const Vec2 &position() const { return position_; }
	// Walls holding the proxy back after the last update: the constraints it rests on
	// (0 free, 1 sliding, 2+ stopped in a corner or dead end).
	uint32_t active_constraints() const { return active_count_; }
	const ProxyConstraint &constraint(uint32_t p_index) const { return constraints_[p_index]; }
	uint32_t last_sweeps() const { return last_sweeps_; }

private:
	bool sweep(const ConstraintGeometry &p_geometry, const Vec2 &p_from, const Vec2 &p_motion, double p_radius,
			DiscHit &r_hit) const;

	Vec2 position_;
	bool placed_ = false;
	ProxyConstraint constraints_[MAX_PROXY_ITERATIONS];
	uint32_t constraint_count_ = 0;
	uint32_t active_count_ = 0;
	uint32_t last_sweeps_ = 0;
};

} // namespace haptics
