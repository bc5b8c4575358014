// The stick's input report: found by usage (GD X/Y, Steering, Button page), decoded to the
// byte, normalised by the logical range, and robust to foreign, short and random reports.

#include "dev_tools/pid/virtual_pid_descriptor.h"
#include "devices/hid/joystick_input.h"
#include "devices/pid/aj_descriptor.h"
#include "hid_test_util.h"

#include <doctest/doctest.h>

#include <random>
#include <vector>

using namespace haptics;
using namespace haptics::hid;

namespace {

JoystickInputLayout layout_of(std::span<const uint8_t> p_descriptor) {
	const ReportDescriptor descriptor = test::parse_or_empty(p_descriptor, false);
	JoystickInputLayout layout;
	const Status status = JoystickInputLayout::find(descriptor, layout);
	REQUIRE_MESSAGE(status.ok(), status.message());
	return layout;
}

} // namespace

TEST_CASE("hid joystick input: AJ's stick report decoded to the byte") {
	const JoystickInputLayout layout = layout_of(pid::compose_aj_descriptor(16));
	CHECK(layout.report_id == 0x01);
	CHECK(layout.report_length == 7);
	CHECK(layout.has_y);
	CHECK(layout.button_count == 16);
	// Buttons 1, 3, 16 | X = +0x4000 | Y = -0x4000 (pushed away from the user).
	const uint8_t report[] = { 0x01, 0x05, 0x80, 0x00, 0x40, 0x00, 0xC0 };
	JoystickSample sample;
	REQUIRE(decode_joystick_input(layout, report, sample));
	CHECK(sample.buttons == 0x8005);
	CHECK(sample.x == doctest::Approx(2.0 * (16384.0 + 32767.0) / 65534.0 - 1.0));
	CHECK(sample.y == doctest::Approx(2.0 * (-16384.0 + 32767.0) / 65534.0 - 1.0));
	const uint8_t pid_state[] = { 0x02, 0x02, 0x03 };
	CHECK_FALSE(decode_joystick_input(layout, pid_state, sample)); // Another report.
	CHECK_FALSE(decode_joystick_input(layout, std::span<const uint8_t>(report, 6), sample)); // Short.
	CHECK_FALSE(decode_joystick_input(layout, std::span<const uint8_t>(), sample));
}

TEST_CASE("hid joystick input: ranges normalise about their centre - a wheel has X only") {
	Field field;
	field.logical_min = 0;
	field.logical_max = 1023;
	CHECK(normalise_axis(field, 0) == -1.0);
	CHECK(normalise_axis(field, 1023) == 1.0);
	CHECK(normalise_axis(field, 511) < 0.0);
	CHECK(normalise_axis(field, 512) > 0.0);
	CHECK(normalise_axis(field, 5000) == 1.0); // Out of range: clamped.
	field.logical_max = 0;
	CHECK(normalise_axis(field, 0) == 0.0); // Empty range.

	const std::vector<uint8_t> wheel = pid::virtual_pid_wheel_descriptor();
	const JoystickInputLayout layout = layout_of(wheel);
	CHECK_FALSE(layout.has_y);
	CHECK(layout.report_length == 4);
	// Only Simulation Steering (no X): still a wheel.
	Status status;
	const ReportDescriptor steering = test::parse_bytes({ 0x05, 0x02, 0x09, 0xC8, 0x15, 0x00, 0x26, 0xFF, 0x03, 0x75, 0x10, 0x95,
																0x01, 0x81, 0x02 },
			&status);
	REQUIRE(status.ok());
	JoystickInputLayout steering_layout;
	REQUIRE(JoystickInputLayout::find(steering, steering_layout).ok());
	const uint8_t report[] = { 0xFF, 0x03 }; // No report IDs: no ID byte.
	JoystickSample sample;
	REQUIRE(decode_joystick_input(steering_layout, report, sample));
	CHECK(sample.x == 1.0);
	// No stick at all.
	const ReportDescriptor keyboard = test::parse_bytes({ 0x05, 0x07, 0x19, 0xE0, 0x29, 0xE7, 0x75, 0x01, 0x95, 0x08, 0x81, 0x02 });
	JoystickInputLayout none;
	CHECK(JoystickInputLayout::find(keyboard, none).code() == StatusCode::UNSUPPORTED);
}

TEST_CASE("hid joystick input: random reports never read out of bounds and stay in range") {
	std::mt19937 random(99);
	const JoystickInputLayout layouts[] = { layout_of(pid::compose_aj_descriptor(16)), layout_of(pid::virtual_pid_descriptor()),
		layout_of(pid::virtual_pid_wheel_descriptor()) };
	size_t decoded = 0;
	for (int i = 0; i < 30000; ++i) {
		const JoystickInputLayout &layout = layouts[i % 3];
		std::vector<uint8_t> report(random() % 12);
		for (uint8_t &byte : report) {
			byte = static_cast<uint8_t>(random());
		}
		if (!report.empty() && random() % 2 == 0) {
			report[0] = layout.report_id;
		}
		JoystickSample sample;
		if (decode_joystick_input(layout, report, sample)) {
			++decoded;
			REQUIRE(report.size() >= layout.report_length);
			REQUIRE(sample.x >= -1.0);
			REQUIRE(sample.x <= 1.0);
			REQUIRE(sample.y >= -1.0);
			REQUIRE(sample.y <= 1.0);
		}
	}
	CHECK(decoded > 1000);
}
