#include "devices/device_enumeration.h"

#include "devices/device_catalog.h"

#include <hidapi.h>
#include <libusb.h>

#include <algorithm>
#include <array>
#include <exception>
#include <initializer_list>
#include <memory>
#include <mutex>
#include <type_traits>
#include <unordered_map>
#include <utility>

namespace haptics {

namespace {

constexpr char32_t REPLACEMENT_CHARACTER = 0xFFFD;

void append_utf8(std::string &r_out, char32_t p_code_point) {
	if (p_code_point > 0x10FFFF || (p_code_point >= 0xD800 && p_code_point <= 0xDFFF)) {
		p_code_point = REPLACEMENT_CHARACTER;
	}
	const auto byte = [&r_out](char32_t p_value) { r_out.push_back(static_cast<char>(p_value)); };
	if (p_code_point < 0x80) {
		byte(p_code_point);
	} else if (p_code_point < 0x800) {
		byte(0xC0 | (p_code_point >> 6));
		byte(0x80 | (p_code_point & 0x3F));
	} else if (p_code_point < 0x10000) {
		byte(0xE0 | (p_code_point >> 12));
		byte(0x80 | ((p_code_point >> 6) & 0x3F));
		byte(0x80 | (p_code_point & 0x3F));
	} else {
		byte(0xF0 | (p_code_point >> 18));
		byte(0x80 | ((p_code_point >> 12) & 0x3F));
		byte(0x80 | ((p_code_point >> 6) & 0x3F));
		byte(0x80 | (p_code_point & 0x3F));
	}
}

// Shared by UTF-16 strings and 16-bit wchar_t; a lone surrogate is left to append_utf8,
// which replaces it.
template <typename Unit>
std::string utf16_units_to_utf8(std::basic_string_view<Unit> p_text) {
	std::string out;
	out.reserve(p_text.size());
	for (size_t i = 0; i < p_text.size(); ++i) {
		const char32_t unit = static_cast<char16_t>(p_text[i]);
		if (unit >= 0xD800 && unit <= 0xDBFF && i + 1 < p_text.size()) {
			const char32_t next = static_cast<char16_t>(p_text[i + 1]);
			if (next >= 0xDC00 && next <= 0xDFFF) {
				append_utf8(out, 0x10000 + ((unit - 0xD800) << 10) + (next - 0xDC00));
				++i;
				continue;
			}
		}
		append_utf8(out, unit);
	}
	return out;
}

std::string from_wide(const wchar_t *p_text) {
	return p_text ? wide_to_utf8(p_text) : std::string();
}

// A warning that cannot be stored is dropped: losing a warning beats terminating.
void add_warning(DeviceList &r_list, std::initializer_list<std::string_view> p_parts) noexcept {
	try {
		std::string text;
		for (const std::string_view part : p_parts) {
			text += part;
		}
		r_list.warnings.push_back(std::move(text));
	} catch (...) {
	}
}

// ---- hidapi ----

// hid_enumerate() and hid_error(nullptr) share global state inside hidapi.
std::mutex hidapi_mutex;

struct HidExit {
	~HidExit() { hid_exit(); }
};

struct HidFreeEnumeration {
	void operator()(hid_device_info *p_list) const { hid_free_enumeration(p_list); }
};

void append_hid_devices(DeviceList &r_list) {
	const std::lock_guard lock(hidapi_mutex);
	if (hid_init() != 0) {
		add_warning(r_list, { "hidapi: cannot initialise (", from_wide(hid_error(nullptr)), ")" });
		return;
	}
	const HidExit hid_exit_at_return;
	const std::unique_ptr<hid_device_info, HidFreeEnumeration> list(hid_enumerate(0, 0));
	if (!list) {
		// hidapi reports "nothing found" as an error; without hidraw that is expected.
		add_warning(r_list,
				{ "hidapi: no HID devices visible (", from_wide(hid_error(nullptr)), ")" });
		return;
	}
	std::vector<DeviceInfo> devices = devices_from_hid_list(list.get());
	r_list.devices.insert(r_list.devices.end(), std::make_move_iterator(devices.begin()),
			std::make_move_iterator(devices.end()));
}

// ---- libusb ----

struct UsbExit {
	void operator()(libusb_context *p_context) const { libusb_exit(p_context); }
};
struct UsbFreeDeviceList {
	void operator()(libusb_device **p_list) const { libusb_free_device_list(p_list, 1); }
};
struct UsbClose {
	void operator()(libusb_device_handle *p_handle) const { libusb_close(p_handle); }
};
using UsbHandle = std::unique_ptr<libusb_device_handle, UsbClose>;

// Reads the UTF-16LE descriptor itself: libusb_get_string_descriptor_ascii() would turn
// every non-ASCII character into '?'.
std::string read_usb_string(libusb_device_handle *p_handle, uint16_t p_language, uint8_t p_index) {
	if (p_index == 0) {
		return {};
	}
	std::array<unsigned char, 256> buffer{};
	const int length = libusb_get_string_descriptor(
			p_handle, p_index, p_language, buffer.data(), static_cast<int>(buffer.size()));
	if (length < 2 || buffer[1] != LIBUSB_DT_STRING) {
		return {};
	}
	std::u16string text;
	const size_t end = std::min<size_t>(static_cast<size_t>(length), buffer[0]);
	for (size_t i = 2; i + 1 < end; i += 2) {
		text.push_back(static_cast<char16_t>(buffer[i] | (buffer[i + 1] << 8)));
	}
	return utf16_to_utf8(text);
}

uint16_t first_usb_language(libusb_device_handle *p_handle) {
	std::array<unsigned char, 4> buffer{};
	const int length = libusb_get_string_descriptor(
			p_handle, 0, 0, buffer.data(), static_cast<int>(buffer.size()));
	if (length < 4) {
		return 0x0409; // US English, what nearly every device offers.
	}
	return static_cast<uint16_t>(buffer[2] | (buffer[3] << 8));
}

// "<bus>-<port>.<port>...", as Linux names the device in sysfs: it survives re-plugging
// into the same socket, unlike the device address.
std::string usb_port_path(libusb_device *p_device) {
	std::string path = std::to_string(libusb_get_bus_number(p_device)) + "-";
	std::array<uint8_t, 7> ports{}; // USB allows at most 7 tiers.
	const int count =
			libusb_get_port_numbers(p_device, ports.data(), static_cast<int>(ports.size()));
	if (count < 0) {
		return path + "addr" + std::to_string(libusb_get_device_address(p_device));
	}
	if (count == 0) {
		return path + "root";
	}
	for (int i = 0; i < count; ++i) {
		if (i > 0) {
			path += '.';
		}
		path += std::to_string(ports[static_cast<size_t>(i)]);
	}
	return path;
}

DeviceInfo usb_device_info(libusb_device *p_device, DeviceList &r_list) {
	DeviceInfo info;
	info.backend = BACKEND_LIBUSB;
	info.path = usb_port_path(p_device);
	info.id = "usb:" + info.path;
	libusb_device_descriptor descriptor{};
	if (libusb_get_device_descriptor(p_device, &descriptor) == 0) {
		info.vendor_id = descriptor.idVendor;
		info.product_id = descriptor.idProduct;
	}
	apply_catalog(info);

	libusb_device_handle *raw_handle = nullptr;
	const int open_result = libusb_open(p_device, &raw_handle);
	if (open_result != 0) {
		// Most devices are not ours to open; only say so for the ones the player wants.
		if (info.known_haptic) {
			add_warning(r_list, { "libusb: ", info.model, " at ", info.id, " cannot be opened (", libusb_error_name(open_result), "); check its udev rules" });
		}
		return info;
	}
	const UsbHandle handle(raw_handle);
	const uint16_t language = first_usb_language(handle.get());
	info.product = read_usb_string(handle.get(), language, descriptor.iProduct);
	info.manufacturer = read_usb_string(handle.get(), language, descriptor.iManufacturer);
	info.serial = read_usb_string(handle.get(), language, descriptor.iSerialNumber);
	return info;
}

void append_usb_devices(DeviceList &r_list) {
	// A private context: other code (or another library) may use libusb in this process.
	libusb_context *raw_context = nullptr;
#if LIBUSB_API_VERSION >= 0x0100010A // 1.0.27 deprecates libusb_init().
	const int init_result = libusb_init_context(&raw_context, nullptr, 0);
#else
	const int init_result = libusb_init(&raw_context);
#endif
	if (init_result != 0) {
		add_warning(r_list,
				{ "libusb: no USB bus available (", libusb_error_name(init_result), ")" });
		return;
	}
	const std::unique_ptr<libusb_context, UsbExit> context(raw_context);
	libusb_device **raw_list = nullptr;
	const ssize_t count = libusb_get_device_list(context.get(), &raw_list);
	if (count < 0) {
		add_warning(r_list, { "libusb: cannot list USB devices (", libusb_error_name(static_cast<int>(count)), ")" });
		return;
	}
	const std::unique_ptr<libusb_device *, UsbFreeDeviceList> list(raw_list);
	if (count == 0) {
		add_warning(r_list,
				{ "libusb: no USB devices visible (no USB bus, or none exposed to this process)" });
		return;
	}
	std::vector<DeviceInfo> devices;
	devices.reserve(static_cast<size_t>(count));
	for (ssize_t i = 0; i < count; ++i) {
		devices.push_back(usb_device_info(raw_list[i], r_list));
	}
	r_list.devices.insert(r_list.devices.end(), std::make_move_iterator(devices.begin()),
			std::make_move_iterator(devices.end()));
}

template <typename Append>
void append_backend(DeviceList &r_list, std::string_view p_backend, Append p_append) noexcept {
	try {
		p_append(r_list);
	} catch (const std::exception &e) {
		add_warning(r_list, { p_backend, ": enumeration aborted (", e.what(), ")" });
	} catch (...) {
		add_warning(r_list, { p_backend, ": enumeration aborted" });
	}
}

} // namespace

std::string wide_to_utf8(std::wstring_view p_text) {
	if constexpr (sizeof(wchar_t) == 2) {
		return utf16_units_to_utf8(p_text);
	} else {
		std::string out;
		out.reserve(p_text.size());
		for (const wchar_t unit : p_text) {
			// Negative values of a signed wchar_t become huge and are replaced.
			using UnsignedWide = std::make_unsigned_t<wchar_t>;
			append_utf8(out, static_cast<char32_t>(static_cast<UnsignedWide>(unit)));
		}
		return out;
	}
}

std::string utf16_to_utf8(std::u16string_view p_text) {
	return utf16_units_to_utf8(p_text);
}

DeviceInfo make_simulated_device_info() {
	DeviceInfo info;
	info.id = SIMULATED_DEVICE_ID;
	info.backend = BACKEND_SIMULATED;
	info.product = SIMULATED_DEVICE_MODEL;
	apply_catalog(info);
	return info;
}

std::vector<DeviceInfo> devices_from_hid_list(const hid_device_info *p_list) {
	std::vector<DeviceInfo> devices;
	std::unordered_map<std::string, size_t> index_by_path;
	for (const hid_device_info *entry = p_list; entry; entry = entry->next) {
		const std::string path = entry->path ? entry->path : "";
		const auto [found, inserted] = index_by_path.try_emplace(path, devices.size());
		if (!inserted) {
			DeviceInfo &existing = devices[found->second];
			const bool found_pid = entry->usage_page == HID_USAGE_PAGE_PID;
			if (found_pid && existing.usage_page != HID_USAGE_PAGE_PID) {
				existing.usage_page = entry->usage_page;
				existing.usage = entry->usage;
			}
			continue;
		}
		DeviceInfo info;
		info.id = "hid:" + path;
		info.backend = BACKEND_HIDAPI;
		info.vendor_id = entry->vendor_id;
		info.product_id = entry->product_id;
		info.path = path;
		info.product = from_wide(entry->product_string);
		info.manufacturer = from_wide(entry->manufacturer_string);
		info.serial = from_wide(entry->serial_number);
		info.usage_page = entry->usage_page;
		info.usage = entry->usage;
		devices.push_back(std::move(info));
	}
	for (DeviceInfo &info : devices) {
		apply_catalog(info);
	}
	return devices;
}

void make_ids_unique(std::vector<DeviceInfo> &r_devices) {
	std::unordered_map<std::string, int> seen;
	for (DeviceInfo &info : r_devices) {
		const int count = ++seen[info.id];
		if (count > 1) {
			// The suffixed id may itself collide with a later one; keep counting until free.
			std::string candidate = info.id + "#" + std::to_string(count);
			for (int extra = count + 1; seen.count(candidate) != 0; ++extra) {
				candidate = info.id + "#" + std::to_string(extra);
			}
			seen[candidate] = 1;
			info.id = std::move(candidate);
		}
	}
}

DeviceList list_devices() noexcept {
	DeviceList list;
	try {
		list.devices.push_back(make_simulated_device_info());
	} catch (...) {
		return list; // Out of memory: nothing else would fit either.
	}
	append_backend(list, BACKEND_HIDAPI, append_hid_devices);
	append_backend(list, BACKEND_LIBUSB, append_usb_devices);
	try {
		make_ids_unique(list.devices);
	} catch (...) {
		add_warning(list, { "device ids may repeat: out of memory" });
	}
	return list;
}

} // namespace haptics
