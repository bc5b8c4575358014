// The constant-force effect's report sequences against the scripted firmware: the sequence of
// docs/devices/hid-pid.md ("Expected bytes") as recorded on the wire (AJ and OFB-like), what the firmware then renders,
// the Block Load answers (Full / Error / garbage / silence / unplug), and the property that
// a level-only change is exactly one Set Constant Force report and a direction-only change
// exactly one Set Effect report.

#include "dev_tools/pid/scripted_pid_joystick.h"
#include "devices/pid/pid_effect.h"
#include "hid_test_util.h"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace haptics;
using namespace haptics::pid;
using Bytes = std::vector<uint8_t>;

namespace {

struct Rig {
	std::shared_ptr<ScriptedPidJoystick> joystick;
	std::unique_ptr<hid::HidTransport> transport;
	PidLayout layout;

	explicit Rig(ScriptedFirmware p_firmware) :
			joystick(std::make_shared<ScriptedPidJoystick>(p_firmware)), transport(make_scripted_transport(joystick)) {
		REQUIRE(transport->open().ok());
		std::vector<uint8_t> bytes;
		REQUIRE(transport->report_descriptor(bytes).ok());
		REQUIRE(PidLayout::build(test::parse_or_empty(bytes, true), layout).ok());
	}

	// Records of one kind since the last clear, as byte vectors.
	std::vector<Bytes> sent(TransferKind p_kind) const {
		std::vector<Bytes> result;
		for (const ScriptedTransfer &transfer : joystick->records()) {
			if (transfer.kind == p_kind) {
				result.push_back(transfer.to_vector());
			}
		}
		return result;
	}
};

PidEffectOptions fast_retries() {
	PidEffectOptions options;
	options.block_load_retry_delay_us = 0;
	return options;
}

} // namespace

TEST_CASE("pid effect: the expected sequence on the wire of the AJ firmware, and the force it renders") {
	Rig rig(ScriptedFirmware::AJ);
	rig.layout.infinite_duration = InfiniteDuration::ALL_ONES; // As K-new, for the golden bytes.
	REQUIRE(initialize_device(*rig.transport, rig.layout).ok());
	CHECK(rig.sent(TransferKind::OUTPUT) == std::vector<Bytes>{ { 0x0C, 0x04 }, { 0x0C, 0x04 }, { 0x0C, 0x03 }, { 0x0C, 0x01 }, { 0x0D, 0xFF } });
	CHECK(rig.joystick->actuators_enabled());
	CHECK(rig.joystick->device_gain() == 255);
	rig.joystick->clear_records();

	ConstantForceEffect effect;
	REQUIRE(effect.upload(*rig.transport, rig.layout, 0x4000, 0x4000, fast_retries()).ok());
	REQUIRE(effect.play(*rig.transport) == DeviceIo::OK);
	const std::vector<ScriptedTransfer> records = rig.joystick->records();
	REQUIRE(records.size() == 5);
	CHECK(records[0].kind == TransferKind::FEATURE_SET);
	CHECK(records[0].to_vector() == Bytes{ 0x05, 0x01, 0x00, 0x00 });
	CHECK(records[1].kind == TransferKind::FEATURE_GET);
	CHECK(records[1].to_vector() == Bytes{ 0x06, 0x01, 0x01, 0xFF, 0xFF });
	CHECK(records[2].to_vector() == Bytes{ 0x01, 0x01, 0x01, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x04, 0x3F, 0x00, 0x00, 0x00, 0x00, 0x00 });
	CHECK(records[3].to_vector() == Bytes{ 0x05, 0x01, 0x88, 0x13 });
	CHECK(records[4].to_vector() == Bytes{ 0x0A, 0x01, 0x01, 0x01 });
	CHECK(effect.block_index() == 1);
	// 5000/10000 at 63·360/255 = 88.9°: X = sin, Y = -cos.
	ScriptedForce force = rig.joystick->rendered_force();
	CHECK(force.playing_effects == 1);
	CHECK(force.x == doctest::Approx(0.5 * std::sin(63.0 * 360.0 / 255.0 * std::numbers::pi / 180.0)));
	CHECK(force.y == doctest::Approx(-0.5 * std::cos(63.0 * 360.0 / 255.0 * std::numbers::pi / 180.0)));
	CHECK_FALSE(rig.joystick->effect(1).duration_infinite); // 0xFFFF is 65.5 s on AJ, not infinite.

	rig.joystick->clear_records();
	REQUIRE(effect.update(*rig.transport, 0x4000, -0x4000) == DeviceIo::OK);
	CHECK(rig.sent(TransferKind::OUTPUT) == std::vector<Bytes>{ { 0x05, 0x01, 0x78, 0xEC } });
	rig.joystick->clear_records();
	REQUIRE(effect.update(*rig.transport, 0xC000, -0x4000) == DeviceIo::OK);
	CHECK(rig.sent(TransferKind::OUTPUT) ==
			std::vector<Bytes>{ { 0x01, 0x01, 0x01, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x04, 0xBF, 0x00, 0x00, 0x00, 0x00, 0x00 } });
	// -5000 at 191·360/255 = 269.6°: pushes +X (the level's sign flips the direction).
	force = rig.joystick->rendered_force();
	CHECK(force.x == doctest::Approx(-0.5 * std::sin(191.0 * 360.0 / 255.0 * std::numbers::pi / 180.0)));
	CHECK(force.x > 0.49);
	rig.joystick->clear_records();
	REQUIRE(effect.stop(*rig.transport) == DeviceIo::OK);
	REQUIRE(effect.erase(*rig.transport) == DeviceIo::OK);
	CHECK(rig.sent(TransferKind::OUTPUT) == std::vector<Bytes>{ { 0x0A, 0x01, 0x03, 0x01 }, { 0x0A, 0x01, 0x03, 0x01 }, { 0x0B, 0x01 } });
	CHECK_FALSE(effect.uploaded());
	CHECK(rig.joystick->allocated_effects() == 0);
	CHECK(rig.joystick->rendered_force().playing_effects == 0);
	CHECK(rig.joystick->stats().pool_reads == 0); // A Pool GET would free every effect on AJ.
}

TEST_CASE("pid effect: AJ's own infinite duration (0x7FFF) keeps the effect playing indefinitely") {
	Rig rig(ScriptedFirmware::AJ);
	REQUIRE(rig.layout.infinite_duration == InfiniteDuration::LOGICAL_MAX);
	REQUIRE(initialize_device(*rig.transport, rig.layout).ok());
	ConstantForceEffect effect;
	REQUIRE(effect.upload(*rig.transport, rig.layout, 0, 0x7FFF, fast_retries()).ok());
	REQUIRE(effect.play(*rig.transport) == DeviceIo::OK);
	CHECK(rig.joystick->effect(effect.block_index()).duration == 0x7FFF);
	CHECK(rig.joystick->effect(effect.block_index()).duration_infinite);
	// Direction 0 = "up": full force pushes the stick away from the user (-Y).
	CHECK(rig.joystick->rendered_force().y == doctest::Approx(-1.0));
	CHECK(rig.joystick->rendered_force().x == doctest::Approx(0.0));
}

TEST_CASE("pid effect: OFB-like firmware: bitmask Device Control and 16-bit direction on the wire") {
	Rig rig(ScriptedFirmware::VIRTUAL);
	REQUIRE(initialize_device(*rig.transport, rig.layout, 0x7FFF).ok());
	CHECK(rig.sent(TransferKind::OUTPUT) == std::vector<Bytes>{ { 0x0C, 0x08 }, { 0x0C, 0x08 }, { 0x0C, 0x04 }, { 0x0C, 0x01 }, { 0x0D, 0x7F } });
	CHECK(rig.joystick->stats().device_resets == 2);
	CHECK(rig.joystick->actuators_enabled());
	rig.joystick->clear_records();
	ConstantForceEffect effect;
	REQUIRE(effect.upload(*rig.transport, rig.layout, 0xC000, -0x4000, fast_retries()).ok());
	REQUIRE(effect.play(*rig.transport) == DeviceIo::OK);
	CHECK(rig.sent(TransferKind::FEATURE_SET) == std::vector<Bytes>{ { 0x11, 0x01, 0x00, 0x00 } });
	CHECK(rig.sent(TransferKind::OUTPUT) ==
			std::vector<Bytes>{ { 0x01, 0x01, 0x01, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x04, 0x78, 0x69 },
					{ 0x05, 0x01, 0x01, 0xC0 }, { 0x0A, 0x01, 0x01, 0x01 } });
	CHECK(rig.joystick->effect(1).duration_infinite); // 0xFFFF is infinite here.
	// -16383/32767 at 270°, device gain 127/255: pushes +X.
	const ScriptedForce force = rig.joystick->rendered_force();
	CHECK(force.x == doctest::Approx(16383.0 / 32767.0 * 127.0 / 255.0).epsilon(1e-6));
	CHECK(force.y == doctest::Approx(0.0).epsilon(1e-6));
}

TEST_CASE("pid effect: Block Load Full / Error / garbage / silence / unplug map to clear errors") {
	struct Case {
		BlockLoadAnswer answer;
		uint32_t count;
		StatusCode code;
		const char *text;
	};
	const Case cases[] = {
		{ BlockLoadAnswer::FULL, 1, StatusCode::DEVICE_ERROR, "no free effect slot (Block Load: Full)" },
		{ BlockLoadAnswer::ERROR, 1, StatusCode::DEVICE_ERROR, "refused the effect (Block Load: Error)" },
		{ BlockLoadAnswer::GARBAGE, 60, StatusCode::DEVICE_ERROR, "did not confirm the effect in 60 Block Load requests (its replies were not a valid Block Load report)" },
		{ BlockLoadAnswer::SILENCE, 60, StatusCode::DEVICE_ERROR, "did not confirm the effect in 60 Block Load requests (GET_REPORT(Feature 0x06) got no answer (timeout))" },
	};
	for (const Case &c : cases) {
		CAPTURE(c.text);
		Rig rig(ScriptedFirmware::AJ);
		rig.joystick->script_block_load(c.answer, c.count);
		ConstantForceEffect effect;
		const Status status = effect.upload(*rig.transport, rig.layout, 0, 0, fast_retries());
		CHECK(status.code() == c.code);
		CHECK_MESSAGE(std::string(status.message()).find(c.text) != std::string::npos, status.message());
		CHECK_FALSE(effect.uploaded());
		CHECK(rig.joystick->stats().feature_gets == c.count);
		CHECK(rig.sent(TransferKind::OUTPUT).empty()); // Nothing after a failed Block Load.
	}
	// Garbage or silence, then the real answer: retried until Success.
	Rig rig(ScriptedFirmware::AJ);
	rig.joystick->script_block_load(BlockLoadAnswer::GARBAGE, 3);
	rig.joystick->script_block_load(BlockLoadAnswer::SILENCE, 2);
	ConstantForceEffect effect;
	Status status = effect.upload(*rig.transport, rig.layout, 0, 0, fast_retries());
	CHECK_MESSAGE(status.ok(), status.message());
	CHECK(effect.block_index() == 1);
	CHECK(rig.sent(TransferKind::FEATURE_GET).size() == 6);
	// Unplugged: DISCONNECTED at once, not 60 retries.
	Rig gone(ScriptedFirmware::AJ);
	gone.joystick->set_plugged(false);
	status = effect.upload(*gone.transport, gone.layout, 0, 0, fast_retries());
	CHECK(status.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(std::string(status.message()) == "PID Create New Effect failed: the device was unplugged (ENODEV)");
}

TEST_CASE("pid effect: level-only changes are one Set Constant Force report, direction-only one Set Effect report") {
	for (const ScriptedFirmware firmware : { ScriptedFirmware::AJ, ScriptedFirmware::VIRTUAL }) {
		Rig rig(firmware);
		REQUIRE(initialize_device(*rig.transport, rig.layout).ok());
		ConstantForceEffect effect;
		REQUIRE(effect.upload(*rig.transport, rig.layout, 0, 0, fast_retries()).ok());
		REQUIRE(effect.play(*rig.transport) == DeviceIo::OK);
		const uint8_t constant_id = rig.layout.report(rig.layout.set_constant.report).id;
		const uint8_t set_effect_id = rig.layout.report(rig.layout.set_effect.report).id;
		const size_t set_effect_length = rig.layout.report(rig.layout.set_effect.report).byte_length;
		std::mt19937 random(firmware == ScriptedFirmware::AJ ? 7u : 8u);
		uint16_t direction = 0;
		int16_t level = 0;
		int level_steps = 0;
		int direction_steps = 0;
		for (int step = 0; step < 500; ++step) {
			const bool change_level = random() % 2 == 0;
			uint16_t next_direction = direction;
			int16_t next_level = level;
			if (change_level) {
				next_level = static_cast<int16_t>(static_cast<int32_t>(random() % 65535) - 32767);
			} else {
				next_direction = static_cast<uint16_t>(random());
			}
			const bool level_changes = magnitude_value(rig.layout, next_level) != effect.magnitude_value();
			const bool direction_changes = direction_value(rig.layout, next_direction) != effect.direction_value();
			rig.joystick->clear_records();
			PidUpdateResult result;
			REQUIRE(effect.update(*rig.transport, next_direction, next_level, &result) == DeviceIo::OK);
			const std::vector<Bytes> sent = rig.sent(TransferKind::OUTPUT);
			if (change_level) {
				CHECK_FALSE(result.sent_set_effect);
				REQUIRE(sent.size() == (level_changes ? 1u : 0u));
				if (level_changes) {
					CHECK(sent[0].size() == 4);
					CHECK(sent[0][0] == constant_id);
					CHECK(rig.joystick->effect(effect.block_index()).magnitude == magnitude_value(rig.layout, next_level));
					++level_steps;
				}
			} else {
				CHECK_FALSE(result.sent_set_constant);
				REQUIRE(sent.size() == (direction_changes ? 1u : 0u));
				if (direction_changes) {
					CHECK(sent[0].size() == set_effect_length);
					CHECK(sent[0][0] == set_effect_id);
					CHECK(rig.joystick->effect(effect.block_index()).direction == direction_value(rig.layout, next_direction));
					++direction_steps;
				}
			}
			direction = next_direction;
			level = next_level;
		}
		CHECK(level_steps > 200);
		CHECK(direction_steps > 200);
		// Same values again: nothing at all.
		rig.joystick->clear_records();
		REQUIRE(effect.update(*rig.transport, direction, level) == DeviceIo::OK);
		CHECK(rig.sent(TransferKind::OUTPUT).empty());
	}
}
