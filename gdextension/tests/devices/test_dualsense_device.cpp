// The DualSense I/O cycle and device against the scripted pad (no threads where a test
// calls io_cycle itself) and the pad's own checks. The hidapi transport and probe:
// test_dualsense_backend.cpp.

#include "dev_tools/dualsense/scripted_dualsense_device.h"
#include "devices/dualsense/dualsense_backend.h"
#include "devices/dualsense/dualsense_crc.h"
#include "devices/dualsense/dualsense_io.h"

#include <doctest/doctest.h>

#include <cstring>
#include <string>

namespace haptics::dualsense {

namespace {

bool contains(const char *p_text, const char *p_part) {
	return std::strstr(p_text, p_part) != nullptr;
}

// A pad, an open transport onto it and an I/O worker, driven by the test itself.
struct Rig {
	std::shared_ptr<ScriptedDualSense> pad;
	std::unique_ptr<DualSenseTransport> transport;
	DualSenseIo io;
	DeviceExchange exchange;

	explicit Rig(Bus p_bus, RumbleRecipe p_recipe = RumbleRecipe::IMPROVED, const MappingConfig &p_mapping = {}) :
			pad(std::make_shared<ScriptedDualSense>(ScriptedDualSenseOptions{ p_bus })),
			transport(make_scripted_transport(pad)),
			io(transport.get(), p_mapping, 0.05) {
		REQUIRE(transport->open());
		io.begin(p_bus, p_recipe);
		DeviceState initial;
		initial.ready = false;
		exchange.reset(initial);
	}

	DeviceIo cycle() { return io.io_cycle(exchange, 0.004); }
};

} // namespace

TEST_CASE("dualsense io: a pushed impact rumbles the pad, then the motors decay to exactly zero") {
	Rig rig(Bus::USB);
	REQUIRE(rig.cycle() == DeviceIo::OK); // First cycle: the whole state.
	CHECK(rig.pad->held().motor_right == 0);
	// The servo renders a 150 Hz transient: its ticks' values swing through zero, the peak
	// over the cycle is what counts.
	rig.io.offer_impact(Vec3{ 0.0, 0.4, 0.0 });
	rig.io.offer_impact(Vec3{ 0.0, -2.4, 0.0 });
	rig.io.offer_impact(Vec3{ 0.0, 0.1, 0.0 });
	REQUIRE(rig.cycle() == DeviceIo::OK);
	CHECK(rig.pad->held().motor_right == 204); // 2.4 / 3 N of 255.
	CHECK(rig.pad->held().motor_left == 153); // (0.8 - 0.5) / 0.5 of 255.
	CHECK(rig.pad->held().improved_rumble);
	uint8_t previous = rig.pad->held().motor_right;
	int cycles = 0;
	while (rig.pad->held().motor_right > 0 && cycles < 250) {
		REQUIRE(rig.cycle() == DeviceIo::OK);
		CHECK(rig.pad->held().motor_right <= previous);
		previous = rig.pad->held().motor_right;
		++cycles;
	}
	CHECK(rig.pad->held().motor_right == 0);
	CHECK(rig.pad->held().motor_left == 0);
	CHECK(cycles < 50);
	// And once silent, no more reports until the keep-alive.
	const uint64_t sent = rig.pad->counters().reports_accepted;
	for (int i = 0; i < 10; ++i) {
		REQUIRE(rig.cycle() == DeviceIo::OK);
	}
	CHECK(rig.pad->counters().reports_accepted == sent);
}

TEST_CASE("dualsense io: legacy firmware gets halved motor values with flag0 0x03") {
	Rig rig(Bus::USB, RumbleRecipe::LEGACY);
	rig.io.offer_impact(Vec3{ 3.0, 0.0, 0.0 });
	REQUIRE(rig.cycle() == DeviceIo::OK);
	const ScriptedPadHeld held = rig.pad->held();
	CHECK(held.motor_right == 0x7F);
	CHECK(held.motor_left == 0x7F);
	CHECK_FALSE(held.improved_rumble);
	CHECK((held.last_report[1] & 0x03) == 0x03);
	CHECK(held.last_report[39] == 0x00); // No flag2 bit 2.
}

TEST_CASE("dualsense io: a continuous force sets trigger resistance - zero force turns the triggers off") {
	Rig rig(Bus::USB);
	ForceCommand press;
	press.force_n = Vec3{ 0.0, 1.5, 0.0 }; // 6 of 8 steps at 2 N full scale.
	REQUIRE(rig.exchange.write_command(press) == DeviceIo::OK);
	REQUIRE(rig.cycle() == DeviceIo::OK);
	ScriptedPadHeld held = rig.pad->held();
	CHECK(trigger_feedback_strength(held.right_trigger) == 6);
	CHECK(trigger_feedback_strength(held.left_trigger) == 6);
	CHECK(held.lightbar == LIGHTBAR_CONTACT);
	CHECK(held.player_leds == PLAYER_LEDS_SESSION);
	uint8_t zones[TRIGGER_ZONES];
	REQUIRE(unpack_trigger_zones(held.right_trigger, zones));
	CHECK(zones[1] == 0);
	CHECK(zones[2] == 6); // From the start zone on.

	REQUIRE(rig.exchange.write_command(ForceCommand{}) == DeviceIo::OK);
	REQUIRE(rig.cycle() == DeviceIo::OK);
	held = rig.pad->held();
	CHECK(held.right_trigger == trigger_off());
	CHECK(held.left_trigger == trigger_off());
	CHECK(held.lightbar == LIGHTBAR_IDLE);
}

TEST_CASE("dualsense io: NaN forces are silence, not a crash") {
	Rig rig(Bus::USB);
	const double nan = std::nan("");
	rig.io.offer_impact(Vec3{ nan, 0.0, 0.0 });
	ForceCommand bad;
	bad.force_n = Vec3{ nan, nan, nan };
	bad.impact_n = Vec3{ 0.0, nan, 0.0 };
	REQUIRE(rig.exchange.write_command(bad) == DeviceIo::OK);
	REQUIRE(rig.cycle() == DeviceIo::OK);
	const ScriptedPadHeld held = rig.pad->held();
	CHECK(held.motor_right == 0);
	CHECK(held.right_trigger == trigger_off());
}

TEST_CASE("dualsense io: the stick and buttons become the device state - y up is the pad's y down negated") {
	Rig rig(Bus::USB);
	DeviceState state;
	REQUIRE(rig.exchange.read_state(state) == DeviceIo::OK);
	CHECK_FALSE(state.ready); // No input report yet.
	rig.pad->set_stick_deflection(0.5, -1.0); // Right and pushed down.
	rig.pad->set_buttons((1u << BUTTON_CROSS) | (1u << BUTTON_R1) | (1u << BUTTON_DPAD_LEFT));
	REQUIRE(rig.cycle() == DeviceIo::OK);
	REQUIRE(rig.exchange.read_state(state) == DeviceIo::OK);
	CHECK(state.ready);
	CHECK(state.position_m.x == doctest::Approx(0.05 * 64.0 / 127.0)); // Raw 192.
	CHECK(state.position_m.y == doctest::Approx(-0.05));
	CHECK(state.position_m.z == 0.0);
	CHECK(state.buttons == ((1u << BUTTON_CROSS) | (1u << BUTTON_R1) | (1u << BUTTON_DPAD_LEFT)));
}

TEST_CASE("dualsense io: the cycle drains queued input reports and keeps the newest") {
	Rig rig(Bus::USB);
	uint8_t old_report[USB_INPUT_SIZE] = { 0x01, 0x00, 0x00, 0x80, 0x80 };
	old_report[8] = 0x08;
	rig.pad->inject_input(old_report, sizeof(old_report)); // Queued before the scripted one.
	rig.pad->set_stick(0xFF, 0x80);
	REQUIRE(rig.cycle() == DeviceIo::OK);
	DeviceState state;
	REQUIRE(rig.exchange.read_state(state) == DeviceIo::OK);
	CHECK(state.position_m.x == doctest::Approx(0.05));
	CHECK(rig.io.stats().input_reports == 2);
}

TEST_CASE("dualsense io: garbled, short and bad-CRC input reports are ignored, the state kept") {
	Rig rig(Bus::BLUETOOTH);
	rig.pad->set_stick(0xFF, 0x80);
	REQUIRE(rig.cycle() == DeviceIo::OK); // Output switches the pad to full reports...
	REQUIRE(rig.cycle() == DeviceIo::OK); // ...which the next cycle reads.
	DeviceState state;
	REQUIRE(rig.exchange.read_state(state) == DeviceIo::OK);
	REQUIRE(state.position_m.x == doctest::Approx(0.05));

	uint8_t bad_crc[BT_INPUT_SIZE] = { 0x31, 0x00, 0x00, 0x80 };
	write_le32(bad_crc + 74, crc32_seeded(CRC_SEED_INPUT, bad_crc, 74) ^ 1u);
	const uint8_t short_report[5] = { 0x31, 0x00, 0x00, 0x80, 0x80 };
	const uint8_t garbage[33] = { 0x7E, 0xFF, 0x00, 0x13 };
	rig.pad->inject_input(bad_crc, sizeof(bad_crc));
	rig.pad->inject_input(short_report, sizeof(short_report));
	rig.pad->inject_input(garbage, sizeof(garbage));
	const uint64_t ignored = rig.io.stats().input_ignored;
	REQUIRE(rig.cycle() == DeviceIo::OK);
	CHECK(rig.io.stats().input_ignored == ignored + 3);
	REQUIRE(rig.exchange.read_state(state) == DeviceIo::OK);
	CHECK(state.position_m.x == doctest::Approx(0.05)); // From the scripted report after them.
}

TEST_CASE("dualsense io: a BT simple report is counted and ignored - the state waits for a full report") {
	Rig rig(Bus::BLUETOOTH);
	const uint8_t simple[10] = { 0x01, 0xFF, 0x80, 0x80, 0x80, 0x08, 0, 0, 0, 0 };
	rig.pad->inject_input(simple, sizeof(simple));
	rig.pad->set_stick(0x00, 0x80);
	REQUIRE(rig.cycle() == DeviceIo::OK);
	CHECK(rig.io.stats().simple_reports == 1);
	DeviceState state;
	REQUIRE(rig.exchange.read_state(state) == DeviceIo::OK);
	CHECK(state.ready);
	CHECK(state.position_m.x == doctest::Approx(-0.05)); // From the full report, not the simple one.
}

TEST_CASE("dualsense io: Bluetooth - simple reports until the first output, sequence per report, CRCs the pad accepts") {
	Rig rig(Bus::BLUETOOTH);
	rig.pad->set_stick(0x80, 0x00);
	uint8_t report[128];
	size_t size = 0;
	REQUIRE(rig.transport->read_input(report, sizeof(report), size) == TransportIo::OK);
	CHECK(size == 10); // The simple report.
	CHECK(report[0] == 0x01);
	REQUIRE(rig.transport->read_input(report, sizeof(report), size) == TransportIo::NO_DATA);

	// Force 20 reports (a changing rumble): the sequence nibble goes 0..15, 0..3.
	for (int i = 0; i < 20; ++i) {
		rig.io.offer_impact(Vec3{ 0.5 + 0.1 * i, 0.0, 0.0 });
		REQUIRE(rig.cycle() == DeviceIo::OK);
	}
	const ScriptedPadCounters counters = rig.pad->counters();
	CHECK(counters.reports_accepted == 20);
	CHECK(counters.reports_rejected == 0);
	CHECK(counters.sequence_errors == 0);
	CHECK(counters.bytes_accepted == 20 * 78);
	REQUIRE(rig.pad->history_size() == 20);
	for (size_t i = 0; i < 20; ++i) {
		CHECK(rig.pad->history(i).bytes[1] == ((i % 16) << 4));
		CHECK(rig.pad->history(i).bytes[2] == 0x10);
	}
	CHECK(rig.pad->history(15).bytes[1] == 0xF0);
	CHECK(rig.pad->history(16).bytes[1] == 0x00); // 15 -> 0.
	CHECK(rig.pad->held().full_reports);
	DeviceState state;
	REQUIRE(rig.exchange.read_state(state) == DeviceIo::OK);
	CHECK(state.ready);
	CHECK(state.position_m.y == doctest::Approx(0.05)); // Raw 0 = full up (128/127 clamped to 1).
	CHECK(rig.io.stats().simple_reports == 0); // The first cycle's output came before its reads.
}

TEST_CASE("dualsense scripted pad: rejects a BT report with a bad CRC, a wrong tag or size, and applies none of it") {
	ScriptedDualSenseOptions options;
	options.bus = Bus::BLUETOOTH;
	auto pad = std::make_shared<ScriptedDualSense>(options);
	auto transport = make_scripted_transport(pad);
	REQUIRE(transport->open());

	OutputState state;
	state.motor_right = 200;
	uint8_t block[COMMON_SIZE];
	encode_common(state, FIELD_RUMBLE, RumbleRecipe::IMPROVED, block);
	OutputReport report;
	wrap_bt_report(block, 0, report);

	OutputReport bad_crc = report;
	bad_crc.bytes[76] ^= 0x10;
	CHECK(transport->write_output(bad_crc.bytes, bad_crc.size) == TransportIo::OK); // Writes succeed...
	OutputReport bad_tag = report;
	bad_tag.bytes[2] = 0x00;
	write_le32(bad_tag.bytes + 74, bt_output_crc(bad_tag.bytes));
	CHECK(transport->write_output(bad_tag.bytes, bad_tag.size) == TransportIo::OK);
	CHECK(transport->write_output(report.bytes, 77) == TransportIo::OK);
	// A CRC over the bytes without the seed: the mistake this check exists for.
	OutputReport no_seed = report;
	write_le32(no_seed.bytes + 74, crc32(no_seed.bytes, 74));
	CHECK(transport->write_output(no_seed.bytes, no_seed.size) == TransportIo::OK);
	CHECK(pad->counters().reports_rejected == 4); // ...the pad ignores them.
	CHECK(pad->counters().reports_accepted == 0);
	CHECK(pad->held().motor_right == 0);

	CHECK(transport->write_output(report.bytes, report.size) == TransportIo::OK);
	CHECK(pad->counters().reports_accepted == 1);
	CHECK(pad->held().motor_right == 200);
}

TEST_CASE("dualsense scripted pad: USB accepts 48 or 63 bytes of report 0x02 only") {
	auto pad = std::make_shared<ScriptedDualSense>();
	auto transport = make_scripted_transport(pad);
	REQUIRE(transport->open());
	uint8_t report[64] = { 0x02, 0x03, 0x00, 0x10, 0x20 };
	CHECK(transport->write_output(report, 63) == TransportIo::OK);
	CHECK(transport->write_output(report, 48) == TransportIo::OK);
	CHECK(transport->write_output(report, 64) == TransportIo::OK);
	report[0] = 0x31;
	CHECK(transport->write_output(report, 63) == TransportIo::OK);
	CHECK(pad->counters().reports_accepted == 2);
	CHECK(pad->counters().reports_rejected == 2);
}

TEST_CASE("dualsense io: an unplug fails the cycle as DISCONNECTED with hidapi's reason - io_stop leaves everything off") {
	Rig rig(Bus::USB);
	ForceCommand press;
	press.force_n = Vec3{ 0.0, 2.0, 0.0 };
	REQUIRE(rig.exchange.write_command(press) == DeviceIo::OK);
	rig.io.offer_impact(Vec3{ 3.0, 0.0, 0.0 });
	REQUIRE(rig.cycle() == DeviceIo::OK);
	REQUIRE(rig.pad->held().motor_right == 255);

	rig.io.io_stop();
	const ScriptedPadHeld held = rig.pad->held();
	CHECK(held.motor_right == 0);
	CHECK(held.motor_left == 0);
	CHECK(held.right_trigger == trigger_off());
	CHECK(held.left_trigger == trigger_off());
	CHECK(held.player_leds == 0);
	CHECK(held.last_report[1] == (0x02 | 0x04 | 0x08)); // Haptics select + both triggers.
	CHECK(held.last_report[11] == 0x05);
	CHECK(held.last_report[22] == 0x05);

	rig.pad->unplug();
	rig.io.offer_impact(Vec3{ 1.0, 0.0, 0.0 }); // Something to send.
	CHECK(rig.cycle() == DeviceIo::DISCONNECTED);
	const DeviceStatus status = rig.exchange.status();
	CHECK(status.io == DeviceIo::DISCONNECTED);
	CHECK(contains(status.reason, "DualSense disconnected"));
	CHECK(contains(status.reason, "No such device"));
	DeviceState state;
	CHECK(rig.exchange.read_state(state) == DeviceIo::DISCONNECTED);
}

TEST_CASE("dualsense device: open reads the firmware version and picks the recipe - close leaves the pad off") {
	struct Case {
		uint16_t version;
		bool edge;
		bool fails;
		RumbleRecipe recipe;
	};
	const Case cases[] = {
		{ 0x0100, false, false, RumbleRecipe::LEGACY },
		{ 0x0224, false, false, RumbleRecipe::IMPROVED },
		{ 0x0100, true, false, RumbleRecipe::IMPROVED },
		{ 0x0100, false, true, RumbleRecipe::IMPROVED }, // Unknown: assumed updated.
	};
	for (const Case &c : cases) {
		for (const Bus bus : { Bus::USB, Bus::BLUETOOTH }) {
			CAPTURE(c.version);
			CAPTURE(static_cast<int>(bus));
			ScriptedDualSenseOptions options;
			options.update_version = c.version;
			options.edge = c.edge;
			options.firmware_info_fails = c.fails;
			ScriptedDualSenseSetup setup = make_scripted_device(bus, options);
			REQUIRE(setup.device->open());
			CHECK(setup.device->rumble_recipe_in_use() == c.recipe);
			CHECK(setup.device->update_version() == (c.fails ? 0 : c.version));
			CHECK(setup.device->bus() == bus);
			CHECK(setup.pad->held().lightbar_taken);
			CHECK(std::string(setup.device->name()) ==
					std::string(c.edge ? "Sony DualSense Edge" : "Sony DualSense") + (bus == Bus::USB ? " (USB)" : " (Bluetooth)"));
			setup.device->close();
			CHECK(setup.pad->counters().reports_rejected == 0);
			const ScriptedPadHeld held = setup.pad->held();
			CHECK(held.motor_right == 0);
			CHECK(held.right_trigger == trigger_off());
			CHECK(held.left_trigger == trigger_off());
		}
	}
}

TEST_CASE("dualsense device: without a bus from the transport, the first input report tells") {
	for (const Bus bus : { Bus::USB, Bus::BLUETOOTH }) {
		ScriptedDualSenseOptions options;
		options.transport_knows_bus = false;
		ScriptedDualSenseSetup setup = make_scripted_device(bus, options);
		REQUIRE(setup.device->open());
		CHECK(setup.device->bus() == bus);
		setup.device->close();
		CHECK(setup.pad->counters().reports_rejected == 0);
	}
}

TEST_CASE("dualsense device: capabilities are vibration-only full-scales - unplugged pads do not open") {
	ScriptedDualSenseSetup setup = make_scripted_device(Bus::BLUETOOTH);
	const DeviceCapabilities capabilities = setup.device->capabilities();
	CHECK(capabilities.output == ForceOutput::VIBRATION);
	CHECK(capabilities.output_dof == 0);
	CHECK(capabilities.input_dof == 2);
	CHECK(capabilities.physical);
	CHECK(capabilities.button_count == 19);
	CHECK(capabilities.limits.max_force_n == doctest::Approx(5.0));
	CHECK(capabilities.limits.max_continuous_force_n == doctest::Approx(2.0));
	CHECK(capabilities.limits.workspace_radius_m == doctest::Approx(0.05));
	CHECK(capabilities.limits.max_stiffness_n_per_m == doctest::Approx(40.0));
	CHECK(setup.device->calibrate().code() == StatusCode::NO_DEVICE);
	DeviceState state;
	CHECK(setup.device->read_state(state) == DeviceIo::FAILED); // Not open.

	setup.pad->unplug();
	const Status status = setup.device->open();
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(contains(status.message(), "scripted Bluetooth DualSense"));
	CHECK_FALSE(setup.device->is_open());
	setup.pad->replug();
	REQUIRE(setup.device->open());
	CHECK(setup.device->capabilities().native_rate_hz == doctest::Approx(125.0));
	CHECK(setup.device->calibrate());
	setup.device->close();

	DualSenseConfig bad;
	bad.stick_radius_m = 0.0;
	ScriptedDualSenseSetup invalid = make_scripted_device(Bus::USB, {}, bad);
	const Status rejected = invalid.device->open();
	CHECK(rejected.code() == StatusCode::OUT_OF_RANGE);
	CHECK(contains(rejected.message(), "stick_radius_m"));

	DualSenseDevice no_transport(nullptr, DualSenseModel::DUALSENSE);
	CHECK(no_transport.open().code() == StatusCode::INVALID_ARGUMENT);
}

} // namespace haptics::dualsense
