#pragma once

// Shared by the SDL backend's tests: a scripted SDL with a runtime over it, listed once (so the
// devices can be opened), filters over its record and a bounded wait for the I/O thread.

#include "dev_tools/sdl/scripted_sdl.h"
#include "devices/sdl/sdl_runtime.h"

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

namespace haptics::sdl_test {

using namespace haptics::sdl;
using Kind = ScriptedSdlCall::Kind;

// Where SDL drives, with its joysticks listed (as on Windows).
inline SdlListOptions driving() {
	SdlListOptions options;
	options.read = true;
	options.joysticks = true;
	return options;
}

struct Rig {
	explicit Rig(std::vector<ScriptedHaptic> p_haptics, std::vector<ScriptedJoystick> p_joysticks = {}) :
			sdl(std::move(p_haptics), std::move(p_joysticks)), runtime(ScriptedSdl::api()) {
		std::string warning;
		(void)runtime.list(driving(), entries, warning);
		sdl.clear_calls();
	}
	ScriptedSdl sdl;
	SdlRuntime runtime;
	std::vector<SdlHapticEntry> entries;
};

inline std::vector<ScriptedSdlCall> calls_of(const std::vector<ScriptedSdlCall> &p_calls, Kind p_kind) {
	std::vector<ScriptedSdlCall> result;
	for (const ScriptedSdlCall &call : p_calls) {
		if (call.kind == p_kind) {
			result.push_back(call);
		}
	}
	return result;
}

inline std::vector<Kind> kinds(const std::vector<ScriptedSdlCall> &p_calls) {
	std::vector<Kind> result;
	for (const ScriptedSdlCall &call : p_calls) {
		result.push_back(call.kind);
	}
	return result;
}

// Polls every millisecond for up to p_seconds.
template <typename Condition>
bool eventually(Condition p_condition, double p_seconds = 2.0) {
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_seconds);
	while (std::chrono::steady_clock::now() < deadline) {
		if (p_condition()) {
			return true;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	return p_condition();
}

} // namespace haptics::sdl_test
