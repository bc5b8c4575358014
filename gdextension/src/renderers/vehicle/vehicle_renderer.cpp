#include "renderers/vehicle/vehicle_renderer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace haptics {

namespace {

// Seqlock's constructor publishes a default value: version 1 means "nothing sent yet".
constexpr uint64_t UNTOUCHED_VERSION = 1;

// The fastest the damper believes the input moves, full deflections a second: a jump of the
// reading (a device reopened) is no spin of the wheel to brake.
constexpr double MAX_INPUT_SPEED = 20.0;

constexpr uint32_t FLAGS[] = { TELEMETRY_FLAG_VEHICLE_MODE, TELEMETRY_FLAG_FRONT_LETTING_GO, TELEMETRY_FLAG_RIPPLE };

// The share of the way a first-order low-pass at p_cutoff_hz moves toward its input in p_dt_s.
double low_pass_step(double p_cutoff_hz, double p_dt_s) {
	return 1.0 - std::exp(-2.0 * std::numbers::pi * p_cutoff_hz * p_dt_s);
}

} // namespace

const RendererInfo &VehicleRenderer::info() {
	static const RendererInfo INFO{ VEHICLE_FORCE_NAMES, FLAGS };
	return INFO;
}

VehicleRenderer::VehicleRenderer(VehicleChannels &r_channels) :
		channels_(r_channels), inbox_(r_channels.settings) {}

void VehicleRenderer::pick_up_settings(double p_dt_s, bool p_restart) {
	(void)p_dt_s;
	if (inbox_.take(config_, p_restart)) {
		tyre_ = BrushTyre{ config_.cornering_coefficient_per_rad, config_.contact_half_length_m,
			config_.mechanical_trail_m };
	}
}

void VehicleRenderer::begin_session(double p_dt_s) {
	(void)p_dt_s;
	frame_version_ = 0; // The latest frame, even one sent before this session, is taken again.
	frames_ = 0;
	have_frame_ = false;
	heard_from_game_ = false;
	reset();
}

void VehicleRenderer::reset() {
	texture_.reset();
	filters_primed_ = false;
	have_x_ = false;
	x_velocity_ = 0.0;
	state_ = VehicleState{};
	state_.frames = frames_;
}

void VehicleRenderer::pick_up() {
	heard_from_game_ = false;
	const uint64_t latest = channels_.frame.version();
	if (latest == frame_version_ || latest <= UNTOUCHED_VERSION) {
		return;
	}
	uint64_t version = 0;
	if (channels_.frame.try_load(frame_, &version)) {
		frame_version_ = version;
		have_frame_ = true;
		heard_from_game_ = true;
		++frames_;
	}
}

void VehicleRenderer::follow_frame(double p_dt_s) {
	const double k = filters_primed_ ? low_pass_step(config_.input_filter_hz, p_dt_s) : 1.0;
	filters_primed_ = true;
	steer_angle_rad_ += k * (frame_.steer_angle_rad - steer_angle_rad_);
	// A landing presses a suspension to several times its standing load for a moment; the
	// rack would pass that to the hand as a spike to the device's limit. Capped before the
	// filter, so the filtered load never exceeds the cap either.
	const double max_load = config_.max_load_ratio * frame_.reference_load_n;
	for (size_t w = 0; w < frame_.wheels.size(); ++w) {
		const TyreContact &contact = frame_.wheels[w];
		Filtered &wheel = wheels_[w];
		// A wheel in the air carries no load: it fades out and back in through the filter.
		const double load = contact.in_contact ? std::min(contact.load_n, max_load) : 0.0;
		wheel.velocity_angle_rad += k * ((frame_.steer_angle_rad - contact.slip_angle_rad) - wheel.velocity_angle_rad);
		wheel.load_n += k * (load - wheel.load_n);
		wheel.grip += k * (contact.grip - wheel.grip);
		wheel.speed_m_per_s += k * (contact.speed_m_per_s - wheel.speed_m_per_s);
	}
}

double VehicleRenderer::aligning_torque(double p_steer_angle_rad) {
	double torque = 0.0;
	double lateral = 0.0;
	double slide = 0.0;
	double fade_sum = 0.0;
	double faded = 0.0;
	for (size_t w = 0; w < frame_.wheels.size(); ++w) {
		const Filtered &wheel = wheels_[w];
		const double alpha = std::clamp(p_steer_angle_rad - wheel.velocity_angle_rad, -MAX_SLIP_ANGLE_RAD,
				MAX_SLIP_ANGLE_RAD);
		const TyreForces forces =
				brush_tyre_forces(tyre_, wheel.load_n, alpha, wheel.grip, frame_.wheels[w].rolling_backward);
		const double fade = std::min(1.0, wheel.speed_m_per_s / config_.low_speed_m_per_s);
		torque += forces.kingpin_torque_nm;
		lateral += forces.lateral_force_n;
		faded += fade * forces.kingpin_torque_nm;
		fade_sum += fade;
		slide = std::max(slide, wheel.load_n > 0.0 ? forces.slide_fraction : 0.0);
	}
	const double count = static_cast<double>(frame_.wheels.size());
	state_.aligning_torque_nm = torque;
	state_.lateral_force_n = lateral;
	state_.slide_fraction = slide;
	state_.speed_fade = count > 0.0 ? fade_sum / count : 0.0;
	state_.peak_torque_nm = count * frame_.reference_load_n * brush_peak_torque_per_load(tyre_);
	return faded;
}

void VehicleRenderer::render(const RenderInput &p_input, RenderResult &r_result) {
	ForceComponents &forces = r_result.forces;
	forces.parts.fill(Vec3{});
	r_result.flags = TELEMETRY_FLAG_VEHICLE_MODE;

	// The steering damper works from the first tick, frame or not.
	const double x = p_input.input.x;
	if (have_x_) {
		const double k = low_pass_step(VELOCITY_FILTER_HZ, p_input.dt_s);
		const double raw = std::clamp((x - last_x_) / p_input.dt_s, -MAX_INPUT_SPEED, MAX_INPUT_SPEED);
		x_velocity_ += k * (raw - x_velocity_);
	}
	last_x_ = x;
	have_x_ = true;
	const double damping = -config_.damping_n_s * x_velocity_;

	double aligning = 0.0;
	RoadTexture::Sample texture;
	if (have_frame_) {
		follow_frame(p_input.dt_s);
		const double steer = frame_.steered_by_device ? -x * frame_.steer_lock_rad : steer_angle_rad_;
		const double torque = aligning_torque(steer);
		const double peak = state_.peak_torque_nm;
		const double gain = peak > 0.0 ? config_.peak_force_n / peak : 0.0;
		aligning = -gain * torque;
		texture = texture_.advance(frame_, config_.roughness_speed_m_per_s, p_input.dt_s);
		state_.steer_angle_rad = steer;
		const bool letting_go = state_.slide_fraction > brush_peak_slide_fraction(tyre_);
		r_result.flags |= (letting_go ? TELEMETRY_FLAG_FRONT_LETTING_GO : 0u) |
				(texture.fastest_ripple_hz > 0.0 ? TELEMETRY_FLAG_RIPPLE : 0u);
	}
	state_.rim_force_n = aligning;
	state_.texture_n = texture.force_n;
	state_.ripple_hz = texture.fastest_ripple_hz;
	state_.frames = frames_;

	forces.parts[ALIGNING_FORCE] = Vec3(aligning, 0.0, 0.0);
	forces.parts[DAMPING_FORCE] = Vec3(damping, 0.0, 0.0);
	forces.parts[TEXTURE_FORCE] = Vec3(texture.force_n, 0.0, 0.0);
	forces.continuous = Vec3(aligning + damping + texture.force_n, 0.0, 0.0);
	// Not filtered: the torque's dependence on the hand is a position loop (see the header);
	// the frame's steps were filtered before the model.
	r_result.continuous = forces.continuous;
}

void VehicleRenderer::publish(const ForceComponents &p_forces, bool p_active) {
	(void)p_forces;
	if (p_active) {
		channels_.state.store(state_);
	}
}

} // namespace haptics
