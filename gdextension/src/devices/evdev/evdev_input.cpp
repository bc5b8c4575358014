#include "devices/evdev/evdev_input.h"

#include "devices/evdev/evdev_ff.h"

#include <algorithm>
#include <cerrno>

namespace haptics::evdev {

AbsRange decode_absinfo(const uint8_t *p_bytes) {
	AbsRange range;
	range.value = get_s32(p_bytes, 0);
	range.minimum = get_s32(p_bytes, 4);
	range.maximum = get_s32(p_bytes, 8);
	range.fuzz = get_s32(p_bytes, 12);
	range.flat = get_s32(p_bytes, 16);
	range.resolution = get_s32(p_bytes, 20);
	return range;
}

Status validate_abs_range(const AbsRange &p_range, const char *p_axis, const char *p_path) {
	if (p_range.maximum <= p_range.minimum) {
		return Status::error(StatusCode::OUT_OF_RANGE, "%s: %s range [%d, %d] is empty", p_path, p_axis, p_range.minimum,
				p_range.maximum);
	}
	return Status::success();
}

double normalise_axis(int32_t p_value, const AbsRange &p_range) {
	// In doubles: int32 extremes (-2^31, 2^31 - 1) would overflow an int difference.
	const double minimum = p_range.minimum;
	const double maximum = p_range.maximum;
	const double half = 0.5 * (maximum - minimum);
	if (!(half > 0.0)) {
		return 0.0;
	}
	const double offset = static_cast<double>(p_value) - 0.5 * (maximum + minimum);
	const double flat = std::clamp(static_cast<double>(p_range.flat), 0.0, 0.5 * half);
	const double magnitude = (std::abs(offset) - flat) / (half - flat);
	if (!(magnitude > 0.0)) {
		return 0.0;
	}
	const double clamped = std::min(magnitude, 1.0);
	return offset < 0.0 ? -clamped : clamped;
}

int32_t EvdevButtonMap::bit_of(uint16_t p_code) const {
	for (uint32_t i = 0; i < count; ++i) {
		if (codes[i] == p_code) {
			return static_cast<int32_t>(i);
		}
	}
	return -1;
}

EvdevButtonMap button_map_from_key_bits(const uint8_t *p_bits, size_t p_size) {
	EvdevButtonMap map;
	const auto add_range = [&](uint32_t p_first, uint32_t p_last) {
		for (uint32_t code = p_first; code <= p_last && map.count < EvdevButtonMap::CAPACITY; ++code) {
			if (test_bit(p_bits, p_size, code)) {
				map.codes[map.count++] = static_cast<uint16_t>(code);
			}
		}
	};
	add_range(EVDEV_BTN_JOYSTICK, EVDEV_KEY_MAX);
	add_range(EVDEV_BTN_MISC, EVDEV_BTN_JOYSTICK - 1);
	return map;
}

void EvdevInputDecoder::configure(const EvdevInputLayout &p_layout) {
	layout_ = p_layout;
	committed_ = Frame{ p_layout.x_range.value, p_layout.y_range.value, 0 };
	pending_ = committed_;
	discarding_ = false;
	needs_resync_ = false;
	stats_ = EvdevInputStats{};
}

void EvdevInputDecoder::apply(uint16_t p_type, uint16_t p_code, int32_t p_value) {
	if (p_type == EVDEV_EV_SYN) {
		if (p_code == EVDEV_SYN_REPORT) {
			if (discarding_) {
				discarding_ = false; // This frame was incomplete: the resync replaces it.
			} else {
				committed_ = pending_;
			}
		} else if (p_code == EVDEV_SYN_DROPPED) {
			++stats_.dropped;
			discarding_ = true;
			needs_resync_ = true;
			pending_ = committed_;
		} else {
			++stats_.ignored;
		}
		return;
	}
	if (discarding_) {
		return;
	}
	if (p_type == EVDEV_EV_ABS && p_code == layout_.x_code) {
		pending_.x = p_value;
	} else if (p_type == EVDEV_EV_ABS && layout_.has_y && p_code == layout_.y_code) {
		pending_.y = p_value;
	} else if (const int32_t bit = p_type == EVDEV_EV_KEY ? layout_.buttons.bit_of(p_code) : -1; bit >= 0) {
		const uint32_t mask = 1u << bit;
		// 0 release, 1 press, 2 autorepeat (still pressed); anything else counts as pressed.
		pending_.buttons = p_value != 0 ? pending_.buttons | mask : pending_.buttons & ~mask;
	} else {
		++stats_.ignored;
	}
}

void EvdevInputDecoder::feed(const uint8_t *p_bytes, size_t p_size) {
	const size_t whole = p_size / INPUT_EVENT_SIZE;
	for (size_t i = 0; i < whole; ++i) {
		const InputEvent event = decode_input_event(p_bytes + i * INPUT_EVENT_SIZE);
		++stats_.events;
		apply(event.type, event.code, event.value);
	}
	stats_.partial_bytes += p_size - whole * INPUT_EVENT_SIZE;
}

void EvdevInputDecoder::apply_resync(int32_t p_x, int32_t p_y, uint32_t p_buttons) {
	committed_ = Frame{ p_x, p_y, p_buttons };
	pending_ = committed_;
	needs_resync_ = false;
}

int resync_input(EvdevSyscalls &r_sys, int p_fd, EvdevInputDecoder &r_decoder) {
	const EvdevInputLayout &layout = r_decoder.layout();
	uint8_t absinfo[INPUT_ABSINFO_SIZE] = {};
	int result = r_sys.ioctl(p_fd, evdev_eviocgabs(layout.x_code), absinfo);
	if (result < 0) {
		return result;
	}
	const int32_t x = decode_absinfo(absinfo).value;
	int32_t y = 0;
	if (layout.has_y) {
		result = r_sys.ioctl(p_fd, evdev_eviocgabs(layout.y_code), absinfo);
		if (result < 0) {
			return result;
		}
		y = decode_absinfo(absinfo).value;
	}
	uint8_t keys[EVDEV_KEY_BITS_BYTES] = {};
	result = r_sys.ioctl(p_fd, evdev_eviocgkey(sizeof(keys)), keys);
	if (result < 0) {
		return result;
	}
	uint32_t buttons = 0;
	for (uint32_t i = 0; i < layout.buttons.count; ++i) {
		buttons |= test_bit(keys, sizeof(keys), layout.buttons.codes[i]) ? 1u << i : 0u;
	}
	r_decoder.apply_resync(x, y, buttons);
	return 0;
}

int drain_input_events(EvdevSyscalls &r_sys, int p_fd, EvdevInputDecoder &r_decoder, uint8_t *r_buffer) {
	for (int i = 0; i < INPUT_MAX_READS_PER_DRAIN; ++i) {
		const int64_t count = r_sys.read(p_fd, r_buffer, INPUT_READ_BUFFER_SIZE);
		if (count == -EAGAIN || count == 0) {
			break;
		}
		if (count < 0) {
			return static_cast<int>(count);
		}
		// A transport claiming more than it was given is broken; never read past the buffer.
		const size_t size = std::min(static_cast<size_t>(count), INPUT_READ_BUFFER_SIZE);
		r_decoder.feed(r_buffer, size);
		if (size < INPUT_READ_BUFFER_SIZE) {
			break; // A partial buffer: the queue is empty now.
		}
	}
	return r_decoder.needs_resync() ? resync_input(r_sys, p_fd, r_decoder) : 0;
}

} // namespace haptics::evdev
