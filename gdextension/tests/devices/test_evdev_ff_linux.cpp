// The evdev force-feedback protocol as bytes (docs/devices/evdev.md [UAPI]): struct ff_effect
// for FF_CONSTANT, the input_event written to play/stop/gain, the ioctl numbers, and the
// mapping from device-space newtons to (direction, level) with the direction goldens of
// docs/devices/hid-pid.md, "Direction".

#include "devices/evdev/evdev_abi.h"
#include "devices/evdev/evdev_ff.h"
#include "evdev_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <linux/input.h>
#include <vector>

using namespace haptics;
using namespace haptics::evdev;

namespace {

std::vector<uint8_t> bytes_of(const FfEffectBytes &p_bytes) {
	return { p_bytes.begin(), p_bytes.end() };
}

FfConstantForce map(double p_x, double p_y, const FfForceMapping &p_mapping = {}) {
	return map_force_to_constant(Vec3(p_x, p_y, 0.0), p_mapping);
}

} // namespace

TEST_CASE("evdev ioctl numbers: docs/devices/evdev.md values, equal to <linux/input.h>") {
	CHECK(EVDEV_EVIOCSFF == 0x40304580u);
	CHECK(EVDEV_EVIOCRMFF == 0x40044581u);
	CHECK(EVDEV_EVIOCGEFFECTS == 0x80044584u);
	CHECK(EVDEV_EVIOCSFF == static_cast<uint32_t>(EVIOCSFF));
	CHECK(evdev_eviocgbit(EVDEV_EV_FF, 16) == 0x80104535u); // _IOC(READ, 'E', 0x20 + 0x15, 16)
	CHECK(evdev_eviocgbit(EVDEV_EV_FF, 16) == static_cast<uint32_t>(EVIOCGBIT(EV_FF, 16)));
	CHECK(evdev_eviocgabs(EVDEV_ABS_X) == 0x80184540u);
	CHECK(evdev_eviocgabs(EVDEV_ABS_Y) == static_cast<uint32_t>(EVIOCGABS(ABS_Y)));
	CHECK(evdev_eviocgname(128) == static_cast<uint32_t>(EVIOCGNAME(128)));
	CHECK(EVDEV_EVIOCGID == static_cast<uint32_t>(EVIOCGID));
	CHECK(ioc_size(EVDEV_EVIOCSFF) == 48);
	CHECK(ioc_nr(evdev_eviocgabs(EVDEV_ABS_WHEEL)) == 0x48);
}

TEST_CASE("evdev ff_effect: FF_CONSTANT, id -1, direction 0x4000, level 0x4000, 1000 ms: golden bytes") {
	FfConstantEffect effect;
	effect.id = -1;
	effect.direction = 0x4000;
	effect.level = 0x4000;
	CHECK(effect.replay_length_ms == 1000); // Finite by default (evdev_ff.h).
	FfEffectBytes bytes;
	encode_constant_effect(effect, bytes);
	const std::vector<uint8_t> golden = {
		0x52, 0x00, 0xff, 0xff, 0x00, 0x40, 0x00, 0x00, 0x00, 0x00, 0xe8, 0x03, 0x00, 0x00, 0x00, 0x00, // header
		0x00, 0x40, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, // level, envelope
		0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, // union tail
	};
	CHECK(bytes_of(bytes) == golden);
	CHECK(bytes_of(bytes) == evdev_test::expected_constant_effect(-1, 0x4000, 0x4000));
}

TEST_CASE("evdev ff_effect: explicit bytes equal <linux/input.h>'s struct for every field") {
	const FfConstantEffect cases[] = {
		{ -1, 0, 0, 0, 0 },
		{ 3, 0xc000, -0x4000, 0, 0 },
		{ 9, 0xffff, 0x7fff, 1500, 20 },
		{ 0, 0x8000, -0x8000, 0xffff, 0xffff },
	};
	for (const FfConstantEffect &effect : cases) {
		CAPTURE(effect.id);
		CAPTURE(effect.level);
		FfEffectBytes ours;
		FfEffectBytes kernel;
		encode_constant_effect(effect, ours);
		encode_constant_effect_kernel_struct(effect, kernel);
		CHECK(bytes_of(ours) == bytes_of(kernel));
		const FfEffectFields fields = decode_ff_effect(ours);
		CHECK(fields.type == 0x52);
		CHECK(fields.id == effect.id);
		CHECK(fields.direction == effect.direction);
		CHECK(fields.constant_level == effect.level);
		CHECK(fields.replay_length_ms == effect.replay_length_ms);
		CHECK(fields.replay_delay_ms == effect.replay_delay_ms);
	}
	FfEffectBytes negative;
	encode_constant_effect({ 3, 0xc000, -0x4000, 0, 0 }, negative);
	CHECK(negative[16] == 0x00);
	CHECK(negative[17] == 0xc0); // -0x4000 as s16 little-endian.
}

TEST_CASE("evdev input_event: play, stop and gain are 24 bytes with type/code/value at 16/18/20") {
	InputEventBytes play;
	encode_input_event(EVDEV_EV_FF, 3, 1, play);
	CHECK(std::vector<uint8_t>(play.begin(), play.end()) == evdev_test::expected_event(0x15, 3, 1));
	const std::vector<uint8_t> gain_golden = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, //
		0x15, 0x00, 0x60, 0x00, 0xff, 0xff, 0x00, 0x00 };
	InputEventBytes gain;
	encode_input_event(EVDEV_EV_FF, EVDEV_FF_GAIN, 0xffff, gain);
	CHECK(std::vector<uint8_t>(gain.begin(), gain.end()) == gain_golden);

	InputEventBytes negative;
	encode_input_event(EVDEV_EV_ABS, EVDEV_ABS_Y, -32767, negative);
	const InputEvent decoded = decode_input_event(negative.data());
	CHECK(decoded.type == EVDEV_EV_ABS);
	CHECK(decoded.code == EVDEV_ABS_Y);
	CHECK(decoded.value == -32767);
}

TEST_CASE("evdev direction goldens (docs/devices/hid-pid.md): +x 0x4000, -x 0xC000, device down 0x8000, up 0x0000") {
	CHECK(map(5.0, 0.0) == FfConstantForce{ 0x4000, 0x7fff });
	CHECK(map(-5.0, 0.0) == FfConstantForce{ 0xc000, 0x7fff });
	// Device -y is toward the user = the axis frame's +Y, which the firmwares put at 0x8000.
	CHECK(map(0.0, -5.0) == FfConstantForce{ 0x8000, 0x7fff });
	CHECK(map(0.0, 5.0) == FfConstantForce{ 0x0000, 0x7fff });
	// Diagonals land half-way: right+down = 135 degrees = 0x6000, left+up = 315 = 0xE000.
	CHECK(map(3.0, -3.0).direction == 0x6000);
	CHECK(map(-3.0, 3.0).direction == 0xe000);
	CHECK(map(3.0, 3.0).direction == 0x2000);
}

TEST_CASE("evdev direction: invert flags flip one axis each") {
	FfForceMapping invert_x;
	invert_x.invert_x = true;
	CHECK(map(5.0, 0.0, invert_x).direction == 0xc000);
	CHECK(map(0.0, 5.0, invert_x).direction == 0x0000);
	FfForceMapping invert_y;
	invert_y.invert_y = true;
	CHECK(map(0.0, 5.0, invert_y).direction == 0x8000);
	CHECK(map(5.0, 0.0, invert_y).direction == 0x4000);
	CHECK(map(3.0, -3.0, invert_y).direction == 0x2000);
}

TEST_CASE("evdev level: |F| / max_force x 0x7FFF, rounded and clamped - z ignored") {
	CHECK(map(2.5, 0.0).level == 16384); // 0.5 x 32767 = 16383.5 rounds away from zero.
	CHECK(map(3.0, -4.0).level == 0x7fff); // |F| = 5 N = max.
	CHECK(map(30.0, -40.0).level == 0x7fff);
	CHECK(map(1.0, 0.0).level == 6553); // 0.2 x 32767 = 6553.4
	CHECK(map_force_to_constant(Vec3(0.0, 0.0, 4.0), {}) == FfConstantForce{});
	FfForceMapping strong;
	strong.max_force_n = 10.0;
	CHECK(map(2.5, 0.0, strong).level == 8192); // 8191.75
}

TEST_CASE("evdev level: non-finite or tiny forces give level 0 with direction 0 (no spurious uploads)") {
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double inf = std::numeric_limits<double>::infinity();
	CHECK(map(nan, nan) == FfConstantForce{});
	CHECK(map(inf, 0.0) == FfConstantForce{});
	CHECK(map(nan, -5.0) == FfConstantForce{ 0x8000, 0x7fff }); // The finite part stays.
	CHECK(map(1e-6, -1e-6) == FfConstantForce{});
	FfForceMapping broken;
	broken.max_force_n = nan;
	CHECK(map(5.0, 0.0, broken) == FfConstantForce{});
	broken.max_force_n = 0.0;
	CHECK(map(5.0, 0.0, broken) == FfConstantForce{});
}

TEST_CASE("evdev wheel: the x component as a signed level at the steering direction 0x4000") {
	FfForceMapping wheel;
	wheel.shape = EvdevShape::WHEEL;
	CHECK(map(2.5, 4.0, wheel) == FfConstantForce{ 0x4000, 16384 });
	CHECK(map(-2.5, 4.0, wheel) == FfConstantForce{ 0x4000, -16384 });
	CHECK(map(-50.0, 0.0, wheel) == FfConstantForce{ 0x4000, -0x7fff });
	CHECK(map(0.0, 4.0, wheel) == FfConstantForce{});
	wheel.invert_x = true;
	CHECK(map(2.5, 0.0, wheel) == FfConstantForce{ 0x4000, -16384 });
}

TEST_CASE("evdev direction: every direction round-trips through the firmware rule X = sin, Y = -cos") {
	// The inverse as the firmwares of docs/devices/hid-pid.md compute it; device y is the axis frame's -Y.
	for (int degrees = 0; degrees < 360; degrees += 7) {
		const double angle = degrees * 3.14159265358979323846 / 180.0;
		const Vec3 force(4.0 * std::cos(angle), 4.0 * std::sin(angle), 0.0);
		const FfConstantForce mapped = map_force_to_constant(force, {});
		const double theta = mapped.direction / 65536.0 * 2.0 * 3.14159265358979323846;
		const double fraction = mapped.level / 32767.0;
		CAPTURE(degrees);
		CHECK(5.0 * fraction * std::sin(theta) == doctest::Approx(force.x).epsilon(1e-3));
		CHECK(-5.0 * fraction * -std::cos(theta) == doctest::Approx(force.y).epsilon(1e-3));
	}
}
