#pragma once

// What the vehicle renderer's doctests share: a wheel (a 1-DOF device whose angle the test
// sets, with an evdev wheel's nominal limits) in a HapticsSystem stepped by hand, in the
// vehicle mode, and a scripted skid-pad: a car on a circle at a constant speed, its front
// wheels' contact velocities from its yaw rate.

#include "renderers/vehicle/brush_tyre.h"
#include "renderers/vehicle/vehicle_port.h"
#include "renderers/vehicle/vehicle_renderer.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace haptics::test {

constexpr double VEHICLE_DT = 0.001;

// A steering wheel: its angle (-1 full left .. 1 full right) is where the test puts it, and the
// force it was last written is kept. The limits are the evdev backend's defaults for a wheel.
class TestWheel final : public HapticDevice {
public:
	static constexpr double RADIUS_M = 0.05;
	static constexpr double MAX_FORCE_N = 5.0;
	static constexpr double MAX_CONTINUOUS_N = 2.5;

	Status open() override {
		open_ = true;
		return Status::success();
	}
	void close() override { open_ = false; }
	bool is_open() const override { return open_; }
	Status calibrate() override { return Status::success(); }
	DeviceCapabilities capabilities() const override {
		DeviceCapabilities caps;
		caps.input_dof = 1;
		caps.output_dof = 1;
		caps.limits = DeviceLimits{ MAX_FORCE_N, MAX_CONTINUOUS_N, 300.0, RADIUS_M };
		caps.native_rate_hz = 0.0;
		caps.physical = true;
		return caps;
	}
	const char *name() const override { return "test wheel"; }
	DeviceIo read_state(DeviceState &r_state) override {
		r_state = DeviceState{};
		r_state.position_m = Vec3(angle * RADIUS_M, 0.0, 0.0);
		return DeviceIo::OK;
	}
	DeviceIo write_force(const ForceCommand &p_command) override {
		written = p_command.force_n;
		return DeviceIo::OK;
	}

	double angle = 0.0;
	Vec3 written;

private:
	bool open_ = false;
};

// The system with the wheel open, no ramp, no slew limit, no dead zone, in the vehicle mode.
struct VehicleRig {
	HapticsSystem system;
	TestWheel *wheel = nullptr;

	explicit VehicleRig(const VehicleConfig &p_config = VehicleConfig{}) {
		auto device = std::make_unique<TestWheel>();
		wheel = device.get();
		REQUIRE(system.open_device(std::move(device)));
		REQUIRE(reconfigure(system, [&](RenderConfig &c) {
			c.servo.safety.startup_ramp_s = 0.0;
			c.servo.safety.slew_rate_n_per_s = 0.0;
			c.servo.input.dead_zone = 0.0;
			c.vehicle = p_config;
			c.servo.render_mode = RenderMode::VEHICLE;
		}));
		// A physical device's session starts once the force is small (SafetyConfig::
		// start_force_n): one tick before any frame, as a game that opens the wheel first.
		REQUIRE(system.step(VEHICLE_DT));
	}

	VehiclePort port() { return VehiclePort(system.renderers().vehicle.channels); }

	// p_ticks ticks, the frame sent again every p_frame_every ticks (a 60 Hz game: 16 or 17).
	void run(int p_ticks, const VehicleFrame &p_frame, int p_frame_every = 16) {
		for (int t = 0; t < p_ticks; ++t) {
			if (t % p_frame_every == 0) {
				REQUIRE(port().set_frame(p_frame));
			}
			REQUIRE(system.step(VEHICLE_DT));
		}
	}

	double part(size_t p_part) const { return system.forces().parts[p_part].x; }
};

// A car on a skid-pad: its centre of mass on a circle of radius R, at speed V, turning left,
// its body slip angle beta (the velocity's angle left of its heading). The front axle is l_f
// ahead of the centre of mass, its wheels half a track either side. Car axes: x forward, y left.
struct SkidPad {
	double radius_m = 30.0;
	double speed_m_per_s = 12.0;
	double body_slip_rad = 0.0;
	double front_axle_m = 1.2;
	double half_track_m = 0.78;

	// The direction (rad, left of the car's heading) of the contact velocity of the front wheel
	// at lateral offset p_y_m (left positive): v_c = v_cg + r x (l_f, y).
	double velocity_angle(double p_y_m) const {
		const double yaw_rate = speed_m_per_s / radius_m;
		const double u = speed_m_per_s * std::cos(body_slip_rad) - yaw_rate * p_y_m;
		const double v = speed_m_per_s * std::sin(body_slip_rad) + yaw_rate * front_axle_m;
		return std::atan2(v, u);
	}
	double contact_speed(double p_y_m) const {
		const double yaw_rate = speed_m_per_s / radius_m;
		return std::hypot(speed_m_per_s * std::cos(body_slip_rad) - yaw_rate * p_y_m,
				speed_m_per_s * std::sin(body_slip_rad) + yaw_rate * front_axle_m);
	}

	// The frame a game sends with its front wheels steered to p_steer_rad: left wheel inner
	// (the turn is to the left), carrying p_inner_n, the right one p_outer_n.
	VehicleFrame frame(double p_steer_rad, double p_inner_n, double p_outer_n, double p_lock_rad) const {
		VehicleFrame out;
		out.steer_angle_rad = p_steer_rad;
		out.steer_lock_rad = p_lock_rad;
		out.steered_by_device = true;
		out.reference_load_n = 4000.0;
		const double sides[2] = { half_track_m, -half_track_m };
		const double loads[2] = { p_inner_n, p_outer_n };
		for (int w = 0; w < 2; ++w) {
			TyreContact contact;
			contact.in_contact = true;
			contact.load_n = loads[w];
			contact.slip_angle_rad = p_steer_rad - velocity_angle(sides[w]);
			contact.speed_m_per_s = contact_speed(sides[w]);
			contact.grip = 1.0;
			REQUIRE(out.wheels.push_back(contact));
		}
		return out;
	}
};

// The rim force the renderer should give for p_frame with the steered wheels at p_steer_rad:
// -peak_force / (n F_ref |M_kp|max per load) x sum M_kp, straight from the model, each load
// capped at max_load_ratio F_ref.
inline double expected_rim_force(const VehicleConfig &p_config, const VehicleFrame &p_frame, double p_steer_rad) {
	const BrushTyre tyre{ p_config.cornering_coefficient_per_rad, p_config.contact_half_length_m,
		p_config.mechanical_trail_m };
	const double max_load = p_config.max_load_ratio * p_frame.reference_load_n;
	double torque = 0.0;
	for (const TyreContact &contact : p_frame.wheels) {
		const double psi = p_frame.steer_angle_rad - contact.slip_angle_rad;
		const double fade = std::min(1.0, contact.speed_m_per_s / p_config.low_speed_m_per_s);
		const double load = contact.in_contact ? std::min(contact.load_n, max_load) : 0.0;
		torque += fade *
				brush_tyre_forces(tyre, load, p_steer_rad - psi, contact.grip, contact.rolling_backward)
						.kingpin_torque_nm;
	}
	const double peak = static_cast<double>(p_frame.wheels.size()) * p_frame.reference_load_n *
			brush_peak_torque_per_load(tyre);
	return -p_config.peak_force_n / peak * torque;
}

} // namespace haptics::test
