#include "dev_tools/evdev/scripted_evdev_kernel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

// The scripted kernel's presets, the script a test drives, and what it reports back.

namespace haptics::evdev {

ScriptedEvdevScript scripted_joystick_script() {
	ScriptedEvdevScript script;
	script.path = "/dev/input/event7";
	script.name = "Arduino LLC Arduino Leonardo";
	script.vendor = 0x2341;
	script.product = 0x8036;
	script.version = 0x0111;
	// hid-pidff's effect set for the AJ descriptor (constant, ramp, periodic waveforms,
	// conditions) plus FF_GAIN from its device-gain report; no FF_AUTOCENTER.
	script.ff_codes = { EVDEV_FF_CONSTANT, EVDEV_FF_RAMP, EVDEV_FF_PERIODIC, 0x53, 0x54, 0x55, 0x56, 0x58, 0x59, 0x5a, 0x5b,
		0x5c, EVDEV_FF_GAIN };
	const AbsRange stick{ 0, -32767, 32767, 0, 0, 0 };
	script.axes = { { EVDEV_ABS_X, stick }, { EVDEV_ABS_Y, stick } };
	script.key_codes = { EVDEV_BTN_TRIGGER, EVDEV_BTN_THUMB, 0x122, 0x123 };
	script.max_effects = 10;
	return script;
}

ScriptedEvdevScript scripted_wheel_script() {
	ScriptedEvdevScript script;
	script.path = "/dev/input/event9";
	script.name = "Scripted FFB wheel";
	script.vendor = 0x1209;
	script.product = 0xffb0;
	script.ff_codes = { EVDEV_FF_CONSTANT, EVDEV_FF_GAIN, EVDEV_FF_AUTOCENTER };
	script.axes = { { EVDEV_ABS_WHEEL, AbsRange{ 32768, 0, 65535, 0, 0, 0 } } };
	script.key_codes = { EVDEV_BTN_SOUTH, 0x131 };
	script.max_effects = 16;
	return script;
}

ScriptedEvdevScript scripted_gamepad_script() {
	ScriptedEvdevScript script;
	script.path = "/dev/input/event11";
	script.name = "Sony Interactive Entertainment DualSense Wireless Controller";
	script.vendor = 0x054c;
	script.product = 0x0ce6;
	script.version = 0x8100; // hid-playstation sets bit 15 (HID_PLAYSTATION_VERSION_PATCH).
	script.ff_codes = { EVDEV_FF_RUMBLE, EVDEV_FF_PERIODIC, EVDEV_FF_SQUARE, EVDEV_FF_TRIANGLE, EVDEV_FF_SINE, EVDEV_FF_GAIN };
	const AbsRange stick{ 128, 0, 255, 0, 0, 0 };
	script.axes = { { EVDEV_ABS_X, stick }, { EVDEV_ABS_Y, stick } };
	script.key_codes = { EVDEV_BTN_SOUTH, 0x131, 0x133, 0x134 };
	script.max_effects = 16;
	return script;
}

bool ScriptedEvdevKernel::has(const std::vector<uint16_t> &p_codes, uint16_t p_code) const {
	return std::find(p_codes.begin(), p_codes.end(), p_code) != p_codes.end();
}

AbsRange *ScriptedEvdevKernel::axis(uint16_t p_code) {
	for (ScriptedAbsAxis &axis : script_.axes) {
		if (axis.code == p_code) {
			return &axis.range;
		}
	}
	return nullptr;
}

void ScriptedEvdevKernel::post_event(uint16_t p_type, uint16_t p_code, int32_t p_value) {
	if (!plugged_) {
		return;
	}
	++event_clock_;
	Chunk chunk;
	chunk.bytes.resize(INPUT_EVENT_SIZE);
	InputEventBytes event;
	encode_input_event(p_type, p_code, p_value, event);
	// A plausible monotonic time stamp: 1 ms per event.
	const uint64_t seconds = 1000 + event_clock_ / 1000;
	const uint64_t microseconds = (event_clock_ % 1000) * 1000;
	for (size_t i = 0; i < 8; ++i) {
		event[i] = static_cast<uint8_t>((seconds >> (8 * i)) & 0xffu);
		event[8 + i] = static_cast<uint8_t>((microseconds >> (8 * i)) & 0xffu);
	}
	std::copy(event.begin(), event.end(), chunk.bytes.begin());
	for (Client &client : clients_) {
		if (!client.alive) {
			continue;
		}
		if (client.queued_events + 1 >= script_.buffer_events) {
			// evdev_pass_values on a full buffer: the client loses the queue and learns so.
			client.queue.clear();
			client.queued_events = 0;
			Chunk dropped;
			dropped.bytes.resize(INPUT_EVENT_SIZE);
			InputEventBytes syn;
			encode_input_event(EVDEV_EV_SYN, EVDEV_SYN_DROPPED, 0, syn);
			std::copy(syn.begin(), syn.end(), dropped.bytes.begin());
			client.queue.push_back(std::move(dropped));
			++client.queued_events;
		}
		client.queue.push_back(chunk);
		++client.queued_events;
	}
}

void ScriptedEvdevKernel::set_plugged(bool p_plugged) {
	std::lock_guard<std::mutex> lock(mutex_);
	if (plugged_ == p_plugged) {
		return;
	}
	plugged_ = p_plugged;
	if (!p_plugged) {
		for (Client &client : clients_) {
			client.alive = false; // evdev_disconnect: every later call on it is -ENODEV.
			client.queue.clear();
			client.queued_events = 0;
		}
	}
	reset_device(); // Gone, or a fresh device: no effects, default gain.
}

bool ScriptedEvdevKernel::plugged() const {
	std::lock_guard<std::mutex> lock(mutex_);
	return plugged_;
}

void ScriptedEvdevKernel::set_axis(uint16_t p_code, int32_t p_value) {
	std::lock_guard<std::mutex> lock(mutex_);
	if (AbsRange *range = axis(p_code)) {
		range->value = std::clamp(p_value, range->minimum, range->maximum);
		post_event(EVDEV_EV_ABS, p_code, range->value);
	}
}

void ScriptedEvdevKernel::set_button(uint16_t p_code, bool p_pressed) {
	std::lock_guard<std::mutex> lock(mutex_);
	if (!has(script_.key_codes, p_code)) {
		return;
	}
	const auto down = std::find(keys_down_.begin(), keys_down_.end(), p_code);
	if (p_pressed && down == keys_down_.end()) {
		keys_down_.push_back(p_code);
	} else if (!p_pressed && down != keys_down_.end()) {
		keys_down_.erase(down);
	}
	post_event(EVDEV_EV_KEY, p_code, p_pressed ? 1 : 0);
}

void ScriptedEvdevKernel::sync() {
	std::lock_guard<std::mutex> lock(mutex_);
	post_event(EVDEV_EV_SYN, EVDEV_SYN_REPORT, 0);
}

void ScriptedEvdevKernel::set_stick_axes(double p_x, double p_y) {
	const auto value_at = [](const AbsRange &p_range, double p_fraction) {
		const double centre = 0.5 * (static_cast<double>(p_range.minimum) + p_range.maximum);
		const double half = 0.5 * (static_cast<double>(p_range.maximum) - p_range.minimum);
		return static_cast<int32_t>(std::lround(centre + std::clamp(p_fraction, -1.0, 1.0) * half));
	};
	uint16_t codes[2] = { EVDEV_ABS_X, EVDEV_ABS_Y };
	int32_t values[2] = {};
	size_t count = 0;
	{
		std::lock_guard<std::mutex> lock(mutex_);
		if (const AbsRange *wheel = axis(EVDEV_ABS_WHEEL)) {
			codes[0] = EVDEV_ABS_WHEEL;
			values[count++] = value_at(*wheel, p_x);
		} else {
			for (size_t i = 0; i < 2; ++i) {
				if (const AbsRange *range = axis(codes[i])) {
					values[i] = value_at(*range, i == 0 ? p_x : p_y);
					count = i + 1;
				}
			}
		}
	}
	for (size_t i = 0; i < count; ++i) {
		set_axis(codes[i], values[i]);
	}
	sync();
}

void ScriptedEvdevKernel::queue_raw_read(const std::vector<uint8_t> &p_bytes) {
	std::lock_guard<std::mutex> lock(mutex_);
	for (Client &client : clients_) {
		if (client.alive && !p_bytes.empty()) {
			client.queue.push_back(Chunk{ p_bytes, 0, true });
		}
	}
}

void ScriptedEvdevKernel::fail_next_ioctl(uint32_t p_request, int p_error) {
	std::lock_guard<std::mutex> lock(mutex_);
	fail_ioctl_request_ = p_request;
	fail_ioctl_error_ = p_error;
}

void ScriptedEvdevKernel::fail_next_write(int p_error) {
	std::lock_guard<std::mutex> lock(mutex_);
	fail_write_error_ = p_error;
}

void ScriptedEvdevKernel::fail_next_read(int p_error) {
	std::lock_guard<std::mutex> lock(mutex_);
	fail_read_error_ = p_error;
}

void ScriptedEvdevKernel::set_recording(bool p_recording) {
	std::lock_guard<std::mutex> lock(mutex_);
	recording_ = p_recording;
}

std::vector<ScriptedEvdevCall> ScriptedEvdevKernel::calls() const {
	std::lock_guard<std::mutex> lock(mutex_);
	return calls_;
}

void ScriptedEvdevKernel::clear_calls() {
	std::lock_guard<std::mutex> lock(mutex_);
	calls_.clear();
}

ScriptedEvdevCounters ScriptedEvdevKernel::counters() const {
	std::lock_guard<std::mutex> lock(mutex_);
	return counters_;
}

ScriptedRenderedForce render_playing_effects(const std::vector<FfEffectFields> &p_playing, uint16_t p_gain) {
	ScriptedRenderedForce force;
	force.gain = p_gain;
	uint32_t strong = 0;
	uint32_t weak = 0;
	for (const FfEffectFields &effect : p_playing) {
		if (effect.type == EVDEV_FF_RUMBLE) {
			strong += static_cast<uint32_t>(effect.rumble_strong) * p_gain / 0xffff;
			weak += static_cast<uint32_t>(effect.rumble_weak) * p_gain / 0xffff;
			++force.rumbles_playing;
		} else if (effect.type == EVDEV_FF_PERIODIC) {
			force.periodic_magnitude = effect.periodic_magnitude;
			++force.periodic_playing;
		} else if (effect.type == EVDEV_FF_CONSTANT) {
			const double theta = effect.direction / 65536.0 * 2.0 * std::numbers::pi;
			const double fraction = effect.constant_level / 32767.0 * (p_gain / 65535.0);
			force.axis_x += fraction * std::sin(theta);
			force.axis_y += -fraction * std::cos(theta);
			force.direction = effect.direction;
			force.level = effect.constant_level;
			++force.playing;
		}
	}
	force.rumble_strong = static_cast<uint16_t>(std::min<uint32_t>(strong, 0xffff));
	force.rumble_weak = static_cast<uint16_t>(std::min<uint32_t>(weak, 0xffff));
	return force;
}

ScriptedRenderedForce ScriptedEvdevKernel::rendered() const {
	std::lock_guard<std::mutex> lock(mutex_);
	std::vector<FfEffectFields> playing;
	for (const Slot &slot : slots_) {
		if (slot.in_use && slot.playing) {
			playing.push_back(slot.effect);
		}
	}
	return render_playing_effects(playing, gain_);
}

int32_t ScriptedEvdevKernel::effects_in_use() const {
	std::lock_guard<std::mutex> lock(mutex_);
	return static_cast<int32_t>(std::count_if(slots_.begin(), slots_.end(), [](const Slot &s) { return s.in_use; }));
}

int32_t ScriptedEvdevKernel::autocenter() const {
	std::lock_guard<std::mutex> lock(mutex_);
	return autocenter_;
}

int32_t ScriptedEvdevKernel::open_fds() const {
	std::lock_guard<std::mutex> lock(mutex_);
	return static_cast<int32_t>(clients_.size());
}

} // namespace haptics::evdev
