#include "core/constraint_renderer.h"

#include "core/telemetry.h"

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

ConstraintRenderer::ConstraintRenderer(GeometryExchange &r_geometry) :
		geometry_(r_geometry) {}

void ConstraintRenderer::begin_session(double p_dt_s) {
	(void)p_dt_s;
	reset();
	updates_ = 0;
}

void ConstraintRenderer::configure(const RenderConfig &p_config, double p_dt_s) {
	(void)p_dt_s;
	solver_.configure(p_config.constraint);
	update_ = p_config.constraint.update;
}

void ConstraintRenderer::reset() {
	solver_.reset();
	last_ = ConstraintOutput{};
}

void ConstraintRenderer::pick_up() {
	geometry_.acquire(); // Also while inactive, so the game's pending walls are taken.
}

void ConstraintRenderer::render(const RenderInput &p_input, RenderResult &r_result) {
	const GeometryExchange::Current geometry = geometry_.current();
	const bool step = update_ == ProxyUpdate::SERVO_RATE || p_input.new_frame;
	last_ = solver_.render(geometry.geometry, geometry.generation, p_input.device.position_m, p_input.device_radius_m,
			step);
	updates_ += last_.stepped ? 1 : 0;
	ForceComponents &forces = r_result.forces;
	forces.normal = last_.force;
	forces.friction = Vec3{};
	forces.weight = Vec3{};
	forces.drag = Vec3{};
	forces.inertia = Vec3{};
	forces.continuous = last_.force;
	r_result.continuous = last_.force; // Not filtered: see the header.
	r_result.flags = TELEMETRY_FLAG_CONSTRAINT_MODE | (last_.active_constraints > 0 ? TELEMETRY_FLAG_PROXY_CONTACT : 0u);
}

void ConstraintRenderer::publish(ServoOutput &r_output, bool p_active) const {
	const GeometryExchange::Current geometry = geometry_.current();
	r_output.geometry_generation = geometry.generation;
	r_output.geometry_segments = geometry.geometry ? static_cast<uint32_t>(geometry.geometry->segment_count()) : 0;
	r_output.proxy_updates = updates_;
	if (p_active) {
		r_output.proxy_maze = last_.proxy;
		r_output.goal_maze = last_.goal;
		r_output.proxy_constraints = last_.active_constraints;
		r_output.proxy_placed = last_.placed;
	}
}

} // namespace haptics
