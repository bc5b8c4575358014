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

ScriptedJoystick scripted_sdl_xinput_pad() {
	return ScriptedJoystick{};
}

ScriptedSdl::ScriptedSdl(std::vector<ScriptedHaptic> p_haptics, std::vector<ScriptedJoystick> p_joysticks) {
	for (ScriptedHaptic &haptic : p_haptics) {
		if (haptic.joystick) {
			Joystick joystick;
			joystick.script.name = haptic.name;
			joystick.script.vendor_id = haptic.vendor_id;
			joystick.script.product_id = haptic.product_id;
			joystick.script.gamepad = false;
			// SDL's DirectInput joysticks rumble through a force-feedback effect.
			joystick.script.rumble = (haptic.features & (SDL_HAPTIC_SINE | SDL_HAPTIC_LEFTRIGHT | SDL_HAPTIC_CONSTANT)) != 0;
			joystick.haptic = static_cast<int>(devices_.size());
			joysticks_.push_back(joystick);
		}
		Device device;
		device.script = std::move(haptic);
		devices_.push_back(std::move(device));
	}
	for (ScriptedJoystick &script : p_joysticks) {
		Joystick joystick;
		joystick.script = std::move(script);
		joysticks_.push_back(joystick);
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

void ScriptedSdl::set_joystick_plugged(size_t p_joystick, bool p_plugged) {
	std::lock_guard lock(mutex_);
	joysticks_.at(first_scripted_joystick() + p_joystick).plugged = p_plugged;
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

bool ScriptedSdl::effect(size_t p_haptic, SdlEffectId p_effect, SDL_HapticEffect &r_data, bool &r_playing) const {
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

int ScriptedSdl::joystick_subsystem_count() const {
	std::lock_guard lock(mutex_);
	return joystick_subsystem_;
}

std::string ScriptedSdl::hint(const std::string &p_name) const {
	std::lock_guard lock(mutex_);
	const auto found = hints_.find(p_name);
	return found != hints_.end() ? found->second : std::string();
}

bool ScriptedSdl::joystick_events() const {
	std::lock_guard lock(mutex_);
	return joystick_events_;
}

size_t ScriptedSdl::first_scripted_joystick() const {
	size_t first = 0;
	while (first < joysticks_.size() && joysticks_[first].haptic >= 0) {
		++first;
	}
	return first;
}

int ScriptedSdl::joystick_references(size_t p_joystick) const {
	std::lock_guard lock(mutex_);
	return joysticks_.at(first_scripted_joystick() + p_joystick).references;
}

void ScriptedSdl::joystick_rumble(size_t p_joystick, uint16_t &r_low, uint16_t &r_high) const {
	std::lock_guard lock(mutex_);
	const Joystick &joystick = joysticks_.at(first_scripted_joystick() + p_joystick);
	r_low = joystick.low;
	r_high = joystick.high;
}

} // namespace haptics::sdl
