#include "devices/sdl/sdl_backend.h"

#include <cstdlib>
#include <cstring>

namespace haptics::sdl {

namespace {

constexpr char DRIVEN_BY_EVDEV[] = "driven by the evdev backend here: SDL's Linux haptics are the same kernel event "
								   "node (choose its evdev: entry, or set HAPTICS_SDL_ON_LINUX=1 to use SDL)";

DeviceAvailability verdict(const SdlHapticEntry &p_entry, bool p_drives) {
	DeviceAvailability availability;
	availability.handled = true;
	if (!p_drives) {
		availability.reason = DRIVEN_BY_EVDEV;
		return availability;
	}
	if (!p_entry.claimed_by.empty()) {
		availability.reason = p_entry.claimed_by;
		return availability;
	}
	if (!p_entry.features_read) {
		availability.reason = "SDL cannot open it: " + p_entry.error;
		return availability;
	}
	if (p_entry.kind == SdlEntryKind::JOYSTICK) {
		availability.openable = p_entry.rumble;
		availability.reason = p_entry.rumble ? std::string() : "SDL offers neither force feedback nor rumble on this joystick";
		return availability;
	}
	SdlOutput output = SdlOutput::CONSTANT;
	const Status chosen = choose_sdl_output(p_entry.features, describe_sdl_features(p_entry), output);
	availability.openable = chosen.ok();
	availability.reason = chosen.ok() ? std::string() : chosen.message();
	return availability;
}

// The entries that win a device they can open over SDL (sdl_backend.h): the specialised
// backends' on a bus, where the USB ids are the device's own (the development tools' scripted
// models carry the ids of what they model, and claim nothing).
bool wins_over_sdl(const DeviceInfo &p_info) {
	const bool bus = p_info.backend == BACKEND_HIDAPI || p_info.backend == BACKEND_LIBUSB;
	const bool specialised = p_info.driver == DRIVER_HID_PID || p_info.driver == DRIVER_DUALSENSE || p_info.driver == DRIVER_FALCON;
	return bus && specialised && p_info.openable && p_info.vendor_id != 0;
}

std::string key_of(const DeviceInfo &p_info) {
	return p_info.path;
}

} // namespace

bool sdl_drives_here() {
#ifdef __linux__
	const char *value = std::getenv(SDL_ON_LINUX_ENV);
	return value != nullptr && std::strcmp(value, "1") == 0;
#else
	return true;
#endif
}

bool sdl_lists_joysticks_here() {
#ifdef _WIN32
	return true;
#else
	return false;
#endif
}

std::vector<SdlClaim> sdl_claims(std::span<const DeviceInfo> p_others) {
	std::vector<SdlClaim> claims;
	for (const DeviceInfo &other : p_others) {
		if (!wins_over_sdl(other)) {
			continue;
		}
		SdlClaim claim;
		claim.vendor_id = other.vendor_id;
		claim.product_id = other.product_id;
		claim.reason = "driven by the " + other.driver + " backend here: choose its entry (" + other.id +
				"), which wins a device both reach";
		claims.push_back(claim);
	}
	return claims;
}

DeviceInfo sdl_device_info(const SdlHapticEntry &p_entry, bool p_drives) {
	DeviceInfo info;
	info.id = std::string(SDL_ID_PREFIX) + p_entry.key;
	info.backend = BACKEND_SDL;
	info.driver = DRIVER_SDL;
	info.path = p_entry.key;
	info.product = p_entry.name;
	info.vendor_id = p_entry.vendor_id;
	info.product_id = p_entry.product_id;
	info.known_haptic = true;
	const DeviceAvailability availability = verdict(p_entry, p_drives);
	info.openable = availability.openable;
	info.unavailable_reason = availability.reason;
	return info;
}

void append_sdl_devices(SdlRuntime &r_runtime, const SdlListOptions &p_options, std::vector<DeviceInfo> &r_devices,
		std::vector<std::string> &r_warnings) {
	std::vector<SdlHapticEntry> entries;
	std::string warning;
	const Status listed = r_runtime.list(p_options, entries, warning);
	if (!warning.empty()) {
		r_warnings.emplace_back("sdl: " + warning);
	}
	if (!listed) {
		r_warnings.emplace_back(std::string("sdl: ") + listed.message());
		return;
	}
	for (const SdlHapticEntry &entry : entries) {
		r_devices.push_back(sdl_device_info(entry, p_options.read));
	}
}

void append_sdl_devices(std::span<const DeviceInfo> p_others, std::vector<DeviceInfo> &r_devices,
		std::vector<std::string> &r_warnings) {
	const bool drives = sdl_drives_here();
	std::string reason;
	SdlRuntime *runtime = SdlRuntime::shared(reason);
	if (runtime == nullptr) {
		// Where evdev drives everything SDL could list, a missing SDL is nothing to report.
		if (drives) {
			r_warnings.emplace_back("sdl: " + reason);
		}
		return;
	}
	SdlListOptions options;
	options.read = drives;
	options.joysticks = drives && sdl_lists_joysticks_here();
	options.claims = sdl_claims(p_others);
	append_sdl_devices(*runtime, options, r_devices, r_warnings);
}

DeviceAvailability probe(SdlRuntime &r_runtime, bool p_drives, const DeviceInfo &p_info) {
	DeviceAvailability availability;
	if (p_info.backend != BACKEND_SDL) {
		return availability;
	}
	SdlHapticEntry entry;
	if (!r_runtime.entry(key_of(p_info), entry)) {
		availability.handled = true;
		availability.reason = "SDL no longer lists '" + key_of(p_info) + "' (unplugged?)";
		return availability;
	}
	return verdict(entry, p_drives);
}

DeviceAvailability probe(const DeviceInfo &p_info) {
	if (p_info.backend != BACKEND_SDL) {
		return {};
	}
	std::string reason;
	SdlRuntime *runtime = SdlRuntime::shared(reason);
	if (runtime == nullptr) {
		DeviceAvailability availability;
		availability.handled = true;
		availability.reason = reason;
		return availability;
	}
	return probe(*runtime, sdl_drives_here(), p_info);
}

Status open_device(SdlRuntime &r_runtime, bool p_drives, const DeviceInfo &p_info, bool p_keep_spring,
		std::unique_ptr<HapticDevice> &r_device) {
	if (p_info.backend != BACKEND_SDL) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "device '%s' belongs to backend '%s', not sdl", p_info.id.c_str(),
				p_info.backend.c_str());
	}
	const DeviceAvailability availability = probe(r_runtime, p_drives, p_info);
	if (!availability.openable) {
		return Status::error(StatusCode::UNSUPPORTED, "'%s': %s", p_info.id.c_str(), availability.reason.c_str());
	}
	SdlDeviceConfig config;
	config.key = key_of(p_info);
	config.model = p_info.model.empty() ? p_info.product : p_info.model;
	config.keep_spring = p_keep_spring;
	auto device = std::make_unique<SdlHapticDevice>(r_runtime, config);
	const Status opened = device->open();
	if (!opened) {
		return opened;
	}
	r_device = std::move(device);
	return Status::success();
}

Status open_device(const DeviceInfo &p_info, bool p_keep_spring, std::unique_ptr<HapticDevice> &r_device) {
	std::string reason;
	SdlRuntime *runtime = SdlRuntime::shared(reason);
	if (runtime == nullptr) {
		return Status::error(StatusCode::NO_DEVICE, "%s", reason.c_str());
	}
	return open_device(*runtime, sdl_drives_here(), p_info, p_keep_spring, r_device);
}

} // namespace haptics::sdl
