// PID layout detection and report encoding, byte for byte: the kernel's scaling (the worked
// values of docs/devices/hid-pid.md), its golden reports on the AJ descriptor, and the OFB-like branches
// (bitmask Device Control, 16-bit direction, +-32767 magnitude) on our virtual descriptor;
// fields whose bits cannot hold their logical range are refused when the layout is built.

#include "dev_tools/pid/virtual_pid_descriptor.h"
#include "devices/pid/aj_descriptor.h"
#include "devices/pid/pid_layout.h"
#include "devices/pid/pid_protocol.h"
#include "hid_test_util.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace haptics;
using namespace haptics::pid;
using Bytes = std::vector<uint8_t>;

namespace {

PidLayout build_layout(std::span<const uint8_t> p_bytes) {
	hid::ReportDescriptor descriptor = test::parse_or_empty(p_bytes, false);
	PidLayout layout;
	const Status status = PidLayout::build(std::move(descriptor), layout);
	REQUIRE_MESSAGE(status.ok(), status.message());
	return layout;
}

PidLayout aj_layout() {
	return build_layout(compose_aj_descriptor(16));
}

PidLayout virtual_layout() {
	return build_layout(virtual_pid_descriptor());
}

Bytes bytes_of(const PidReport &p_report) {
	return Bytes(p_report.bytes, p_report.bytes + p_report.length);
}

hid::Field range_field(int64_t p_min, int64_t p_max, uint32_t p_bits = 16) {
	hid::Field field;
	field.logical_min = p_min;
	field.logical_max = p_max;
	field.bit_size = p_bits;
	field.count = 1;
	return field;
}

} // namespace

TEST_CASE("pid protocol: the kernel's scaling gives the worked values of docs/devices/hid-pid.md") {
	const hid::Field dir_255 = range_field(0, 255, 8);
	const hid::Field dir_36000 = range_field(0, 36000);
	CHECK(scale_direction(0x4000, dir_255) == 63);
	CHECK(scale_direction(0x4000, dir_36000) == 9000);
	CHECK(scale_direction(0x8000, dir_255) == 127);
	CHECK(scale_direction(0x8000, dir_36000) == 18000);
	CHECK(scale_direction(0xC000, dir_255) == 191);
	CHECK(scale_direction(0xC000, dir_36000) == 27000);
	const hid::Field level_10000 = range_field(-10000, 10000);
	CHECK(scale_signed(0x4000, level_10000) == 5000);
	CHECK(scale_signed(-0x4000, level_10000) == -5000);
	CHECK(scale_signed(0x7FFF, level_10000) == 10000);
	CHECK(scale_signed(-0x8000, level_10000) == -10000);
	CHECK(scale_signed(0, level_10000) == 0);
	const hid::Field level_32767 = range_field(-32767, 32767);
	CHECK(scale_signed(0x4000, level_32767) == 16384);
	CHECK(scale_signed(-0x4000, level_32767) == -16383); // Truncation asymmetry.
	CHECK(scale_unsigned(0xFFFF, range_field(0, 255, 8)) == 255);
	CHECK(scale_unsigned(0x7FFF, range_field(0, 255, 8)) == 127);
	// Lmin >= 0: negative levels use rescale(-v, 0x8000).
	const hid::Field magnitude_only = range_field(0, 10000);
	CHECK(scale_signed(0x4000, magnitude_only) == 5000);
	CHECK(scale_signed(-0x4000, magnitude_only) == 5000);
}

TEST_CASE("pid layout: AJ reports, keys and quirks found by usage [docs/devices/hid-pid.md]") {
	const PidLayout layout = aj_layout();
	CHECK(layout.report(layout.set_effect.report).id == 0x01);
	CHECK(layout.report(layout.set_constant.report).id == 0x05);
	CHECK(layout.report(layout.effect_operation.report).id == 0x0A);
	CHECK(layout.report(layout.block_free_report).id == 0x0B);
	CHECK(layout.report(layout.device_control.report).id == 0x0C);
	CHECK(layout.report(layout.device_gain_report).id == 0x0D);
	CHECK(layout.report(layout.create_new_effect_report).id == 0x05);
	CHECK(layout.report(layout.create_new_effect_report).type == hid::ReportType::FEATURE);
	CHECK(layout.report(layout.block_load.report).id == 0x06);
	CHECK(layout.report(layout.pool_report).id == 0x07);
	CHECK(layout.set_effect.constant_key == 1);
	CHECK(layout.create_constant_key == 1);
	CHECK(layout.effect_operation.start_key == 1);
	CHECK(layout.effect_operation.stop_key == 3);
	CHECK(layout.device_control.enable_key == 1);
	CHECK(layout.device_control.stop_all_key == 3);
	CHECK(layout.device_control.reset_key == 4);
	CHECK_FALSE(layout.device_control.bitmask);
	CHECK(layout.block_load.success_key == 1);
	CHECK(layout.block_load.full_key == 2);
	CHECK(layout.block_load.error_key == 3);
	CHECK(layout.max_effects == 40);
	CHECK_FALSE(layout.set_effect.start_delay.found());
	CHECK((layout.quirks & QUIRK_MISSING_DELAY) != 0);
	CHECK((layout.quirks & QUIRK_AJ_FIRMWARE) != 0);
	CHECK((layout.quirks & QUIRK_PERMISSIVE_CONTROL) == 0);
	CHECK(layout.infinite_duration == InfiniteDuration::LOGICAL_MAX);
	CHECK(infinite_duration_value(layout) == 0x7FFF);
	// The fragment alone (tolerantly parsed) gives the same layout.
	const PidLayout fragment = build_layout(aj_pid_descriptor());
	CHECK(fragment.report(fragment.set_effect.report).byte_length == 18);
}

TEST_CASE("pid layout: OFB-like virtual descriptor: Start Delay, bitmask control (permissive), ALL_ONES duration") {
	const PidLayout layout = virtual_layout();
	CHECK(layout.set_effect.start_delay.found());
	CHECK(layout.device_control.bitmask);
	CHECK((layout.quirks & QUIRK_DEVICE_CONTROL_BITMASK) != 0);
	CHECK((layout.quirks & QUIRK_PERMISSIVE_CONTROL) != 0); // Bitmask bits are 0..1, not 1-based.
	CHECK((layout.quirks & QUIRK_MISSING_DELAY) == 0);
	CHECK(layout.infinite_duration == InfiniteDuration::ALL_ONES);
	CHECK(layout.report(layout.create_new_effect_report).id == 0x11);
	CHECK(layout.report(layout.block_load.report).id == 0x12);
	CHECK(layout.report(layout.pool_report).id == 0x13);
	CHECK(layout.device_control.reset_key == 4);
}

TEST_CASE("pid layout: a descriptor missing what a constant force needs is refused, naming it") {
	Bytes bytes = compose_aj_descriptor(16);
	const Bytes constant_report = { 0x09, 0x73, 0xA1, 0x02 };
	const auto at = std::search(bytes.begin(), bytes.end(), constant_report.begin(), constant_report.end());
	REQUIRE(at != bytes.end());
	*(at + 1) = 0x7B; // No longer a Set Constant Force collection.
	hid::ReportDescriptor descriptor = test::parse_or_empty(bytes, true);
	PidLayout layout;
	Status status = PidLayout::build(std::move(descriptor), layout);
	CHECK(status.code() == StatusCode::UNSUPPORTED);
	CHECK(std::string(status.message()) == "PID layout: no Set Constant Force report (0x73)");
	CHECK_FALSE(has_pid_layout(bytes, &status));
	// A plain joystick is not a PID device at all.
	const Bytes joystick = { 0x05, 0x01, 0x09, 0x04, 0xA1, 0x01, 0x09, 0x30, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02, 0xC0 };
	CHECK_FALSE(has_pid_layout(joystick, &status));
	CHECK(std::string(status.message()).find("no Set Effect report (0x21)") != std::string::npos);
	CHECK(has_pid_layout(compose_aj_descriptor(16)));
}

TEST_CASE("pid layout: a field whose bits cannot hold its logical range is refused at layout time, naming report and usage") {
	// Set Effect Gain 0..1000 in 8 bits: Linux writes the logical maximum, so the first effect
	// would fail. Set Constant Force Magnitude -10000..10000 in 8 signed bits, likewise.
	struct Case {
		Bytes item; // Unique in the AJ descriptor.
		size_t patch_at;
		Bytes patch;
		size_t main_item_offset; // In the PID part: the Output item of the field.
		const char *expected;
	};
	const Case cases[] = {
		{ { 0x09, 0x52, 0x15, 0x00, 0x26, 0xFF, 0x00 }, 5, { 0xE8, 0x03 }, 0xB8,
				"PID layout: Set Effect report 1: Gain (0x52) has logical range 0..1000, which 8 unsigned bits cannot hold" },
		{ { 0x09, 0x70, 0x16, 0xF0, 0xD8, 0x26, 0x10, 0x27, 0x36, 0xF0, 0xD8, 0x46, 0x10, 0x27, 0x75, 0x10 }, 15, { 0x08 }, 0x2A0,
				"PID layout: Set Constant Force report 5: Magnitude (0x70) has logical range -10000..10000, which 8 signed bits cannot hold" },
	};
	for (const Case &test : cases) {
		CAPTURE(test.expected);
		Bytes bytes = compose_aj_descriptor(16);
		const auto at = std::search(bytes.begin(), bytes.end(), test.item.begin(), test.item.end());
		REQUIRE(at != bytes.end());
		std::copy(test.patch.begin(), test.patch.end(), at + static_cast<std::ptrdiff_t>(test.patch_at));
		const size_t offset = bytes.size() - AJ_PID_DESCRIPTOR_SIZE + test.main_item_offset;
		const std::string expected = std::string(test.expected) + " (descriptor byte " + std::to_string(offset) + ")";
		PidLayout layout;
		Status status = PidLayout::build(test::parse_or_empty(bytes, false), layout);
		CHECK(status.code() == StatusCode::UNSUPPORTED);
		CHECK(std::string(status.message()) == expected);
		// The probe's check says the same, so the device is listed as unusable with the reason.
		CHECK_FALSE(has_pid_layout(bytes, &status));
		CHECK(std::string(status.message()) == expected);
	}
}

TEST_CASE("pid protocol: golden reports on the AJ descriptor (Linux infinite = all ones)") {
	PidLayout layout = aj_layout();
	layout.infinite_duration = InfiniteDuration::ALL_ONES; // What K-new writes, as docs/devices/hid-pid.md mimics.
	PidReport report;
	REQUIRE(encode_create_constant_effect(layout, report));
	CHECK(bytes_of(report) == Bytes{ 0x05, 0x01, 0x00, 0x00 });
	REQUIRE(encode_set_effect(layout, 1, 0x4000, report));
	CHECK(bytes_of(report) == Bytes{ 0x01, 0x01, 0x01, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x04, 0x3F, 0x00, 0x00, 0x00, 0x00, 0x00 });
	REQUIRE(encode_set_constant_force(layout, 1, 0x4000, report));
	CHECK(bytes_of(report) == Bytes{ 0x05, 0x01, 0x88, 0x13 });
	REQUIRE(encode_effect_operation(layout, 1, EffectOperation::START, 1, report));
	CHECK(bytes_of(report) == Bytes{ 0x0A, 0x01, 0x01, 0x01 });
	REQUIRE(encode_set_constant_force(layout, 1, -0x4000, report));
	CHECK(bytes_of(report) == Bytes{ 0x05, 0x01, 0x78, 0xEC });
	REQUIRE(encode_set_effect(layout, 1, 0xC000, report));
	CHECK(bytes_of(report) == Bytes{ 0x01, 0x01, 0x01, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x04, 0xBF, 0x00, 0x00, 0x00, 0x00, 0x00 });
	REQUIRE(encode_effect_operation(layout, 1, EffectOperation::STOP, 1, report));
	CHECK(bytes_of(report) == Bytes{ 0x0A, 0x01, 0x03, 0x01 });
	REQUIRE(encode_block_free(layout, 1, report));
	CHECK(bytes_of(report) == Bytes{ 0x0B, 0x01 });
	REQUIRE(encode_device_gain(layout, 0x7FFF, report));
	CHECK(bytes_of(report) == Bytes{ 0x0D, 0x7F });
	REQUIRE(encode_device_control(layout, DeviceCommand::RESET, report));
	CHECK(bytes_of(report) == Bytes{ 0x0C, 0x04 });
	REQUIRE(encode_device_control(layout, DeviceCommand::ENABLE_ACTUATORS, report));
	CHECK(bytes_of(report) == Bytes{ 0x0C, 0x01 });
	REQUIRE(encode_device_control(layout, DeviceCommand::STOP_ALL_EFFECTS, report));
	CHECK(bytes_of(report) == Bytes{ 0x0C, 0x03 });
	// AJ's own infinite (the layout's choice for this descriptor): 0x7FFF [docs/devices/hid-pid.md, "Infinite duration"].
	layout.infinite_duration = InfiniteDuration::LOGICAL_MAX;
	REQUIRE(encode_set_effect(layout, 1, 0x4000, report));
	CHECK(bytes_of(report) == Bytes{ 0x01, 0x01, 0x01, 0xFF, 0x7F, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x04, 0x3F, 0x00, 0x00, 0x00, 0x00, 0x00 });
}

TEST_CASE("pid protocol: OFB-like bitmask Device Control, 16-bit direction, +-32767 magnitude") {
	const PidLayout layout = virtual_layout();
	PidReport report;
	REQUIRE(encode_device_control(layout, DeviceCommand::RESET, report));
	CHECK(bytes_of(report) == Bytes{ 0x0C, 0x08 });
	REQUIRE(encode_device_control(layout, DeviceCommand::ENABLE_ACTUATORS, report));
	CHECK(bytes_of(report) == Bytes{ 0x0C, 0x01 });
	REQUIRE(encode_device_control(layout, DeviceCommand::STOP_ALL_EFFECTS, report));
	CHECK(bytes_of(report) == Bytes{ 0x0C, 0x04 });
	REQUIRE(encode_create_constant_effect(layout, report));
	CHECK(bytes_of(report) == Bytes{ 0x11, 0x01, 0x00, 0x00 });
	// EBI | type | duration FFFF | repeat | sample | delay | gain FF | button | 0x04 | 9000 = 0x2328
	REQUIRE(encode_set_effect(layout, 3, 0x4000, report));
	CHECK(bytes_of(report) == Bytes{ 0x01, 0x03, 0x01, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x04, 0x28, 0x23 });
	REQUIRE(encode_set_constant_force(layout, 3, -0x4000, report));
	CHECK(bytes_of(report) == Bytes{ 0x05, 0x03, 0x01, 0xC0 }); // -16383
	REQUIRE(encode_set_constant_force(layout, 3, 0x4000, report));
	CHECK(bytes_of(report) == Bytes{ 0x05, 0x03, 0x00, 0x40 }); // 16384
}

TEST_CASE("pid protocol: Block Load replies map to Success / Full / Error / garbage") {
	const PidLayout layout = aj_layout();
	uint8_t block = 0;
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x01, 0x01, 0xFF, 0xFF }, block) == BlockLoadResult::SUCCESS);
	CHECK(block == 1);
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x28, 0x01, 0x00, 0x00 }, block) == BlockLoadResult::SUCCESS);
	CHECK(block == 40);
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x00, 0x02, 0x00, 0x00 }, block) == BlockLoadResult::FULL);
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x00, 0x03, 0x00, 0x00 }, block) == BlockLoadResult::ERROR);
	CHECK(decode_block_load(layout, Bytes{ 0x07, 0x01, 0x01, 0x00, 0x00 }, block) == BlockLoadResult::GARBAGE); // other ID
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x01, 0x00, 0x00, 0x00 }, block) == BlockLoadResult::GARBAGE); // status 0
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x01, 0x07, 0x00, 0x00 }, block) == BlockLoadResult::GARBAGE);
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x00, 0x01, 0x00, 0x00 }, block) == BlockLoadResult::GARBAGE); // EBI 0
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x29, 0x01, 0x00, 0x00 }, block) == BlockLoadResult::GARBAGE); // EBI 41
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x01 }, block) == BlockLoadResult::GARBAGE); // truncated
	CHECK(decode_block_load(layout, Bytes{}, block) == BlockLoadResult::GARBAGE);
	// Success without the trailing RAM-pool bytes is still Success.
	CHECK(decode_block_load(layout, Bytes{ 0x06, 0x02, 0x01 }, block) == BlockLoadResult::SUCCESS);
}
