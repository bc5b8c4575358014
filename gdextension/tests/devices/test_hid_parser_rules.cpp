// The HID parser's item-level rules on small hand-made descriptors: sign extension by item
// size and the unsigned-maximum rule, usage pages declared after usages, extended usages,
// ranges, PUSH/POP, delimiters, long items, padding, unit exponents, descriptors without
// report IDs; and the bit helpers.

#include "devices/hid/report_bits.h"
#include "devices/hid/report_descriptor.h"
#include "hid_test_util.h"

#include <doctest/doctest.h>

#include <string>

using namespace haptics;
using namespace haptics::hid;
using haptics::test::find_field;
using haptics::test::parse_bytes;

namespace {

// One Input field of 8 bits with usage GD X, preceded by p_items; no report ID.
ReportDescriptor one_field(std::initializer_list<uint8_t> p_items, Status *r_status = nullptr) {
	std::vector<uint8_t> bytes = { 0x05, 0x01, 0x09, 0x30 };
	bytes.insert(bytes.end(), p_items);
	bytes.insert(bytes.end(), { 0x75, 0x08, 0x95, 0x01, 0x81, 0x02 });
	return test::parse_or_empty(bytes, true, r_status);
}

} // namespace

TEST_CASE("hid parser rules: logical maximum is unsigned when the minimum is >= 0 (Linux), signed otherwise") {
	struct Case {
		std::initializer_list<uint8_t> items;
		int64_t min, max;
	};
	const Case cases[] = {
		{ { 0x15, 0x00, 0x26, 0xFF, 0x00 }, 0, 255 }, // `26 FF 00` is 255, not -1
		{ { 0x15, 0x00, 0x25, 0xFF }, 0, 255 }, // 1-byte 0xFF with min 0: unsigned
		{ { 0x15, 0x81, 0x25, 0x7F }, -127, 127 },
		{ { 0x16, 0x00, 0x80, 0x26, 0xFF, 0x7F }, -32768, 32767 },
		{ { 0x15, 0xFF, 0x25, 0xFF }, -1, -1 }, // min < 0: the 1-byte max sign-extends
		{ { 0x25, 0xFF, 0x15, 0x00 }, 0, 255 }, // maximum before minimum: same answer
		{ { 0x17, 0x00, 0x00, 0x00, 0x80, 0x27, 0xFF, 0xFF, 0xFF, 0x7F }, -2147483648LL, 2147483647LL },
		{ { 0x15, 0x00, 0x27, 0xFF, 0xFF, 0xFF, 0xFF }, 0, 4294967295LL }, // unsigned 32-bit max
	};
	for (const Case &c : cases) {
		Status status;
		const ReportDescriptor descriptor = one_field(c.items, &status);
		REQUIRE_MESSAGE(status.ok(), status.message());
		REQUIRE(descriptor.fields.size() == 1);
		CHECK(descriptor.fields[0].logical_min == c.min);
		CHECK(descriptor.fields[0].logical_max == c.max);
	}
	// Physical follows the same rule, and (0, 0) means "as logical".
	const ReportDescriptor physical = one_field({ 0x15, 0x00, 0x26, 0xFF, 0x00, 0x35, 0x00, 0x46, 0x10, 0x27 });
	CHECK(physical.fields[0].physical_max == 10000);
	const ReportDescriptor as_logical = one_field({ 0x15, 0x81, 0x25, 0x7F });
	CHECK(as_logical.fields[0].physical_min == -127);
	CHECK(as_logical.fields[0].physical_max == 127);
}

TEST_CASE("hid parser rules: usage pages, extended usages, ranges and delimiters") {
	// Usage before its Usage Page (Linux re-pages trailing usages at the main item).
	Status status;
	ReportDescriptor descriptor = parse_bytes({ 0x09, 0x30, 0x05, 0x01, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02 }, &status);
	REQUIRE(status.ok());
	CHECK(descriptor.usages[0] == make_usage(0x01, 0x30));
	// A 4-byte usage keeps its own page whatever the current page is.
	descriptor = parse_bytes({ 0x05, 0x0F, 0x0B, 0x02, 0x00, 0x0A, 0x00, 0x09, 0x22, 0x75, 0x08, 0x95, 0x02, 0x91, 0x02 });
	REQUIRE(descriptor.fields.size() == 1);
	CHECK(descriptor.usages[0] == make_usage(0x0A, 0x02));
	CHECK(descriptor.usages[1] == make_usage(0x0F, 0x22));
	// Usage Minimum/Maximum expand; a variable field past its usages repeats the last (Linux).
	descriptor = parse_bytes({ 0x05, 0x09, 0x19, 0x01, 0x29, 0x03, 0x75, 0x01, 0x95, 0x05, 0x81, 0x02 });
	REQUIRE(descriptor.fields.size() == 1);
	const Field &buttons = descriptor.fields[0];
	CHECK(buttons.usage_count == 3);
	CHECK(buttons.max_usage() == 5);
	CHECK(descriptor.usage(buttons, 2) == make_usage(0x09, 3));
	CHECK(descriptor.usage(buttons, 4) == make_usage(0x09, 3));
	// Delimited aliases: only the first set counts.
	descriptor = parse_bytes({ 0x05, 0x01, 0xA9, 0x01, 0x09, 0x30, 0x09, 0x32, 0xA9, 0x00, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02 });
	REQUIRE(descriptor.fields.size() == 1);
	CHECK(descriptor.fields[0].usage_count == 2);
	descriptor = parse_bytes({ 0x05, 0x01, 0xA9, 0x01, 0x09, 0x30, 0xA9, 0x00, 0xA9, 0x01, 0x09, 0x32, 0xA9, 0x00, 0x75, 0x08,
			0x95, 0x01, 0x81, 0x02 });
	REQUIRE(descriptor.fields.size() == 1);
	CHECK(descriptor.fields[0].usage_count == 1);
	CHECK(descriptor.usages[0] == make_usage(0x01, 0x30));
}

TEST_CASE("hid parser rules: PUSH/POP, long items, padding, unit exponents, no report IDs") {
	Status status;
	const ReportDescriptor descriptor = parse_bytes(
			{
					0x05, 0x01, 0x75, 0x08, 0x95, 0x01, // 8-bit values
					0xA4, 0x75, 0x10, 0x55, 0x0D, 0x09, 0x30, 0x81, 0x02, 0xB4, // PUSH, 16-bit X, exponent nibble -3, POP
					0x09, 0x31, 0x81, 0x02, // Y: size 8 and exponent 0 again
					0xFE, 0x02, 0x10, 0xAA, 0xBB, // a long item: skipped
					0x75, 0x04, 0x81, 0x03, // 4 bits of padding: no field
					0x55, 0xFD, 0x09, 0x32, 0x81, 0x02, // 4-bit Z, exponent byte 0xFD = -3
			},
			&status);
	REQUIRE_MESSAGE(status.ok(), status.message());
	CHECK_FALSE(descriptor.uses_report_ids);
	CHECK(descriptor.quirks.long_items == 1);
	REQUIRE(descriptor.fields.size() == 3);
	const Field *x = find_field(descriptor, ReportType::INPUT, 0, make_usage(0x01, 0x30));
	const Field *y = find_field(descriptor, ReportType::INPUT, 0, make_usage(0x01, 0x31));
	const Field *z = find_field(descriptor, ReportType::INPUT, 0, make_usage(0x01, 0x32));
	REQUIRE(x);
	REQUIRE(y);
	REQUIRE(z);
	CHECK(x->bit_offset == 0); // No ID byte.
	CHECK(x->bit_size == 16);
	CHECK(x->unit_exponent == -3);
	CHECK(y->bit_offset == 16);
	CHECK(y->bit_size == 8); // POP restored size and exponent.
	CHECK(y->unit_exponent == 0);
	CHECK(z->bit_offset == 28); // After 4 padding bits.
	CHECK(z->bit_size == 4);
	CHECK(z->unit_exponent == -3);
	REQUIRE(descriptor.reports.size() == 1);
	CHECK(descriptor.reports[0].byte_length == 4); // 32 bits, no ID byte
}

TEST_CASE("hid bits: pack and unpack across byte boundaries, signed and unsigned, bounds-checked") {
	uint8_t buffer[4] = { 0xFF, 0xFF, 0xFF, 0xFF };
	REQUIRE(insert_bits(buffer, 4, 12, 0xABC));
	CHECK(buffer[0] == 0xCF);
	CHECK(buffer[1] == 0xAB);
	CHECK(buffer[2] == 0xFF); // Neighbours untouched.
	uint32_t value = 0;
	REQUIRE(extract_bits(buffer, 4, 12, value));
	CHECK(value == 0xABC);
	REQUIRE(insert_bits(buffer, 0, 32, 0x12345678));
	REQUIRE(extract_bits(buffer, 0, 32, value));
	CHECK(value == 0x12345678);
	CHECK(sign_extend(0x7F, 7) == -1);
	CHECK(sign_extend(0x3F, 7) == 63);
	CHECK(sign_extend(0xD8F0, 16) == -10000);
	CHECK_FALSE(extract_bits(buffer, 25, 8, value)); // Past the end.
	CHECK_FALSE(insert_bits(buffer, 0, 33, 0)); // Wider than 32 bits.
	CHECK_FALSE(extract_bits(std::span<const uint8_t>(), 0, 1, value));

	Field field;
	field.bit_offset = 8;
	field.bit_size = 16;
	field.count = 2;
	field.logical_min = -10000;
	field.logical_max = 10000;
	uint8_t report[5] = {};
	REQUIRE(write_field(report, field, 1, -5000).ok());
	CHECK(report[3] == 0x78);
	CHECK(report[4] == 0xEC);
	int64_t read = 0;
	REQUIRE(read_field(report, field, 1, read).ok());
	CHECK(read == -5000);
	const Status too_big = write_field(report, field, 0, 40000);
	CHECK(too_big.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::string(too_big.message()).find("does not fit") != std::string::npos);
	CHECK(read_field(std::span<const uint8_t>(report, 4), field, 1, read).code() == StatusCode::OUT_OF_RANGE);
	CHECK_FALSE(read_field_value(report, field, 2, read)); // Element past the count.
}
