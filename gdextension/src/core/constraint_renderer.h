#pragma once

// The constraint-based renderer as the servo runs it: device position -> goal in the maze ->
// finite proxy update -> F = k_c (proxy - device), in newtons, device space.
//
//   goal  = to_maze(device.xy)
//   F.xy  = k_c (to_device(proxy) - device.xy),   F.z = 0
// Only the normal force, as in the study: the proxy is frictionless, so the force is always
// along the normals of the walls holding it; it is reported as the `normal` component. z is
// left free (the maze is planar). The force is not low-pass filtered: a filter inside a
// position-feedback loop adds phase lag, which makes a stiff wall spongy and can make it
// unstable, and the force is already continuous at the servo rate.
//
// The renderer follows the geometry the servo currently holds (GeometryExchange, picked up
// every tick whatever the render mode). When the geometry changes, the proxy keeps its place
// if the disc still fits there in the new walls (re-sending the same maze must not teleport
// the avatar through a wall), and is re-placed otherwise. It is re-placed too on reset() (a
// new session, a switch of render mode) and when the radius changes. Until it is placed the
// force is zero.
//
// No allocation; state is the proxy, the resolved mapping and the last configuration.

#include "core/config.h"
#include "core/finite_proxy.h"
#include "core/geometry_exchange.h"
#include "core/maze_mapping.h"
#include "core/renderer.h"
#include "core/vec3.h"

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

// The proxy and the force law alone, without the servo's channels: what tests compare the
// engine against.
class ConstraintSolver {
public:
	void reset();
	void configure(const ConstraintConfig &p_config);
	// p_geometry: what the servo holds now (null before any was set: no force).
	// p_step_proxy: false holds the proxy where it is (the FRAME_RATE variant between
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

class ConstraintRenderer final : public Renderer {
public:
	explicit ConstraintRenderer(GeometryExchange &r_geometry);

	void begin_session(double p_dt_s) override;
	void configure(const RenderConfig &p_config, double p_dt_s) override;
	void reset() override;
	void pick_up() override;
	void render(const RenderInput &p_input, RenderResult &r_result) override;
	void publish(ServoOutput &r_output, bool p_active) const override;

private:
	GeometryExchange &geometry_;
	ConstraintSolver solver_;
	ProxyUpdate update_ = ProxyUpdate::SERVO_RATE;
	ConstraintOutput last_;
	uint64_t updates_ = 0;
};

// The force law, exposed so tests can compare the engine against the proxy alone.
Vec3 constraint_force(const MazeTransform &p_transform, const Vec2 &p_proxy, const Vec3 &p_device_m,
		double p_stiffness_n_per_m);

} // namespace haptics
