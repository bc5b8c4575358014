#include "core/servo/servo_pipeline.h"

#include "core/servo/input_vector.h"

#include <limits>

namespace haptics {

namespace {

// Seqlock's constructor publishes a default value: version 1 means "nothing submitted yet".
constexpr uint64_t UNTOUCHED_VERSION = 1;

void scale_forces(ForceComponents &r_forces, double p_scale) {
	for (Vec3 &part : r_forces.parts) {
		part = part * p_scale;
	}
	r_forces.continuous = r_forces.continuous * p_scale;
}

} // namespace

ServoPipeline::ServoPipeline(ServoChannels &r_channels, std::span<Renderer *const> p_renderers) :
		channels_(r_channels), renderers_(p_renderers) {}

void ServoPipeline::begin_session(HapticDevice *p_device, double p_dt_s) {
	device_ = p_device;
	capabilities_ = p_device->capabilities();
	limits_ = capabilities_.limits;
	dt_s_ = p_dt_s;
	time_s_ = 0.0;
	tick_ = 0;

	config_version_ = 0;
	ServoConfig config = channels_.config.load();
	channels_.config.try_load(config, &config_version_);
	apply_config(config);
	for (Renderer *renderer : renderers_) {
		renderer->pick_up_settings(dt_s_, true);
	}
	for (Renderer *renderer : renderers_) {
		renderer->begin_session(dt_s_);
	}
	safety_.reset();
	transients_ = TransientBank{};
	peak_.reset();

	// The latest frame, even one submitted before this session, is picked up by the first
	// tick as if it had just arrived; the watchdog takes over if no newer one follows.
	submitted_ = GameFrame{};
	frame_version_ = UNTOUCHED_VERSION;
	have_heartbeat_ = false;
	last_heartbeat_s_ = 0.0;
	new_frame_ = false;
	frames_received_ = 0;

	telemetry_drops_ = 0;
	clamped_ticks_ = 0;
	non_finite_ticks_ = 0;
	telemetry_countdown_ = 0;
}

bool ServoPipeline::apply_config(const ServoConfig &p_config) {
	const bool switched = p_config.render_mode != config_.render_mode;
	config_ = p_config;
	input_radius_m_ = config_.input.input_radius_m > 0.0 ? config_.input.input_radius_m : limits_.workspace_radius_m;
	// The continuous rating protects motors; a simulation has none, and its forces stay
	// as the game was tuned (peak limit only).
	const bool physical = capabilities_.physical;
	safety_.configure(config_.safety,
			SafetyDevice{ limits_.max_force_n, physical ? limits_.max_continuous_force_n : 0.0, physical });
	return switched;
}

void ServoPipeline::pick_up_inputs(bool p_period_changed) {
	bool switched = false;
	bool configured = p_period_changed;
	if (channels_.config.version() != config_version_) {
		ServoConfig config;
		uint64_t version = 0;
		if (channels_.config.try_load(config, &version)) {
			config_version_ = version;
			switched = apply_config(config);
			configured = true;
		}
	}
	// The servo's configuration is published after every renderer's settings and with every
	// change of them (servo_channels.h), so the renderers look at theirs only then.
	if (configured) {
		for (Renderer *renderer : renderers_) {
			renderer->pick_up_settings(dt_s_, false);
		}
	}
	if (switched) {
		active().reset(); // Each mode starts from rest; the slew limiter smooths the hand-over.
	}
	new_frame_ = false;
	if (channels_.frame.version() != frame_version_) {
		uint64_t version = 0;
		if (channels_.frame.try_load(submitted_, &version)) {
			frame_version_ = version;
			new_frame_ = true;
			++frames_received_;
		}
	}
	// Bounded by the queue's capacity.
	ImpactEvent event;
	while (channels_.impacts.try_pop(event)) {
		transients_.add(event, config_.default_impact, config_.safety.max_impact_force_n,
				config_.safety.force_scale);
	}
	for (Renderer *renderer : renderers_) {
		renderer->pick_up();
	}
	if (new_frame_ || active().heard_from_game()) {
		have_heartbeat_ = true;
		last_heartbeat_s_ = time_s_;
		peak_.next_window();
	}
}

DeviceIo ServoPipeline::tick(double p_dt_s) {
	const bool period_changed = p_dt_s != dt_s_; // Manual stepping may; the renderers follow.
	dt_s_ = p_dt_s;
	device_->begin_tick(p_dt_s);
	DeviceState state;
	const DeviceIo read = device_->read_state(state);
	if (read != DeviceIo::OK) {
		return read;
	}
	++tick_;
	time_s_ += p_dt_s;
	pick_up_inputs(period_changed);
	const bool game_3d = submitted_.space == GameSpace::SPACE;
	const bool on_ground = game_3d && capabilities_.input_dof == 2;
	if (on_ground) {
		state.position_m = stick_to_ground(state.position_m);
		state.velocity_m_per_s = stick_to_ground(state.velocity_m_per_s);
	}

	const Vec3 input = input_vector(state.position_m, input_radius_m_, config_.input.dead_zone);
	const RenderInput render_input{ state, input, submitted_.frame, new_frame_, p_dt_s, limits_.workspace_radius_m,
		capabilities_.has_orientation };
	active().render(render_input, rendered_);
	const double scale = config_.safety.force_scale;
	if (scale != 1.0) {
		scale_forces(rendered_.forces, scale);
	}

	ForceComponents &forces = rendered_.forces;
	const Vec3 impact = transients_.advance(p_dt_s);
	Vec3 continuous = scale != 1.0 ? rendered_.continuous * scale : rendered_.continuous;
	if (!game_3d && capabilities_.input_dof >= 3 && active().planar() && config_.plane_hold.stiffness_n_per_m > 0.0) {
		continuous.z += -config_.plane_hold.stiffness_n_per_m * state.position_m.z -
				config_.plane_hold.damping_n_s_per_m * state.velocity_m_per_s.z;
	}
	const double frame_age = have_heartbeat_ ? time_s_ - last_heartbeat_s_ : std::numeric_limits<double>::infinity();
	const SafetyResult safety = safety_.apply(continuous, impact, frame_age, p_dt_s, state.ready);
	forces.smoothed = safety.continuous;
	forces.impact = impact;
	forces.total = safety.total;
	peak_.add(safety.total, p_dt_s);
	forces.peak = peak_.peak();

	const DeviceIo written = device_->write_force(on_ground ? ForceCommand{ ground_to_stick(safety.total),
																	  ground_to_stick(safety.impact) }
															: ForceCommand{ safety.total, safety.impact });
	if (written != DeviceIo::OK) {
		return written;
	}
	clamped_ticks_ += safety.clamped ? 1 : 0;
	non_finite_ticks_ += safety.non_finite ? 1 : 0;
	publish(state, input, forces, safety, rendered_.flags);
	return DeviceIo::OK;
}

void ServoPipeline::publish(const DeviceState &p_state, const Vec3 &p_input, const ForceComponents &p_forces,
		const SafetyResult &p_safety, uint32_t p_renderer_flags) {
	uint32_t flags = p_renderer_flags;
	flags |= !submitted_.frame.contacts.empty() ? TELEMETRY_FLAG_CONTACT : 0u;
	flags |= submitted_.frame.in_water ? TELEMETRY_FLAG_IN_WATER : 0u;
	flags |= p_safety.watchdog_tripped ? TELEMETRY_FLAG_WATCHDOG : 0u;
	flags |= p_safety.clamped ? TELEMETRY_FLAG_CLAMPED : 0u;
	flags |= p_safety.ramp_gain < 1.0 ? TELEMETRY_FLAG_RAMPING : 0u;
	flags |= p_safety.non_finite ? TELEMETRY_FLAG_NON_FINITE : 0u;
	flags |= new_frame_ ? TELEMETRY_FLAG_NEW_FRAME : 0u;

	if (config_.telemetry.enabled) {
		if (telemetry_countdown_ == 0) {
			const TelemetrySample sample = make_telemetry_sample(time_s_, p_input, p_state.position_m, p_forces, flags);
			if (!channels_.telemetry.try_push(sample)) {
				++telemetry_drops_;
			}
			telemetry_countdown_ = config_.telemetry.decimation;
		}
		--telemetry_countdown_;
	}

	ServoOutput output;
	output.time_s = time_s_;
	output.tick = tick_;
	output.input = p_input;
	output.position_m = p_state.position_m;
	output.buttons = p_state.buttons;
	output.flags = flags;
	output.forces = p_forces;
	output.frame_age_s = have_heartbeat_ ? time_s_ - last_heartbeat_s_ : -1.0;
	output.ramp_gain = p_safety.ramp_gain;
	output.watchdog_gain = p_safety.watchdog_gain;
	output.frames_received = frames_received_;
	output.bank_drops = transients_.drops();
	output.telemetry_drops = telemetry_drops_;
	output.clamped_ticks = clamped_ticks_;
	output.non_finite_ticks = non_finite_ticks_;
	output.render_mode = config_.render_mode;
	for (size_t mode = 0; mode < renderers_.size(); ++mode) {
		renderers_[mode]->publish(p_forces, mode == static_cast<size_t>(config_.render_mode));
	}
	channels_.output.store(output);
}

} // namespace haptics
