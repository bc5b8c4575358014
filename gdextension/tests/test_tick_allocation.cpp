// "No allocation inside a tick", checked rather than promised: the global operator new is
// replaced by one that counts calls made while this thread is inside a manual step. The
// threaded servo runs exactly the same ServoPipeline::tick. Skipped under the sanitizers,
// which bring their own allocator.

#include "renderers/pong/pong_port.h"
#include "renderers/vehicle/vehicle_port.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <new>

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define HAPTICS_COUNT_ALLOCATIONS 1

namespace {
thread_local bool t_watching = false;
thread_local unsigned long t_allocations = 0;
} // namespace

void *operator new(std::size_t p_size) {
	if (t_watching) {
		++t_allocations;
	}
	if (void *memory = std::malloc(p_size == 0 ? 1 : p_size)) {
		return memory;
	}
	throw std::bad_alloc();
}

void operator delete(void *p_memory) noexcept {
	std::free(p_memory);
}

void operator delete(void *p_memory, std::size_t) noexcept {
	std::free(p_memory);
}
#endif

using namespace haptics;

TEST_CASE("a tick allocates nothing, whatever it renders") {
#ifdef HAPTICS_COUNT_ALLOCATIONS
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	REQUIRE(system.set_hand_target({ 0.04, -0.03, 0.0 }));
	unsigned long allocations = 0;
	for (int k = 0; k < 2000; ++k) {
		if (k % 20 == 0) {
			Frame frame;
			add_contact(frame, { 0.0, 1.0, 0.0 });
			add_contact(frame, { -1.0, 0.2, 0.0 });
			add_resting(frame, { 0.0, -1.0, 0.0 }, 0.5);
			set_water(frame, k > 1000, 0.4, 0.2);
			REQUIRE(system.submit_frame(frame));
		}
		if (k % 50 == 0) {
			ImpactEvent event;
			event.direction = { 0.0, 1.0, 0.0 };
			event.speed_m_per_s = 3.0;
			REQUIRE(system.push_impact(event));
		}
		t_allocations = 0;
		t_watching = true;
		const Status status = system.step(0.001);
		t_watching = false;
		allocations += t_allocations;
		REQUIRE(status);
	}
	CHECK(allocations == 0);
	// The counter works: an allocation while watching is seen.
	t_allocations = 0;
	t_watching = true;
	int *volatile probe = new int(3); // volatile: the allocation may not be elided.
	t_watching = false;
	delete probe;
	CHECK(t_allocations == 1);
#else
	MESSAGE("allocation counting is off under sanitizers");
#endif
}

TEST_CASE("a pong tick allocates nothing: contacts, bounces, effects, commands and events") {
#ifdef HAPTICS_COUNT_ALLOCATIONS
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	REQUIRE(system.set_hand_target({ 0.0, 0.02, 0.0 }));
	REQUIRE(reconfigure(system, [](RenderConfig &r_config) { r_config.servo.render_mode = RenderMode::PONG; }));
	PongPort pong(system.renderers().pong.channels);
	PongInput input;
	input.local_player = 0;
	input.players[0].avatar = { 0.0, 1.0, 2.0 };
	input.players[0].normal = { 0.0, 1.0, 0.2 };
	input.players[0].spin = true;
	input.players[1].kinematic = true;
	input.players[1].avatar = { 0.0, 1.0, -2.0 };
	input.players[1].paddle_velocity = { 0.5, 0.0, 0.0 };
	PongEvent events[16];
	unsigned long allocations = 0;
	uint64_t contacts = 0;
	for (int k = 0; k < 4000; ++k) {
		if (k % 16 == 0) {
			REQUIRE(pong.set_input(input));
		}
		if (k % 1000 == 0) {
			PongCommand serve;
			serve.type = PongCommandType::SET_BALL;
			serve.position = { 0.0, 1.5, 2.0 }; // Onto the paddle, again and again.
			serve.spin = { 0.0, 20.0, 0.0 };
			REQUIRE(pong.push_command(serve));
			PongCommand effect;
			effect.type = PongCommandType::EFFECT;
			effect.player = 0;
			effect.kind = k % 2000 == 0 ? PongEffectKind::REMOTE : PongEffectKind::SLOW;
			REQUIRE(pong.push_command(effect));
			effect.kind = PongEffectKind::RECOIL;
			effect.direction = { 0.0, 0.0, 1.0 };
			REQUIRE(pong.push_command(effect));
		}
		t_allocations = 0;
		t_watching = true;
		const Status status = system.step(0.001);
		t_watching = false;
		allocations += t_allocations;
		REQUIRE(status);
		pong.drain_events(events, 16);
		contacts = pong.state().paddle_contacts;
	}
	CHECK(contacts >= 4); // The ticks watched did the work: the ball met the paddle.
	CHECK(allocations == 0);
#else
	MESSAGE("allocation counting is off under sanitizers");
#endif
}

TEST_CASE("a vehicle tick allocates nothing: tyres, kerbs, roughness, the damper") {
#ifdef HAPTICS_COUNT_ALLOCATIONS
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	REQUIRE(reconfigure(system, [](RenderConfig &r_config) { r_config.servo.render_mode = RenderMode::VEHICLE; }));
	VehiclePort vehicle(system.renderers().vehicle.channels);
	VehicleFrame frame;
	frame.steer_angle_rad = 0.1;
	for (int w = 0; w < 2; ++w) {
		TyreContact contact;
		contact.in_contact = true;
		contact.load_n = 4000.0;
		contact.slip_angle_rad = 0.03 + 0.2 * w;
		contact.speed_m_per_s = 12.0;
		contact.roughness_n = 0.2;
		contact.ripple_n = 0.5;
		contact.ripple_spacing_m = 0.3;
		REQUIRE(frame.wheels.push_back(contact));
	}
	unsigned long allocations = 0;
	for (int k = 0; k < 2000; ++k) {
		if (k % 16 == 0) {
			REQUIRE(vehicle.set_frame(frame));
			REQUIRE(system.set_hand_target({ 0.02 * ((k / 16) % 5 - 2), 0.0, 0.0 }));
		}
		t_allocations = 0;
		t_watching = true;
		const Status status = system.step(0.001);
		t_watching = false;
		allocations += t_allocations;
		REQUIRE(status);
	}
	CHECK(vehicle.state().frames > 100); // The ticks watched did the work.
	CHECK(vehicle.state().ripple_hz > 0.0);
	CHECK(allocations == 0);
#else
	MESSAGE("allocation counting is off under sanitizers");
#endif
}
