// The HID report-descriptor parser on the real AJ PID descriptor (docs/devices/hid-pid.md: the
// report-ID map, field offsets and quirks), on the composed AJ joystick descriptor and on our
// OFB-like virtual descriptor.

#include "dev_tools/pid/virtual_pid_descriptor.h"
#include "devices/hid/report_descriptor.h"
#include "devices/pid/aj_descriptor.h"
#include "devices/pid/pid_usages.h"
#include "hid_test_util.h"
#include "sha256.h"

#include <doctest/doctest.h>

#include <cstring>
#include <string>

using namespace haptics;
using namespace haptics::hid;
using haptics::pid::pid_usage;
using haptics::test::find_field;
using haptics::test::parse_or_empty;

namespace {

struct ExpectedField {
	ReportType type;
	uint8_t id;
	uint32_t usage;
	uint32_t bit_offset; // From byte 0 = report ID.
	uint32_t bit_size;
	uint32_t count;
	int64_t logical_min;
	int64_t logical_max;
	bool variable;
};

void check_fields(const ReportDescriptor &p_descriptor, std::initializer_list<ExpectedField> p_expected) {
	for (const ExpectedField &expected : p_expected) {
		CAPTURE(report_type_name(expected.type));
		CAPTURE(expected.id);
		CAPTURE(expected.usage);
		const Field *field = find_field(p_descriptor, expected.type, expected.id, expected.usage);
		REQUIRE(field != nullptr);
		CHECK(field->bit_offset == expected.bit_offset);
		CHECK(field->bit_size == expected.bit_size);
		CHECK(field->count == expected.count);
		CHECK(field->logical_min == expected.logical_min);
		CHECK(field->logical_max == expected.logical_max);
		CHECK(field->is_variable() == expected.variable);
	}
}

constexpr uint32_t GD(uint16_t p_id) {
	return make_usage(0x01, p_id);
}
constexpr uint32_t ORDINAL(uint16_t p_id) {
	return make_usage(0x0A, p_id);
}

} // namespace

TEST_CASE("hid parser: the transcribed AJ descriptor has the published size and SHA-256 [AJ FFBDescriptor.h]") {
	const uint8_t abc[] = { 'a', 'b', 'c' };
	REQUIRE(test::sha256_hex(abc) == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"); // FIPS 180-2 vector
	CHECK(pid::aj_pid_descriptor().size() == 1227);
	CHECK(test::sha256_hex(pid::aj_pid_descriptor()) == "d4b0768523b7a361d363bc91716e5c0001b9aea84ce8634b1cbd6e174e8f36e9");
}

TEST_CASE("hid parser: AJ report-ID map and wire lengths [docs/devices/hid-pid.md]") {
	const std::vector<uint8_t> bytes = pid::compose_aj_descriptor(16);
	Status status;
	const ReportDescriptor descriptor = parse_or_empty(bytes, true, &status);
	REQUIRE_MESSAGE(status.ok(), status.message());
	CHECK(descriptor.uses_report_ids);
	struct Entry {
		ReportType type;
		uint8_t id;
		uint32_t length;
	};
	const Entry expected[] = {
		{ ReportType::INPUT, 0x01, 7 }, // The joystick part: 16 buttons, X, Y.
		{ ReportType::INPUT, 0x02, 3 }, // PID State
		{ ReportType::OUTPUT, 0x01, 18 }, // Set Effect
		{ ReportType::OUTPUT, 0x02, 14 }, // Set Envelope
		{ ReportType::OUTPUT, 0x03, 15 }, // Set Condition
		{ ReportType::OUTPUT, 0x04, 12 }, // Set Periodic
		{ ReportType::OUTPUT, 0x05, 4 }, // Set Constant Force
		{ ReportType::OUTPUT, 0x06, 6 }, // Set Ramp Force
		{ ReportType::OUTPUT, 0x07, 16 }, // Custom Force Data
		{ ReportType::OUTPUT, 0x08, 2 }, // Download Force Sample
		{ ReportType::OUTPUT, 0x0A, 4 }, // Effect Operation
		{ ReportType::OUTPUT, 0x0B, 2 }, // Block Free
		{ ReportType::OUTPUT, 0x0C, 2 }, // Device Control
		{ ReportType::OUTPUT, 0x0D, 2 }, // Device Gain
		{ ReportType::OUTPUT, 0x0E, 5 }, // Set Custom Force
		{ ReportType::FEATURE, 0x05, 4 }, // Create New Effect
		{ ReportType::FEATURE, 0x06, 5 }, // Block Load
		{ ReportType::FEATURE, 0x07, 5 }, // Pool
	};
	CHECK(descriptor.reports.size() == std::size(expected));
	for (const Entry &entry : expected) {
		CAPTURE(report_type_name(entry.type));
		CAPTURE(entry.id);
		const Report *report = descriptor.find_report(entry.type, entry.id);
		REQUIRE(report != nullptr);
		CHECK(report->byte_length == entry.length);
	}
}

TEST_CASE("hid parser: AJ field byte/bit offsets and ranges [docs/devices/hid-pid.md]") {
	const ReportDescriptor descriptor = parse_or_empty(pid::aj_pid_descriptor(), false);
	REQUIRE(descriptor.reports.size() == 17);
	constexpr ReportType O = ReportType::OUTPUT;
	constexpr ReportType F = ReportType::FEATURE;
	constexpr ReportType I = ReportType::INPUT;
	check_fields(descriptor,
			{
					// Set Effect (01): EBI 1; type 2; duration 3-4, repeat 5-6, sample 7-8; gain 9; button 10;
					// byte 11 bit0 X, bit1 Y, bit2 Direction Enable; direction 12, 13; TSBO 14-15, 16-17.
					{ O, 0x01, pid_usage(0x22), 8, 8, 1, 1, 40, true },
					{ O, 0x01, pid_usage(0x26), 16, 8, 1, 1, 12, false },
					{ O, 0x01, pid_usage(0x50), 24, 16, 3, 0, 32767, true },
					{ O, 0x01, pid_usage(0x52), 72, 8, 1, 0, 255, true },
					{ O, 0x01, pid_usage(0x53), 80, 8, 1, 1, 8, true },
					{ O, 0x01, GD(0x30), 88, 1, 2, 0, 1, true },
					{ O, 0x01, pid_usage(0x56), 90, 1, 1, 0, 1, true },
					{ O, 0x01, ORDINAL(1), 96, 8, 2, 0, 255, true },
					{ O, 0x01, ORDINAL(2), 96, 8, 2, 0, 255, true },
					{ O, 0x02, pid_usage(0x5B), 16, 16, 2, 0, 10000, true }, // Envelope levels 2-3, 4-5
					{ O, 0x02, pid_usage(0x5C), 48, 32, 2, 0, 32767, true }, // times u32 6-9, 10-13
					{ O, 0x03, pid_usage(0x23), 16, 4, 1, 0, 3, true }, // Condition: PBO low nibble of 2
					{ O, 0x03, pid_usage(0x60), 24, 16, 1, -10000, 10000, true }, // CP Offset 3-4
					{ O, 0x03, pid_usage(0x61), 40, 16, 2, -10000, 10000, true }, // coefficients 5-8
					{ O, 0x03, pid_usage(0x63), 72, 16, 2, 0, 10000, true }, // saturations 9-12
					{ O, 0x03, pid_usage(0x65), 104, 16, 1, 0, 10000, true }, // dead band 13-14
					{ O, 0x04, pid_usage(0x70), 16, 16, 1, 0, 10000, true }, // Periodic magnitude 2-3
					{ O, 0x04, pid_usage(0x6F), 32, 16, 1, -10000, 10000, true }, // offset 4-5
					{ O, 0x04, pid_usage(0x71), 48, 16, 1, 0, 35999, true }, // phase 6-7
					{ O, 0x04, pid_usage(0x72), 64, 32, 1, 0, 32767, true }, // period 8-11
					{ O, 0x05, pid_usage(0x22), 8, 8, 1, 1, 40, true }, // Set Constant Force
					{ O, 0x05, pid_usage(0x70), 16, 16, 1, -10000, 10000, true },
					{ O, 0x06, pid_usage(0x75), 16, 16, 2, -10000, 10000, true }, // Ramp
					{ O, 0x0A, pid_usage(0x79), 16, 8, 1, 1, 3, false }, // Effect Operation
					{ O, 0x0A, pid_usage(0x7C), 24, 8, 1, 0, 255, true },
					{ O, 0x0B, pid_usage(0x22), 8, 8, 1, 1, 40, true }, // Block Free
					{ O, 0x0C, pid_usage(0x97), 8, 8, 1, 1, 6, false }, // Device Control array
					{ O, 0x0D, pid_usage(0x7E), 8, 8, 1, 0, 255, true }, // Device Gain
					{ F, 0x05, pid_usage(0x26), 8, 8, 1, 1, 12, false }, // Create New Effect type
					{ F, 0x05, GD(0x3B), 16, 10, 1, 0, 511, true }, // Byte Count, 10 bits
					{ F, 0x06, pid_usage(0x22), 8, 8, 1, 1, 40, true }, // Block Load EBI
					{ F, 0x06, pid_usage(0x8C), 16, 8, 1, 1, 3, false }, // status
					{ F, 0x06, pid_usage(0xAC), 24, 16, 1, 0, 65535, false }, // RAM pool (Array! quirk 5)
					{ F, 0x07, pid_usage(0x80), 8, 16, 1, 0, 65535, true }, // Pool size 1-2
					{ F, 0x07, pid_usage(0x83), 24, 8, 1, 0, 255, true }, // simultaneous max 3
					{ F, 0x07, pid_usage(0xA9), 32, 1, 2, 0, 1, true }, // managed / shared bits of 4
					{ I, 0x02, pid_usage(0x9F), 8, 1, 5, 0, 1, true }, // PID State
					{ I, 0x02, pid_usage(0x94), 16, 1, 1, 0, 1, true },
					{ I, 0x02, pid_usage(0x22), 17, 7, 1, 1, 40, true },
			});
	// The Set Effect durations are ms: unit 0x1003 (SI linear, time), exponent -3.
	const Field *duration = find_field(descriptor, O, 0x01, pid_usage(0x50));
	REQUIRE(duration);
	CHECK(duration->unit == 0x1003);
	CHECK(duration->unit_exponent == -3);
	CHECK(descriptor.field_usages(*duration)[1] == pid_usage(0x54)); // bytes 5-6: Trigger Repeat
	CHECK(descriptor.field_usages(*duration)[2] == pid_usage(0x51)); // bytes 7-8: Sample Period
}

TEST_CASE("hid parser: AJ descriptor quirks are visible [docs/devices/hid-pid.md quirks 1, 3-6]") {
	const ReportDescriptor descriptor = parse_or_empty(pid::aj_pid_descriptor(), false);
	// 1: no Start Delay anywhere in Set Effect.
	CHECK(find_field(descriptor, ReportType::OUTPUT, 0x01, pid_usage(0xA7)) == nullptr);
	// 3: thirteen effect-type usages (0x28 twice) for the logical range 1..12.
	const Field *type = find_field(descriptor, ReportType::OUTPUT, 0x01, pid_usage(0x26));
	REQUIRE(type);
	CHECK(type->usage_count == 13);
	CHECK(descriptor.usage(*type, 11) == pid_usage(0x28));
	CHECK(descriptor.usage(*type, 12) == pid_usage(0x28));
	// 4: Download Force Sample: two usages, one value.
	const Field *sample = find_field(descriptor, ReportType::OUTPUT, 0x08, GD(0x30));
	REQUIRE(sample);
	CHECK(sample->usage_count == 2);
	CHECK(sample->count == 1);
	// 6: Direction carries no unit (reset before its main item); physical 0..36000.
	const Field *direction = find_field(descriptor, ReportType::OUTPUT, 0x01, ORDINAL(1));
	REQUIRE(direction);
	CHECK(direction->unit == 0);
	CHECK(direction->physical_max == 36000);
	CHECK(direction->logical_usage == pid_usage(0x57));
	// Custom Force Data's samples are Buffered Bytes (flags 0x102).
	const Field *custom = find_field(descriptor, ReportType::OUTPUT, 0x07, pid_usage(0x69));
	REQUIRE(custom);
	CHECK(custom->flags == (FIELD_VARIABLE | FIELD_BUFFERED_BYTES));
	CHECK(custom->count == 12);
}

TEST_CASE("hid parser: the AJ fragment alone closes one collection too many [docs/devices/hid-pid.md quirk 2]") {
	Status strict;
	parse_or_empty(pid::aj_pid_descriptor(), true, &strict);
	CHECK(strict.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::string(strict.message()).find("byte 1226") != std::string::npos);
	CHECK(std::string(strict.message()).find("END_COLLECTION") != std::string::npos);

	Status tolerant;
	const ReportDescriptor descriptor = parse_or_empty(pid::aj_pid_descriptor(), false, &tolerant);
	CHECK(tolerant.ok());
	CHECK(descriptor.quirks.unmatched_end_collections == 1);
	CHECK(descriptor.quirks.first_unmatched_end_offset == 1226);
}

TEST_CASE("hid parser: AJ composed descriptors, as Joystick.cpp builds it and with the application closed first") {
	// As AJ @ ed86e27 builds it: the joystick part's last End Collection closes a Physical
	// collection, and the PID part's extra one closes the Application: balanced.
	const std::vector<uint8_t> as_built = pid::compose_aj_descriptor(16);
	Status status;
	const ReportDescriptor descriptor = parse_or_empty(as_built, true, &status);
	REQUIRE_MESSAGE(status.ok(), status.message());
	CHECK(descriptor.quirks.unmatched_end_collections == 0);
	// So every PID report sits inside the Joystick application.
	const Field *ebi = find_field(descriptor, ReportType::OUTPUT, 0x01, pid_usage(0x22));
	REQUIRE(ebi);
	int32_t collection = ebi->collection;
	while (descriptor.collections[static_cast<size_t>(collection)].parent >= 0) {
		collection = descriptor.collections[static_cast<size_t>(collection)].parent;
	}
	CHECK(descriptor.collections[static_cast<size_t>(collection)].usage == GD(0x04));
	CHECK(descriptor.collections[static_cast<size_t>(collection)].type == static_cast<uint8_t>(CollectionType::APPLICATION));

	// The first reading (the joystick part closed on its own): the last byte is unmatched.
	const std::vector<uint8_t> closed = pid::compose_aj_descriptor(16, true);
	parse_or_empty(closed, true, &status);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	const std::string expected_offset = "byte " + std::to_string(closed.size() - 1);
	CHECK_MESSAGE(std::string(status.message()).find(expected_offset) != std::string::npos, status.message());
	const ReportDescriptor tolerant = parse_or_empty(closed, false, &status);
	CHECK(status.ok());
	CHECK(tolerant.quirks.unmatched_end_collections == 1);
	CHECK(tolerant.reports.size() == descriptor.reports.size());

	// Odd button counts are padded to whole bytes: 5 buttons -> 1 byte + X, Y.
	const ReportDescriptor five = parse_or_empty(pid::compose_aj_descriptor(5), true);
	REQUIRE(five.find_report(ReportType::INPUT, 1));
	CHECK(five.find_report(ReportType::INPUT, 1)->byte_length == 6);
	CHECK(find_field(five, ReportType::INPUT, 1, GD(0x30))->bit_offset == 16);
}

TEST_CASE("hid parser: our OFB-like virtual descriptor (Start Delay, bitmask control, 16-bit direction)") {
	Status status;
	const ReportDescriptor descriptor = parse_or_empty(pid::virtual_pid_descriptor(), true, &status);
	REQUIRE_MESSAGE(status.ok(), status.message());
	constexpr ReportType O = ReportType::OUTPUT;
	constexpr ReportType F = ReportType::FEATURE;
	check_fields(descriptor,
			{
					{ ReportType::INPUT, 0x01, make_usage(0x09, 1), 8, 1, 8, 0, 1, true },
					{ ReportType::INPUT, 0x01, GD(0x31), 16, 16, 2, -32767, 32767, true },
					{ O, 0x01, pid_usage(0xA7), 24, 16, 4, 0, 65535, true }, // 4th of the time values: bytes 9-10
					{ O, 0x01, pid_usage(0x52), 88, 8, 1, 0, 255, true },
					{ O, 0x01, pid_usage(0x56), 106, 1, 1, 0, 1, true },
					{ O, 0x01, ORDINAL(1), 112, 16, 1, 0, 36000, true },
					{ O, 0x05, pid_usage(0x70), 16, 16, 1, -32767, 32767, true },
					{ O, 0x0C, pid_usage(0x97), 8, 1, 6, 0, 1, true }, // bitmask
					{ F, 0x11, pid_usage(0x26), 8, 8, 1, 1, 11, false },
					{ F, 0x12, pid_usage(0x8C), 16, 8, 1, 1, 3, false },
					{ F, 0x13, pid_usage(0xA9), 32, 1, 2, 0, 1, true },
			});
	CHECK(descriptor.find_report(O, 0x01)->byte_length == 16);
	CHECK(descriptor.find_report(O, 0x0C)->byte_length == 2);
	CHECK(descriptor.find_report(F, 0x12)->byte_length == 5);
	// POP restored the globals the direction changed: the next field has no unit.
	const Field *direction = find_field(descriptor, O, 0x01, ORDINAL(1));
	CHECK(direction->unit == 0x14);
	CHECK(direction->unit_exponent == -2);
	CHECK(find_field(descriptor, O, 0x05, pid_usage(0x70))->unit == 0);
}
