// The DualSense's motors are shared with Godot's SDL (its HIDAPI PS5 driver writes its own
// output reports to the same pad for Input.start_joy_vibration; docs/linux-kernel.md,
// "Godot's SDL beside ours"). Our reports set the motor valid bits only while our own rumble
// is on, on the report that ends it and the next keep-alive, so they do not cut a rumble SDL
// set later. The triggers stay ours.

#include "dev_tools/dualsense/scripted_dualsense_device.h"
#include "devices/dualsense/dualsense_io.h"
#include "devices/dualsense/dualsense_mapping.h"

#include <doctest/doctest.h>

#include <memory>

namespace haptics::dualsense {

namespace {

constexpr uint8_t FLAG0_MOTOR_BITS = FLAG0_COMPATIBLE_VIBRATION | FLAG0_HAPTICS_SELECT;

struct Sent {
	bool motor_bits = false; // flag0 bits 0-1 or flag2 bit 2.
	uint8_t motor_left = 0;
	uint8_t motor_right = 0;
	bool trigger_bits = false;
};

Sent sent(const uint8_t *p_report) {
	const uint8_t *block = p_report + USB_COMMON_OFFSET;
	Sent result;
	result.motor_bits = (block[common::VALID_FLAG0] & FLAG0_MOTOR_BITS) != 0 ||
			(block[common::VALID_FLAG2] & FLAG2_COMPATIBLE_VIBRATION2) != 0;
	result.motor_left = block[common::MOTOR_LEFT];
	result.motor_right = block[common::MOTOR_RIGHT];
	result.trigger_bits = (block[common::VALID_FLAG0] & (FLAG0_RIGHT_TRIGGER | FLAG0_LEFT_TRIGGER)) != 0;
	return result;
}

// A USB pad, an open transport onto it and an I/O worker the test cycles itself.
struct Rig {
	std::shared_ptr<ScriptedDualSense> pad = std::make_shared<ScriptedDualSense>(ScriptedDualSenseOptions{ Bus::USB });
	std::unique_ptr<DualSenseTransport> transport = make_scripted_transport(pad);
	DualSenseIo io{ transport.get(), MappingConfig{}, 0.05 };
	DeviceExchange exchange;

	Rig() {
		REQUIRE(transport->open());
		io.begin(Bus::USB, RumbleRecipe::IMPROVED);
		exchange.reset(DeviceState{});
	}

	// What SDL sends for Input.start_joy_vibration(0.5, 1.0): 48 bytes, the improved recipe.
	void sdl_vibrates() {
		uint8_t report[48] = { USB_OUTPUT_REPORT_ID };
		report[USB_COMMON_OFFSET + common::VALID_FLAG0] = FLAG0_HAPTICS_SELECT;
		report[USB_COMMON_OFFSET + common::VALID_FLAG2] = FLAG2_COMPATIBLE_VIBRATION2;
		report[USB_COMMON_OFFSET + common::MOTOR_RIGHT] = 0x7F;
		report[USB_COMMON_OFFSET + common::MOTOR_LEFT] = 0xFF;
		REQUIRE(transport->write_output(report, sizeof(report)) == TransportIo::OK);
	}

	// p_cycles of 4 ms with p_command; counts our reports and those with the motor bits.
	void run(const ForceCommand &p_command, int p_cycles, int &r_reports, int &r_with_motor_bits) {
		REQUIRE(exchange.write_command(p_command) == DeviceIo::OK);
		pad->clear_history();
		for (int i = 0; i < p_cycles; ++i) {
			REQUIRE(io.io_cycle(exchange, 0.004) == DeviceIo::OK);
		}
		r_reports = static_cast<int>(pad->history_size());
		r_with_motor_bits = 0;
		for (size_t i = 0; i < pad->history_size(); ++i) {
			r_with_motor_bits += sent(pad->history(i).bytes).motor_bits ? 1 : 0;
		}
	}
};

} // namespace

TEST_CASE("dualsense shared motors: the planner sets the rumble field only while ours is on, at its end and the next keep-alive") {
	OutputPlanner planner;
	OutputState state;
	ForceCommand press;
	press.force_n = Vec3{ 0.0, 1.0, 0.0 };
	CHECK(planner.plan(press, 0.0, 0.004, state) == FIELDS_HELD); // First report: no rumble bits.
	CHECK_FALSE(planner.rumble_on_pad());

	// A hit: every report carries the levels while they are non-zero.
	uint32_t fields = planner.plan(press, 3.0, 0.004, state);
	CHECK((fields & FIELD_RUMBLE));
	CHECK(state.motor_right == 255);
	CHECK(planner.rumble_on_pad());
	int with_rumble = 0;
	int ends = 0;
	for (int i = 0; i < 100; ++i) {
		fields = planner.plan(press, 0.0, 0.004, state);
		const bool zero = state.motor_left == 0 && state.motor_right == 0;
		with_rumble += (fields & FIELD_RUMBLE) != 0 && !zero ? 1 : 0;
		ends += (fields & FIELD_RUMBLE) != 0 && zero ? 1 : 0; // The stop: motors 0, once.
		CHECK((zero || (fields & FIELD_RUMBLE) != 0)); // Never a report of ours without its rumble.
	}
	CHECK(with_rumble > 5);
	CHECK(ends == 1);
	CHECK_FALSE(planner.rumble_on_pad());

	// The next keep-alive states the stop once more (a lost Bluetooth report would leave the
	// pad rumbling); later ones re-assert triggers and lights only.
	int keep_alives = 0;
	int stops = 0;
	for (int i = 0; i < 400; ++i) {
		fields = planner.plan(press, 0.0, 0.004, state);
		keep_alives += fields != 0 ? 1 : 0;
		if ((fields & FIELD_RUMBLE) != 0) {
			++stops;
			CHECK(keep_alives == 1);
			CHECK(fields == FIELDS_STATE);
			CHECK((state.motor_left == 0 && state.motor_right == 0));
		} else if (fields != 0) {
			CHECK(fields == FIELDS_HELD);
		}
	}
	CHECK(stops == 1);
	CHECK(keep_alives == 3); // 1.6 s at a 0.5 s keep-alive.
}

TEST_CASE("dualsense shared motors: on the wire - clear bits without rumble, levels with it, 0 at the end and the next keep-alive, clear again") {
	Rig rig;
	ForceCommand press;
	press.force_n = Vec3{ 0.0, 1.0, 0.0 };
	int reports = 0;
	int with_motor_bits = 0;
	rig.run(press, 300, reports, with_motor_bits); // 1.2 s: the first report and two keep-alives.
	CHECK(reports == 3);
	CHECK(with_motor_bits == 0);
	CHECK(sent(rig.pad->history(0).bytes).trigger_bits);

	REQUIRE(rig.exchange.write_command(press) == DeviceIo::OK);
	rig.io.offer_impact(Vec3{ 2.4, 0.0, 0.0 });
	rig.pad->clear_history();
	REQUIRE(rig.io.io_cycle(rig.exchange, 0.004) == DeviceIo::OK);
	REQUIRE(rig.pad->history_size() == 1);
	const Sent hit = sent(rig.pad->history(0).bytes);
	CHECK(hit.motor_bits);
	CHECK(hit.motor_right == 204); // 2.4 / 3 N of 255, full values (improved recipe).
	CHECK(hit.motor_left == 153);

	rig.run(press, 50, reports, with_motor_bits); // The decay, then its one stop.
	REQUIRE(reports >= 2);
	CHECK(with_motor_bits == reports);
	const Sent stop = sent(rig.pad->history(rig.pad->history_size() - 1).bytes);
	CHECK(stop.motor_left == 0);
	CHECK(stop.motor_right == 0);
	CHECK(rig.pad->held().motor_right == 0);

	rig.run(press, 300, reports, with_motor_bits);
	CHECK(reports == 2); // Keep-alives: the first states the stop once more, the next does not.
	CHECK(with_motor_bits == 1);
	CHECK_FALSE(sent(rig.pad->history(1).bytes).motor_bits);
}

TEST_CASE("dualsense shared motors: a rumble SDL set outlives our reports and io_stop - the triggers stay ours") {
	Rig rig;
	ForceCommand press;
	press.force_n = Vec3{ 0.0, 2.0, 0.0 };
	int reports = 0;
	int with_motor_bits = 0;
	rig.run(press, 10, reports, with_motor_bits);
	rig.sdl_vibrates();
	rig.run(press, 250, reports, with_motor_bits); // 1 s: two keep-alives.
	CHECK(reports == 2);
	CHECK(with_motor_bits == 0);
	ScriptedPadHeld held = rig.pad->held();
	CHECK(held.motor_left == 0xFF); // SDL's, kept.
	CHECK(held.motor_right == 0x7F);
	CHECK(trigger_feedback_strength(held.right_trigger) == 8);
	CHECK(trigger_feedback_strength(held.left_trigger) == 8);

	rig.io.io_stop(); // Triggers and lights off; the motors are not ours to stop.
	held = rig.pad->held();
	CHECK(held.motor_left == 0xFF);
	CHECK(held.right_trigger == trigger_off());
	CHECK(held.player_leds == 0);
}

} // namespace haptics::dualsense
