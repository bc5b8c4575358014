// Descriptors as Windows gives them (issue 38, item 2): Windows keeps a descriptor only as parsed
// caps and hidapi >= 0.14 rebuilds the bytes from them (dev_tools/hid/windows_rebuilt_descriptor.h,
// docs/devices/hid.md). Every descriptor the suite knows is rebuilt both ways the model reads an
// array's range (as declared, as hidapi's own samples show; and "maximum..0", as a SideWinder
// Force Feedback 2 showed): the parser must find the same values in it and the PID layout the
// same reports, fields, bit offsets and ranges.

#include "dev_tools/hid/windows_rebuilt_descriptor.h"
#include "dev_tools/pid/virtual_pid_descriptor.h"
#include "devices/pid/aj_descriptor.h"
#include "devices/pid/pid_layout.h"
#include "devices/pid/pid_usages.h"
#include "hid_test_util.h"
#ifndef _WIN32
#include "dev_tools/uhid/dualsense_uhid.h" // dev_tools/uhid is Linux's (cmake/platform.cmake).
#endif

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

using namespace haptics;
using namespace haptics::pid;
using hid::WindowsArrayRange;
using Bytes = std::vector<uint8_t>;

namespace {

struct Known {
	std::string name;
	Bytes bytes;
	bool pid;
};

// Every whole descriptor the suite knows. Left out: AJ's PID part alone and
// compose_aj_descriptor(..., true), whose PID collections sit outside any Application
// collection; Windows would make each a device of its own, so no one rebuild holds them.
std::vector<Known> known_descriptors() {
	std::vector<Known> known;
	for (const int buttons : { 1, 8, 13, 16, 32 }) {
		known.push_back({ "AJ, " + std::to_string(buttons) + " buttons", compose_aj_descriptor(static_cast<uint8_t>(buttons)), true });
	}
	known.push_back({ "AJ with a Start Delay", aj_start_delay_descriptor(), true });
	const std::span<const uint8_t> stick = virtual_pid_descriptor();
	known.push_back({ "virtual PID joystick", Bytes(stick.begin(), stick.end()), true });
	known.push_back({ "virtual PID wheel", virtual_pid_wheel_descriptor(), true });
	// test_pid_protocol.cpp's plain joystick (not a PID device).
	known.push_back({ "plain joystick", { 0x05, 0x01, 0x09, 0x04, 0xA1, 0x01, 0x09, 0x30, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02, 0xC0 }, false });
#ifndef _WIN32
	const std::span<const uint8_t> dualsense = uhid::dualsense_usb_descriptor();
	known.push_back({ "DualSense (USB)", Bytes(dualsense.begin(), dualsense.end()), false });
#endif
	return known;
}

Bytes rebuilt(const Bytes &p_bytes, WindowsArrayRange p_range) {
	REQUIRE(hid::count_top_level_collections(p_bytes) == 1);
	Bytes bytes;
	const Status status = hid::windows_rebuilt_descriptor(p_bytes, 0, hid::WindowsRebuildOptions{ p_range }, bytes);
	REQUIRE_MESSAGE(status.ok(), std::string(status.message()));
	return bytes;
}

std::string text(const char *p_format, ...) __attribute__((format(HAPTICS_PRINTF, 1, 2)));
std::string text(const char *p_format, ...) {
	char buffer[256];
	va_list arguments;
	va_start(arguments, p_format);
	std::vsnprintf(buffer, sizeof(buffer), p_format, arguments);
	va_end(arguments);
	return buffer;
}

// One line per value the parser finds (an array: per slot, with its usages), sorted by report
// and bit. Windows keeps no physical range nor unit for 1-bit values and arrays, so those are
// compared for wider values only; p_array_ranges leaves the arrays' logical ranges out.
std::vector<std::string> values_of(const Bytes &p_bytes, bool p_array_ranges) {
	const hid::ReportDescriptor descriptor = test::parse_or_empty(p_bytes, false);
	std::vector<std::string> lines;
	for (const hid::Report &report : descriptor.reports) {
		lines.push_back(text("%s %03u: %u bytes", hid::report_type_name(report.type), report.id, report.byte_length));
		for (const hid::Field &field : descriptor.report_fields(report)) {
			const bool array = !field.is_variable();
			const hid::Collection none;
			const hid::Collection &collection = field.collection < 0 ? none : descriptor.collections[static_cast<size_t>(field.collection)];
			std::string common = text(" %u bits, flags 0x%03X, in 0x%08X (type %u, logical 0x%08X)", field.bit_size,
					field.flags & 0x1FF, collection.usage, collection.type, field.logical_usage);
			if (!array || p_array_ranges) {
				common += text(", %lld..%lld", static_cast<long long>(field.logical_min), static_cast<long long>(field.logical_max));
			}
			if (!array && field.bit_size > 1) {
				common += text(", physical %lld..%lld, unit 0x%X e%d", static_cast<long long>(field.physical_min),
						static_cast<long long>(field.physical_max), field.unit, field.unit_exponent);
			}
			std::string usages;
			for (const uint32_t usage : descriptor.field_usages(field)) {
				usages += text(" %08X", usage);
			}
			for (uint32_t i = 0; i < field.count; ++i) {
				const std::string what = array ? " usages" + usages : text(" usage %08X", descriptor.usage(field, i));
				lines.push_back(text("%s %03u bit %05u:", hid::report_type_name(report.type), report.id,
										field.bit_offset + i * field.bit_size) +
						what + common);
			}
		}
	}
	std::sort(lines.begin(), lines.end());
	return lines;
}

std::string field_line(const PidLayout &p_layout, const char *p_name, int32_t p_field, uint32_t p_index = 0,
		bool p_range = true) {
	if (p_field < 0) {
		return text("%s: absent", p_name);
	}
	const hid::Field &field = p_layout.field(p_field);
	std::string usages;
	for (const uint32_t usage : p_layout.descriptor.field_usages(field)) {
		usages += text(" %08X", usage);
	}
	return text("%s: bit %u, %u bits, %s,", p_name, field.bit_offset + p_index * field.bit_size, field.bit_size,
				   field.is_variable() ? "variable" : "array") +
			(p_range ? text(" %lld..%lld,", static_cast<long long>(field.logical_min), static_cast<long long>(field.logical_max)) : "") +
			(field.is_variable() ? text(" usage %08X", p_layout.descriptor.usage(field, p_index)) : " usages" + usages);
}

std::string ref_line(const PidLayout &p_layout, const char *p_name, const FieldRef &p_ref, bool p_range = true) {
	return field_line(p_layout, p_name, p_ref.field, p_ref.index, p_range);
}

std::string report_line(const PidLayout &p_layout, const char *p_name, int32_t p_report) {
	if (p_report < 0) {
		return text("%s: absent", p_name);
	}
	const hid::Report &report = p_layout.report(p_report);
	return text("%s: %s %u, %u bytes", p_name, hid::report_type_name(report.type), report.id, report.byte_length);
}

// Everything the layout found, resolved to reports, bits, ranges and usages (not to field
// indexes, which a rebuild may split or merge differently).
std::vector<std::string> layout_of(const PidLayout &p_layout) {
	const SetEffectLayout &effect = p_layout.set_effect;
	const EffectOperationLayout &operation = p_layout.effect_operation;
	const DeviceControlLayout &control = p_layout.device_control;
	const BlockLoadLayout &load = p_layout.block_load;
	return {
		report_line(p_layout, "Set Effect", effect.report),
		ref_line(p_layout, "block index", effect.block_index),
		ref_line(p_layout, "duration", effect.duration),
		ref_line(p_layout, "gain", effect.gain),
		ref_line(p_layout, "trigger button", effect.trigger_button),
		ref_line(p_layout, "trigger repeat", effect.trigger_repeat),
		ref_line(p_layout, "direction enable", effect.direction_enable),
		ref_line(p_layout, "start delay", effect.start_delay),
		field_line(p_layout, "effect type", effect.type_field),
		field_line(p_layout, "direction", effect.direction_field),
		text("constant key %u", effect.constant_key),
		report_line(p_layout, "Set Constant Force", p_layout.set_constant.report),
		ref_line(p_layout, "block index", p_layout.set_constant.block_index),
		ref_line(p_layout, "magnitude", p_layout.set_constant.magnitude),
		report_line(p_layout, "Effect Operation", operation.report),
		ref_line(p_layout, "block index", operation.block_index),
		ref_line(p_layout, "loop count", operation.loop_count),
		field_line(p_layout, "operation", operation.operation_field),
		text("keys start %u, solo %u, stop %u", operation.start_key, operation.start_solo_key, operation.stop_key),
		report_line(p_layout, "Device Control", control.report),
		field_line(p_layout, "control", control.field),
		text("bitmask %d, keys %u %u %u %u %u %u", control.bitmask, control.enable_key, control.disable_key,
				control.stop_all_key, control.reset_key, control.pause_key, control.continue_key),
		report_line(p_layout, "Block Load", load.report),
		ref_line(p_layout, "block index", load.block_index),
		// AJ declares it an Array (docs/devices/hid-pid.md, "AJ's descriptor", quirk 5), so a
		// rebuild through the value slots loses its minimum; it is never read, so its range is not
		// compared (its place is).
		ref_line(p_layout, "RAM pool available", load.ram_pool_available,
				!load.ram_pool_available.found() || p_layout.field(load.ram_pool_available).is_variable()),
		field_line(p_layout, "status", load.status_field),
		text("keys success %u, full %u, error %u", load.success_key, load.full_key, load.error_key),
		report_line(p_layout, "Create New Effect", p_layout.create_new_effect_report),
		field_line(p_layout, "effect type", p_layout.create_type_field),
		text("constant key %u", p_layout.create_constant_key),
		report_line(p_layout, "Block Free", p_layout.block_free_report),
		ref_line(p_layout, "block index", p_layout.block_free_index),
		report_line(p_layout, "Device Gain", p_layout.device_gain_report),
		ref_line(p_layout, "gain", p_layout.device_gain),
		report_line(p_layout, "PID Pool", p_layout.pool_report),
		text("max effects %u, quirks 0x%X, infinite %u", p_layout.max_effects, p_layout.quirks & ~QUIRK_REVERSED_ARRAY_RANGES,
				static_cast<unsigned>(p_layout.infinite_duration)),
	};
}

PidLayout layout_or_fail(const Bytes &p_bytes) {
	PidLayout layout;
	const Status status = PidLayout::build(test::parse_or_empty(p_bytes, false), layout);
	REQUIRE_MESSAGE(status.ok(), std::string(status.message()));
	return layout;
}

// "" when equal, else the first line that differs.
std::string difference(const std::vector<std::string> &p_rebuilt, const std::vector<std::string> &p_original) {
	for (size_t i = 0; i < std::max(p_rebuilt.size(), p_original.size()); ++i) {
		const std::string rebuilt_line = i < p_rebuilt.size() ? p_rebuilt[i] : "(none)";
		const std::string original_line = i < p_original.size() ? p_original[i] : "(none)";
		if (rebuilt_line != original_line) {
			return "line " + std::to_string(i) + ": rebuilt '" + rebuilt_line + "', original '" + original_line + "'";
		}
	}
	return "";
}

bool contains(const Bytes &p_bytes, const Bytes &p_sequence) {
	return std::search(p_bytes.begin(), p_bytes.end(), p_sequence.begin(), p_sequence.end()) != p_bytes.end();
}

const hid::Field *selector(const PidLayout &p_layout, int32_t p_field) {
	return p_field >= 0 ? &p_layout.field(p_field) : nullptr;
}

} // namespace

TEST_CASE("hid windows rebuilt: every known descriptor parses to the same values as its original") {
	for (const Known &known : known_descriptors()) {
		CAPTURE(known.name);
		const Bytes as_declared = rebuilt(known.bytes, WindowsArrayRange::BUTTON_SLOTS);
		CHECK(as_declared != known.bytes); // A rebuild, not a copy: Windows keeps no descriptor bytes.
		CHECK(difference(values_of(as_declared, true), values_of(known.bytes, true)) == "");
		// Read through the value slots only the arrays' ranges change.
		const Bytes reversed = rebuilt(known.bytes, WindowsArrayRange::VALUE_SLOTS);
		CHECK(difference(values_of(reversed, false), values_of(known.bytes, false)) == "");
	}
}

TEST_CASE("hid windows rebuilt: each PID descriptor gives the PID layout of its original") {
	for (const Known &known : known_descriptors()) {
		if (!known.pid) {
			continue;
		}
		CAPTURE(known.name);
		const std::vector<std::string> original = layout_of(layout_or_fail(known.bytes));
		for (const WindowsArrayRange range : { WindowsArrayRange::BUTTON_SLOTS, WindowsArrayRange::VALUE_SLOTS }) {
			CAPTURE(static_cast<int>(range));
			const PidLayout layout = layout_or_fail(rebuilt(known.bytes, range));
			CHECK(difference(layout_of(layout), original) == "");
			// Set only when selector arrays came back N..0: each PID descriptor here has some.
			CHECK(((layout.quirks & QUIRK_REVERSED_ARRAY_RANGES) != 0) == (range == WindowsArrayRange::VALUE_SLOTS));
		}
	}
}

TEST_CASE("hid windows rebuilt: AJ's arrays come back as the SideWinder's did, 12..0, 3..0, 3..0, 6..0, and are read as 1..N") {
	const Bytes original = compose_aj_descriptor(16);
	const Bytes as_declared = rebuilt(original, WindowsArrayRange::BUTTON_SLOTS);
	const Bytes reversed = rebuilt(original, WindowsArrayRange::VALUE_SLOTS);
	// Set Effect's effect type: Logical 1..12 (or 12..0), 8 bits x 1, Physical 0..0 (a button
	// keeps none; AJ declares 1..12), Output (Array).
	CHECK(contains(as_declared, { 0x09, 0x28, 0x09, 0x28, 0x15, 0x01, 0x25, 0x0C, 0x75, 0x08, 0x95, 0x01, 0x35, 0x00, 0x45, 0x00, 0x91, 0x00 }));
	CHECK(contains(reversed, { 0x09, 0x28, 0x09, 0x28, 0x15, 0x0C, 0x25, 0x00, 0x75, 0x08, 0x95, 0x01, 0x35, 0x00, 0x45, 0x00, 0x91, 0x00 }));
	CHECK_FALSE(contains(reversed, { 0x15, 0x01, 0x25, 0x0C }));

	const hid::ReportDescriptor parsed = test::parse_or_empty(reversed, false);
	struct Expected {
		hid::ReportType type;
		uint8_t id;
		uint16_t first_usage;
		int64_t maximum;
	};
	const Expected arrays[] = {
		{ hid::ReportType::OUTPUT, 0x01, ET_CONSTANT_FORCE, 12 },
		{ hid::ReportType::OUTPUT, 0x0A, OP_EFFECT_START, 3 },
		{ hid::ReportType::FEATURE, 0x06, BLOCK_LOAD_SUCCESS, 3 },
		{ hid::ReportType::OUTPUT, 0x0C, DC_ENABLE_ACTUATORS, 6 },
	};
	for (const Expected &expected : arrays) {
		CAPTURE(expected.first_usage);
		const hid::Field *field = test::find_field(parsed, expected.type, expected.id, pid_usage(expected.first_usage));
		REQUIRE(field != nullptr);
		CHECK_FALSE(field->is_variable());
		CHECK(field->logical_min == expected.maximum); // Reversed: maximum..0.
		CHECK(field->logical_max == 0);
	}

	const PidLayout layout = layout_or_fail(reversed);
	CHECK((layout.quirks & QUIRK_REVERSED_ARRAY_RANGES) != 0);
	const hid::Field *const read_back[] = { selector(layout, layout.set_effect.type_field),
		selector(layout, layout.effect_operation.operation_field), selector(layout, layout.block_load.status_field),
		selector(layout, layout.device_control.field), selector(layout, layout.create_type_field) };
	const int64_t maxima[] = { 12, 3, 3, 6, 12 };
	for (size_t i = 0; i < std::size(maxima); ++i) {
		REQUIRE(read_back[i] != nullptr);
		CHECK(read_back[i]->logical_min == 1);
		CHECK(read_back[i]->logical_max == maxima[i]);
	}
	CHECK(layout.set_effect.constant_key == 1);
	CHECK(layout.device_control.reset_key == 4);
	CHECK(layout.block_load.full_key == 2);
}

TEST_CASE("pid layout: an effect-type array that is broken, not rebuilt, is still refused, naming it") {
	// AJ's Set Effect effect type (its list ends with 0x28 twice) declared 12..3 or 0..12: neither
	// is what a Windows rebuild gives (maximum..0), so neither is read as 1..12.
	const Bytes declared = { 0x09, 0x28, 0x09, 0x28, 0x15, 0x01, 0x25, 0x0C };
	const Bytes broken[] = { { 0x09, 0x28, 0x09, 0x28, 0x15, 0x0C, 0x25, 0x03 }, { 0x09, 0x28, 0x09, 0x28, 0x15, 0x00, 0x25, 0x0C } };
	for (const Bytes &patch : broken) {
		Bytes bytes = compose_aj_descriptor(16);
		const auto at = std::search(bytes.begin(), bytes.end(), declared.begin(), declared.end());
		REQUIRE(at != bytes.end());
		std::copy(patch.begin(), patch.end(), at);
		PidLayout layout;
		const Status status = PidLayout::build(test::parse_or_empty(bytes, false), layout);
		CHECK(status.code() == StatusCode::UNSUPPORTED);
		CHECK(std::string(status.message()) == "PID layout: no Set Effect effect-type array with logical minimum 1 (0x25)");
	}
}

TEST_CASE("hid windows rebuilt: a small descriptor comes back byte for byte as hidapi writes it") {
	// Joystick, report 1: buttons 1-3 (Usage Min/Max), 5 bits of padding, X and Y (one main item),
	// then in a Logical collection an array of three listed usages in 4 bits, the report ending
	// at bit 36 of 40.
	const Bytes original = {
		0x05, 0x01, 0x09, 0x04, 0xA1, 0x01, 0x85, 0x01, // Joystick, Application, Report ID 1
		0x05, 0x09, 0x19, 0x01, 0x29, 0x03, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x03, 0x81, 0x02, // buttons
		0x95, 0x05, 0x81, 0x03, // padding
		0x05, 0x01, 0x09, 0x30, 0x09, 0x31, 0x15, 0x81, 0x25, 0x7F, 0x35, 0x00, 0x45, 0x64, 0x75, 0x0C, 0x95, 0x02, 0x81, 0x02,
		0x05, 0x0F, 0x09, 0x25, 0xA1, 0x02, 0x09, 0x26, 0x09, 0x27, 0x09, 0x30, 0x15, 0x01, 0x25, 0x03, 0x75, 0x04, 0x95, 0x01,
		0x81, 0x00, 0xC0, // Effect Type array
		0xC0
	};
	// Windows keeps X and Y as two caps, Y first, and the array as three, last usage first; the
	// rebuild merges X and Y back, lists the array's usages in order after its parent's caps,
	// pads the gap and the tail (inside the collection, after the report's last cap), and resets
	// the physical maximum Y set before the array (`45 00`): a button keeps no physical range.
	const Bytes expected = {
		0x05, 0x01, 0x09, 0x04, 0xA1, 0x01, // Joystick, Application
		0x85, 0x01, 0x05, 0x09, 0x19, 0x01, 0x29, 0x03, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x03, 0x81, 0x02, // buttons
		0x75, 0x05, 0x95, 0x01, 0x81, 0x03, // the gap
		0x05, 0x01, 0x09, 0x30, 0x09, 0x31, 0x15, 0x81, 0x25, 0x7F, 0x35, 0x00, 0x45, 0x64, 0x75, 0x0C, 0x95, 0x02, 0x81, 0x02,
		0x05, 0x0F, 0x09, 0x25, 0xA1, 0x02, // Effect Type, Logical
		0x09, 0x26, 0x09, 0x27, 0x09, 0x30, 0x15, 0x01, 0x25, 0x03, 0x75, 0x04, 0x95, 0x01, 0x45, 0x00, 0x81, 0x00,
		0x75, 0x04, 0x95, 0x01, 0x81, 0x03, // the tail
		0xC0, 0xC0
	};
	CHECK(rebuilt(original, WindowsArrayRange::BUTTON_SLOTS) == expected);
}
