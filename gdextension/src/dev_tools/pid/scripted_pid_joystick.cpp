#include "dev_tools/pid/scripted_pid_joystick.h"

#include "dev_tools/pid/scripted_pid_profile.h"
#include "dev_tools/pid/virtual_pid_descriptor.h"
#include "devices/pid/aj_descriptor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

namespace haptics::pid {

ScriptedPidJoystick::ScriptedPidJoystick(ScriptedFirmware p_firmware, size_t p_record_capacity) :
		firmware_(p_firmware), profile_(profile_for(p_firmware)), record_capacity_(p_record_capacity) {
	if (p_firmware == ScriptedFirmware::AJ) {
		descriptor_ = compose_aj_descriptor(16);
	} else if (p_firmware == ScriptedFirmware::AJ_START_DELAY) {
		descriptor_ = aj_start_delay_descriptor();
	} else if (p_firmware == ScriptedFirmware::VIRTUAL_WHEEL) {
		descriptor_ = virtual_pid_wheel_descriptor();
	} else {
		const std::span<const uint8_t> bytes = virtual_pid_descriptor();
		descriptor_.assign(bytes.begin(), bytes.end());
	}
	records_.reserve(p_record_capacity);
	power_on();
}

void ScriptedPidJoystick::power_on() {
	for (ScriptedEffect &effect : effects_) {
		effect = ScriptedEffect{};
	}
	actuators_enabled_ = false;
	paused_ = false;
	device_gain_ = 255;
	pending_block_ = 0;
	pending_status_ = 0;
}

void ScriptedPidJoystick::set_plugged(bool p_plugged) {
	const std::lock_guard lock(mutex_);
	if (p_plugged && !plugged_) {
		power_on(); // Plugged back: the firmware starts from scratch.
	}
	plugged_ = p_plugged;
}

bool ScriptedPidJoystick::plugged() const {
	const std::lock_guard lock(mutex_);
	return plugged_;
}

void ScriptedPidJoystick::set_stick(double p_x, double p_y) {
	const std::lock_guard lock(mutex_);
	stick_x_ = p_x;
	stick_y_ = p_y;
}

void ScriptedPidJoystick::set_buttons(uint32_t p_buttons) {
	const std::lock_guard lock(mutex_);
	buttons_ = p_buttons;
}

void ScriptedPidJoystick::script_block_load(BlockLoadAnswer p_answer, uint32_t p_count) {
	const std::lock_guard lock(mutex_);
	block_load_script_.insert(block_load_script_.end(), p_count, p_answer);
}

std::vector<ScriptedTransfer> ScriptedPidJoystick::records() const {
	const std::lock_guard lock(mutex_);
	return records_;
}

void ScriptedPidJoystick::clear_records() {
	const std::lock_guard lock(mutex_);
	records_.clear();
}

ScriptedJoystickStats ScriptedPidJoystick::stats() const {
	const std::lock_guard lock(mutex_);
	return stats_;
}

bool ScriptedPidJoystick::effect_active(const ScriptedEffect &p_effect, size_t p_index) const {
	if (!p_effect.allocated || !p_effect.playing) {
		return false;
	}
	if (p_effect.duration_infinite) {
		return true;
	}
	const auto elapsed = std::chrono::steady_clock::now() - started_[p_index];
	return elapsed < std::chrono::milliseconds(p_effect.duration);
}

ScriptedForce ScriptedPidJoystick::rendered_force() const {
	const std::lock_guard lock(mutex_);
	ScriptedForce force;
	if (!plugged_ || !actuators_enabled_ || paused_) {
		return force;
	}
	for (size_t i = 1; i <= MAX_EFFECTS; ++i) {
		const ScriptedEffect &effect = effects_[i];
		// Polar only: the direction-enable-only case of AJ's getEffectForce.
		if (!effect_active(effect, i) || effect.type != CONSTANT_FORCE_TYPE || (effect.enable_bits & 0x04) == 0) {
			continue;
		}
		const double theta = effect.direction * profile_.degrees_per_direction_unit * std::numbers::pi / 180.0;
		const double level = static_cast<double>(effect.magnitude) / profile_.magnitude_max * (effect.gain / 255.0) *
				(device_gain_ / 255.0);
		force.x += level * std::sin(theta);
		force.y += -level * std::cos(theta);
		++force.playing_effects;
	}
	force.x = std::clamp(force.x, -1.0, 1.0);
	force.y = std::clamp(force.y, -1.0, 1.0);
	return force;
}

ScriptedEffect ScriptedPidJoystick::effect(uint8_t p_block_index) const {
	const std::lock_guard lock(mutex_);
	if (p_block_index == 0 || p_block_index > MAX_EFFECTS) {
		return {};
	}
	ScriptedEffect effect = effects_[p_block_index];
	effect.playing = effect_active(effect, p_block_index);
	return effect;
}

uint32_t ScriptedPidJoystick::allocated_effects() const {
	const std::lock_guard lock(mutex_);
	return static_cast<uint32_t>(std::count_if(std::begin(effects_), std::end(effects_), [](const ScriptedEffect &p_effect) {
		return p_effect.allocated;
	}));
}

bool ScriptedPidJoystick::actuators_enabled() const {
	const std::lock_guard lock(mutex_);
	return actuators_enabled_;
}

uint8_t ScriptedPidJoystick::device_gain() const {
	const std::lock_guard lock(mutex_);
	return device_gain_;
}

void ScriptedPidJoystick::record(TransferKind p_kind, std::span<const uint8_t> p_bytes) {
	if (records_.size() >= record_capacity_) {
		++stats_.records_dropped;
		return;
	}
	ScriptedTransfer transfer;
	transfer.kind = p_kind;
	transfer.length = static_cast<uint8_t>(std::min<size_t>(p_bytes.size(), PID_MAX_REPORT_BYTES));
	if (transfer.length > 0) {
		std::memcpy(transfer.bytes, p_bytes.data(), transfer.length);
	}
	records_.push_back(transfer);
}

} // namespace haptics::pid
