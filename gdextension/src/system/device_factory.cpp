#include "system/device_factory.h"

#include "devices/dualsense/dualsense_backend.h"
#include "devices/falcon/falcon_backend.h"
#include "devices/openhaptics/openhaptics_backend.h"
#include "devices/pid/pid_backend.h"
#if HAPTICS_SDL3
#include "devices/sdl/sdl_backend.h"
#endif
#include "system/platform_backends.h"

#include <cstdlib>
#include <string_view>

namespace haptics {

namespace {

DeviceAvailability probe_simulated(const DeviceInfo &p_info) {
	DeviceAvailability availability;
	availability.handled = p_info.backend == BACKEND_SIMULATED;
	availability.openable = availability.handled;
	return availability;
}

Status open_falcon(const DeviceInfo &p_info, const DeviceOpenOptions &p_options, std::unique_ptr<HapticDevice> &r_device) {
	return falcon::open_device(p_info, p_options.falcon_firmware_path, r_device);
}

Status open_hid_pid(const DeviceInfo &p_info, const DeviceOpenOptions &, std::unique_ptr<HapticDevice> &r_device) {
	return pid::open_device(p_info, r_device);
}

Status open_openhaptics(const DeviceInfo &p_info, const DeviceOpenOptions &, std::unique_ptr<HapticDevice> &r_device) {
	return openhaptics::open_device(p_info, r_device);
}

Status open_dualsense(const DeviceInfo &p_info, const DeviceOpenOptions &, std::unique_ptr<HapticDevice> &r_device) {
	return dualsense::open_device(p_info, r_device);
}

#if HAPTICS_SDL3
// SDL takes the gain itself when it opens a haptic (sdl_device.h): only the spring is asked.
Status open_sdl(const DeviceInfo &p_info, const DeviceOpenOptions &p_options, std::unique_ptr<HapticDevice> &r_device) {
	return sdl::open_device(p_info, !p_options.spring_off, r_device);
}
#endif

// The first row whose probe handles a device drives it; order matters only where two
// backends could claim one device.
constexpr BackendRow BACKENDS[] = {
	{ DRIVER_SIMULATED, probe_simulated, nullptr },
	{ DRIVER_FALCON, falcon::probe, open_falcon },
	{ DRIVER_DUALSENSE, dualsense::probe, open_dualsense },
	// After the DualSense: any other hidapi device with PID reports. When the kernel's PID
	// driver is bound it says so, and a platform row (platform_backends.h) drives the stick.
	{ DRIVER_HID_PID, pid::probe, open_hid_pid },
	{ DRIVER_OPENHAPTICS, openhaptics::probe, open_openhaptics },
#if HAPTICS_SDL3
	// Only SDL's own entries (backend "sdl"); which backend wins a device both reach:
	// devices/sdl/sdl_backend.h.
	{ DRIVER_SDL, sdl::probe, open_sdl },
#endif
};

// The first row, common then this platform's, for which p_matches is true; null if none.
template <typename Matches>
const BackendRow *find_backend(Matches p_matches) {
	for (const BackendRow &backend : BACKENDS) {
		if (p_matches(backend)) {
			return &backend;
		}
	}
	for (const BackendRow &backend : platform_backends()) {
		if (p_matches(backend)) {
			return &backend;
		}
	}
	return nullptr;
}

// Added at initialisation, before any listing, and only read afterwards: no lock.
std::vector<DeviceSource> &sources() {
	static std::vector<DeviceSource> added;
	return added;
}

const DeviceSource *source_of(const DeviceInfo &p_info) {
	for (const DeviceSource &source : sources()) {
		if (p_info.backend == source.backend) {
			return &source;
		}
	}
	return nullptr;
}

} // namespace

void add_device_source(const DeviceSource &p_source) {
	for (const DeviceSource &source : sources()) {
		if (source.backend == p_source.backend) {
			return;
		}
	}
	sources().push_back(p_source);
}

std::span<const DeviceSource> device_sources() {
	return sources();
}

void probe_devices(std::vector<DeviceInfo> &r_devices) {
	for (DeviceInfo &info : r_devices) {
		info.driver.clear();
		info.openable = false;
		info.unavailable_reason = "no force-feedback driver for this device";
		if (const DeviceSource *source = source_of(info)) {
			source->probe(info);
			continue;
		}
		DeviceAvailability availability;
		const BackendRow *backend = find_backend([&](const BackendRow &p_row) {
			availability = p_row.probe(info);
			return availability.handled;
		});
		if (backend != nullptr) {
			// A driver found force feedback the catalog could not see (AJ sticks report a
			// joystick top-level collection; evdev nodes have no catalog row).
			info.known_haptic = true;
			info.driver = backend->driver;
			info.openable = availability.openable;
			info.unavailable_reason = availability.openable ? std::string() : availability.reason;
		}
	}
}

DeviceList list_all_devices() {
	DeviceList list = list_devices();
	append_platform_devices(list);
	// HD finds its device by configuration name, not on a bus: one entry when the runtime
	// loads, or when the player pointed at one that does not (to say why).
	const DeviceInfo openhaptics_entry = openhaptics::make_default_device_info();
	if (openhaptics_entry.openable || std::getenv(openhaptics::HD_LIBRARY_ENV) != nullptr) {
		list.devices.push_back(openhaptics_entry);
	}
	for (const DeviceSource &source : sources()) {
		source.append(list.devices);
	}
	probe_devices(list.devices);
#if HAPTICS_SDL3
	// After the others' verdicts: a device a specialised backend can open is theirs, and SDL
	// does not even open it (devices/sdl/sdl_backend.h). SDL's entries come with their verdicts.
	std::vector<DeviceInfo> sdl_devices;
	sdl::append_sdl_devices(list.devices, sdl_devices, list.warnings);
	list.devices.insert(list.devices.end(), sdl_devices.begin(), sdl_devices.end());
#endif
	return list;
}

Status open_listed_device(const DeviceInfo &p_info, const DeviceOpenOptions &p_options,
		std::unique_ptr<HapticDevice> &r_device) {
	if (const DeviceSource *source = source_of(p_info)) {
		return source->open(p_info, r_device);
	}
	const BackendRow *backend = find_backend(
			[&](const BackendRow &p_row) { return p_row.open != nullptr && p_row.probe(p_info).handled; });
	if (backend != nullptr) {
		return backend->open(p_info, p_options, r_device);
	}
	return Status::error(StatusCode::UNSUPPORTED, "no force-feedback driver for '%s' (%s)", p_info.id.c_str(),
			p_info.model.empty() ? p_info.product.c_str() : p_info.model.c_str());
}

} // namespace haptics
