// The DualSense rendering mapping (dualsense_mapping.h): impact envelope -> rumble, continuous
// force -> trigger strength with hysteresis, stick -> position, and when reports go out.

#include "devices/dualsense/dualsense_mapping.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

namespace haptics::dualsense {

TEST_CASE("dualsense mapping: a full-scale impact gives full rumble on both motors, then decays to exactly zero") {
	RumbleMapper rumble;
	rumble.configure(MappingConfig{});
	RumbleLevels levels = rumble.update(3.0, 0.004);
	CHECK(levels.right == 255);
	CHECK(levels.left == 255);
	levels = rumble.update(10.0, 0.004); // Beyond full scale: clamped.
	CHECK(levels.right == 255);
	int cycles = 0;
	uint8_t previous = levels.right;
	while (levels.right > 0 && cycles < 1000) {
		levels = rumble.update(0.0, 0.004);
		CHECK(levels.right <= previous); // Monotone release.
		previous = levels.right;
		++cycles;
	}
	CHECK(levels.right == 0);
	CHECK(levels.left == 0);
	// 15 ms release to 1 %: about 70 ms, never the whole second.
	CHECK(cycles < 50);
}

TEST_CASE("dualsense mapping: small hits use only the weak motor - the strong one joins above the knee") {
	RumbleMapper rumble;
	rumble.configure(MappingConfig{});
	RumbleLevels levels = rumble.update(0.6, 0.004); // 20 % of full scale.
	CHECK(levels.right == 51);
	CHECK(levels.left == 0);
	rumble.reset();
	levels = rumble.update(1.5, 0.004); // 50 %: at the knee.
	CHECK(levels.right == 128);
	CHECK(levels.left == 0);
	rumble.reset();
	levels = rumble.update(2.25, 0.004); // 75 %: halfway above the knee.
	CHECK(levels.right == 191);
	CHECK(levels.left == 128);

	MappingConfig never;
	never.strong_motor_knee = 1.0;
	rumble.configure(never);
	rumble.reset();
	CHECK(rumble.update(3.0, 0.004).left == 0);
}

TEST_CASE("dualsense mapping: below the floor, negative or non-finite impacts are silent") {
	RumbleMapper rumble;
	rumble.configure(MappingConfig{});
	CHECK(rumble.update(0.02, 0.004).right == 0); // 0.67 % < 1 % floor.
	CHECK(rumble.update(std::numeric_limits<double>::quiet_NaN(), 0.004).right == 0);
	CHECK(rumble.update(std::numeric_limits<double>::infinity(), 0.004).right == 0);
	CHECK(rumble.update(-3.0, 0.004).right == 255); // A magnitude: the sign is the direction's.
}

TEST_CASE("dualsense mapping: trigger strength 1..8 proportional to the continuous force, off at zero") {
	TriggerMapper trigger;
	trigger.configure(MappingConfig{}); // 2 N full scale: 0.25 N per step.
	CHECK(trigger.update(0.0) == 0);
	CHECK(trigger.update(0.1) == 0); // 0.4 of a step.
	CHECK(trigger.update(0.25) == 1);
	trigger.reset();
	CHECK(trigger.update(1.0) == 4);
	trigger.reset();
	CHECK(trigger.update(2.0) == 8);
	CHECK(trigger.update(50.0) == 8);
	CHECK(trigger.update(-1.0) == 4); // A magnitude.
	CHECK(trigger.update(std::numeric_limits<double>::quiet_NaN()) == 0);
}

TEST_CASE("dualsense mapping: the trigger level has hysteresis at a step boundary") {
	TriggerMapper trigger;
	trigger.configure(MappingConfig{});
	REQUIRE(trigger.update(1.0) == 4); // 4.0 steps.
	CHECK(trigger.update(1.13) == 4); // 4.52 steps: would round to 5, within the hysteresis.
	CHECK(trigger.update(1.10) == 4);
	CHECK(trigger.update(1.17) == 5); // 4.68 steps: clearly in 5.
	CHECK(trigger.update(1.10) == 5); // 4.4: back within 5's band.
	CHECK(trigger.update(1.08) == 4); // 4.32: clearly in 4.
	REQUIRE(trigger.update(0.25) == 1);
	CHECK(trigger.update(0.1) == 1); // 0.4 steps: within 1's band.
	CHECK(trigger.update(0.08) == 0); // 0.32: off.
}

TEST_CASE("dualsense mapping: stick deflection -> position, y negated, full throw = the radius") {
	PadInput input;
	CHECK(stick_position_m(input, 0.05).x == 0.0);
	CHECK(stick_position_m(input, 0.05).y == 0.0);
	input.left_x = 0xFF;
	input.left_y = 0x00; // Pushed up (the pad's y grows downward).
	Vec3 position = stick_position_m(input, 0.05);
	CHECK(position.x == doctest::Approx(0.05));
	CHECK(position.y == doctest::Approx(0.05));
	CHECK(position.z == 0.0);
	input.left_x = 0x00; // -128 / 127: clamped to -1.
	input.left_y = 0xFF; // Pushed down.
	position = stick_position_m(input, 0.05);
	CHECK(position.x == doctest::Approx(-0.05));
	CHECK(position.y == doctest::Approx(-0.05));
}

TEST_CASE("dualsense mapping: the planner sends everything first, then only changes, plus keep-alives") {
	OutputPlanner planner;
	OutputState state;
	const ForceCommand idle{};
	CHECK(planner.plan(idle, 0.0, 0.004, state) == FIELDS_HELD); // No rumble of ours: motors left alone.
	CHECK(state.lightbar == LIGHTBAR_IDLE);
	CHECK(state.player_leds == PLAYER_LEDS_SESSION);
	CHECK(state.right_trigger == trigger_off());
	CHECK(planner.plan(idle, 0.0, 0.004, state) == 0u); // Nothing changed.

	// An impact: rumble only.
	CHECK(planner.plan(idle, 1.5, 0.004, state) == FIELD_RUMBLE);
	CHECK(state.motor_right == 128);

	// A continuous force: triggers and lightbar change, rumble rides along.
	ForceCommand press;
	press.force_n = Vec3{ 0.0, 1.0, 0.0 };
	const uint32_t fields = planner.plan(press, 0.0, 0.004, state);
	CHECK((fields & FIELD_RIGHT_TRIGGER));
	CHECK((fields & FIELD_LEFT_TRIGGER));
	CHECK((fields & FIELD_LIGHTBAR));
	CHECK((fields & FIELD_RUMBLE));
	CHECK_FALSE((fields & FIELD_PLAYER_LEDS));
	CHECK(trigger_feedback_strength(state.right_trigger) == 4);
	CHECK(state.lightbar == LIGHTBAR_CONTACT);
	TriggerEffect expected;
	REQUIRE(trigger_feedback(2, 4, expected));
	CHECK(state.left_trigger == expected);

	// Held steady (after the rumble has died away): silent until the keep-alive re-sends all.
	for (int i = 0; i < 40; ++i) {
		planner.plan(press, 0.0, 0.004, state);
	}
	int quiet = 0;
	uint32_t resent = 0;
	for (int i = 0; i < 200 && resent == 0; ++i) {
		resent = planner.plan(press, 0.0, 0.004, state);
		quiet += resent == 0 ? 1 : 0;
	}
	CHECK(resent == FIELDS_STATE); // The first keep-alive after a rumble states its stop again.
	CHECK(state.motor_right == 0);
	CHECK(quiet > 50); // 0.5 s keep-alive at 4 ms: about 125 - 40 quiet cycles.
	resent = 0;
	for (int i = 0; i < 200 && resent == 0; ++i) {
		resent = planner.plan(press, 0.0, 0.004, state);
	}
	CHECK(resent == FIELDS_HELD); // The next leaves the motors alone.

	// The impact share is not continuous force: a pure impact leaves the triggers off.
	planner.reset();
	ForceCommand hit;
	hit.force_n = Vec3{ 2.0, 0.0, 0.0 };
	hit.impact_n = Vec3{ 2.0, 0.0, 0.0 };
	planner.plan(hit, 2.0, 0.004, state);
	CHECK(state.right_trigger == trigger_off());
	CHECK(state.motor_right > 0);
}

TEST_CASE("dualsense mapping: one trigger only, and the off state") {
	MappingConfig config;
	config.left_trigger = false;
	OutputPlanner planner(config);
	ForceCommand press;
	press.force_n = Vec3{ 0.0, 2.0, 0.0 };
	OutputState state;
	planner.plan(press, 0.0, 0.004, state);
	CHECK(trigger_feedback_strength(state.right_trigger) == 8);
	CHECK(state.left_trigger == trigger_off());

	const OutputState off = OutputPlanner::off_state();
	CHECK(off.motor_left == 0);
	CHECK(off.motor_right == 0);
	CHECK(off.right_trigger == trigger_off());
	CHECK(off.left_trigger == trigger_off());
	CHECK(off.player_leds == 0);
}

TEST_CASE("dualsense mapping: configuration ranges are checked and the field named") {
	CHECK(validate_mapping_config(MappingConfig{}));
	MappingConfig config;
	config.impact_full_scale_n = 0.0;
	Status status = validate_mapping_config(config);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::string(status.message()).find("impact_full_scale_n") != std::string::npos);
	config = MappingConfig{};
	config.continuous_full_scale_n = std::nan("");
	CHECK(validate_mapping_config(config).code() == StatusCode::INVALID_ARGUMENT);
	config = MappingConfig{};
	config.trigger_start_zone = 10;
	CHECK(std::string(validate_mapping_config(config).message()).find("trigger_start_zone") != std::string::npos);
	config = MappingConfig{};
	config.rumble_floor = 0.5;
	CHECK_FALSE(validate_mapping_config(config));
	config = MappingConfig{};
	config.keep_alive_s = 0.0;
	CHECK_FALSE(validate_mapping_config(config));
}

} // namespace haptics::dualsense
