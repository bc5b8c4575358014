#include "renderers/constraint/constraint_renderer.h"

namespace haptics {

namespace {

constexpr uint32_t FLAGS[] = { TELEMETRY_FLAG_CONSTRAINT_MODE, TELEMETRY_FLAG_PROXY_CONTACT };

} // namespace

const RendererInfo &ConstraintRenderer::info() {
	static const RendererInfo INFO{ CONSTRAINT_FORCE_NAMES, FLAGS };
	return INFO;
}

ConstraintRenderer::ConstraintRenderer(ConstraintChannels &r_channels) :
		channels_(r_channels), inbox_(r_channels.settings) {}

void ConstraintRenderer::pick_up_settings(double p_dt_s, bool p_restart) {
	(void)p_dt_s;
	if (inbox_.take(config_, p_restart)) {
		solver_.configure(config_);
	}
}

void ConstraintRenderer::begin_session(double p_dt_s) {
	(void)p_dt_s;
	reset();
	updates_ = 0;
}

void ConstraintRenderer::reset() {
	solver_.reset();
	last_ = ConstraintOutput{};
}

void ConstraintRenderer::pick_up() {
	channels_.geometry.acquire(); // Also while inactive, so the game's pending walls are taken.
}

void ConstraintRenderer::render(const RenderInput &p_input, RenderResult &r_result) {
	const GeometryExchange::Current geometry = channels_.geometry.current();
	const bool step = config_.update == ProxyUpdate::SERVO || p_input.new_frame;
	last_ = solver_.render(geometry.geometry, geometry.generation, p_input.device.position_m, p_input.device_radius_m,
			step);
	updates_ += last_.stepped ? 1 : 0;
	ForceComponents &forces = r_result.forces;
	forces.parts.fill(Vec3{});
	forces.parts[WALL_FORCE] = last_.force;
	forces.continuous = last_.force;
	r_result.continuous = last_.force; // Not filtered: see the header.
	r_result.flags = TELEMETRY_FLAG_CONSTRAINT_MODE | (last_.active_constraints > 0 ? TELEMETRY_FLAG_PROXY_CONTACT : 0u);
}

void ConstraintRenderer::publish(const ForceComponents &p_forces, bool p_active) {
	(void)p_forces;
	const GeometryExchange::Current geometry = channels_.geometry.current();
	if (!p_active && !published_active_ && geometry.generation == published_.geometry_generation &&
			updates_ == published_.updates) {
		return; // Inactive, and the walls are the ones the game already sees.
	}
	ProxyState state;
	state.geometry_generation = geometry.generation;
	state.geometry_segments = geometry.geometry ? static_cast<uint32_t>(geometry.geometry->segment_count()) : 0;
	state.updates = updates_;
	if (p_active) {
		state.proxy = last_.proxy;
		state.goal = last_.goal;
		state.constraints = last_.active_constraints;
		state.placed = last_.placed;
	}
	channels_.state.store(state);
	published_ = state;
	published_active_ = p_active;
}

} // namespace haptics
