// Untrusted descriptors: every malformed or absurd input is a clear Status naming the byte
// offset, never a crash; a descriptor cut short says it is truncated, in both modes; tolerant
// mode accepts the unmatched END_COLLECTION real firmware ships. Then a bounded fuzz loop (fixed seed) over random and mutated-AJ descriptors through
// the parser, the PID layout finder, the encoders and the input decoder, which must stay
// clean under ASan/UBSan.

#include "dev_tools/pid/virtual_pid_descriptor.h"
#include "devices/hid/joystick_input.h"
#include "devices/hid/report_descriptor.h"
#include "devices/pid/aj_descriptor.h"
#include "devices/pid/pid_layout.h"
#include "devices/pid/pid_protocol.h"
#include "hid_test_util.h"

#include <doctest/doctest.h>

#include <random>
#include <string>

using namespace haptics;
using namespace haptics::hid;

namespace {

Status parse_status(const std::vector<uint8_t> &p_bytes, bool p_strict = true) {
	Status status;
	test::parse_or_empty(p_bytes, p_strict, &status);
	return status;
}

void check_error(const std::vector<uint8_t> &p_bytes, StatusCode p_code, const char *p_text) {
	const Status status = parse_status(p_bytes);
	CAPTURE(status.message());
	CHECK(status.code() == p_code);
	CHECK(std::string(status.message()).find(p_text) != std::string::npos);
}

std::vector<uint8_t> repeat(std::vector<uint8_t> p_head, std::initializer_list<uint8_t> p_unit, size_t p_times) {
	for (size_t i = 0; i < p_times; ++i) {
		p_head.insert(p_head.end(), p_unit);
	}
	return p_head;
}

// What must hold for any descriptor the parser accepted.
void check_invariants(const ReportDescriptor &p_descriptor) {
	for (const Report &report : p_descriptor.reports) {
		REQUIRE(report.byte_length <= MAX_REPORT_BYTES);
		REQUIRE(report.first_field + report.field_count <= p_descriptor.fields.size());
		for (const Field &field : p_descriptor.report_fields(report)) {
			REQUIRE(field.type == report.type);
			REQUIRE(field.report_id == report.id);
			REQUIRE(field.bit_offset + static_cast<uint64_t>(field.bit_size) * field.count <= report.bit_length);
			REQUIRE(field.usage_first + field.usage_count <= p_descriptor.usages.size());
			REQUIRE(field.collection < static_cast<int32_t>(p_descriptor.collections.size()));
		}
	}
	for (size_t i = 0; i < p_descriptor.collections.size(); ++i) {
		REQUIRE(p_descriptor.collections[i].parent < static_cast<int32_t>(i));
	}
}

// Drives everything downstream of a parsed descriptor with bounded buffers.
void exercise_downstream(ReportDescriptor &&p_descriptor, std::mt19937 &r_random) {
	JoystickInputLayout input;
	if (JoystickInputLayout::find(p_descriptor, input)) {
		uint8_t report[64];
		for (int i = 0; i < 4; ++i) {
			for (uint8_t &byte : report) {
				byte = static_cast<uint8_t>(r_random());
			}
			report[0] = i % 2 == 0 ? input.report_id : report[0];
			JoystickSample sample;
			if (decode_joystick_input(input, std::span<const uint8_t>(report, r_random() % 65), sample)) {
				REQUIRE(sample.x >= -1.0);
				REQUIRE(sample.x <= 1.0);
				REQUIRE(sample.y >= -1.0);
				REQUIRE(sample.y <= 1.0);
			}
		}
	}
	pid::PidLayout layout;
	if (!pid::PidLayout::build(std::move(p_descriptor), layout)) {
		return;
	}
	pid::PidReport report;
	const uint16_t direction = static_cast<uint16_t>(r_random());
	const int16_t level = static_cast<int16_t>(r_random());
	(void)pid::encode_create_constant_effect(layout, report);
	(void)pid::encode_set_effect(layout, 1, direction, report);
	(void)pid::encode_set_constant_force(layout, 1, level, report);
	(void)pid::encode_effect_operation(layout, 1, pid::EffectOperation::STOP, 1, report);
	(void)pid::encode_device_control(layout, pid::DeviceCommand::RESET, report);
	(void)pid::encode_device_gain(layout, 0xFFFF, report);
	(void)pid::encode_block_free(layout, 1, report);
	uint8_t reply[64];
	for (uint8_t &byte : reply) {
		byte = static_cast<uint8_t>(r_random());
	}
	uint8_t block = 0;
	(void)pid::decode_block_load(layout, std::span<const uint8_t>(reply, r_random() % 65), block);
}

} // namespace

TEST_CASE("hid malformed: truncated, oversized and empty descriptors name the offending byte") {
	check_error({}, StatusCode::INVALID_ARGUMENT, "empty");
	check_error(std::vector<uint8_t>(4097, 0x00), StatusCode::OUT_OF_RANGE, "4097 bytes");
	check_error({ 0x05, 0x01, 0x09, 0x30, 0x26, 0xFF }, StatusCode::INVALID_ARGUMENT, "item 0x26 at byte 4 needs 2 data bytes, 1 left");
	check_error({ 0x05 }, StatusCode::INVALID_ARGUMENT, "at byte 0");
	check_error({ 0x05, 0x01, 0xFE, 0x05, 0x10, 0x01 }, StatusCode::INVALID_ARGUMENT, "long item at byte 2");
	check_error({ 0x05, 0x01, 0xFE }, StatusCode::INVALID_ARGUMENT, "long item at byte 2 is truncated");
	check_error({ 0x0C }, StatusCode::INVALID_ARGUMENT, "reserved item type 0x0C at byte 0");
	CHECK(parse_status({ 0x0C }, false).ok()); // Tolerant: skipped.
}

TEST_CASE("hid malformed: an unmatched END_COLLECTION (strict fails, tolerant records)") {
	check_error({ 0x05, 0x01, 0xC0 }, StatusCode::INVALID_ARGUMENT, "END_COLLECTION at byte 2 closes no open collection");
	Status status;
	const ReportDescriptor tolerant = test::parse_bytes({ 0xA1, 0x01, 0xC0, 0xC0 }, &status, false);
	CHECK(status.ok());
	CHECK(tolerant.quirks.unmatched_end_collections == 1);
	CHECK(tolerant.quirks.first_unmatched_end_offset == 3);
}

TEST_CASE("hid malformed: a descriptor cut short is truncated, saying so with the byte offset, strict or tolerant") {
	// The AJ descriptor cut at an item boundary inside its Joystick application (opened at
	// byte 4), just after Set Effect's End Collection: tolerant parsing used to accept it and
	// lose every report after the cut.
	std::vector<uint8_t> cut = pid::compose_aj_descriptor(16);
	cut.resize(cut.size() - pid::AJ_PID_DESCRIPTOR_SIZE + 0x134);
	const std::string cut_error = "HID descriptor is truncated at byte " + std::to_string(cut.size()) +
			": 1 collection(s) still open at the end (outermost opened at byte 4)";
	const struct {
		std::vector<uint8_t> bytes;
		std::string expected;
	} cases[] = {
		{ { 0x05, 0x01, 0x09, 0x30, 0x26, 0xFF }, "HID descriptor is truncated: item 0x26 at byte 4 needs 2 data bytes, 1 left" },
		{ { 0x05, 0x01, 0xFE, 0x05, 0x10, 0x01 }, "HID descriptor is truncated: long item at byte 2 declares 5 data bytes, 1 left" },
		{ { 0x05, 0x01, 0x09, 0x04, 0xA1, 0x01, 0xA1, 0x00, 0xC0 },
				"HID descriptor is truncated at byte 9: 1 collection(s) still open at the end (outermost opened at byte 4)" },
		{ cut, cut_error },
	};
	for (const auto &test : cases) {
		for (const bool strict : { true, false }) {
			CAPTURE(test.expected);
			CAPTURE(strict);
			Status status;
			const ReportDescriptor descriptor = test::parse_or_empty(test.bytes, strict, &status);
			CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
			CHECK(std::string(status.message()) == test.expected);
			CHECK(descriptor.reports.empty());
		}
	}
}

TEST_CASE("hid malformed: absurd sizes and counts hit the hard limits") {
	check_error({ 0x96, 0xFF, 0xFF }, StatusCode::OUT_OF_RANGE, "report count 65535 at byte 0 (limit 4096)");
	check_error({ 0x76, 0x01, 0x01 }, StatusCode::OUT_OF_RANGE, "report size 257 bits at byte 0");
	check_error({ 0x97, 0xFF, 0xFF, 0xFF, 0xFF }, StatusCode::OUT_OF_RANGE, "report count 4294967295");
	// 256 bits x 200 = 6400 bytes in one report.
	check_error({ 0x05, 0x01, 0x09, 0x30, 0x76, 0x00, 0x01, 0x95, 0xC8, 0x81, 0x02 }, StatusCode::OUT_OF_RANGE,
			"input report 0 grows past 4096 bytes at byte 9");
	check_error({ 0x05, 0x09, 0x19, 0x00, 0x2A, 0xFF, 0xFF }, StatusCode::OUT_OF_RANGE, "usage range at byte 4 has 65536 usages");
	check_error({ 0x29, 0x05 }, StatusCode::INVALID_ARGUMENT, "usage maximum at byte 0 without a minimum");
	check_error({ 0x85, 0x00 }, StatusCode::INVALID_ARGUMENT, "report ID 0 at byte 0");
	check_error({ 0x86, 0x00, 0x01 }, StatusCode::INVALID_ARGUMENT, "report ID 256");
	check_error({ 0x05, 0x01, 0x09, 0x30, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02, 0x85, 0x01, 0x09, 0x31, 0x81, 0x02 },
			StatusCode::INVALID_ARGUMENT, "main item at byte 8 comes before any Report ID");
	// 513 one-bit fields.
	check_error(repeat({ 0x05, 0x01, 0x75, 0x01, 0x95, 0x01 }, { 0x09, 0x30, 0x81, 0x02 }, 513), StatusCode::OUT_OF_RANGE,
			"more than 512 fields");
	// 33 ranges of 255 usages: more than 8192 usages in 200 bytes.
	check_error(repeat({ 0x05, 0x09, 0x75, 0x01, 0x95, 0x01 }, { 0x19, 0x01, 0x29, 0xFF, 0x81, 0x00 }, 33), StatusCode::OUT_OF_RANGE,
			"more than 8192 usages");
}

TEST_CASE("hid malformed: global stack and collection nesting limits") {
	check_error({ 0x05, 0x01, 0xB4 }, StatusCode::INVALID_ARGUMENT, "POP at byte 2 without a matching PUSH");
	check_error(std::vector<uint8_t>(9, 0xA4), StatusCode::OUT_OF_RANGE, "PUSH at byte 8 nests deeper than 8");
	check_error(repeat({}, { 0xA1, 0x02 }, 33), StatusCode::OUT_OF_RANGE, "collections nested deeper than 32 at byte 64");
	std::vector<uint8_t> deep_but_fine = repeat({}, { 0xA1, 0x02 }, 32);
	deep_but_fine.insert(deep_but_fine.end(), 32, 0xC0);
	CHECK(parse_status(deep_but_fine).ok());
	check_error({ 0xA9, 0x01, 0xA9, 0x01 }, StatusCode::INVALID_ARGUMENT, "nested delimiter at byte 2");
}

TEST_CASE("hid fuzz: random and mutated-AJ descriptors through parser, PID layout, encoders and input decoder") {
	std::mt19937 random(0x5EED1234u);
	const std::vector<uint8_t> aj = pid::compose_aj_descriptor(16);
	const std::span<const uint8_t> ours = pid::virtual_pid_descriptor();
	// Item prefixes that reach the parser's branches more often than uniform bytes would.
	constexpr uint8_t PREFIXES[] = { 0x05, 0x06, 0x09, 0x0B, 0x15, 0x16, 0x17, 0x19, 0x25, 0x26, 0x27, 0x29, 0x2A, 0x55, 0x65, 0x75,
		0x76, 0x81, 0x85, 0x91, 0x95, 0x96, 0xA1, 0xA4, 0xA9, 0xB1, 0xB4, 0xC0, 0xFE };
	size_t accepted = 0;
	size_t layouts = 0;
	constexpr int ITERATIONS = 20000;
	for (int iteration = 0; iteration < ITERATIONS; ++iteration) {
		std::vector<uint8_t> bytes;
		const int kind = iteration % 4;
		if (kind == 0) {
			bytes.resize(random() % 300);
			for (size_t i = 0; i < bytes.size(); ++i) {
				bytes[i] = random() % 3 == 0 ? PREFIXES[random() % std::size(PREFIXES)] : static_cast<uint8_t>(random());
			}
		} else {
			bytes = kind == 3 ? std::vector<uint8_t>(ours.begin(), ours.end()) : aj;
			const int mutations = 1 + static_cast<int>(random() % 6);
			for (int m = 0; m < mutations && !bytes.empty(); ++m) {
				const size_t at = random() % bytes.size();
				switch (random() % 5) {
					case 0:
						bytes[at] = static_cast<uint8_t>(random());
						break;
					case 1:
						bytes[at] ^= static_cast<uint8_t>(1u << (random() % 8));
						break;
					case 2:
						bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(at));
						break;
					case 3:
						bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at), PREFIXES[random() % std::size(PREFIXES)]);
						break;
					default:
						bytes.resize(at);
						break;
				}
			}
		}
		for (const bool strict : { true, false }) {
			ReportDescriptor descriptor;
			const Status status = ReportDescriptor::parse(bytes, ParseOptions{ strict }, descriptor);
			if (!status) {
				REQUIRE(status.message()[0] != '\0');
				REQUIRE(descriptor.reports.empty());
				continue;
			}
			++accepted;
			check_invariants(descriptor);
			if (!strict) {
				const size_t before = descriptor.reports.size();
				exercise_downstream(std::move(descriptor), random);
				layouts += before > 0 ? 1 : 0;
			}
		}
	}
	MESSAGE("fuzz: " << ITERATIONS << " descriptors, " << accepted << " parses accepted, " << layouts << " went downstream");
	CHECK(accepted > ITERATIONS / 4); // The mutations must not all be rejected: the loop reaches deep paths.
}
