// Bounded fuzz loops (fixed seeds, so a failure reproduces) over everything that takes
// bytes or text from outside: event streams (whole, torn, garbage) into the decoder and
// through the scripted kernel, sysfs capability strings, absinfo ranges, forces, and
// arbitrary ioctls/effects into the scripted kernel. Run under ASan+UBSan too.

#include "dev_tools/evdev/scripted_evdev_kernel.h"
#include "devices/evdev/evdev_bits.h"
#include "devices/evdev/evdev_ff.h"
#include "devices/evdev/evdev_input.h"
#include "evdev_test_support.h"

#include <doctest/doctest.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace haptics;
using namespace haptics::evdev;

namespace {

int32_t random_value(std::mt19937 &r_random) {
	switch (r_random() % 4) {
		case 0:
			return static_cast<int32_t>(r_random() % 65536) - 32768;
		case 1:
			return std::numeric_limits<int32_t>::min();
		case 2:
			return std::numeric_limits<int32_t>::max();
		default:
			return static_cast<int32_t>(r_random());
	}
}

std::vector<uint8_t> random_stream(std::mt19937 &r_random) {
	std::vector<uint8_t> bytes;
	const size_t events = r_random() % 24;
	const uint16_t types[] = { EVDEV_EV_SYN, EVDEV_EV_KEY, EVDEV_EV_ABS, 0x04, EVDEV_EV_FF, 0xffff };
	for (size_t i = 0; i < events; ++i) {
		const uint16_t type = types[r_random() % 6];
		const uint16_t code = r_random() % 2 ? static_cast<uint16_t>(r_random() % 4) : static_cast<uint16_t>(r_random());
		const std::vector<uint8_t> event = evdev_test::expected_event(type, code, random_value(r_random));
		bytes.insert(bytes.end(), event.begin(), event.end());
	}
	if (r_random() % 3 == 0) { // Garbage or a torn tail.
		const size_t extra = r_random() % 40;
		for (size_t i = 0; i < extra; ++i) {
			bytes.push_back(static_cast<uint8_t>(r_random()));
		}
	}
	return bytes;
}

EvdevInputLayout fuzz_layout() {
	EvdevInputLayout layout;
	layout.x_range = { 0, -32767, 32767, 0, 64, 0 };
	layout.y_range = { 0, 0, 1023, 0, 0, 0 };
	for (uint16_t i = 0; i < 8; ++i) {
		layout.buttons.codes[i] = static_cast<uint16_t>(EVDEV_BTN_TRIGGER + i);
	}
	layout.buttons.count = 8;
	return layout;
}

bool in_unit_range(double p_value) {
	return std::isfinite(p_value) && p_value >= -1.0 && p_value <= 1.0;
}

} // namespace

TEST_CASE("evdev fuzz: random event streams keep the decoder's state bounded and count torn bytes") {
	std::mt19937 random(1234);
	EvdevInputDecoder decoder;
	decoder.configure(fuzz_layout());
	uint64_t expected_partial = 0;
	bool bounded = true;
	for (int i = 0; i < 3000; ++i) {
		const std::vector<uint8_t> bytes = random_stream(random);
		decoder.feed(bytes.data(), bytes.size());
		expected_partial += bytes.size() % INPUT_EVENT_SIZE;
		bounded = bounded && in_unit_range(decoder.x()) && in_unit_range(decoder.y());
		if (decoder.needs_resync()) {
			decoder.apply_resync(random_value(random), random_value(random), 0);
		}
	}
	CHECK(bounded);
	CHECK(decoder.stats().partial_bytes == expected_partial);
	CHECK((decoder.buttons() >> 8) == 0u); // Only mapped buttons ever set.
}

TEST_CASE("evdev fuzz: raw chunks, events and overflows through the scripted kernel's read()") {
	std::mt19937 random(99);
	ScriptedEvdevScript script = scripted_joystick_script();
	script.buffer_events = 32;
	ScriptedEvdevKernel kernel(script);
	const int fd = kernel.open_device(script.path.c_str());
	REQUIRE(fd >= 0);
	kernel.set_recording(false);
	EvdevInputDecoder decoder;
	decoder.configure(fuzz_layout());
	std::vector<uint8_t> buffer(INPUT_READ_BUFFER_SIZE);
	bool ok = true;
	for (int i = 0; i < 1500; ++i) {
		switch (random() % 4) {
			case 0:
				kernel.queue_raw_read(random_stream(random));
				break;
			case 1:
				kernel.set_stick_axes(std::ldexp(static_cast<double>(random()), -31) - 1.0, 0.0);
				break;
			case 2:
				for (int k = 0; k < 40; ++k) { // Overflow the 32-event queue.
					kernel.set_axis(EVDEV_ABS_X, random_value(random));
				}
				break;
			default:
				kernel.set_button(static_cast<uint16_t>(EVDEV_BTN_TRIGGER + random() % 4), random() % 2);
				break;
		}
		ok = ok && drain_input_events(kernel, fd, decoder, buffer.data()) == 0;
		ok = ok && in_unit_range(decoder.x()) && in_unit_range(decoder.y());
	}
	CHECK(ok);
	CHECK(decoder.stats().dropped > 0);
	CHECK(decoder.stats().events > 1000);
}

TEST_CASE("evdev fuzz: any printed bitmask parses back to itself - garbage never crashes") {
	std::mt19937_64 random(7);
	for (int i = 0; i < 2000; ++i) {
		const uint64_t low = random() & (random() % 2 ? ~0ull : 0xffull);
		const uint64_t high = random() % 3 == 0 ? 0 : random();
		// The kernel's form: "%lx" words, most significant first, leading zero words left out.
		char text[64];
		if (high != 0) {
			std::snprintf(text, sizeof(text), "%" PRIx64 " %" PRIx64 "\n", high, low);
		} else {
			std::snprintf(text, sizeof(text), "%" PRIx64 "\n", low);
		}
		uint8_t bits[EVDEV_FF_BITS_BYTES];
		REQUIRE(parse_sysfs_bitmask(text, 64, "ff", bits, sizeof(bits)).ok());
		bool same = true;
		for (uint32_t bit = 0; bit < 128; ++bit) {
			const bool expected = bit < 64 ? (low >> bit) & 1 : (high >> (bit - 64)) & 1;
			same = same && test_bit(bits, sizeof(bits), bit) == expected;
		}
		CHECK_MESSAGE(same, text);
	}
	const char alphabet[] = "0123456789abcdefABCDEFxz- \n\t\x01\xff";
	for (int i = 0; i < 5000; ++i) {
		std::string text(random() % 90, ' ');
		for (char &c : text) {
			c = alphabet[random() % (sizeof(alphabet) - 1)];
		}
		uint8_t bits[EVDEV_KEY_BITS_BYTES];
		const Status status = parse_sysfs_bitmask(text, random() % 2 ? 64 : 32, "fuzz", bits, sizeof(bits));
		CHECK((status.ok() || std::string(status.message()).rfind("fuzz: ", 0) == 0));
	}
}

TEST_CASE("evdev fuzz: any force maps to a finite level within 0x7FFF, zero level with direction 0") {
	std::mt19937_64 random(3);
	const double specials[] = { 0.0, -0.0, 1e-300, -1e300, std::numeric_limits<double>::infinity(),
		-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(),
		std::numeric_limits<double>::denorm_min(), 5.0, -5.0 };
	const auto pick = [&]() {
		return random() % 3 == 0 ? specials[random() % 10] : std::ldexp(static_cast<double>(random() % 2000) - 1000.0, -6);
	};
	bool ok = true;
	for (int i = 0; i < 20000; ++i) {
		FfForceMapping mapping;
		mapping.shape = random() % 2 ? EvdevShape::WHEEL : EvdevShape::JOYSTICK;
		mapping.invert_x = random() % 2;
		mapping.invert_y = random() % 2;
		mapping.max_force_n = random() % 10 == 0 ? pick() : 5.0;
		const FfConstantForce force = map_force_to_constant(Vec3(pick(), pick(), pick()), mapping);
		ok = ok && force.level >= -0x7fff; // Never -0x8000: symmetric full scale.
		ok = ok && (force.level != 0 || force.direction == 0);
		ok = ok && (mapping.shape == EvdevShape::JOYSTICK ? force.level >= 0 : force.direction == 0 || force.direction == 0x4000);
	}
	CHECK(ok);
}

TEST_CASE("evdev fuzz: arbitrary ioctls, effects and writes never make the scripted kernel misbehave") {
	std::mt19937 random(42);
	ScriptedEvdevKernel kernel(scripted_wheel_script());
	const int fd = kernel.open_device("/dev/input/event9");
	kernel.set_recording(false);
	for (int i = 0; i < 20000; ++i) {
		alignas(8) uint8_t arg[128 + 8] = {};
		for (size_t b = 0; b < 48; ++b) {
			arg[b] = static_cast<uint8_t>(random());
		}
		arg[128] = 0xa5; // A guard the kernel model must never reach (it copies <= 96 bytes).
		uint32_t request;
		switch (random() % 4) {
			case 0:
				request = EVDEV_EVIOCSFF;
				if (random() % 2) {
					put_u16(arg, 0, EVDEV_FF_CONSTANT);
				}
				break;
			case 1:
				request = ioc(IOC_READ, 'E', random() % 256, random() % 0x4000);
				break;
			case 2:
				request = EVDEV_EVIOCRMFF;
				break;
			default:
				request = static_cast<uint32_t>(random());
				break;
		}
		void *pointer = request == EVDEV_EVIOCRMFF ? reinterpret_cast<void *>(static_cast<intptr_t>(random() % 40) - 20) : arg;
		const int result = kernel.ioctl(fd, request, pointer);
		REQUIRE(result >= -4095);
		REQUIRE(arg[128] == 0xa5);
		const std::vector<uint8_t> event = evdev_test::expected_event(EVDEV_EV_FF, static_cast<uint16_t>(random() % 128),
				random_value(random));
		REQUIRE(kernel.write(fd, event.data(), random() % 4 ? event.size() : random() % 24) >= -4095);
	}
	const ScriptedRenderedForce rendered = kernel.rendered();
	CHECK(std::isfinite(rendered.axis_x));
	CHECK(std::abs(rendered.axis_x) <= 16.0 + 1e-9); // At most max_effects (16) at full level.
	CHECK(kernel.effects_in_use() <= 16);
}

TEST_CASE("evdev fuzz: random absinfo ranges normalise into [-1, 1] or validate as empty") {
	std::mt19937 random(11);
	bool ok = true;
	for (int i = 0; i < 20000; ++i) {
		AbsRange range{ 0, random_value(random), random_value(random), 0, random_value(random), 0 };
		const bool valid = validate_abs_range(range, "ABS_X", "fuzz").ok();
		ok = ok && valid == (range.maximum > range.minimum);
		ok = ok && in_unit_range(normalise_axis(random_value(random), range));
	}
	CHECK(ok);
}
