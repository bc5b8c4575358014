// Which effects the kernel driver offers: EVIOCGBIT(EV_FF) bytes and sysfs capabilities/ff
// text, with canned bitmasks where FF_CONSTANT (bit 0x52) is set and where it is not.

#include "devices/evdev/evdev_abi.h"
#include "devices/evdev/evdev_bits.h"
#include "devices/evdev/evdev_effect.h"

#include <doctest/doctest.h>

#include <cstring>
#include <string>

using namespace haptics;
using namespace haptics::evdev;

namespace {

struct FfBits {
	uint8_t bytes[EVDEV_FF_BITS_BYTES] = {};
};

FfBits parse64(const char *p_text, Status *r_status = nullptr) {
	FfBits bits;
	const Status status = parse_sysfs_bitmask(p_text, 64, "capabilities/ff", bits.bytes, sizeof(bits.bytes));
	if (r_status) {
		*r_status = status;
	} else {
		REQUIRE_MESSAGE(status.ok(), status.message());
	}
	return bits;
}

} // namespace

TEST_CASE("evdev EVIOCGBIT(EV_FF): bit 0x52 is byte 10 bit 2 - set -> constant force, unset -> a clear error") {
	uint8_t bits[EVDEV_FF_BITS_BYTES] = {};
	bits[10] = 0x04; // 0x52 = 82 = 8 * 10 + 2
	bits[12] = 0x03; // FF_GAIN 0x60, FF_AUTOCENTER 0x61
	EvdevFfFeatures features = ff_features_from_bits(bits, sizeof(bits));
	CHECK(features.constant);
	CHECK(features.gain);
	CHECK(features.autocenter);
	CHECK(require_constant_force(features, "/dev/input/event7").ok());

	bits[10] = 0x01 | 0x02 | 0x08; // Rumble, periodic, spring: everything around 0x52 but it.
	features = ff_features_from_bits(bits, sizeof(bits));
	CHECK_FALSE(features.constant);
	const Status status = require_constant_force(features, "/dev/input/event7");
	CHECK(status.code() == StatusCode::UNSUPPORTED);
	CHECK(std::string(status.message()) ==
			"the kernel driver offers no constant force on this device (/dev/input/event7: no FF_CONSTANT in "
			"EVIOCGBIT(EV_FF))");
}

TEST_CASE("evdev sysfs capabilities/ff: most significant word first, 64-bit words") {
	// A wheel: FF_CONSTANT (64 + 18), FF_GAIN (64 + 32), FF_AUTOCENTER (64 + 33).
	FfBits wheel = parse64("300040000 0\n");
	CHECK(test_bit(wheel.bytes, sizeof(wheel.bytes), EVDEV_FF_CONSTANT));
	CHECK(test_bit(wheel.bytes, sizeof(wheel.bytes), EVDEV_FF_GAIN));
	CHECK(test_bit(wheel.bytes, sizeof(wheel.bytes), EVDEV_FF_AUTOCENTER));
	CHECK_FALSE(test_bit(wheel.bytes, sizeof(wheel.bytes), EVDEV_FF_RUMBLE));
	CHECK(wheel.bytes[10] == 0x04);
	CHECK(wheel.bytes[12] == 0x03);

	// A rumble gamepad: rumble, periodic, square, triangle, sine, gain; no constant force.
	FfBits pad = parse64("107030000 0");
	CHECK(test_bit(pad.bytes, sizeof(pad.bytes), EVDEV_FF_RUMBLE));
	CHECK(test_bit(pad.bytes, sizeof(pad.bytes), EVDEV_FF_PERIODIC));
	CHECK(test_bit(pad.bytes, sizeof(pad.bytes), 0x5a)); // FF_SINE
	CHECK_FALSE(test_bit(pad.bytes, sizeof(pad.bytes), EVDEV_FF_CONSTANT));

	// The low word only: bit 0x02 lands in byte 0 (not in word 1).
	FfBits low = parse64("4");
	CHECK(low.bytes[0] == 0x04);
	CHECK_FALSE(test_bit(low.bytes, sizeof(low.bytes), EVDEV_FF_CONSTANT));

	FfBits none = parse64("0");
	for (uint8_t byte : none.bytes) {
		CHECK(byte == 0);
	}
	FfBits empty = parse64("");
	CHECK(empty.bytes[10] == 0);
}

TEST_CASE("evdev sysfs capabilities/ff: 32-bit words spread the same bits over more words") {
	FfBits bits;
	REQUIRE(parse_sysfs_bitmask("3 40000 0 0", 32, "ff", bits.bytes, sizeof(bits.bytes)).ok());
	CHECK(test_bit(bits.bytes, sizeof(bits.bytes), EVDEV_FF_CONSTANT));
	CHECK(test_bit(bits.bytes, sizeof(bits.bytes), EVDEV_FF_GAIN));
	CHECK(test_bit(bits.bytes, sizeof(bits.bytes), EVDEV_FF_AUTOCENTER));
	// The 64-bit reading of "300040000" is too wide for a 32-bit word.
	const Status status = parse_sysfs_bitmask("300040000 0", 32, "ff", bits.bytes, sizeof(bits.bytes));
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::string(status.message()) == "ff: word '300040000' is wider than 32 bits");
}

TEST_CASE("evdev sysfs capabilities/ff: garbage is an error naming the file, never a crash") {
	Status status;
	parse64("12g4 0", &status);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::string(status.message()) == "capabilities/ff: 'g' in '12g4' is not a hex digit");
	parse64("1ffffffffffffffff 0", &status); // 17 digits
	CHECK(std::string(status.message()) == "capabilities/ff: word '1ffffffffffffffff' is wider than 64 bits");
	parse64("0x52", &status);
	CHECK_FALSE(status.ok());
	std::string many;
	for (int i = 0; i < 65; ++i) {
		many += "0 ";
	}
	parse64(many.c_str(), &status);
	CHECK(std::string(status.message()) == "capabilities/ff: more than 64 words");
	// Leading zeros and odd spacing are tolerated; bits beyond the buffer are dropped.
	FfBits padded = parse64("  0000000000000000000000300040000 \t 0 ");
	CHECK(test_bit(padded.bytes, sizeof(padded.bytes), EVDEV_FF_CONSTANT));
	FfBits high = parse64("ffffffffffffffff 0 0 0");
	CHECK(high.bytes[0] == 0);
	CHECK(high.bytes[15] == 0);
	// Width other than 32/64.
	CHECK_FALSE(parse_sysfs_bitmask("1", 16, "ff", padded.bytes, sizeof(padded.bytes)).ok());
}
