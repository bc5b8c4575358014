// The simulated device: a stylus held by a spring-damper hand, the rendered force acting on
// it, end stops, determinism, stability over the servo rates, and unplugging.

#include "devices/simulated_device.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <initializer_list>

using namespace haptics;

namespace {

// Drives the device like the servo does, with a constant rendered force.
DeviceState run(SimulatedDevice &r_device, double p_rate_hz, double p_seconds, const Vec3 &p_force,
		double *r_max_x = nullptr) {
	const double dt = 1.0 / p_rate_hz;
	DeviceState state;
	for (int k = 0; k < static_cast<int>(std::lround(p_seconds * p_rate_hz)); ++k) {
		r_device.begin_tick(dt);
		REQUIRE(r_device.read_state(state) == DeviceIo::OK);
		REQUIRE(r_device.write_force({ p_force, {} }) == DeviceIo::OK);
		if (r_max_x) {
			*r_max_x = std::max(*r_max_x, state.position_m.x);
		}
	}
	return state;
}

} // namespace

TEST_CASE("simulated device: Omni-like limits and a name") {
	SimulatedDevice device;
	const DeviceLimits limits = device.limits();
	CHECK(limits.workspace_radius_m == 0.10);
	CHECK(limits.max_force_n == 3.3);
	CHECK(limits.max_stiffness_n_per_m == 700.0);
	CHECK(std::strlen(device.name()) > 0);
	CHECK(device.has_hand());
}

TEST_CASE("simulated device: the hand pulls the stylus to its target") {
	SimulatedDevice device;
	REQUIRE(device.open());
	REQUIRE(device.set_hand_target({ 0.03, -0.02, 0.01 }));
	const DeviceState state = run(device, 1000.0, 2.0, {});
	CHECK(state.position_m.x == doctest::Approx(0.03).epsilon(1e-6));
	CHECK(state.position_m.y == doctest::Approx(-0.02).epsilon(1e-6));
	CHECK(state.position_m.z == doctest::Approx(0.01).epsilon(1e-6));
	CHECK(length(state.velocity_m_per_s) < 1e-6);
}

TEST_CASE("simulated device: a rendered force pushes the stylus off the hand's target") {
	SimulatedDevice device;
	REQUIRE(device.open());
	REQUIRE(device.set_hand_target({ 0.05, 0.0, 0.0 }));
	const DeviceState state = run(device, 1000.0, 2.0, { -1.5, 0.0, 0.0 });
	// Equilibrium: k_h (target - x) = 1.5 N -> x = 0.05 - 1.5 / 300.
	CHECK(state.position_m.x == doctest::Approx(0.045).epsilon(1e-6));
}

TEST_CASE("simulated device: stable and convergent at 250 to 4000 Hz, even with a stiff hand") {
	for (const double rate : { 250.0, 1000.0, 4000.0 }) {
		for (const double stiffness : { 300.0, 1e5 }) {
			CAPTURE(rate);
			CAPTURE(stiffness);
			SimulatedDeviceConfig config;
			config.hand_stiffness_n_per_m = stiffness;
			SimulatedDevice device(config);
			REQUIRE(device.open());
			REQUIRE(device.set_hand_target({ 0.08, 0.0, 0.0 }));
			double max_x = 0.0;
			const DeviceState state = run(device, rate, 3.0, {}, &max_x);
			CHECK(state.position_m.x == doctest::Approx(0.08).epsilon(1e-6));
			CHECK(max_x <= 0.1 + 1e-12); // Never beyond the end stop, never blowing up.
			CHECK(is_finite(state.position_m));
		}
	}
}

TEST_CASE("simulated device: end stops hold the stylus on the workspace sphere") {
	SimulatedDevice device;
	REQUIRE(device.open());
	REQUIRE(device.set_hand_target({ 0.0, 0.0, 0.5 }));
	const DeviceState state = run(device, 1000.0, 1.0, {});
	CHECK(length(state.position_m) == doctest::Approx(0.1));
	CHECK(state.position_m.z == doctest::Approx(0.1));
	CHECK(device.set_hand_target({ 0.0, 2.0, 0.0 }).code() == StatusCode::OUT_OF_RANGE);
	CHECK(device.set_hand_target({ NAN, 0.0, 0.0 }).code() == StatusCode::INVALID_ARGUMENT);
}

TEST_CASE("simulated device: deterministic under the same script") {
	const auto script = [] {
		SimulatedDevice device;
		REQUIRE(device.open());
		DeviceState state;
		for (int k = 0; k < 2000; ++k) {
			if (k % 100 == 0) {
				REQUIRE(device.set_hand_target({ 0.001 * (k % 700) / 10.0, -0.03, 0.0 }));
			}
			device.begin_tick(0.001);
			REQUIRE(device.read_state(state) == DeviceIo::OK);
			REQUIRE(device.write_force({ { -0.1 * std::sin(k * 0.01), 0.2, 0.0 }, {} }) == DeviceIo::OK);
		}
		return state.position_m;
	};
	const Vec3 a = script();
	const Vec3 b = script();
	CHECK(std::memcmp(&a, &b, sizeof(Vec3)) == 0);
}

TEST_CASE("simulated device: unplugging gives clear errors, plugging back in works") {
	SimulatedDevice device;
	REQUIRE(device.open());
	device.set_plugged(false);
	DeviceState state;
	CHECK(device.read_state(state) == DeviceIo::DISCONNECTED);
	CHECK(device.write_zero() == DeviceIo::DISCONNECTED);
	device.close();
	const Status reopen = device.open();
	CHECK(reopen.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(std::strstr(reopen.message(), "unplugged") != nullptr);
	device.set_plugged(true);
	CHECK(device.open());
	CHECK(device.read_state(state) == DeviceIo::OK);
}

TEST_CASE("simulated device: configuration is validated by name") {
	SimulatedDeviceConfig config;
	config.stylus_mass_kg = 0.0;
	const Status status = validate_simulated_device_config(config);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::strstr(status.message(), "simulated_device.stylus_mass_kg") != nullptr);
	config = SimulatedDeviceConfig{};
	config.hand_damping_n_s_per_m = INFINITY;
	CHECK(validate_simulated_device_config(config).code() == StatusCode::INVALID_ARGUMENT);
	HapticsSystem system;
	CHECK_FALSE(system.open_simulated_device(config));
	CHECK_FALSE(system.has_device());
}

TEST_CASE("engine + simulated device: pushing into a wall moves the stylus back off the hand's target") {
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	ForceModelConfig model;
	model.default_contact = ContactMaterial{ 2.0, 1.0 };
	REQUIRE(reconfigure(system, [&](RenderConfig &c) { // Default smoothing and safety.
		c.movement.force_model = model;
		c.servo.input.dead_zone = 0.0;
	}));
	REQUIRE(system.set_hand_target({ 0.05, 0.0, 0.0 }));
	Frame wall;
	add_contact(wall, { -1.0, 0.0, 0.0 }); // A wall on the right; normal points back at the player.
	for (int k = 0; k < 3000; ++k) {
		if (k % 20 == 0) {
			REQUIRE(system.submit_frame(wall));
		}
		REQUIRE(system.step(0.001));
	}
	// The stylus settles where the hand's spring balances the rendered force
	// F = -k x / R: 300 (0.05 - x) = 2 x / 0.1  ->  x = 15 / 320 = 0.046875 m, F = -0.9375 N.
	const Vec3 position = system.device_position();
	CHECK(position.x == doctest::Approx(0.046875).epsilon(1e-4));
	CHECK(position.x < 0.05);
	CHECK(system.forces().total.x == doctest::Approx(-0.9375).epsilon(1e-3));
	CHECK(system.input_vector().x == doctest::Approx(0.46875).epsilon(1e-4));

	// Without the wall the stylus goes all the way to the hand.
	for (int k = 0; k < 3000; ++k) {
		if (k % 20 == 0) {
			REQUIRE(system.submit_frame(Frame{}));
		}
		REQUIRE(system.step(0.001));
	}
	CHECK(system.device_position().x == doctest::Approx(0.05).epsilon(1e-4));
	CHECK(length(system.forces().total) < 1e-4);
}
