// The stick and buttons as evdev reports them: axis ranges with the flat band, y negated
// (joysticks report +Y toward the user), SDL-ordered buttons, frames committed at
// SYN_REPORT, SYN_DROPPED recovery with EVIOCGABS/EVIOCGKEY, and garbage/short reads.

#include "dev_tools/evdev/scripted_evdev_kernel.h"
#include "devices/evdev/evdev_input.h"
#include "evdev_test_support.h"

#include <doctest/doctest.h>

#include <cerrno>
#include <climits>
#include <string>
#include <vector>

using namespace haptics;
using namespace haptics::evdev;

namespace {

std::vector<uint8_t> events(std::initializer_list<std::vector<uint8_t>> p_events) {
	std::vector<uint8_t> bytes;
	for (const std::vector<uint8_t> &event : p_events) {
		bytes.insert(bytes.end(), event.begin(), event.end());
	}
	return bytes;
}

std::vector<uint8_t> abs_event(uint16_t p_code, int32_t p_value) {
	return evdev_test::expected_event(EVDEV_EV_ABS, p_code, p_value);
}

std::vector<uint8_t> key_event(uint16_t p_code, int32_t p_value) {
	return evdev_test::expected_event(EVDEV_EV_KEY, p_code, p_value);
}

std::vector<uint8_t> syn(uint16_t p_code = EVDEV_SYN_REPORT) {
	return evdev_test::expected_event(EVDEV_EV_SYN, p_code, 0);
}

EvdevInputLayout stick_layout() {
	EvdevInputLayout layout;
	layout.x_range = { 0, -32767, 32767, 0, 0, 0 };
	layout.y_range = { 0, -32767, 32767, 0, 0, 0 };
	layout.buttons.codes[0] = EVDEV_BTN_TRIGGER;
	layout.buttons.codes[1] = EVDEV_BTN_THUMB;
	layout.buttons.count = 2;
	return layout;
}

} // namespace

TEST_CASE("evdev axis: [-32767, 32767] and [0, 65535] map to [-1, 1], centre 0") {
	const AbsRange stick{ 0, -32767, 32767, 0, 0, 0 };
	CHECK(normalise_axis(32767, stick) == 1.0);
	CHECK(normalise_axis(-32767, stick) == -1.0);
	CHECK(normalise_axis(0, stick) == 0.0);
	CHECK(normalise_axis(16384, stick) == doctest::Approx(16384.0 / 32767.0));
	CHECK(normalise_axis(40000, stick) == 1.0); // Beyond the declared range: clamped.
	const AbsRange wheel{ 0, 0, 65535, 0, 0, 0 };
	CHECK(normalise_axis(0, wheel) == -1.0);
	CHECK(normalise_axis(65535, wheel) == 1.0);
	CHECK(normalise_axis(32768, wheel) == doctest::Approx(0.5 / 32767.5));
}

TEST_CASE("evdev axis: the driver's flat band reads 0 and the rest is rescaled to reach 1") {
	const AbsRange flat{ 0, -1000, 1000, 0, 100, 0 };
	CHECK(normalise_axis(100, flat) == 0.0);
	CHECK(normalise_axis(-100, flat) == 0.0);
	CHECK(normalise_axis(550, flat) == doctest::Approx(0.5));
	CHECK(normalise_axis(-1000, flat) == -1.0);
	const AbsRange absurd_flat{ 0, -1000, 1000, 0, 5000, 0 }; // Capped at half the half-range.
	CHECK(normalise_axis(1000, absurd_flat) == 1.0);
	CHECK(normalise_axis(750, absurd_flat) == doctest::Approx(0.5));
	const AbsRange negative_flat{ 0, -1000, 1000, 0, -50, 0 };
	CHECK(normalise_axis(500, negative_flat) == doctest::Approx(0.5));
}

TEST_CASE("evdev axis: extreme and empty ranges never overflow - validation names the axis") {
	const AbsRange full{ 0, INT32_MIN, INT32_MAX, 0, 0, 0 };
	CHECK(normalise_axis(INT32_MAX, full) == 1.0);
	CHECK(normalise_axis(INT32_MIN, full) == -1.0);
	CHECK(std::abs(normalise_axis(0, full)) < 1e-9);
	const AbsRange empty{ 5, 5, 5, 0, 0, 0 };
	CHECK(normalise_axis(5, empty) == 0.0);
	const Status status = validate_abs_range(empty, "ABS_X", "/dev/input/event7");
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::string(status.message()) == "/dev/input/event7: ABS_X range [5, 5] is empty");
	CHECK(validate_abs_range({ 0, 10, -10, 0, 0, 0 }, "ABS_Y", "p").code() == StatusCode::OUT_OF_RANGE);
}

TEST_CASE("evdev absinfo: value, minimum, maximum, fuzz, flat, resolution as six s32") {
	uint8_t bytes[24] = {};
	const int32_t fields[6] = { -5, -32767, 32767, 16, 128, 3 };
	for (int i = 0; i < 6; ++i) {
		put_s32(bytes, static_cast<size_t>(4 * i), fields[i]);
	}
	const AbsRange range = decode_absinfo(bytes);
	CHECK(range.value == -5);
	CHECK(range.minimum == -32767);
	CHECK(range.maximum == 32767);
	CHECK(range.fuzz == 16);
	CHECK(range.flat == 128);
	CHECK(range.resolution == 3);
}

TEST_CASE("evdev buttons: SDL order (BTN_JOYSTICK.. then BTN_MISC..), keyboard keys left out, 32 at most") {
	uint8_t bits[EVDEV_KEY_BITS_BYTES] = {};
	for (uint32_t code : { 30u, 0x100u, 0x120u, 0x121u, 0x130u, 0x2c0u }) { // KEY_A, BTN_0, ...
		set_bit(bits, sizeof(bits), code);
	}
	EvdevButtonMap map = button_map_from_key_bits(bits, sizeof(bits));
	REQUIRE(map.count == 5);
	CHECK(map.codes[0] == 0x120);
	CHECK(map.codes[1] == 0x121);
	CHECK(map.codes[2] == 0x130);
	CHECK(map.codes[3] == 0x2c0);
	CHECK(map.codes[4] == 0x100);
	CHECK(map.bit_of(0x130) == 2);
	CHECK(map.bit_of(30) == -1);

	for (uint32_t code = 0x120; code < 0x200; ++code) {
		set_bit(bits, sizeof(bits), code);
	}
	map = button_map_from_key_bits(bits, sizeof(bits));
	CHECK(map.count == 32);
	CHECK(map.codes[31] == 0x13f);
}

TEST_CASE("evdev decoder: values commit at SYN_REPORT - y is negated - buttons press and release") {
	EvdevInputDecoder decoder;
	decoder.configure(stick_layout());
	const std::vector<uint8_t> first = events({ abs_event(EVDEV_ABS_X, 32767), abs_event(EVDEV_ABS_Y, 32767),
			key_event(EVDEV_BTN_THUMB, 1) });
	decoder.feed(first.data(), first.size());
	CHECK(decoder.x() == 0.0); // No SYN_REPORT yet: nothing committed.
	const std::vector<uint8_t> report = syn();
	decoder.feed(report.data(), report.size());
	CHECK(decoder.x() == 1.0);
	CHECK(decoder.y() == -1.0); // +Y toward the user = device down.
	CHECK(decoder.buttons() == 0b10u);
	const std::vector<uint8_t> second = events({ key_event(EVDEV_BTN_THUMB, 0), key_event(EVDEV_BTN_TRIGGER, 2), syn() });
	decoder.feed(second.data(), second.size());
	CHECK(decoder.buttons() == 0b01u); // Autorepeat (2) counts as pressed.
	CHECK(decoder.stats().events == 7);
	CHECK(decoder.stats().ignored == 0);
}

TEST_CASE("evdev decoder: unknown types/codes are counted and skipped - a partial event is never read") {
	EvdevInputDecoder decoder;
	decoder.configure(stick_layout());
	std::vector<uint8_t> bytes = events({ evdev_test::expected_event(0x04, 0x04, 589825), // EV_MSC MSC_SCAN
			abs_event(0x05, 77), key_event(30, 1), evdev_test::expected_event(EVDEV_EV_SYN, 9, 0), abs_event(EVDEV_ABS_X, -32767),
			syn() });
	bytes.resize(bytes.size() + 13, 0xee); // 13 bytes of a torn event.
	decoder.feed(bytes.data(), bytes.size());
	CHECK(decoder.x() == -1.0);
	CHECK(decoder.stats().events == 6);
	CHECK(decoder.stats().ignored == 4);
	CHECK(decoder.stats().partial_bytes == 13);
	decoder.feed(bytes.data(), 23); // Less than one event.
	CHECK(decoder.stats().partial_bytes == 36);
	decoder.feed(nullptr, 0);
	CHECK(decoder.stats().events == 6);
}

TEST_CASE("evdev decoder: SYN_DROPPED discards the torn frame and asks for a resync") {
	EvdevInputDecoder decoder;
	decoder.configure(stick_layout());
	const std::vector<uint8_t> bytes = events({ abs_event(EVDEV_ABS_X, 1000), syn(), abs_event(EVDEV_ABS_X, 2000),
			syn(EVDEV_SYN_DROPPED), abs_event(EVDEV_ABS_X, 3000), syn(), abs_event(EVDEV_ABS_X, 4000) });
	decoder.feed(bytes.data(), bytes.size());
	CHECK(decoder.raw_x() == 1000); // 2000 was pending when the drop came, 3000 in the torn frame.
	CHECK(decoder.needs_resync());
	CHECK(decoder.stats().dropped == 1);
	decoder.apply_resync(4242, -17, 0b1);
	CHECK_FALSE(decoder.needs_resync());
	CHECK(decoder.raw_x() == 4242);
	CHECK(decoder.raw_y() == -17);
	CHECK(decoder.buttons() == 0b1u);
}

TEST_CASE("evdev drain through the scripted kernel: stick, buttons, short and torn reads") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	const int fd = kernel->open_device("/dev/input/event7");
	EvdevInputDecoder decoder;
	decoder.configure(stick_layout());
	std::vector<uint8_t> buffer(INPUT_READ_BUFFER_SIZE);

	kernel->set_stick_axes(0.5, 0.25); // Axis frame: +y toward the user.
	kernel->set_button(EVDEV_BTN_TRIGGER, true);
	kernel->sync();
	REQUIRE(drain_input_events(*kernel, fd, decoder, buffer.data()) == 0);
	CHECK(decoder.x() == doctest::Approx(0.5).epsilon(1e-4));
	CHECK(decoder.y() == doctest::Approx(-0.25).epsilon(1e-4));
	CHECK(decoder.buttons() == 0b1u);

	kernel->queue_raw_read(std::vector<uint8_t>(13, 0x42)); // A broken transport's short read.
	REQUIRE(drain_input_events(*kernel, fd, decoder, buffer.data()) == 0);
	CHECK(decoder.stats().partial_bytes == 13);
	CHECK(decoder.x() == doctest::Approx(0.5).epsilon(1e-4));

	REQUIRE(drain_input_events(*kernel, fd, decoder, buffer.data()) == 0); // Empty: -EAGAIN inside.
	kernel->fail_next_read(EIO);
	CHECK(drain_input_events(*kernel, fd, decoder, buffer.data()) == -EIO);
	kernel->set_plugged(false);
	CHECK(drain_input_events(*kernel, fd, decoder, buffer.data()) == -ENODEV);
}

TEST_CASE("evdev drain: an overflowing kernel buffer (SYN_DROPPED) resyncs with EVIOCGABS and EVIOCGKEY") {
	ScriptedEvdevScript script = scripted_joystick_script();
	script.buffer_events = 16;
	auto kernel = std::make_shared<ScriptedEvdevKernel>(script);
	const int fd = kernel->open_device("/dev/input/event7");
	EvdevInputDecoder decoder;
	decoder.configure(stick_layout());
	std::vector<uint8_t> buffer(INPUT_READ_BUFFER_SIZE);
	for (int i = 0; i < 40; ++i) {
		kernel->set_stick_axes(i / 40.0, -i / 40.0);
	}
	kernel->set_button(EVDEV_BTN_THUMB, true); // No SYN after it: only the resync can see it.
	kernel->clear_calls();
	REQUIRE(drain_input_events(*kernel, fd, decoder, buffer.data()) == 0);
	CHECK(decoder.stats().dropped == 1);
	CHECK(decoder.x() == doctest::Approx(39 / 40.0).epsilon(1e-4));
	CHECK(decoder.y() == doctest::Approx(39 / 40.0).epsilon(1e-4));
	CHECK(decoder.buttons() == 0b10u);
	std::vector<uint32_t> queries;
	for (const ScriptedEvdevCall &call : kernel->calls()) {
		if (call.kind == ScriptedEvdevCall::Kind::IOCTL) {
			queries.push_back(call.request);
		}
	}
	CHECK(queries == std::vector<uint32_t>{ 0x80184540u, 0x80184541u, evdev_eviocgkey(96) });
}
