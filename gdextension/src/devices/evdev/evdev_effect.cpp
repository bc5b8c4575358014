#include "devices/evdev/evdev_effect.h"

#include <cerrno>
#include <utility>

namespace haptics::evdev {

EvdevFfFeatures ff_features_from_bits(const uint8_t *p_bits, size_t p_size) {
	EvdevFfFeatures features;
	features.constant = test_bit(p_bits, p_size, EVDEV_FF_CONSTANT);
	features.periodic = test_bit(p_bits, p_size, EVDEV_FF_PERIODIC);
	features.rumble = test_bit(p_bits, p_size, EVDEV_FF_RUMBLE);
	features.gain = test_bit(p_bits, p_size, EVDEV_FF_GAIN);
	features.autocenter = test_bit(p_bits, p_size, EVDEV_FF_AUTOCENTER);
	return features;
}

std::string describe_ff_features(const EvdevFfFeatures &p_features) {
	std::string text;
	const std::pair<bool, const char *> names[] = {
		{ p_features.constant, "constant" },
		{ p_features.periodic, "periodic" },
		{ p_features.rumble, "rumble" },
		{ p_features.gain, "gain" },
		{ p_features.autocenter, "autocenter" },
	};
	for (const auto &[offered, name] : names) {
		if (offered) {
			text += text.empty() ? "" : " ";
			text += name;
		}
	}
	if (text.empty()) {
		text = "no force feedback";
	}
	if (p_features.max_effects > 0) {
		text += ", " + std::to_string(p_features.max_effects) + " effects";
	}
	return text;
}

Status choose_ff_output(const EvdevFfFeatures &p_features, const char *p_path, EvdevOutput &r_output) {
	if (p_features.constant) {
		r_output = EvdevOutput::CONSTANT;
		return Status::success();
	}
	if (p_features.rumble) {
		r_output = EvdevOutput::RUMBLE;
		return Status::success();
	}
	return Status::error(StatusCode::UNSUPPORTED,
			"the kernel driver offers neither constant force nor rumble on this device (%s: no FF_CONSTANT or FF_RUMBLE in "
			"EVIOCGBIT(EV_FF))",
			p_path);
}

Status query_ff_features(EvdevSyscalls &r_sys, int p_fd, const char *p_path, EvdevFfFeatures &r_features) {
	uint8_t bits[EVDEV_FF_BITS_BYTES] = {};
	const int copied = r_sys.ioctl(p_fd, evdev_eviocgbit(EVDEV_EV_FF, sizeof(bits)), bits);
	if (copied < 0) {
		// ENOTTY/EINVAL: the path is not an evdev node at all (a file, a hidraw node).
		return Status::error(copied == -ENODEV ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
				"%s: EVIOCGBIT(EV_FF) failed: %s (%s)%s", p_path, errno_text(copied), errno_name(copied),
				copied == -ENOTTY || copied == -EINVAL ? "; not an evdev node?" : "");
	}
	r_features = ff_features_from_bits(bits, sizeof(bits));
	int max_effects = 0;
	if (r_sys.ioctl(p_fd, EVDEV_EVIOCGEFFECTS, &max_effects) >= 0) {
		r_features.max_effects = max_effects;
	}
	return Status::success();
}

Status require_constant_force(const EvdevFfFeatures &p_features, const char *p_path) {
	if (!p_features.constant) {
		return Status::error(StatusCode::UNSUPPORTED,
				"the kernel driver offers no constant force on this device (%s: no FF_CONSTANT in EVIOCGBIT(EV_FF))", p_path);
	}
	return Status::success();
}

int EvdevConstantForce::write_event(uint16_t p_code, int32_t p_value) {
	encode_input_event(EVDEV_EV_FF, p_code, p_value, event_);
	const int64_t written = sys_->write(fd_, event_.data(), event_.size());
	if (written < 0) {
		return static_cast<int>(written);
	}
	return written == static_cast<int64_t>(event_.size()) ? 0 : -EIO;
}

int EvdevConstantForce::upload(FfConstantEffect &r_effect) {
	encode_constant_effect(r_effect, bytes_);
	const int result = sys_->ioctl(fd_, EVDEV_EVIOCSFF, bytes_.data());
	if (result < 0) {
		return result;
	}
	// The kernel writes the id it chose back into the struct (always the same on update).
	r_effect.id = get_s16(bytes_.data(), FF_EFFECT_ID_OFFSET);
	++uploads_;
	return 0;
}

Status EvdevConstantForce::start(EvdevSyscalls &r_sys, int p_fd, const EvdevFfFeatures &p_features, const char *p_path) {
	stop_and_erase();
	sys_ = &r_sys;
	fd_ = p_fd;
	uploads_ = 0;
	const auto failed = [&](int p_error, const char *p_step) {
		stop_and_erase();
		return Status::error(p_error == -ENODEV ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
				"%s: %s failed: %s (%s)", p_path, p_step, errno_text(p_error), errno_name(p_error));
	};
	int result = 0;
	if (p_features.gain && (result = write_event(EVDEV_FF_GAIN, 0xffff)) < 0) {
		return failed(result, "setting the gain (FF_GAIN)");
	}
	if (p_features.autocenter && (result = write_event(EVDEV_FF_AUTOCENTER, 0)) < 0) {
		return failed(result, "turning autocentre off (FF_AUTOCENTER)");
	}
	FfConstantEffect effect; // id -1, level 0, infinite: nothing felt until the first update.
	if ((result = upload(effect)) < 0) {
		return failed(result, "uploading the constant force (EVIOCSFF)");
	}
	if (effect.id < 0) {
		return failed(-EINVAL, "uploading the constant force (the kernel returned no effect id)");
	}
	effect_ = effect;
	started_ = true;
	if ((result = write_event(static_cast<uint16_t>(effect_.id), 1)) < 0) {
		return failed(result, "playing the constant force");
	}
	return Status::success();
}

int EvdevConstantForce::update(const FfConstantForce &p_force) {
	if (!started_) {
		return -EBADF;
	}
	if (p_force == current()) {
		return 0;
	}
	FfConstantEffect next = effect_;
	next.direction = p_force.direction;
	next.level = p_force.level;
	const int result = upload(next);
	if (result < 0) {
		return result;
	}
	effect_ = next;
	return 0;
}

int EvdevConstantForce::stop_and_erase() {
	if (!started_) {
		return 0;
	}
	// Each step on its own: an unplugged device fails them all, and a zero upload that
	// fails must not keep the effect from being stopped and erased.
	int first_error = update(FfConstantForce{});
	const int stopped = write_event(static_cast<uint16_t>(effect_.id), 0);
	first_error = first_error < 0 ? first_error : stopped;
	const int erased = sys_->ioctl(fd_, EVDEV_EVIOCRMFF,
			reinterpret_cast<void *>(static_cast<intptr_t>(effect_.id)));
	first_error = first_error < 0 ? first_error : erased;
	started_ = false;
	effect_ = FfConstantEffect{};
	return first_error < 0 ? first_error : 0;
}

} // namespace haptics::evdev
