// What the real ff-core does (seen on Debian 12's 6.1 under QEMU: docs/linux-kernel.md, and the
// VM test evdev-uinput, which puts the scripted kernel beside the real one) and the scripted
// kernel must do too, with what our backend makes of it:
//  - a device whose driver offers FF_PERIODIC is also offered FF_RUMBLE, which ff-core hands
//    the driver as a 50 ms sine;
//  - closing a node stops and erases the effects that file uploaded, so a client that opens
//    the node again owns nothing: it must upload anew, not update its old id.

#include "dev_tools/evdev/scripted_evdev_device.h"
#include "devices/evdev/evdev_backend.h"
#include "devices/evdev/evdev_device.h"
#include "evdev_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cerrno>
#include <vector>

using namespace haptics;
using namespace haptics::evdev;
using Kind = ScriptedEvdevCall::Kind;

namespace {

int upload_effect(ScriptedEvdevKernel &r_kernel, int p_fd, FfEffectBytes &r_bytes) {
	const int result = r_kernel.ioctl(p_fd, EVDEV_EVIOCSFF, r_bytes.data());
	return result < 0 ? result : get_s16(r_bytes.data(), FF_EFFECT_ID_OFFSET);
}

void play(ScriptedEvdevKernel &r_kernel, int p_fd, int p_id, int32_t p_count) {
	InputEventBytes event;
	encode_input_event(EVDEV_EV_FF, static_cast<uint16_t>(p_id), p_count, event);
	REQUIRE(r_kernel.write(p_fd, event.data(), event.size()) == static_cast<int64_t>(event.size()));
}

} // namespace

TEST_CASE("evdev scripted kernel: FF_PERIODIC brings FF_RUMBLE, and a rumble plays as ff-core's 50 ms sine") {
	const ScriptedEvdevScript script = scripted_joystick_script(); // PID effects, no FF_RUMBLE of its own.
	REQUIRE(std::find(script.ff_codes.begin(), script.ff_codes.end(), EVDEV_FF_RUMBLE) == script.ff_codes.end());
	ScriptedEvdevKernel kernel(script);
	const int fd = kernel.open_device(script.path.c_str());
	REQUIRE(fd >= 0);

	// The real 6.1 kernel's EVIOCGBIT(EV_FF) for this script on a uinput device (VM run).
	uint8_t bits[EVDEV_FF_BITS_BYTES] = {};
	CHECK(kernel.ioctl(fd, evdev_eviocgbit(EVDEV_EV_FF, sizeof(bits)), bits) == static_cast<int>(sizeof(bits)));
	const std::vector<uint8_t> real_kernel = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0x1f, 0x01, 0, 0, 0 };
	CHECK(std::vector<uint8_t>(bits, bits + sizeof(bits)) == real_kernel);
	EvdevFfFeatures features;
	REQUIRE(query_ff_features(kernel, fd, script.path.c_str(), features).ok());
	CHECK(features.rumble);
	CHECK(describe_ff_features(features) == "constant periodic rumble gain, 10 effects");

	// strong 0x6000 / 3 + weak 0x3000 / 6 = 10240, as the uinput device received it.
	FfEffectBytes bytes;
	encode_rumble_effect(FfRumbleEffect{ -1, 0x6000, 0x3000, 0 }, bytes);
	const int id = upload_effect(kernel, fd, bytes);
	REQUIRE(id >= 0);
	play(kernel, fd, id, 1);
	ScriptedRenderedForce rendered = kernel.rendered();
	CHECK(rendered.periodic_playing == 1);
	CHECK(rendered.periodic_magnitude == 10240);
	CHECK(rendered.rumbles_playing == 0);
	// Updating it as a rumble again is compatible (both sides converted), and takes effect.
	encode_rumble_effect(FfRumbleEffect{ static_cast<int16_t>(id), 0x3000, 0, 0 }, bytes);
	CHECK(upload_effect(kernel, fd, bytes) == id);
	CHECK(kernel.rendered().periodic_magnitude == 0x3000 / 3);
	// The record keeps what the client sent: a rumble.
	const std::vector<ScriptedEvdevCall> calls = evdev_test::ff_calls(kernel.calls());
	REQUIRE_FALSE(calls.empty());
	CHECK(get_u16(calls.back().bytes.data(), FF_EFFECT_TYPE_OFFSET) == EVDEV_FF_RUMBLE);

	// Without FF_PERIODIC there is nothing to emulate rumble with.
	ScriptedEvdevKernel wheel(scripted_wheel_script());
	const int wheel_fd = wheel.open_device(scripted_wheel_script().path.c_str());
	CHECK(wheel.ioctl(wheel_fd, evdev_eviocgbit(EVDEV_EV_FF, sizeof(bits)), bits) > 0);
	CHECK_FALSE(test_bit(bits, sizeof(bits), EVDEV_FF_RUMBLE));
	encode_rumble_effect(FfRumbleEffect{ -1, 0x6000, 0x3000, 0 }, bytes);
	CHECK(upload_effect(wheel, wheel_fd, bytes) == -EINVAL);

	// A waveform the device does not offer is refused like a type it does not offer.
	ScriptedEvdevKernel pad(scripted_gamepad_script());
	const int pad_fd = pad.open_device(scripted_gamepad_script().path.c_str());
	bytes.fill(0);
	put_u16(bytes.data(), FF_EFFECT_TYPE_OFFSET, EVDEV_FF_PERIODIC);
	put_u16(bytes.data(), FF_EFFECT_ID_OFFSET, 0xffff);
	put_u16(bytes.data(), FF_PERIODIC_WAVEFORM_OFFSET, 0x5b); // FF_SAW_UP
	CHECK(upload_effect(pad, pad_fd, bytes) == -EINVAL);
	put_u16(bytes.data(), FF_PERIODIC_WAVEFORM_OFFSET, EVDEV_FF_SINE);
	CHECK(upload_effect(pad, pad_fd, bytes) == 0);
}

TEST_CASE("evdev backend: a device offering FF_PERIODIC but no constant force opens as rumble, as the kernel offers it") {
	ScriptedEvdevScript script = scripted_joystick_script();
	script.ff_codes = { EVDEV_FF_PERIODIC, EVDEV_FF_SINE, EVDEV_FF_GAIN };
	auto kernel = std::make_shared<ScriptedEvdevKernel>(script);
	DeviceInfo info;
	info.backend = "evdev";
	info.path = script.path;
	CHECK(probe(info, *kernel).openable);
	EvdevDeviceConfig config;
	config.path = script.path;
	EvdevDevice device(kernel, config);
	REQUIRE(device.open().ok());
	CHECK(device.features().rumble);
	CHECK(device.output() == EvdevOutput::RUMBLE);
	CHECK(device.capabilities().output == ForceOutput::VIBRATION);
	CHECK(kernel->rendered().periodic_playing == 1); // The rumble, converted.
	device.close();
	CHECK(kernel->effects_in_use() == 0);
}

TEST_CASE("evdev scripted kernel: closing a node stops and erases its effects - a reopened device uploads anew") {
	const ScriptedEvdevScript script = scripted_joystick_script();
	auto kernel = std::make_shared<ScriptedEvdevKernel>(script);
	const int first = kernel->open_device(script.path.c_str());
	const int other = kernel->open_device(script.path.c_str());
	FfEffectBytes bytes;
	encode_constant_effect(FfConstantEffect{ -1, 0x4000, 0x2000, 0, 0 }, bytes);
	const int id = upload_effect(*kernel, first, bytes);
	REQUIRE(id >= 0);
	play(*kernel, first, id, 1);
	encode_constant_effect(FfConstantEffect{ -1, 0xc000, 0x1000, 0, 0 }, bytes);
	const int other_id = upload_effect(*kernel, other, bytes);
	REQUIRE(other_id >= 0);
	CHECK(kernel->rendered().playing == 1);

	// The first client goes away without erasing: its effect stops and its slot is free;
	// the other client's effect stays. Its old id is dead for anyone: no update brings it back.
	CHECK(kernel->close(first) == 0);
	CHECK(kernel->rendered().playing == 0);
	CHECK(kernel->effects_in_use() == 1);
	const int again = kernel->open_device(script.path.c_str());
	encode_constant_effect(FfConstantEffect{ static_cast<int16_t>(id), 0x4000, 0x2000, 0, 0 }, bytes);
	CHECK(upload_effect(*kernel, again, bytes) == -EINVAL);
	CHECK(kernel->close(again) == 0);
	CHECK(kernel->close(other) == 0);
	CHECK(kernel->effects_in_use() == 0);

	// Our device, closed and opened again (a reconnect), uploads a new effect (id -1) before
	// any update, and renders.
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	device->close();
	kernel->clear_calls();
	REQUIRE(device->open().ok());
	std::vector<ScriptedEvdevCall> uploads;
	for (const ScriptedEvdevCall &call : evdev_test::ff_calls(kernel->calls())) {
		if (call.kind == Kind::IOCTL && call.request == EVDEV_EVIOCSFF) {
			uploads.push_back(call);
		}
	}
	REQUIRE_FALSE(uploads.empty());
	CHECK(get_s16(uploads.front().bytes.data(), FF_EFFECT_ID_OFFSET) == -1);
	REQUIRE(device->write_force(ForceCommand{ Vec3(2.5, 0.0, 0.0), Vec3() }) == DeviceIo::OK);
	CHECK(evdev_test::wait_until([&] { return kernel->rendered().playing == 1 && kernel->rendered().level == 16384; }));
	device->close();
	CHECK(kernel->effects_in_use() == 0);
}
