// Impact transients: A(v) e^(-t/tau) sin(2 pi f t) along a direction, superposed, bounded,
// and overlaid raw on the smoothed continuous force.

#include "core/servo/transients.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace haptics;

namespace {

constexpr double PI = std::numbers::pi;

ImpactEvent impact(const Vec3 &p_direction, double p_speed, double p_gain, double p_frequency_hz, double p_decay_s) {
	ImpactEvent event;
	event.direction = p_direction;
	event.speed_m_per_s = p_speed;
	event.material = ImpactMaterial{ p_gain, p_frequency_hz, p_decay_s };
	return event;
}

double expected(double p_amplitude, double p_frequency_hz, double p_decay_s, double p_t) {
	return p_amplitude * std::exp(-p_t / p_decay_s) * std::sin(2.0 * PI * p_frequency_hz * p_t);
}

} // namespace

TEST_CASE("transient: every sample is A e^(-t/tau) sin(2 pi f t) along the unit direction") {
	TransientBank bank;
	const double dt = 1.0 / 4000.0;
	// A = gain * speed = 0.5 N s/m * 4 m/s = 2 N; direction given unnormalised.
	CHECK(bank.add(impact({ 0.0, 3.0, 0.0 }, 4.0, 0.5, 100.0, 0.03), ImpactMaterial{}, 10.0));
	for (int k = 1; k <= 400; ++k) {
		const Vec3 value = bank.advance(dt);
		const double t = k * dt;
		CHECK(value.x == 0.0);
		CHECK(value.z == 0.0);
		CHECK(std::abs(value.y - expected(2.0, 100.0, 0.03, t)) < 1e-9);
	}
}

TEST_CASE("transient: peak, frequency by zero crossings, and decay") {
	TransientBank bank;
	const double rate = 4000.0;
	const double dt = 1.0 / rate;
	const double amplitude = 2.0, frequency = 100.0, decay = 0.03;
	bank.add(impact({ 1.0, 0.0, 0.0 }, 4.0, 0.5, frequency, decay), ImpactMaterial{}, 10.0);
	std::vector<double> samples;
	for (int k = 1; k <= static_cast<int>(5 * decay * rate); ++k) {
		samples.push_back(bank.advance(dt).x);
	}

	// Peak: the analytic maximum of the first lobe, at t = atan(2 pi f tau) / (2 pi f).
	const double omega = 2.0 * PI * frequency;
	const double t_peak = std::atan(omega * decay) / omega;
	const double analytic_peak = amplitude * std::exp(-t_peak / decay) * std::sin(omega * t_peak);
	double sampled_peak = 0.0;
	for (const double s : samples) {
		sampled_peak = std::max(sampled_peak, std::abs(s));
	}
	CHECK(sampled_peak == doctest::Approx(analytic_peak).epsilon(0.005)); // 4 kHz: 9 degree steps.
	CHECK(sampled_peak <= analytic_peak + 1e-12);

	// Frequency: interpolated zero crossings, two per period.
	std::vector<double> crossings;
	for (size_t n = 1; n < samples.size(); ++n) {
		if ((samples[n - 1] < 0.0) != (samples[n] < 0.0)) {
			const double fraction = samples[n - 1] / (samples[n - 1] - samples[n]);
			crossings.push_back((static_cast<double>(n) + fraction) * dt); // Sample n is at (n + 1) dt.
		}
	}
	REQUIRE(crossings.size() >= 20);
	const double measured_frequency =
			static_cast<double>(crossings.size() - 1) / (2.0 * (crossings.back() - crossings.front()));
	CHECK(measured_frequency == doctest::Approx(frequency).epsilon(0.01));

	// Decay: quarter periods (every 40 samples from sample 10, t = 2.5 ms + m 10 ms) land on
	// sin = 1, so they are the envelope itself.
	const double first = samples[9];
	const double fifth = samples[9 + 4 * 40];
	const double measured_decay = (4.0 * 0.01) / std::log(first / fifth);
	CHECK(measured_decay == doctest::Approx(decay).epsilon(1e-6));
	CHECK(first == doctest::Approx(amplitude * std::exp(-0.0025 / decay)).epsilon(1e-9));
}

TEST_CASE("transient: amplitude scales with speed and gain, capped at the maximum") {
	const auto first_sample = [](double p_speed, double p_gain, double p_max) {
		TransientBank bank;
		bank.add(impact({ 1.0, 0.0, 0.0 }, p_speed, p_gain, 250.0, 0.02), ImpactMaterial{}, p_max);
		return bank.advance(0.001).x;
	};
	const double unit = std::exp(-0.001 / 0.02) * std::sin(2.0 * PI * 250.0 * 0.001); // sin(pi/2) = 1
	CHECK(first_sample(1.0, 0.5, 10.0) == doctest::Approx(0.5 * unit));
	CHECK(first_sample(2.0, 0.5, 10.0) == doctest::Approx(1.0 * unit));
	CHECK(first_sample(2.0, 1.5, 10.0) == doctest::Approx(3.0 * unit));
	CHECK(first_sample(20.0, 1.5, 2.5) == doctest::Approx(2.5 * unit));
}

TEST_CASE("transient: the default material is used when the event asks for it") {
	TransientBank bank;
	ImpactEvent event;
	event.direction = { 0.0, 0.0, -1.0 };
	event.speed_m_per_s = 2.0;
	bank.add(event, ImpactMaterial{ 0.25, 250.0, 0.05 }, 10.0);
	CHECK(bank.advance(0.001).z == doctest::Approx(-0.5 * std::exp(-0.001 / 0.05)));
}

TEST_CASE("transient: concurrent transients superpose") {
	const ImpactEvent a = impact({ 1.0, 0.0, 0.0 }, 2.0, 0.5, 120.0, 0.03);
	const ImpactEvent b = impact({ 0.0, 1.0, 0.0 }, 1.0, 1.0, 300.0, 0.01);
	TransientBank both, only_a, only_b;
	both.add(a, ImpactMaterial{}, 10.0);
	only_a.add(a, ImpactMaterial{}, 10.0);
	for (int k = 0; k < 5; ++k) {
		both.advance(0.001);
		only_a.advance(0.001);
	}
	both.add(b, ImpactMaterial{}, 10.0); // Starts 5 ms later.
	only_b.add(b, ImpactMaterial{}, 10.0);
	CHECK(both.active_count() == 2);
	for (int k = 0; k < 100; ++k) {
		const Vec3 sum = both.advance(0.001);
		const Vec3 parts = only_a.advance(0.001) + only_b.advance(0.001);
		CHECK(std::abs(sum.x - parts.x) < 1e-12);
		CHECK(std::abs(sum.y - parts.y) < 1e-12);
	}
}

TEST_CASE("transient: expires once its envelope is negligible") {
	TransientBank bank;
	bank.add(impact({ 1.0, 0.0, 0.0 }, 4.0, 0.5, 100.0, 0.01), ImpactMaterial{}, 10.0);
	for (int k = 0; k < 150; ++k) { // 15 tau: 2 N e^-15 = 0.6 uN < EXPIRY_N.
		bank.advance(0.001);
	}
	CHECK(bank.active_count() == 0);
	CHECK(bank.advance(0.001) == Vec3{});
	// A zero-speed impact renders nothing and is not a drop.
	CHECK(bank.add(impact({ 1.0, 0.0, 0.0 }, 0.0, 0.5, 100.0, 0.01), ImpactMaterial{}, 10.0));
	CHECK(bank.active_count() == 0);
	CHECK(bank.drops() == 0);
}

TEST_CASE("transient: a full bank counts drops, keeps the strongest, never fails") {
	TransientBank bank;
	for (size_t n = 0; n < TransientBank::CAPACITY; ++n) {
		CHECK(bank.add(impact({ 1.0, 0.0, 0.0 }, 1.0, 0.1, 100.0, 0.05), ImpactMaterial{}, 10.0));
	}
	CHECK_FALSE(bank.add(impact({ 1.0, 0.0, 0.0 }, 1.0, 0.01, 100.0, 0.05), ImpactMaterial{}, 10.0)); // Weaker: lost.
	CHECK_FALSE(bank.add(impact({ 0.0, 1.0, 0.0 }, 1.0, 2.0, 250.0, 0.05), ImpactMaterial{}, 10.0)); // Stronger: kept.
	CHECK(bank.drops() == 2);
	CHECK(bank.active_count() == TransientBank::CAPACITY);
	const Vec3 value = bank.advance(0.001);
	// The strong one (2 N along y, sin(pi/2)) replaced one of the sixteen along x.
	CHECK(value.y == doctest::Approx(2.0 * std::exp(-0.001 / 0.05)));
	CHECK(value.x == doctest::Approx(15.0 * 0.1 * std::exp(-0.001 / 0.05) * std::sin(2.0 * PI * 100.0 * 0.001)));
}

TEST_CASE("engine: impacts are overlaid raw on the smoothed continuous force") {
	HapticsSystem system;
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(system.open_simulated_device(device));
	REQUIRE(system.set_hand_target({ 0.0, -0.05, 0.0 })); // Pressing down: i = (0, -0.5, 0).
	ForceModelConfig model;
	model.default_contact = ContactMaterial{ 2.0, 1.0 };
	REQUIRE(reconfigure(system, [&](RenderConfig &c) {
		c.movement.force_model = model;
		c.servo.input.dead_zone = 0.0;
	}));
	SafetyConfig safety;
	safety.startup_ramp_s = 0.0;
	safety.slew_rate_n_per_s = 0.0;
	REQUIRE(reconfigure(system, [&](RenderConfig &c) { c.servo.safety = safety; }));

	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 }); // Landing on a floor: continuous force steps to 1 N up.
	REQUIRE(system.submit_frame(frame));
	REQUIRE(system.push_impact(impact({ 0.0, 1.0, 0.0 }, 3.0, 0.5, 250.0, 0.02)));
	const double dt = 0.001;
	for (int k = 1; k <= 20; ++k) {
		REQUIRE(system.step(dt));
		const ForceComponents f = system.forces();
		CHECK(f.continuous.y == doctest::Approx(1.0)); // Raw continuous: a step.
		CHECK(f.smoothed.y < 0.6); // Smoothed: still rising after 20 ms.
		const double raw = expected(1.5, 250.0, 0.02, k * dt);
		if (k == 1) { // The filter has barely moved; the impact is already at full strength.
			CHECK(f.smoothed.y < 0.01);
			CHECK(f.impact.y == doctest::Approx(1.5 * std::exp(-0.05)));
		}
		CHECK(f.impact.y == doctest::Approx(raw).epsilon(1e-9));
		CHECK(f.total.y == doctest::Approx(f.smoothed.y + raw).epsilon(1e-9));
	}
}
