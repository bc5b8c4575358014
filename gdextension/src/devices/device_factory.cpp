#include "devices/device_factory.h"

#include "devices/dualsense/dualsense_backend.h"
#include "devices/evdev/evdev_backend.h"
#include "devices/evdev/evdev_enumeration.h"
#include "devices/falcon/falcon_backend.h"
#include "devices/openhaptics/openhaptics_backend.h"
#include "devices/pid/pid_backend.h"
#include "devices/scripted_device.h"

#include <atomic>
#include <cstdlib>
#include <string_view>

namespace haptics {

namespace {

struct BackendRow {
	std::string_view driver;
	DeviceAvailability (*probe)(const DeviceInfo &p_info);
	Status (*open)(const DeviceInfo &p_info, const DeviceOpenOptions &p_options, std::unique_ptr<HapticDevice> &r_device);
};

DeviceAvailability probe_simulated(const DeviceInfo &p_info) {
	DeviceAvailability availability;
	availability.handled = p_info.backend == BACKEND_SIMULATED;
	availability.openable = availability.handled;
	return availability;
}

Status open_falcon(const DeviceInfo &p_info, const DeviceOpenOptions &p_options, std::unique_ptr<HapticDevice> &r_device) {
	return falcon::open_device(p_info, p_options.falcon_firmware_path, r_device);
}

// Scripted devices: each backend's device class over its software model (scripted_device.h).
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

Status open_evdev(const DeviceInfo &p_info, const DeviceOpenOptions &, std::unique_ptr<HapticDevice> &r_device) {
	return evdev::open_device(p_info, r_device);
}

Status open_hid_pid(const DeviceInfo &p_info, const DeviceOpenOptions &, std::unique_ptr<HapticDevice> &r_device) {
	return pid::open_device(p_info, r_device);
}

Status open_openhaptics(const DeviceInfo &p_info, const DeviceOpenOptions &, std::unique_ptr<HapticDevice> &r_device) {
	return openhaptics::open_device(p_info, r_device);
}

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

Status open_dualsense(const DeviceInfo &p_info, const DeviceOpenOptions &, std::unique_ptr<HapticDevice> &r_device) {
	return dualsense::open_device(p_info, r_device);
}

DeviceAvailability probe_scripted(const DeviceInfo &p_info);

// The first row whose probe handles a device drives it; order matters only where two
// backends could claim one device.
constexpr BackendRow BACKENDS[] = {
	{ DRIVER_SIMULATED, probe_simulated, nullptr },
	{ "scripted", probe_scripted, nullptr }, // Opened through SCRIPTED below.
	{ DRIVER_FALCON, falcon::probe, open_falcon },
	{ DRIVER_DUALSENSE, dualsense::probe, open_dualsense },
	// After the DualSense: any other hidapi device with PID reports. When the kernel's PID
	// driver is bound it says so and the evdev row below drives the same stick.
	{ DRIVER_HID_PID, pid::probe, open_hid_pid },
	{ DRIVER_EVDEV, evdev::probe, open_evdev },
	{ DRIVER_OPENHAPTICS, openhaptics::probe, open_openhaptics },
};

constexpr ScriptedRow SCRIPTED[] = {
	{ DRIVER_FALCON, "Novint Falcon (scripted)", make_scripted_falcon },
	{ DRIVER_DUALSENSE, "Sony DualSense (scripted, USB)", make_scripted_dualsense },
	{ DRIVER_EVDEV, "Force-feedback joystick (scripted, evdev)", make_scripted_evdev },
	{ DRIVER_HID_PID, "HID PID joystick (scripted, AJ firmware)", make_scripted_hid_pid },
};
constexpr size_t SCRIPTED_COUNT = sizeof(SCRIPTED) / sizeof(SCRIPTED[0]);

// One cable per scripted driver, for the whole process: unplugging survives a reopen.
struct Cable {
	std::atomic<bool> plugged{ true };
};
Cable scripted_cables[SCRIPTED_COUNT];

const ScriptedRow *find_scripted(const DeviceInfo &p_info, size_t *r_index = nullptr) {
	if (p_info.backend != BACKEND_SCRIPTED) {
		return nullptr;
	}
	for (size_t i = 0; i < SCRIPTED_COUNT; ++i) {
		if (p_info.id == std::string(SCRIPTED_ID_PREFIX) + std::string(SCRIPTED[i].driver)) {
			if (r_index) {
				*r_index = i;
			}
			return &SCRIPTED[i];
		}
	}
	return nullptr;
}

DeviceAvailability probe_scripted(const DeviceInfo &p_info) {
	DeviceAvailability availability;
	size_t index = 0;
	availability.handled = find_scripted(p_info, &index) != nullptr;
	availability.openable = availability.handled && scripted_cables[index].plugged.load();
	availability.reason = availability.openable ? "" : "unplugged (scripted cable)";
	return availability;
}

void append_scripted_devices(std::vector<DeviceInfo> &r_devices) {
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

} // namespace

bool scripted_devices_enabled() {
	const char *value = std::getenv(SCRIPTED_DEVICES_VARIABLE);
	return value != nullptr && std::string_view(value) == "1";
}

void probe_devices(std::vector<DeviceInfo> &r_devices) {
	for (DeviceInfo &info : r_devices) {
		info.driver.clear();
		info.openable = false;
		info.unavailable_reason = "no force-feedback driver for this device";
		for (const BackendRow &backend : BACKENDS) {
			const DeviceAvailability availability = backend.probe(info);
			if (availability.handled) {
				// A driver found force feedback the catalog could not see (AJ sticks
				// report a joystick top-level collection; evdev nodes have no catalog row).
				info.known_haptic = true;
				info.driver = backend.driver;
				info.openable = availability.openable;
				info.unavailable_reason = availability.openable ? std::string() : availability.reason;
				break;
			}
		}
	}
}

DeviceList list_all_devices() {
	DeviceList list = list_devices();
	// The kernel's force-feedback drivers (hid-pidff, wheel drivers) own most FFB devices
	// and expose them here, not on hidraw.
	evdev::enumerate_evdev_devices(list.devices, list.warnings);
	// HD finds its device by configuration name, not on a bus: one entry when the runtime
	// loads, or when the player pointed at one that does not (to say why).
	const DeviceInfo openhaptics_entry = openhaptics::make_default_device_info();
	if (openhaptics_entry.openable || std::getenv(openhaptics::HD_LIBRARY_ENV) != nullptr) {
		list.devices.push_back(openhaptics_entry);
	}
	if (scripted_devices_enabled()) {
		append_scripted_devices(list.devices);
	}
	probe_devices(list.devices);
	for (DeviceInfo &info : list.devices) {
		if (info.backend == BACKEND_SCRIPTED) {
			info.driver = info.id.substr(SCRIPTED_ID_PREFIX.size());
		}
	}
	return list;
}

Status open_listed_device(const DeviceInfo &p_info, const DeviceOpenOptions &p_options,
		std::unique_ptr<HapticDevice> &r_device) {
	size_t index = 0;
	if (const ScriptedRow *row = find_scripted(p_info, &index)) {
		ScriptedModelHooks hooks;
		std::unique_ptr<HapticDevice> inner = row->make(hooks);
		r_device = std::make_unique<ScriptedDevice>(std::move(inner), std::move(hooks), scripted_cables[index].plugged);
		return Status::success();
	}
	for (const BackendRow &backend : BACKENDS) {
		if (backend.open == nullptr || !backend.probe(p_info).handled) {
			continue;
		}
		return backend.open(p_info, p_options, r_device);
	}
	return Status::error(StatusCode::UNSUPPORTED, "no force-feedback driver for '%s' (%s)", p_info.id.c_str(),
			p_info.model.empty() ? p_info.product.c_str() : p_info.model.c_str());
}

} // namespace haptics
