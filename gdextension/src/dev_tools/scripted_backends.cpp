#include "dev_tools/scripted_backends.h"

#include "dev_tools/dualsense/scripted_dualsense_device.h"
#if HAPTICS_EVDEV
#include "dev_tools/evdev/scripted_evdev_device.h"
#endif
#include "dev_tools/falcon/scripted_falcon_device.h"
#include "dev_tools/pid/scripted_pid_device.h"
#include "dev_tools/scripted_device.h"
#include "system/device_factory.h"

#include <atomic>
#include <cstdlib>
#include <string>

namespace haptics {

namespace {

// Each backend's device class over its software model, with the hooks the game drives it by.
struct ScriptedRow {
	std::string_view driver;
	const char *model_name;
	std::unique_ptr<HapticDevice> (*make)(ScriptedModelHooks &r_hooks);
};

std::unique_ptr<HapticDevice> make_scripted_falcon(ScriptedModelHooks &r_hooks) {
	std::shared_ptr<falcon::ScriptedFalcon> model = std::make_shared<falcon::ScriptedFalcon>();
	model->set_device_position(Vec3{});
	r_hooks.set_position = [model](const Vec3 &p_position) { model->set_device_position(p_position); };
	r_hooks.set_plugged = [model](bool p_plugged) { p_plugged ? model->replug() : model->unplug(); };
	return falcon::make_scripted_device(model);
}

// A stick's deflection is its position over its nominal radius (capabilities()).
std::unique_ptr<HapticDevice> make_scripted_dualsense(ScriptedModelHooks &r_hooks) {
	dualsense::ScriptedDualSenseSetup setup = dualsense::make_scripted_device(dualsense::Bus::USB);
	std::shared_ptr<dualsense::ScriptedDualSense> pad = setup.pad;
	const double radius = setup.device->capabilities().limits.workspace_radius_m;
	r_hooks.set_position = [pad, radius](const Vec3 &p_position) {
		pad->set_stick_deflection(p_position.x / radius, p_position.y / radius);
	};
	r_hooks.set_plugged = [pad](bool p_plugged) { p_plugged ? pad->replug() : pad->unplug(); };
	return std::move(setup.device);
}

#if HAPTICS_EVDEV
std::unique_ptr<HapticDevice> make_scripted_evdev(ScriptedModelHooks &r_hooks) {
	std::shared_ptr<evdev::ScriptedEvdevKernel> kernel = std::make_shared<evdev::ScriptedEvdevKernel>();
	std::unique_ptr<HapticDevice> device = evdev::make_scripted_device(kernel);
	const double radius = device->capabilities().limits.workspace_radius_m;
	// The stick's axis frame has +y toward the user: our y up is its -y.
	r_hooks.set_position = [kernel, radius](const Vec3 &p_position) {
		kernel->set_stick_axes(p_position.x / radius, -p_position.y / radius);
	};
	r_hooks.set_plugged = [kernel](bool p_plugged) { kernel->set_plugged(p_plugged); };
	return device;
}
#endif

// An AJ-firmware stick: HID's y grows toward the user, ours up.
std::unique_ptr<HapticDevice> make_scripted_hid_pid(ScriptedModelHooks &r_hooks) {
	std::shared_ptr<pid::ScriptedPidJoystick> stick = std::make_shared<pid::ScriptedPidJoystick>(pid::ScriptedFirmware::AJ);
	std::unique_ptr<HapticDevice> device = pid::make_scripted_device(stick);
	const double radius = device->capabilities().limits.workspace_radius_m;
	r_hooks.set_position = [stick, radius](const Vec3 &p_position) {
		stick->set_stick(p_position.x / radius, -p_position.y / radius);
	};
	r_hooks.set_plugged = [stick](bool p_plugged) { stick->set_plugged(p_plugged); };
	return device;
}

constexpr ScriptedRow SCRIPTED[] = {
	{ DRIVER_FALCON, "Novint Falcon (scripted)", make_scripted_falcon },
	{ DRIVER_DUALSENSE, "Sony DualSense (scripted, USB)", make_scripted_dualsense },
#if HAPTICS_EVDEV
	{ DRIVER_EVDEV, "Force-feedback joystick (scripted, evdev)", make_scripted_evdev },
#endif
	{ DRIVER_HID_PID, "HID PID joystick (scripted, AJ firmware)", make_scripted_hid_pid },
};
constexpr size_t SCRIPTED_COUNT = sizeof(SCRIPTED) / sizeof(SCRIPTED[0]);

// One cable per scripted driver, for the whole process: unplugging survives a reopen.
struct Cable {
	std::atomic<bool> plugged{ true };
};
Cable scripted_cables[SCRIPTED_COUNT];

// The row of a scripted device's id, or null.
const ScriptedRow *find_scripted(const DeviceInfo &p_info, size_t *r_index) {
	for (size_t i = 0; i < SCRIPTED_COUNT; ++i) {
		if (p_info.id == std::string(SCRIPTED_ID_PREFIX) + std::string(SCRIPTED[i].driver)) {
			*r_index = i;
			return &SCRIPTED[i];
		}
	}
	return nullptr;
}

void append_scripted(std::vector<DeviceInfo> &r_devices) {
	if (!scripted_devices_enabled()) {
		return;
	}
	for (const ScriptedRow &row : SCRIPTED) {
		DeviceInfo info;
		info.id = std::string(SCRIPTED_ID_PREFIX) + std::string(row.driver);
		info.backend = BACKEND_SCRIPTED;
		info.path = info.id;
		info.product = row.model_name;
		info.model = row.model_name;
		info.known_haptic = true;
		r_devices.push_back(std::move(info));
	}
}

void probe_scripted(DeviceInfo &r_info) {
	size_t index = 0;
	const ScriptedRow *row = find_scripted(r_info, &index);
	if (row == nullptr) {
		return; // Not one of ours: no driver, as the factory left it.
	}
	r_info.known_haptic = true;
	r_info.driver = row->driver;
	r_info.openable = scripted_cables[index].plugged.load();
	r_info.unavailable_reason = r_info.openable ? "" : "unplugged (scripted cable)";
}

Status open_scripted(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device) {
	size_t index = 0;
	const ScriptedRow *row = find_scripted(p_info, &index);
	if (row == nullptr) {
		return Status::error(StatusCode::UNSUPPORTED, "no scripted model for '%s'", p_info.id.c_str());
	}
	ScriptedModelHooks hooks;
	std::unique_ptr<HapticDevice> inner = row->make(hooks);
	r_device = std::make_unique<ScriptedDevice>(std::move(inner), std::move(hooks), scripted_cables[index].plugged);
	return Status::success();
}

} // namespace

void register_scripted_devices() {
	add_device_source(DeviceSource{ BACKEND_SCRIPTED, append_scripted, probe_scripted, open_scripted });
}

bool scripted_devices_enabled() {
	const char *value = std::getenv(SCRIPTED_DEVICES_VARIABLE);
	return value != nullptr && std::string_view(value) == "1";
}

} // namespace haptics
