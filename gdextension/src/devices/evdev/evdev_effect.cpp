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

Status EvdevConstantForce::start(EvdevSyscalls &r_sys, int p_fd, const EvdevFfFeatures &p_features, const char *p_path,
		const EvdevTakeover &p_takeover) {
	stop_and_erase();
	FfConstantEffect effect; // id -1, level 0: nothing felt until the first update.
	encode_constant_effect(effect, slot_.bytes());
	const Status started = slot_.start(r_sys, p_fd, p_features, p_takeover, "the constant force", p_path);
	effect_ = effect;
	effect_.id = slot_.id();
	return started;
}

int EvdevConstantForce::update(const FfConstantForce &p_force) {
	if (!slot_.started()) {
		return -EBADF;
	}
	if (p_force == current()) {
		return 0;
	}
	FfConstantEffect next = effect_;
	next.direction = p_force.direction;
	next.level = p_force.level;
	encode_constant_effect(next, slot_.bytes());
	const int result = slot_.upload();
	if (result < 0) {
		return result;
	}
	effect_ = next;
	return 0;
}

int EvdevConstantForce::stop_and_erase() {
	if (!slot_.started()) {
		return 0;
	}
	const int zeroed = update(FfConstantForce{});
	effect_ = FfConstantEffect{};
	return slot_.stop_and_erase(zeroed);
}

} // namespace haptics::evdev
