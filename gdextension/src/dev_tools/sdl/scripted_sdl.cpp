#include "dev_tools/sdl/scripted_sdl.h"

namespace haptics::sdl {

ScriptedHaptic scripted_sdl_stick() {
	return ScriptedHaptic{};
}

ScriptedHaptic scripted_sdl_wheel() {
	ScriptedHaptic wheel;
	wheel.name = "Scripted FFB Wheel";
	wheel.features = SDL_HAPTIC_CONSTANT | SDL_HAPTIC_GAIN | SDL_HAPTIC_AUTOCENTER;
	wheel.axes = 1;
	return wheel;
}

ScriptedHaptic scripted_sdl_pad() {
	ScriptedHaptic pad;
	pad.name = "Microsoft X-Box 360 pad";
	pad.features = SDL_HAPTIC_LEFTRIGHT;
	pad.max_effects = 16;
	return pad;
}

ScriptedSdl::ScriptedSdl(std::vector<ScriptedHaptic> p_haptics) {
	for (ScriptedHaptic &haptic : p_haptics) {
		Device device;
		device.script = std::move(haptic);
		devices_.push_back(std::move(device));
	}
	scripted_sdl_current = this;
}

ScriptedSdl::~ScriptedSdl() {
	if (scripted_sdl_current == this) {
		scripted_sdl_current = nullptr;
	}
}

void ScriptedSdl::set_plugged(size_t p_haptic, bool p_plugged) {
	std::lock_guard lock(mutex_);
	devices_.at(p_haptic).plugged = p_plugged;
}

void ScriptedSdl::fail_next(ScriptedSdlCall::Kind p_kind, const std::string &p_text) {
	std::lock_guard lock(mutex_);
	fail_kind_ = p_kind;
	fail_text_ = p_text;
}

std::vector<ScriptedSdlCall> ScriptedSdl::calls() const {
	std::lock_guard lock(mutex_);
	return calls_;
}

void ScriptedSdl::clear_calls() {
	std::lock_guard lock(mutex_);
	calls_.clear();
}

bool ScriptedSdl::effect(size_t p_haptic, SDL_HapticEffectID p_effect, SDL_HapticEffect &r_data, bool &r_playing) const {
	std::lock_guard lock(mutex_);
	const Device &device = devices_.at(p_haptic);
	if (p_effect < 0 || p_effect >= static_cast<int>(device.effects.size()) || !device.effects[p_effect].in_use) {
		return false;
	}
	r_data = device.effects[p_effect].data;
	r_playing = device.effects[p_effect].playing;
	return true;
}

int ScriptedSdl::effects_in_use(size_t p_haptic) const {
	std::lock_guard lock(mutex_);
	int count = 0;
	for (const Effect &effect : devices_.at(p_haptic).effects) {
		count += effect.in_use ? 1 : 0;
	}
	return count;
}

int ScriptedSdl::open_references(size_t p_haptic) const {
	std::lock_guard lock(mutex_);
	return devices_.at(p_haptic).references;
}

int ScriptedSdl::gain(size_t p_haptic) const {
	std::lock_guard lock(mutex_);
	return devices_.at(p_haptic).gain;
}

int ScriptedSdl::autocenter(size_t p_haptic) const {
	std::lock_guard lock(mutex_);
	return devices_.at(p_haptic).autocenter;
}

int ScriptedSdl::subsystem_count() const {
	std::lock_guard lock(mutex_);
	return subsystem_;
}

} // namespace haptics::sdl
