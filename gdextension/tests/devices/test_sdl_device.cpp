// The SDL backend's device over a scripted SDL (dev_tools/sdl/scripted_sdl.h): what it asks SDL
// to play (effect type, direction, level, length, renewal, rumble magnitudes), in what order,
// what it leaves behind, and what a vanished device or a refusal becomes.

#include "devices/sdl/sdl_device.h"
#include "sdl_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>

using namespace haptics;
using namespace haptics::sdl;
using namespace haptics::sdl_test;

namespace {

SdlDeviceConfig config_for(const std::string &p_key) {
	SdlDeviceConfig config;
	config.key = p_key;
	return config;
}

// Writes p_force each millisecond for p_seconds (as the servo would).
void hold(SdlHapticDevice &r_device, const Vec3 &p_force, double p_seconds, const Vec3 &p_impact = {}) {
	const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_seconds);
	while (std::chrono::steady_clock::now() < end) {
		REQUIRE(r_device.write_force(ForceCommand{ p_force, p_impact }) == DeviceIo::OK);
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
}

} // namespace

TEST_CASE("sdl device: a stick opens with one finite constant effect, run once, after SDL's own gain and autocentre") {
	Rig rig({ scripted_sdl_stick() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	const std::vector<ScriptedSdlCall> calls = rig.sdl.calls();
	// SDL_OpenHaptic sets gain 100 and autocentre 0 itself; we add nothing to them by default.
	CHECK(kinds(calls) == std::vector<Kind>{ Kind::OPEN, Kind::GAIN, Kind::AUTOCENTER, Kind::CREATE, Kind::RUN });
	const SDL_HapticEffect &created = calls.at(3).data;
	CHECK(created.type == SDL_HAPTIC_CONSTANT);
	CHECK(created.constant.direction.type == SDL_HAPTIC_POLAR);
	CHECK(created.constant.level == 0);
	CHECK(created.constant.length == SDL_EFFECT_LENGTH_MS);
	CHECK(calls.at(4).value == 1);
	CHECK(device.output() == SdlOutput::CONSTANT);
	const DeviceCapabilities capabilities = device.capabilities();
	CHECK(capabilities.output == ForceOutput::DIRECTIONAL);
	CHECK(capabilities.output_dof == 2);
	CHECK(capabilities.input_dof == 0);
	CHECK(std::strcmp(device.name(), "Arduino LLC Arduino Leonardo#0") == 0);
	device.close();
}

TEST_CASE("sdl device: the servo's force becomes one update of the same effect, level and angle as mapped") {
	Rig rig({ scripted_sdl_stick() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	rig.sdl.clear_calls();
	hold(device, Vec3(0.0, 1.0, 0.0), 0.1); // 1 N up of 5 N full scale.
	const std::vector<ScriptedSdlCall> updates = calls_of(rig.sdl.calls(), Kind::UPDATE);
	REQUIRE(updates.size() == 1); // Unchanged forces are not sent again.
	CHECK(updates[0].effect == 0);
	CHECK(updates[0].data.constant.level == 6553);
	CHECK(updates[0].data.constant.direction.dir[0] == 0);
	CHECK(updates[0].data.constant.length == SDL_EFFECT_LENGTH_MS);
	SDL_HapticEffect playing{};
	bool is_playing = false;
	REQUIRE(rig.sdl.effect(0, 0, playing, is_playing));
	CHECK(is_playing);
	hold(device, Vec3(-2.0, 0.0, 0.0), 0.05);
	const std::vector<ScriptedSdlCall> more = calls_of(rig.sdl.calls(), Kind::UPDATE);
	REQUIRE(more.size() == 2);
	CHECK(more[1].data.constant.direction.dir[0] == 27000);
	CHECK(more[1].data.constant.level == 13107);
	device.close();
}

TEST_CASE("sdl device: a held force is run again before its length ends, every renewal within the length") {
	Rig rig({ scripted_sdl_stick() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	const auto start = std::chrono::steady_clock::now();
	hold(device, Vec3(0.5, 0.0, 0.0), 0.9);
	const std::vector<ScriptedSdlCall> runs = calls_of(rig.sdl.calls(), Kind::RUN);
	REQUIRE(runs.size() >= 3); // The first at open, then every 0.25 s.
	auto previous = runs.front().when;
	for (size_t i = 1; i < runs.size(); ++i) {
		const double gap_s = std::chrono::duration<double>(runs[i].when - previous).count();
		CHECK(gap_s < SDL_EFFECT_LENGTH_MS / 1000.0 / 2.0);
		CHECK(runs[i].value == 1);
		previous = runs[i].when;
	}
	CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - previous).count() < 0.5);
	CHECK(std::chrono::duration<double>(runs.back().when - start).count() > 0.5);
	device.close();
}

TEST_CASE("sdl device: non-finite or huge forces never reach SDL as such") {
	Rig rig({ scripted_sdl_stick() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	const double nan = std::numeric_limits<double>::quiet_NaN();
	hold(device, Vec3(1e12, -1e12, 0.0), 0.03);
	hold(device, Vec3(nan, nan, nan), 0.03);
	hold(device, Vec3(std::numeric_limits<double>::infinity(), 0.0, 0.0), 0.03);
	const std::vector<ScriptedSdlCall> updates = calls_of(rig.sdl.calls(), Kind::UPDATE);
	REQUIRE(updates.size() == 2); // Full scale at 135 degrees, then zero (NaN and inf alike).
	CHECK(updates[0].data.constant.level == SDL_LEVEL_MAX);
	CHECK(updates[0].data.constant.direction.dir[0] == 13500);
	CHECK(updates[1].data.constant.level == 0);
	for (const ScriptedSdlCall &update : updates) {
		const Vec3 rendered = constant_effect_force_n(update.data, device.config().max_force_n);
		CHECK(std::isfinite(rendered.x));
		CHECK(length(rendered) <= device.config().max_force_n + 1e-9);
	}
	device.close();
}

TEST_CASE("sdl device: a one-axis wheel uses the steering axis and a signed level") {
	Rig rig({ scripted_sdl_wheel() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	CHECK(device.capabilities().output_dof == 1);
	hold(device, Vec3(-1.25, 2.0, 0.0), 0.05);
	const std::vector<ScriptedSdlCall> calls = rig.sdl.calls();
	const std::vector<ScriptedSdlCall> created = calls_of(calls, Kind::CREATE);
	REQUIRE(created.size() == 1);
	CHECK(created[0].data.constant.direction.type == SDL_HAPTIC_STEERING_AXIS);
	const std::vector<ScriptedSdlCall> updates = calls_of(calls, Kind::UPDATE);
	REQUIRE(updates.size() == 1);
	CHECK(updates[0].data.constant.direction.type == SDL_HAPTIC_STEERING_AXIS);
	CHECK(updates[0].data.constant.level == -8192); // -1.25 / 5 * 32767
	device.close();
}

TEST_CASE("sdl device: a rumble pad renders impacts on both motors, not the contact force") {
	Rig rig({ scripted_sdl_pad() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	CHECK(device.output() == SdlOutput::LEFTRIGHT);
	CHECK(device.capabilities().output == ForceOutput::VIBRATION);
	const std::vector<ScriptedSdlCall> created = calls_of(rig.sdl.calls(), Kind::CREATE);
	REQUIRE(created.size() == 1);
	CHECK(created[0].data.type == SDL_HAPTIC_LEFTRIGHT);
	CHECK(created[0].data.leftright.length == SDL_EFFECT_LENGTH_MS);
	rig.sdl.clear_calls();
	hold(device, Vec3(0.0, 2.0, 0.0), 0.05); // Standing on a floor: nothing to feel.
	CHECK(calls_of(rig.sdl.calls(), Kind::UPDATE).empty());
	hold(device, Vec3(0.0, 3.0, 0.0), 0.01, Vec3(0.0, 3.0, 0.0)); // The strongest hit.
	REQUIRE(eventually([&] { return !calls_of(rig.sdl.calls(), Kind::UPDATE).empty(); }));
	const ScriptedSdlCall first = calls_of(rig.sdl.calls(), Kind::UPDATE).front();
	CHECK(first.data.type == SDL_HAPTIC_LEFTRIGHT);
	CHECK(first.data.leftright.small_magnitude == 0x7fff);
	CHECK(first.data.leftright.large_magnitude == 0x7fff);
	hold(device, Vec3(), 0.2); // It fades to silence.
	const ScriptedSdlCall last = calls_of(rig.sdl.calls(), Kind::UPDATE).back();
	CHECK(last.data.leftright.small_magnitude == 0);
	CHECK(last.data.leftright.large_magnitude == 0);
	device.close();
}

TEST_CASE("sdl device: the game that keeps the centring spring has it set back to full after SDL's open") {
	Rig rig({ scripted_sdl_stick() });
	SdlDeviceConfig config = config_for(rig.entries.at(0).key);
	config.keep_spring = true;
	SdlHapticDevice device(rig.runtime, config);
	REQUIRE(device.open().ok());
	const std::vector<ScriptedSdlCall> autocentre = calls_of(rig.sdl.calls(), Kind::AUTOCENTER);
	REQUIRE(autocentre.size() == 2);
	CHECK(autocentre[0].value == 0); // SDL_OpenHaptic's.
	CHECK(autocentre[1].value == 100); // Ours.
	CHECK(rig.sdl.autocenter(0) == 100);
	CHECK(rig.sdl.gain(0) == 100); // SDL's, whatever the game asked: see sdl_device.h.
	device.close();
}

TEST_CASE("sdl device: close leaves zero, stopped, destroyed and the haptic closed") {
	Rig rig({ scripted_sdl_stick() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	hold(device, Vec3(1.0, 0.0, 0.0), 0.05);
	rig.sdl.clear_calls();
	device.close();
	const std::vector<ScriptedSdlCall> calls = rig.sdl.calls();
	CHECK(kinds(calls) == std::vector<Kind>{ Kind::UPDATE, Kind::STOP, Kind::DESTROY, Kind::CLOSE });
	CHECK(calls.at(0).data.constant.level == 0);
	CHECK(rig.sdl.effects_in_use(0) == 0);
	CHECK(rig.sdl.open_references(0) == 0);
	CHECK(rig.runtime.open_count() == 0);
	CHECK_FALSE(device.is_open());
	device.close(); // Idempotent.
	CHECK(rig.sdl.calls().size() == calls.size());
}

TEST_CASE("sdl device: a device that disappears mid-session is DISCONNECTED with SDL's text, another failure is FAILED") {
	Rig rig({ scripted_sdl_stick() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	hold(device, Vec3(1.0, 0.0, 0.0), 0.03);
	rig.sdl.set_plugged(0, false);
	DeviceState state;
	const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
	while (device.read_state(state) == DeviceIo::OK && std::chrono::steady_clock::now() < end) {
		(void)device.write_force(ForceCommand{ Vec3(0.0, 1.0, 0.0), Vec3() });
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	const DeviceStatus status = device.status();
	CHECK(status.io == DeviceIo::DISCONNECTED);
	CHECK(std::strstr(status.reason.c_str(), "was unplugged") != nullptr);
	CHECK(std::strstr(status.reason.c_str(), "Haptic: Error updating the effect: No such device") != nullptr);
	device.close();
	CHECK(rig.sdl.open_references(0) == 0);

	rig.sdl.set_plugged(0, true);
	std::vector<SdlHapticEntry> entries;
	std::string warning;
	REQUIRE(rig.runtime.list(driving(), entries, warning).ok());
	SdlHapticDevice again(rig.runtime, config_for(entries.at(0).key));
	REQUIRE(again.open().ok());
	rig.sdl.fail_next(Kind::UPDATE, "Haptic: Error updating the effect: Input/output error");
	CHECK(eventually([&] {
		(void)again.write_force(ForceCommand{ Vec3(0.0, -1.0, 0.0), Vec3() });
		return again.status().io != DeviceIo::OK;
	}));
	CHECK(again.status().io == DeviceIo::FAILED);
	CHECK(std::strstr(again.status().reason.c_str(), "Input/output error") != nullptr);
	again.close();
}

TEST_CASE("sdl device: open refuses bad configs, unknown keys, SDL's refusals and featureless haptics, leaving nothing open") {
	ScriptedHaptic denied = scripted_sdl_stick();
	denied.name = "Denied";
	denied.open_error = "Haptic: Unable to open /dev/input/event9: Permission denied";
	ScriptedHaptic bare = scripted_sdl_stick();
	bare.name = "Gain only";
	bare.features = SDL_HAPTIC_GAIN;
	Rig rig({ denied, bare });
	SdlDeviceConfig bad = config_for("Gain only#0");
	bad.rate_hz = std::numeric_limits<double>::quiet_NaN();
	Status status = SdlHapticDevice(rig.runtime, bad).open();
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::strstr(status.message(), "sdl_device.rate_hz") != nullptr);
	bad = config_for("Gain only#0");
	bad.max_continuous_force_n = 6.0;
	CHECK(SdlHapticDevice(rig.runtime, bad).open().code() == StatusCode::OUT_OF_RANGE);
	CHECK(rig.sdl.calls().empty());

	status = SdlHapticDevice(rig.runtime, config_for("Nobody#0")).open();
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(std::strstr(status.message(), "no longer lists 'Nobody#0'") != nullptr);
	status = SdlHapticDevice(rig.runtime, config_for("Denied#0")).open();
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(std::strstr(status.message(), "Permission denied") != nullptr);
	status = SdlHapticDevice(rig.runtime, config_for("Gain only#0")).open();
	CHECK(status.code() == StatusCode::UNSUPPORTED);
	CHECK(std::strstr(status.message(), "neither constant force nor rumble") != nullptr);
	CHECK(rig.sdl.open_references(1) == 0);
	CHECK(rig.runtime.open_count() == 0);
}
