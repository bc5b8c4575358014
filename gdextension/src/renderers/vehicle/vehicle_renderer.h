#pragma once

// A car's steering as the servo renders it on a wheel device (render mode VEHICLE): the game
// measures its steered wheels each physics frame (VehicleFrame: load, slip angle, speed,
// surface) and the servo turns them into the rim force every tick, on the device's x axis
// (a wheel's one axis; a stick's or a stylus's x):
//
//   aligning  -g sum_w fade(v) M_kp(F_z, alpha_w, mu)      (brush_tyre.h)
//             alpha_w = delta(x) - psi_w                   steered by the device
//             delta(x) = -x steer_lock                     (x: the input vector's, right +)
//             psi_w = steer_angle - slip_angle_w           the contact's velocity direction
//             g = peak_force / (n F_ref |M_kp|max per load)  (the axle's peak felt as peak_force)
//             fade(v) = min(1, v / low_speed)
//   damping   -b dx/dt                                      (x differentiated, low-passed)
//   texture   kerb ripples and roughness                    (road_texture.h)
//
// Why alpha moves with the device: the torque depends on the steering angle, and the hand
// turns the wheel between frames. Taking delta from the device at every tick closes that
// dependence (the tyres' centring stiffness, dM/d delta) at 1 kHz; from the frame alone it
// would be a spring delayed by a frame, which a stiff wheel turns into a buzz. The frame's
// own measurements (psi, load, grip, speed) step at the frame rate and reach the model
// through a first-order low-pass (input_filter_hz), which adds no lag to the hand's loop.
// The load is capped first at max_load_ratio times the frame's reference load (the car's
// weight over its wheels), so a landing's moment of three times that is no spike.
//
// Sign: M_kp > 0 turns the wheels left (VehicleBody3D.steering's sense), the device's +x is
// right, so the rim force is -g M_kp: in a left turn the tyres pull the rim back to the right,
// toward straight ahead.
//
// Its state for the game (VehicleState) is stored every tick while active. The game's frame is
// its watchdog heartbeat (heard_from_game). Until the first frame it renders nothing. 3D or
// not does not matter: it renders x alone; planar() stays true, so a 3-DOF stylus used as a
// wheel is held in the screen's plane. No allocation.

#include "core/render/renderer.h"
#include "core/render/renderer_info.h"
#include "core/render/settings_inbox.h"
#include "renderers/vehicle/brush_tyre.h"
#include "renderers/vehicle/road_texture.h"
#include "renderers/vehicle/vehicle_channels.h"
#include "renderers/vehicle/vehicle_port.h"

#include <array>
#include <cstdint>

namespace haptics {

// Its force components (VehicleForce) and telemetry flags (TELEMETRY_FLAG_VEHICLE_MODE,
// TELEMETRY_FLAG_FRONT_LETTING_GO, TELEMETRY_FLAG_RIPPLE): vehicle.schema.toml.
static_assert(TELEMETRY_FLAG_VEHICLE_MODE >= (1u << FIRST_RENDERER_FLAG_BIT));

class VehicleRenderer final : public Renderer {
public:
	using Config = VehicleConfig;
	using Channels = VehicleChannels;
	using Port = VehiclePort;
	static const RendererInfo &info();

	// The steering damper's velocity estimate is low-passed at this cutoff.
	static constexpr double VELOCITY_FILTER_HZ = 40.0;

	explicit VehicleRenderer(VehicleChannels &r_channels);

	void pick_up_settings(double p_dt_s, bool p_restart) override;
	void begin_session(double p_dt_s) override;
	void reset() override;
	void pick_up() override;
	bool heard_from_game() const override { return heard_from_game_; }
	void render(const RenderInput &p_input, RenderResult &r_result) override;
	void publish(const ForceComponents &p_forces, bool p_active) override;

private:
	// One steered wheel's measurements as the model takes them, after the input filter.
	struct Filtered {
		double velocity_angle_rad = 0.0; // psi
		double load_n = 0.0;
		double grip = 0.0;
		double speed_m_per_s = 0.0;
	};

	void follow_frame(double p_dt_s);
	double aligning_torque(double p_steer_angle_rad);

	VehicleChannels &channels_;
	SettingsInbox<VehicleConfig> inbox_;
	VehicleConfig config_;
	BrushTyre tyre_;
	RoadTexture texture_;

	VehicleFrame frame_; // The latest the game sent.
	uint64_t frame_version_ = 0; // Of channels_.frame, last taken.
	uint64_t frames_ = 0;
	bool have_frame_ = false;
	bool heard_from_game_ = false;
	bool filters_primed_ = false;

	std::array<Filtered, VEHICLE_MAX_STEERED_WHEELS> wheels_{};
	double steer_angle_rad_ = 0.0; // The frame's delta, filtered.

	double last_x_ = 0.0;
	double x_velocity_ = 0.0; // Input units per second, filtered.
	bool have_x_ = false;

	VehicleState state_;
};

} // namespace haptics
