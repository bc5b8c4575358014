#include "dev_tools/scripted_device.h"

#include <cmath>

namespace haptics {

ScriptedDevice::ScriptedDevice(std::unique_ptr<HapticDevice> p_inner, ScriptedModelHooks p_hooks,
		std::atomic<bool> &r_cable) :
		inner_(std::move(p_inner)), hooks_(std::move(p_hooks)), cable_(r_cable) {
	if (hooks_.set_plugged) {
		hooks_.set_plugged(cable_.load(std::memory_order_acquire));
	}
}

ScriptedDevice::~ScriptedDevice() {
	inner_->close();
}

Status ScriptedDevice::open() {
	if (!cable_.load(std::memory_order_acquire)) {
		return Status::error(StatusCode::DEVICE_DISCONNECTED, "cannot open '%s': its (scripted) cable is unplugged",
				inner_->name());
	}
	return inner_->open();
}

Status ScriptedDevice::set_hand_target(const Vec3 &p_target_m) {
	if (!std::isfinite(p_target_m.x) || !std::isfinite(p_target_m.y) || !std::isfinite(p_target_m.z)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "hand_target: not finite (%g, %g, %g)", p_target_m.x,
				p_target_m.y, p_target_m.z);
	}
	if (!hooks_.set_position) {
		return Status::error(StatusCode::UNSUPPORTED, "device '%s' has no scripted position", inner_->name());
	}
	hooks_.set_position(p_target_m);
	return Status::success();
}

void ScriptedDevice::set_plugged(bool p_plugged) {
	cable_.store(p_plugged, std::memory_order_release);
	if (hooks_.set_plugged) {
		hooks_.set_plugged(p_plugged);
	}
}

} // namespace haptics
