#include "renderers/constraint/constraint_solver.h"

namespace haptics {

Vec3 constraint_force(const MazeTransform &p_transform, const Vec2 &p_proxy, const Vec3 &p_device_m,
		double p_stiffness_n_per_m) {
	const Vec2 proxy_m = p_transform.to_device(p_proxy);
	return { p_stiffness_n_per_m * (proxy_m.x - p_device_m.x), p_stiffness_n_per_m * (proxy_m.y - p_device_m.y), 0.0 };
}

void ConstraintSolver::reset() {
	proxy_.reset();
}

void ConstraintSolver::configure(const ConstraintConfig &p_config) {
	if (p_config.proxy_radius != config_.proxy_radius) {
		proxy_.reset(); // A larger disc may no longer fit where the old one was.
	}
	config_ = p_config;
}

ConstraintOutput ConstraintSolver::render(const ConstraintGeometry *p_geometry, uint64_t p_generation,
		const Vec3 &p_device_m, double p_device_radius_m, bool p_step_proxy) {
	ConstraintOutput output;
	if (p_geometry == nullptr) {
		proxy_.reset();
		generation_ = 0;
		return output;
	}
	output.has_geometry = true;
	if (p_generation != generation_ || p_device_radius_m != device_radius_m_) {
		const bool was_placed = proxy_.placed();
		const Vec2 kept = proxy_.position();
		transform_ = resolve_maze_mapping(p_geometry->mapping(), p_device_radius_m);
		generation_ = p_generation;
		device_radius_m_ = p_device_radius_m;
		if (was_placed) {
			proxy_.try_place(*p_geometry, kept, config_.proxy_radius);
		}
	}
	output.goal = transform_.to_maze({ p_device_m.x, p_device_m.y });
	if (p_step_proxy) {
		proxy_.update(*p_geometry, output.goal, config_.proxy_radius, config_.max_iterations);
		output.stepped = true;
	}
	output.placed = proxy_.placed();
	if (!output.placed) {
		output.proxy = output.goal;
		return output;
	}
	output.proxy = proxy_.position();
	output.active_constraints = proxy_.active_constraints();
	output.force = constraint_force(transform_, output.proxy, p_device_m, config_.stiffness_n_per_m);
	return output;
}

} // namespace haptics
