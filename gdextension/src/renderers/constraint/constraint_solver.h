#pragma once

// The constraint-based force law without the servo's channels: device position -> goal in
// the maze -> finite proxy update -> F = k_c (proxy - device), in newtons, device space
// (constraint_renderer.h says why so). What the renderer runs, and what tests compare the
// engine against.

#include "core/base/vec2.h"
#include "core/base/vec3.h"
#include "renderers/constraint/constraint_config.h"
#include "renderers/constraint/constraint_geometry.h"
#include "renderers/constraint/finite_proxy.h"
#include "renderers/constraint/maze_mapping.h"

#include <cstdint>

namespace haptics {

struct ConstraintOutput {
	Vec3 force; // N, device space.
	Vec2 proxy; // Maze units; the goal while the proxy is not placed.
	Vec2 goal; // Maze units.
	uint32_t active_constraints = 0; // Walls holding the proxy (0 free, 1 sliding, 2+ stopped).
	bool placed = false;
	bool has_geometry = false;
	bool stepped = false; // The proxy was updated this tick.
};

class ConstraintSolver {
public:
	void reset();
	void configure(const ConstraintConfig &p_config);
	// p_geometry: what the servo holds now (null before any was set: no force).
	// p_step_proxy: false holds the proxy where it is (the FRAME variant between
	// frames); the force still follows the device. p_device_radius_m resolves a mapping
	// whose half extent is 0.
	ConstraintOutput render(const ConstraintGeometry *p_geometry, uint64_t p_generation, const Vec3 &p_device_m,
			double p_device_radius_m, bool p_step_proxy);

	const FiniteProxy &proxy() const { return proxy_; }
	const MazeTransform &transform() const { return transform_; }

private:
	FiniteProxy proxy_;
	ConstraintConfig config_;
	MazeTransform transform_;
	uint64_t generation_ = 0; // Of the geometry transform_ was resolved for; 0 = none.
	double device_radius_m_ = 0.0;
};

// The force law, exposed so tests can compare the engine against the proxy alone.
Vec3 constraint_force(const MazeTransform &p_transform, const Vec2 &p_proxy, const Vec3 &p_device_m,
		double p_stiffness_n_per_m);

} // namespace haptics
