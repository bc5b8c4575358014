#include "dev_tools/evdev/scripted_evdev_kernel.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

// The syscall side of the scripted kernel; the script, presets and rendered force are in
// scripted_evdev_script.cpp.

namespace haptics::evdev {

ScriptedEvdevKernel::ScriptedEvdevKernel(ScriptedEvdevScript p_script) :
		script_(std::move(p_script)) {
	reset_device();
}

void ScriptedEvdevKernel::reset_device() {
	slots_.assign(static_cast<size_t>(std::max<int32_t>(script_.max_effects, 0)), Slot{});
	keys_down_.clear();
	gain_ = 0xffff;
	autocenter_ = -1;
}

ScriptedEvdevKernel::Client *ScriptedEvdevKernel::find_client(int p_fd) {
	for (Client &client : clients_) {
		if (client.fd == p_fd) {
			return &client;
		}
	}
	return nullptr;
}

void ScriptedEvdevKernel::record(ScriptedEvdevCall::Kind p_kind, int p_fd, uint32_t p_request, const void *p_bytes,
		size_t p_size, int64_t p_result) {
	if (!recording_) {
		return;
	}
	ScriptedEvdevCall call;
	call.kind = p_kind;
	call.fd = p_fd;
	call.request = p_request;
	if (p_bytes && p_size > 0) {
		const uint8_t *bytes = static_cast<const uint8_t *>(p_bytes);
		call.bytes.assign(bytes, bytes + p_size);
	}
	call.result = p_result;
	calls_.push_back(std::move(call));
}

int ScriptedEvdevKernel::open_device(const char *p_path) {
	std::lock_guard<std::mutex> lock(mutex_);
	int result;
	if (!p_path || !plugged_ || script_.path != p_path) {
		result = -ENOENT; // Unplugged: udev removed the node.
	} else if (script_.open_error != 0) {
		result = -script_.open_error;
	} else {
		result = next_fd_++;
		clients_.push_back(Client{ result, true, {}, 0 });
	}
	record(ScriptedEvdevCall::Kind::OPEN, -1, 0, p_path, p_path ? std::strlen(p_path) : 0, result);
	return result;
}

int ScriptedEvdevKernel::close(int p_fd) {
	std::lock_guard<std::mutex> lock(mutex_);
	const auto it = std::find_if(clients_.begin(), clients_.end(), [&](const Client &c) { return c.fd == p_fd; });
	int result = -EBADF;
	if (it != clients_.end()) {
		if (it->alive) { // input_ff_flush: the file's effects go with it.
			for (Slot &slot : slots_) {
				if (slot.in_use && slot.owner_fd == p_fd) {
					slot = Slot{};
				}
			}
		}
		clients_.erase(it);
		result = 0;
	}
	record(ScriptedEvdevCall::Kind::CLOSE, p_fd, 0, nullptr, 0, result);
	return result;
}

int ScriptedEvdevKernel::ioctl(int p_fd, uint32_t p_request, void *p_arg) {
	std::lock_guard<std::mutex> lock(mutex_);
	++counters_.ioctls;
	// What the caller sent, captured before the kernel writes back into it (EVIOCSFF's id
	// is recorded as sent, -1 for a new effect); EVIOCRMFF's id comes by value.
	uint8_t sent[FF_EFFECT_SIZE];
	size_t sent_size = 0;
	if (p_request == EVDEV_EVIOCSFF && p_arg) {
		std::memcpy(sent, p_arg, FF_EFFECT_SIZE);
		sent_size = FF_EFFECT_SIZE;
	} else if (p_request == EVDEV_EVIOCRMFF) {
		put_s32(sent, 0, static_cast<int32_t>(reinterpret_cast<intptr_t>(p_arg)));
		sent_size = 4;
	}
	Client *client = find_client(p_fd);
	size_t answered = 0; // Bytes the kernel wrote into the argument.
	int result;
	if (!client) {
		result = -EBADF;
	} else if (!client->alive) {
		result = -ENODEV;
	} else if (fail_ioctl_error_ != 0 && (fail_ioctl_request_ == 0 || fail_ioctl_request_ == p_request)) {
		result = -fail_ioctl_error_;
		fail_ioctl_error_ = 0;
	} else if (!p_arg && p_request != EVDEV_EVIOCRMFF) {
		result = -EFAULT;
	} else {
		result = ioctl_locked(*client, p_request, p_arg, answered);
	}
	const void *bytes = sent_size > 0 ? static_cast<const void *>(sent) : p_arg;
	const size_t size = sent_size > 0 ? sent_size : (result >= 0 ? answered : 0);
	counters_.ioctl_bytes += size;
	record(ScriptedEvdevCall::Kind::IOCTL, p_fd, p_request, bytes, size, result);
	return result;
}

int ScriptedEvdevKernel::copy_bits(uint32_t p_event_type, uint8_t *r_out, size_t p_size) const {
	uint8_t bits[EVDEV_KEY_BITS_BYTES] = {}; // The largest map we answer.
	size_t kernel_size = 0;
	switch (p_event_type) {
		case 0:
			kernel_size = EVDEV_EV_BITS_BYTES;
			set_bit(bits, kernel_size, EVDEV_EV_SYN);
			if (!script_.key_codes.empty()) {
				set_bit(bits, kernel_size, EVDEV_EV_KEY);
			}
			if (!script_.axes.empty()) {
				set_bit(bits, kernel_size, EVDEV_EV_ABS);
			}
			if (!script_.ff_codes.empty()) {
				set_bit(bits, kernel_size, EVDEV_EV_FF);
			}
			break;
		case EVDEV_EV_KEY:
			kernel_size = EVDEV_KEY_BITS_BYTES;
			for (uint16_t code : script_.key_codes) {
				set_bit(bits, kernel_size, code);
			}
			break;
		case EVDEV_EV_ABS:
			kernel_size = EVDEV_ABS_BITS_BYTES;
			for (const ScriptedAbsAxis &axis : script_.axes) {
				set_bit(bits, kernel_size, axis.code);
			}
			break;
		case EVDEV_EV_FF:
			kernel_size = EVDEV_FF_BITS_BYTES;
			for (uint16_t code = 0; code <= EVDEV_FF_MAX; ++code) {
				if (advertises(code)) {
					set_bit(bits, kernel_size, code);
				}
			}
			break;
		default:
			kernel_size = EVDEV_EV_BITS_BYTES; // Types the device lacks: an empty map.
			break;
	}
	const size_t copied = std::min(p_size, kernel_size);
	std::memcpy(r_out, bits, copied);
	return static_cast<int>(copied);
}

int ScriptedEvdevKernel::ioctl_locked(Client &r_client, uint32_t p_request, void *p_arg, size_t &r_answered) {
	uint8_t *arg = static_cast<uint8_t *>(p_arg);
	const uint32_t size = ioc_size(p_request);
	const uint32_t nr = ioc_nr(p_request);
	if (ioc_type(p_request) != EVDEV_IOC_TYPE) {
		return -EINVAL;
	}
	if (p_request == EVDEV_EVIOCSFF) {
		return upload(r_client, arg);
	}
	if (p_request == EVDEV_EVIOCRMFF) {
		return erase(r_client, static_cast<int>(reinterpret_cast<intptr_t>(p_arg)));
	}
	if (p_request == EVDEV_EVIOCGEFFECTS) {
		put_s32(arg, 0, script_.max_effects);
		r_answered = 4;
		return 0;
	}
	if (p_request == EVDEV_EVIOCGID) {
		put_u16(arg, 0, script_.bustype);
		put_u16(arg, 2, script_.vendor);
		put_u16(arg, 4, script_.product);
		put_u16(arg, 6, script_.version);
		r_answered = INPUT_ID_SIZE;
		return 0;
	}
	if (ioc_dir(p_request) != IOC_READ) {
		return -EINVAL;
	}
	if (nr == EVIOCGNAME_NR) {
		if (script_.name.empty()) {
			return -ENOENT;
		}
		const size_t copied = std::min<size_t>(size, script_.name.size() + 1);
		std::memcpy(arg, script_.name.c_str(), copied);
		r_answered = copied;
		return static_cast<int>(copied);
	}
	if (nr == EVIOCGKEY_NR) {
		uint8_t keys[EVDEV_KEY_BITS_BYTES] = {};
		for (uint16_t code : keys_down_) {
			set_bit(keys, sizeof(keys), code);
		}
		const size_t copied = std::min<size_t>(size, sizeof(keys));
		std::memcpy(arg, keys, copied);
		r_answered = copied;
		return static_cast<int>(copied);
	}
	if (nr >= EVIOCGBIT_NR && nr <= EVIOCGBIT_NR + EVDEV_EV_MAX) {
		const int copied = copy_bits(nr - EVIOCGBIT_NR, arg, size);
		r_answered = static_cast<size_t>(copied);
		return copied;
	}
	if (nr >= EVIOCGABS_NR && nr <= EVIOCGABS_NR + EVDEV_ABS_MAX) {
		// The kernel answers for any axis (zeros for one the device lacks).
		const AbsRange *range = axis(static_cast<uint16_t>(nr - EVIOCGABS_NR));
		const AbsRange value = range ? *range : AbsRange{};
		uint8_t info[INPUT_ABSINFO_SIZE];
		const int32_t fields[6] = { value.value, value.minimum, value.maximum, value.fuzz, value.flat, value.resolution };
		for (size_t i = 0; i < 6; ++i) {
			put_s32(info, 4 * i, fields[i]);
		}
		const size_t copied = std::min<size_t>(size, sizeof(info));
		std::memcpy(arg, info, copied);
		r_answered = copied;
		return 0;
	}
	return -EINVAL;
}

bool ScriptedEvdevKernel::advertises(uint16_t p_code) const {
	// input_ff_create: "we can emulate RUMBLE with periodic effects".
	return has(script_.ff_codes, p_code) || (p_code == EVDEV_FF_RUMBLE && has(script_.ff_codes, EVDEV_FF_PERIODIC));
}

int ScriptedEvdevKernel::upload(Client &r_client, uint8_t *r_effect) {
	FfEffectBytes bytes;
	std::memcpy(bytes.data(), r_effect, bytes.size());
	FfEffectFields effect = decode_ff_effect(bytes);
	// input_ff_upload's checks, against what the device advertises; then compat_effect for a
	// rumble the driver itself does not take: a 50 ms sine of 2/3 strong + 1/3 weak (halved).
	if (effect.type < EVDEV_FF_RUMBLE || effect.type > EVDEV_FF_RAMP || !advertises(effect.type)) {
		return -EINVAL;
	}
	if (effect.type == EVDEV_FF_PERIODIC &&
			(effect.periodic_waveform < EVDEV_FF_SQUARE || effect.periodic_waveform > 0x5d || !advertises(effect.periodic_waveform))) {
		return -EINVAL;
	}
	if (!has(script_.ff_codes, effect.type)) {
		const int magnitude = effect.rumble_strong / 3 + effect.rumble_weak / 6;
		effect.type = EVDEV_FF_PERIODIC;
		effect.periodic_waveform = EVDEV_FF_SINE;
		effect.periodic_period_ms = 50;
		effect.periodic_magnitude = static_cast<int16_t>(magnitude);
		effect.rumble_strong = 0;
		effect.rumble_weak = 0;
	}
	int id = effect.id;
	if (id == -1) {
		const auto free_slot = std::find_if(slots_.begin(), slots_.end(), [](const Slot &s) { return !s.in_use; });
		if (free_slot == slots_.end()) {
			return -ENOSPC;
		}
		id = static_cast<int>(free_slot - slots_.begin());
		put_u16(r_effect, FF_EFFECT_ID_OFFSET, static_cast<uint16_t>(id)); // Back to the caller.
	} else if (id < 0 || id >= static_cast<int>(slots_.size()) || !slots_[static_cast<size_t>(id)].in_use) {
		return -EINVAL;
	} else if (slots_[static_cast<size_t>(id)].owner_fd != r_client.fd) {
		return -EACCES;
	} else if (const FfEffectFields &old = slots_[static_cast<size_t>(id)].effect;
			   old.type != effect.type || (effect.type == EVDEV_FF_PERIODIC && old.periodic_waveform != effect.periodic_waveform)) {
		return -EINVAL; // check_effects_compatible.
	}
	Slot &slot = slots_[static_cast<size_t>(id)];
	slot.in_use = true;
	slot.owner_fd = r_client.fd;
	slot.effect = effect;
	slot.effect.id = static_cast<int16_t>(id);
	++counters_.uploads;
	return 0;
}

int ScriptedEvdevKernel::erase(Client &r_client, int p_id) {
	if (p_id < 0 || p_id >= static_cast<int>(slots_.size()) || !slots_[static_cast<size_t>(p_id)].in_use) {
		return -EINVAL;
	}
	if (slots_[static_cast<size_t>(p_id)].owner_fd != r_client.fd) {
		return -EACCES;
	}
	slots_[static_cast<size_t>(p_id)] = Slot{};
	return 0;
}

void ScriptedEvdevKernel::handle_event(const InputEvent &p_event) {
	// input_ff_event: out-of-range values and effects not in use are ignored, not errors;
	// negative values never reach it (input_get_disposition).
	if (p_event.type != EVDEV_EV_FF || p_event.value < 0) {
		return;
	}
	if (p_event.code == EVDEV_FF_GAIN) {
		if (has(script_.ff_codes, EVDEV_FF_GAIN) && p_event.value <= 0xffff) {
			gain_ = static_cast<uint16_t>(p_event.value);
		}
	} else if (p_event.code == EVDEV_FF_AUTOCENTER) {
		if (has(script_.ff_codes, EVDEV_FF_AUTOCENTER) && p_event.value <= 0xffff) {
			autocenter_ = p_event.value;
		}
	} else if (p_event.code < slots_.size() && slots_[p_event.code].in_use) {
		slots_[p_event.code].playing = p_event.value > 0;
	}
}

int64_t ScriptedEvdevKernel::write(int p_fd, const void *p_bytes, size_t p_size) {
	std::lock_guard<std::mutex> lock(mutex_);
	++counters_.writes;
	Client *client = find_client(p_fd);
	int64_t result = 0;
	if (!client) {
		result = -EBADF;
	} else if (!client->alive) {
		result = -ENODEV;
	} else if (fail_write_error_ != 0) {
		result = -fail_write_error_;
		fail_write_error_ = 0;
	} else if (p_size != 0 && p_size < INPUT_EVENT_SIZE) {
		result = -EINVAL;
	} else {
		const uint8_t *bytes = static_cast<const uint8_t *>(p_bytes);
		size_t offset = 0;
		for (; offset + INPUT_EVENT_SIZE <= p_size; offset += INPUT_EVENT_SIZE) {
			handle_event(decode_input_event(bytes + offset));
		}
		result = static_cast<int64_t>(offset);
	}
	if (result > 0) {
		counters_.write_bytes += static_cast<uint64_t>(result);
	}
	record(ScriptedEvdevCall::Kind::WRITE, p_fd, 0, p_bytes, result > 0 ? static_cast<size_t>(result) : 0, result);
	return result;
}

int64_t ScriptedEvdevKernel::read(int p_fd, void *r_bytes, size_t p_capacity) {
	std::lock_guard<std::mutex> lock(mutex_);
	++counters_.reads;
	Client *client = find_client(p_fd);
	int64_t result = 0;
	uint8_t *out = static_cast<uint8_t *>(r_bytes);
	if (!client) {
		result = -EBADF;
	} else if (!client->alive) {
		result = -ENODEV;
	} else if (fail_read_error_ != 0) {
		result = -fail_read_error_;
		fail_read_error_ = 0;
	} else if (p_capacity < INPUT_EVENT_SIZE) {
		result = -EINVAL;
	} else if (client->queue.empty()) {
		result = -EAGAIN;
	} else if (client->queue.front().raw) {
		Chunk &chunk = client->queue.front();
		const size_t count = std::min(p_capacity, chunk.bytes.size() - chunk.offset);
		std::memcpy(out, chunk.bytes.data() + chunk.offset, count);
		chunk.offset += count;
		if (chunk.offset == chunk.bytes.size()) {
			client->queue.pop_front();
		}
		result = static_cast<int64_t>(count);
	} else {
		size_t count = 0;
		while (!client->queue.empty() && !client->queue.front().raw && count + INPUT_EVENT_SIZE <= p_capacity) {
			std::memcpy(out + count, client->queue.front().bytes.data(), INPUT_EVENT_SIZE);
			count += INPUT_EVENT_SIZE;
			client->queue.pop_front();
			--client->queued_events;
		}
		result = static_cast<int64_t>(count);
	}
	if (result > 0) {
		counters_.read_bytes += static_cast<uint64_t>(result);
	}
	record(ScriptedEvdevCall::Kind::READ, p_fd, 0, r_bytes, result > 0 ? static_cast<size_t>(result) : 0, result);
	return result;
}

} // namespace haptics::evdev
