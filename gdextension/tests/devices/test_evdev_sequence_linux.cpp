// The ff.rst sequence against the scripted kernel, byte for byte: gain, autocentre,
// upload (id -1 -> the kernel's id), play, updates (one EVIOCSFF with the same id, only on
// a change, never a re-play), stop and erase; the force the device then renders; errors.

#include "dev_tools/evdev/scripted_evdev_kernel.h"
#include "devices/evdev/evdev_effect.h"
#include "evdev_test_support.h"

#include <doctest/doctest.h>

#include <cerrno>
#include <memory>
#include <string>

using namespace haptics;
using namespace haptics::evdev;
using Kind = ScriptedEvdevCall::Kind;

namespace {

struct Started {
	std::shared_ptr<ScriptedEvdevKernel> kernel;
	int fd = -1;
	EvdevFfFeatures features;
	EvdevConstantForce effect;
};

// Opens the script's node, reads its features and starts the effect; the record is then
// cleared so each test sees only what it caused.
void start(Started &r_started, ScriptedEvdevScript p_script = scripted_joystick_script(),
		const EvdevTakeover &p_takeover = {}) {
	r_started.kernel = std::make_shared<ScriptedEvdevKernel>(std::move(p_script));
	ScriptedEvdevKernel &kernel = *r_started.kernel;
	r_started.fd = kernel.open_device(kernel.script().path.c_str());
	REQUIRE(r_started.fd >= 0);
	REQUIRE(query_ff_features(kernel, r_started.fd, "/dev/input/event7", r_started.features).ok());
	kernel.clear_calls();
	const Status status = r_started.effect.start(kernel, r_started.fd, r_started.features, "/dev/input/event7", p_takeover);
	REQUIRE_MESSAGE(status.ok(), status.message());
}

void check_upload(const ScriptedEvdevCall &p_call, int16_t p_id, uint16_t p_direction, int16_t p_level) {
	CHECK(p_call.kind == Kind::IOCTL);
	CHECK(p_call.request == 0x40304580u);
	CHECK(p_call.bytes == evdev_test::expected_constant_effect(p_id, p_direction, p_level));
	CHECK(p_call.result == 0);
}

void check_write(const ScriptedEvdevCall &p_call, uint16_t p_code, int32_t p_value) {
	CHECK(p_call.kind == Kind::WRITE);
	CHECK(p_call.bytes == evdev_test::expected_event(0x15, p_code, p_value));
	CHECK(p_call.result == 24);
}

} // namespace

TEST_CASE("evdev sequence: features of the PID joystick (constant, gain, no autocentre, 10 effects)") {
	Started s;
	start(s);
	CHECK(s.features.constant);
	CHECK(s.features.gain);
	CHECK_FALSE(s.features.autocenter);
	CHECK(s.features.max_effects == 10);
}

TEST_CASE("evdev sequence: start = upload id -1 level 0, play id 1, and the player's gain is left alone") {
	Started s;
	start(s);
	const auto calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 2);
	check_upload(calls[0], -1, 0, 0);
	check_write(calls[1], 0, 1); // The kernel gave id 0.
	CHECK(s.effect.id() == 0);
	CHECK(s.kernel->autocenter() == -1);
}

TEST_CASE("evdev sequence: a game that takes the gain sets it to 0xFFFF first (no autocentre offered)") {
	Started s;
	start(s, scripted_joystick_script(), EvdevTakeover{ true, true });
	const auto calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 3);
	check_write(calls[0], 0x60, 0xffff);
	check_upload(calls[1], -1, 0, 0);
	check_write(calls[2], 0, 1);
	CHECK(s.effect.id() == 0);
	CHECK(s.kernel->effects_in_use() == 1);
	CHECK(s.kernel->rendered().playing == 1);
	CHECK(s.kernel->rendered().gain == 0xffff);
	CHECK(s.kernel->autocenter() == -1);
}

TEST_CASE("evdev sequence: a wheel offering FF_AUTOCENTER gets autocentre 0 before the upload") {
	Started s;
	start(s, scripted_wheel_script());
	const auto calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 3);
	check_write(calls[0], 0x61, 0);
	check_upload(calls[1], -1, 0, 0);
	check_write(calls[2], 0, 1);
	CHECK(s.kernel->autocenter() == 0);
}

TEST_CASE("evdev sequence: a game that keeps the centring spring leaves the wheel's autocentre alone") {
	Started s;
	start(s, scripted_wheel_script(), EvdevTakeover{ false, false });
	const auto calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 2);
	check_upload(calls[0], -1, 0, 0);
	CHECK(s.kernel->autocenter() == -1);
}

TEST_CASE("evdev sequence: the id the kernel writes back is used for play, updates and erase") {
	Started s;
	ScriptedEvdevScript script = scripted_joystick_script();
	s.kernel = std::make_shared<ScriptedEvdevKernel>(script);
	// Another client holds slots 0 and 1, so ours is 2.
	const int other = s.kernel->open_device(script.path.c_str());
	FfEffectBytes bytes;
	for (int i = 0; i < 2; ++i) {
		encode_constant_effect(FfConstantEffect{}, bytes);
		REQUIRE(s.kernel->ioctl(other, EVDEV_EVIOCSFF, bytes.data()) == 0);
	}
	s.fd = s.kernel->open_device(script.path.c_str());
	REQUIRE(query_ff_features(*s.kernel, s.fd, "/dev/input/event7", s.features).ok());
	s.kernel->clear_calls();
	REQUIRE(s.effect.start(*s.kernel, s.fd, s.features, "/dev/input/event7").ok());
	CHECK(s.effect.id() == 2);
	REQUIRE(s.effect.update({ 0x4000, 0x1000 }) == 0);
	REQUIRE(s.effect.stop_and_erase() == 0);
	const auto calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 6);
	check_write(calls[1], 2, 1);
	check_upload(calls[2], 2, 0x4000, 0x1000);
	check_upload(calls[3], 2, 0, 0);
	check_write(calls[4], 2, 0);
	CHECK(calls[5].request == 0x40044581u);
	CHECK(calls[5].bytes == evdev_test::int_bytes(2));
	CHECK(s.kernel->effects_in_use() == 2); // The other client's stay.
}

TEST_CASE("evdev sequence golden: a level update is ONE EVIOCSFF with the same id and no re-play") {
	Started s;
	start(s);
	s.kernel->clear_calls();
	REQUIRE(s.effect.update({ 0x4000, 0x2000 }) == 0);
	auto calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 1);
	check_upload(calls[0], 0, 0x4000, 0x2000);

	s.kernel->clear_calls();
	REQUIRE(s.effect.update({ 0x4000, 0x2001 }) == 0); // Level only.
	calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 1);
	check_upload(calls[0], 0, 0x4000, 0x2001);

	s.kernel->clear_calls();
	REQUIRE(s.effect.update({ 0xc000, 0x2001 }) == 0); // Direction only.
	calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 1);
	check_upload(calls[0], 0, 0xc000, 0x2001);
	CHECK(s.kernel->rendered().playing == 1); // Still playing: updated in place.
}

TEST_CASE("evdev sequence: an unchanged quantised force sends nothing") {
	Started s;
	start(s);
	REQUIRE(s.effect.update({ 0x8000, 100 }) == 0);
	const uint64_t uploads = s.effect.uploads();
	s.kernel->clear_calls();
	for (int i = 0; i < 50; ++i) {
		REQUIRE(s.effect.update({ 0x8000, 100 }) == 0);
	}
	CHECK(s.kernel->calls().empty());
	CHECK(s.effect.uploads() == uploads);
}

TEST_CASE("evdev sequence: stop = level 0 upload, EV_FF id value 0, EVIOCRMFF id by value - idempotent") {
	Started s;
	start(s);
	REQUIRE(s.effect.update({ 0x4000, 0x7fff }) == 0);
	s.kernel->clear_calls();
	CHECK(s.effect.stop_and_erase() == 0);
	const auto calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() == 3);
	check_upload(calls[0], 0, 0, 0);
	check_write(calls[1], 0, 0);
	CHECK(calls[2].request == 0x40044581u);
	CHECK(calls[2].bytes == evdev_test::int_bytes(0));
	CHECK(calls[2].result == 0);
	CHECK(s.kernel->effects_in_use() == 0);
	CHECK(s.kernel->rendered().playing == 0);
	s.kernel->clear_calls();
	CHECK(s.effect.stop_and_erase() == 0);
	CHECK(s.kernel->calls().empty());
	CHECK(s.effect.update({ 0x4000, 1 }) == -EBADF); // Not started.
}

TEST_CASE("evdev sequence end to end: device newtons -> bytes -> the force the firmware renders") {
	Started s;
	start(s);
	FfForceMapping mapping; // 5 N full scale.
	REQUIRE(s.effect.update(map_force_to_constant(Vec3(3.0, -2.0, 0.0), mapping)) == 0);
	ScriptedRenderedForce rendered = s.kernel->rendered();
	CHECK(rendered.axis_x == doctest::Approx(3.0 / 5.0).epsilon(1e-3));
	CHECK(rendered.axis_y == doctest::Approx(2.0 / 5.0).epsilon(1e-3)); // Device down = axis +Y.
	REQUIRE(s.effect.update(map_force_to_constant(Vec3(-1.0, 4.0, 0.0), mapping)) == 0);
	rendered = s.kernel->rendered();
	CHECK(rendered.axis_x == doctest::Approx(-1.0 / 5.0).epsilon(1e-3));
	CHECK(rendered.axis_y == doctest::Approx(-4.0 / 5.0).epsilon(1e-3));
	REQUIRE(s.effect.update(map_force_to_constant(Vec3(), mapping)) == 0);
	rendered = s.kernel->rendered();
	CHECK(rendered.axis_x == 0.0);
	CHECK(rendered.axis_y == 0.0);
}

TEST_CASE("evdev sequence: no free effect slot (ENOSPC) is a clear error and leaves nothing behind") {
	ScriptedEvdevScript script = scripted_joystick_script();
	script.max_effects = 0;
	ScriptedEvdevKernel kernel(script);
	const int fd = kernel.open_device(script.path.c_str());
	EvdevFfFeatures features;
	REQUIRE(query_ff_features(kernel, fd, "/dev/input/event7", features).ok());
	EvdevConstantForce effect;
	const Status status = effect.start(kernel, fd, features, "/dev/input/event7");
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(std::string(status.message()) ==
			"/dev/input/event7: uploading the constant force (EVIOCSFF) failed: No space left on device (ENOSPC)");
	CHECK_FALSE(effect.started());
}

TEST_CASE("evdev sequence: a failing play erases the uploaded effect - unplugged -> DEVICE_DISCONNECTED") {
	Started s;
	s.kernel = std::make_shared<ScriptedEvdevKernel>();
	s.fd = s.kernel->open_device("/dev/input/event7");
	REQUIRE(query_ff_features(*s.kernel, s.fd, "/dev/input/event7", s.features).ok());
	s.kernel->clear_calls();
	EvdevConstantForce effect;
	s.features.gain = false; // So the play is the first write, and it fails.
	s.kernel->fail_next_write(EIO);
	Status status = effect.start(*s.kernel, s.fd, s.features, "/dev/input/event7");
	CHECK(std::string(status.message()) == "/dev/input/event7: playing the constant force failed: Input/output error (EIO)");
	CHECK(s.kernel->effects_in_use() == 0);
	const auto calls = evdev_test::ff_calls(s.kernel->calls());
	REQUIRE(calls.size() >= 2);
	CHECK(calls.back().request == EVDEV_EVIOCRMFF);

	s.kernel->set_plugged(false);
	status = effect.start(*s.kernel, s.fd, s.features, "/dev/input/event7");
	CHECK(status.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(std::string(status.message()).find("ENODEV") != std::string::npos);
}

TEST_CASE("evdev scripted kernel: EVIOCSFF answers like ff-core (wrong type, foreign id, unknown id)") {
	ScriptedEvdevKernel kernel(scripted_wheel_script()); // Constant only, no periodic.
	const int a = kernel.open_device("/dev/input/event9");
	const int b = kernel.open_device("/dev/input/event9");
	FfEffectBytes bytes;
	encode_constant_effect(FfConstantEffect{}, bytes);
	REQUIRE(kernel.ioctl(a, EVDEV_EVIOCSFF, bytes.data()) == 0);
	CHECK(get_s16(bytes.data(), 2) == 0);
	CHECK(kernel.ioctl(b, EVDEV_EVIOCSFF, bytes.data()) == -EACCES); // a's effect.
	CHECK(kernel.ioctl(b, EVDEV_EVIOCRMFF, reinterpret_cast<void *>(intptr_t{ 0 })) == -EACCES);
	put_u16(bytes.data(), 2, 5);
	CHECK(kernel.ioctl(a, EVDEV_EVIOCSFF, bytes.data()) == -EINVAL); // Not in use.
	put_u16(bytes.data(), 0, EVDEV_FF_PERIODIC);
	put_u16(bytes.data(), 2, 0xffff);
	CHECK(kernel.ioctl(a, EVDEV_EVIOCSFF, bytes.data()) == -EINVAL); // Not offered.
	CHECK(kernel.ioctl(a, 0x12345678u, bytes.data()) == -EINVAL);
	CHECK(kernel.ioctl(999, EVDEV_EVIOCSFF, bytes.data()) == -EBADF);
	CHECK(kernel.close(a) == 0);
	CHECK(kernel.effects_in_use() == 0); // The file's effects went with it.
}
