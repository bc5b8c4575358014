// The common backend soak (backend_soak.h) through the evdev device and the scripted kernel:
// the 1 kHz servo renders a floor the stick presses into, the device is unplugged in the
// middle (the servo stops itself with DEVICE_DISCONNECTED and the device's reason),
// replugged, reopened, and at the end the kernel's record shows zero force, stop, erase.

#include "backend_soak.h"
#include "dev_tools/evdev/scripted_evdev_device.h"
#include "devices/evdev/evdev_backend.h"
#include "evdev_test_support.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

using namespace haptics;
using namespace haptics::evdev;
using Kind = ScriptedEvdevCall::Kind;

TEST_CASE("evdev soak: 1 kHz servo through the scripted kernel, unplug, replug, reopen") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	// Pulled halfway toward the user = device y -0.5: into the floor whose normal is +y.
	kernel->set_stick_axes(0.0, 0.5);
	test::BackendSoakScript script;
	script.make_device = [&] { return make_scripted_device(kernel); };
	script.unplug = [&] { kernel->set_plugged(false); };
	script.replug = [&] {
		kernel->set_plugged(true);
		kernel->set_stick_axes(0.0, 0.5);
	};
	// A hand on the stick: small wiggles every 5 ms, so input events flow during the soak
	// (and the force changes, so updates do).
	std::atomic<bool> stop_hand{ false };
	std::thread hand([&] {
		for (int i = 0; !stop_hand.load(); ++i) {
			kernel->set_stick_axes(0.02 * (i % 5 - 2), 0.5 + 0.01 * (i % 7));
			std::this_thread::sleep_for(std::chrono::milliseconds(5));
		}
	});
	HapticsSystem system;
	const test::BackendSoakResult result = test::run_backend_soak(system, script);
	stop_hand.store(true);
	hand.join();

	REQUIRE(result.opened_first);
	REQUIRE(result.opened_again);
	CHECK(result.stopped_on_unplug);
	CHECK(result.status_after_unplug == StatusCode::DEVICE_DISCONNECTED);
	CHECK(result.device_status_after_unplug.io == DeviceIo::DISCONNECTED);
	CHECK(std::string(result.device_status_after_unplug.reason).find("/dev/input/event7 was unplugged") !=
			std::string::npos);
	CHECK(result.ticks_first >= 600); // ~1000 expected; generous for a loaded 2-core machine.
	CHECK(result.ticks_second >= 600);
	CHECK(result.peak_total_force_n > 0.5);

	const std::vector<ScriptedEvdevCall> calls = kernel->calls();
	int first_fd = -1;
	int second_fd = -1;
	uint64_t uploads_with_force = 0;
	bool only_upward = true; // Up to the wiggle's sideways share.
	size_t unplugged_at = calls.size();
	for (size_t i = 0; i < calls.size(); ++i) {
		const ScriptedEvdevCall &call = calls[i];
		if (call.kind == Kind::OPEN && call.result >= 0) {
			(first_fd < 0 ? first_fd : second_fd) = static_cast<int>(call.result);
		}
		if (call.kind == Kind::IOCTL && call.request == EVDEV_EVIOCSFF && call.result == 0) {
			FfEffectBytes bytes;
			std::copy(call.bytes.begin(), call.bytes.end(), bytes.begin());
			const FfEffectFields fields = decode_ff_effect(bytes);
			if (fields.constant_level != 0) {
				++uploads_with_force;
				const bool upward = fields.direction < 0x0800 || fields.direction > 0xf800; // Within 11 degrees.
				only_upward = only_upward && upward && fields.constant_level > 0;
			}
		}
		if (call.fd == first_fd && call.result == -ENODEV && unplugged_at == calls.size()) {
			unplugged_at = i;
		}
	}
	REQUIRE(second_fd > first_fd);
	CHECK(uploads_with_force > 0);
	CHECK(only_upward); // The floor pushes device +y: direction ~0x0000 (evdev_ff.h).
	// After the unplug nothing on the dead fd succeeded (the kernel answers ENODEV).
	for (size_t i = unplugged_at; i < calls.size(); ++i) {
		if (calls[i].fd == first_fd && calls[i].kind != Kind::CLOSE) {
			CHECK(calls[i].result == -ENODEV);
		}
	}
	// The end: zero, stop, erase, close on the second fd; nothing left rendering.
	std::vector<ScriptedEvdevCall> tail;
	for (const ScriptedEvdevCall &call : calls) {
		if (call.fd == second_fd && (call.kind == Kind::WRITE || call.kind == Kind::CLOSE || (call.kind == Kind::IOCTL && (call.request == EVDEV_EVIOCSFF || call.request == EVDEV_EVIOCRMFF)))) {
			tail.push_back(call);
		}
	}
	REQUIRE(tail.size() >= 4);
	const size_t n = tail.size();
	CHECK(tail[n - 4].bytes == evdev_test::expected_constant_effect(0, 0, 0));
	CHECK(tail[n - 3].bytes == evdev_test::expected_event(EVDEV_EV_FF, 0, 0));
	CHECK(tail[n - 2].request == EVDEV_EVIOCRMFF);
	CHECK(tail[n - 1].kind == Kind::CLOSE);
	CHECK(kernel->rendered().playing == 0);
	CHECK(kernel->effects_in_use() == 0);
	CHECK(kernel->open_fds() == 0);

	const ScriptedEvdevCounters counters = kernel->counters();
	const double seconds = result.seconds_first + result.seconds_second;
	const auto per_second = [&](uint64_t p_count) { return static_cast<double>(p_count) / seconds; };
	CHECK(counters.read_bytes > 0);
	MESSAGE("evdev soak: ticks " << result.ticks_first << " + " << result.ticks_second << " in " << seconds << " s; "
								 << per_second(counters.ioctls) << " ioctls/s, " << per_second(counters.uploads)
								 << " EVIOCSFF/s, " << per_second(counters.ioctl_bytes + counters.write_bytes)
								 << " bytes/s to the kernel, " << per_second(counters.read_bytes) << " bytes/s read");
}
