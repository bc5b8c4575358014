// Adaptive-trigger blocks (docs/devices/dualsense.md): the four example blocks byte for byte, the packing
// round-trips for every zone/strength combination, and bad parameters are named.

#include "dualsense_test_util.h"

#include "devices/dualsense/dualsense_triggers.h"

#include <doctest/doctest.h>

#include <cstring>
#include <string>

namespace haptics::dualsense {

TEST_CASE("dualsense triggers: the example blocks of docs/devices/dualsense.md") {
	TriggerEffect effect;
	SUBCASE("off") {
		effect = trigger_off();
		const uint8_t expected[] = { 0x05, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 };
		CHECK_BYTES(effect.bytes, TRIGGER_BLOCK_SIZE, expected, sizeof(expected));
		CHECK(TriggerEffect{} == trigger_off());
	}
	SUBCASE("feedback P=0 S=8") {
		REQUIRE(trigger_feedback(0, 8, effect));
		const uint8_t expected[] = { 0x21, 0xFF, 0x03, 0xFF, 0xFF, 0xFF, 0x3F, 0x00, 0x00, 0x00, 0x00 };
		CHECK_BYTES(effect.bytes, TRIGGER_BLOCK_SIZE, expected, sizeof(expected));
	}
	SUBCASE("feedback P=3 S=5") {
		REQUIRE(trigger_feedback(3, 5, effect));
		const uint8_t expected[] = { 0x21, 0xF8, 0x03, 0x00, 0x48, 0x92, 0x24, 0x00, 0x00, 0x00, 0x00 };
		CHECK_BYTES(effect.bytes, TRIGGER_BLOCK_SIZE, expected, sizeof(expected));
	}
	SUBCASE("vibration P=0 A=8 F=30") {
		REQUIRE(trigger_vibration(0, 8, 30, effect));
		const uint8_t expected[] = { 0x26, 0xFF, 0x03, 0xFF, 0xFF, 0xFF, 0x3F, 0x00, 0x00, 0x1E, 0x00 };
		CHECK_BYTES(effect.bytes, TRIGGER_BLOCK_SIZE, expected, sizeof(expected));
	}
	SUBCASE("weapon start 2 end 5 S=8") {
		REQUIRE(trigger_weapon(2, 5, 8, effect));
		const uint8_t expected[] = { 0x25, 0x24, 0x00, 0x07, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00 };
		CHECK_BYTES(effect.bytes, TRIGGER_BLOCK_SIZE, expected, sizeof(expected));
	}
}

TEST_CASE("dualsense triggers: feedback from every start zone at every strength round-trips") {
	for (int start = 0; start < TRIGGER_ZONES; ++start) {
		for (int strength = 1; strength <= TRIGGER_MAX_STRENGTH; ++strength) {
			CAPTURE(start);
			CAPTURE(strength);
			TriggerEffect effect;
			REQUIRE(trigger_feedback(start, strength, effect));
			CHECK(effect.mode() == TRIGGER_MODE_FEEDBACK);
			uint8_t zones[TRIGGER_ZONES];
			REQUIRE(unpack_trigger_zones(effect, zones));
			for (int zone = 0; zone < TRIGGER_ZONES; ++zone) {
				CHECK(zones[zone] == (zone >= start ? strength : 0));
			}
			CHECK(trigger_feedback_strength(effect) == strength);
			// Mask and value fields never spill into each other or past p5.
			CHECK(effect.param(1) <= 0x03);
			CHECK(effect.param(5) <= 0x3F);
			for (size_t p = 6; p < 10; ++p) {
				CHECK(effect.param(p) == 0);
			}
		}
	}
}

TEST_CASE("dualsense triggers: arbitrary per-zone patterns round-trip (feedback and vibration)") {
	// A deterministic walk over patterns: each zone 0..8 from a linear congruential sequence.
	uint32_t seed = 12345;
	for (int round = 0; round < 500; ++round) {
		uint8_t values[TRIGGER_ZONES];
		bool any = false;
		for (uint8_t &value : values) {
			seed = seed * 1664525u + 1013904223u;
			value = static_cast<uint8_t>((seed >> 24) % 9);
			any = any || value != 0;
		}
		if (!any) {
			values[round % TRIGGER_ZONES] = 1;
		}
		CAPTURE(round);
		TriggerEffect feedback;
		REQUIRE(trigger_feedback_zones(values, feedback));
		uint8_t back[TRIGGER_ZONES];
		REQUIRE(unpack_trigger_zones(feedback, back));
		CHECK(std::memcmp(back, values, sizeof(values)) == 0);

		const int frequency = 1 + round % 255;
		TriggerEffect vibration;
		REQUIRE(trigger_vibration_zones(values, frequency, vibration));
		REQUIRE(unpack_trigger_zones(vibration, back));
		CHECK(std::memcmp(back, values, sizeof(values)) == 0);
		CHECK(vibration.param(TRIGGER_VIBRATION_FREQUENCY_PARAM) == frequency);
		// Same packing, different mode and the frequency: nothing else differs.
		for (size_t p = 0; p < 8; ++p) {
			CHECK(vibration.param(p) == feedback.param(p));
		}
	}
}

TEST_CASE("dualsense triggers: weapon zones for every valid start/end") {
	for (int start = 2; start <= 7; ++start) {
		for (int end = start + 1; end <= 8; ++end) {
			TriggerEffect effect;
			REQUIRE(trigger_weapon(start, end, 3, effect));
			const uint32_t zones = effect.param(0) | effect.param(1) << 8;
			CHECK(zones == ((1u << start) | (1u << end)));
			CHECK(effect.param(2) == 2);
		}
	}
}

TEST_CASE("dualsense triggers: out-of-range parameters are named and leave the block alone") {
	TriggerEffect effect;
	REQUIRE(trigger_feedback(0, 8, effect));
	const TriggerEffect before = effect;

	Status status = trigger_feedback(10, 1, effect);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::string(status.message()).find("start_zone") != std::string::npos);
	status = trigger_feedback(0, 0, effect);
	CHECK(std::string(status.message()).find("strength") != std::string::npos);
	CHECK_FALSE(trigger_feedback(0, 9, effect));
	CHECK_FALSE(trigger_feedback(-1, 4, effect));
	CHECK_FALSE(trigger_vibration(0, 4, 0, effect));
	CHECK_FALSE(trigger_vibration(0, 4, 256, effect));
	CHECK_FALSE(trigger_weapon(1, 5, 4, effect));
	CHECK_FALSE(trigger_weapon(4, 4, 4, effect));
	CHECK_FALSE(trigger_weapon(4, 9, 4, effect));
	const uint8_t none[TRIGGER_ZONES] = {};
	status = trigger_feedback_zones(none, effect);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	const uint8_t too_strong[TRIGGER_ZONES] = { 0, 0, 9 };
	status = trigger_feedback_zones(too_strong, effect);
	CHECK(std::string(status.message()).find("strengths[2]") != std::string::npos);
	CHECK(effect == before);
}

TEST_CASE("dualsense triggers: unpacking other modes yields nothing") {
	uint8_t zones[TRIGGER_ZONES] = { 1, 2, 3 };
	TriggerEffect weapon;
	REQUIRE(trigger_weapon(2, 5, 8, weapon));
	CHECK_FALSE(unpack_trigger_zones(weapon, zones));
	CHECK(zones[0] == 0);
	CHECK(trigger_feedback_strength(weapon) == 0);
	CHECK(trigger_feedback_strength(trigger_off()) == 0);
}

} // namespace haptics::dualsense
