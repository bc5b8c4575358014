#include "dev_tools/gadget/usb_gadget.h"

#include "dev_tools/kernel_device_io.h"

#include <dirent.h>
#include <fcntl.h>
#include <linux/usb/functionfs.h>
#include <poll.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace haptics::gadget {

namespace {

constexpr const char *GADGETS = "/sys/kernel/config/usb_gadget";
constexpr const char *UDC_CLASS = "/sys/class/udc";
constexpr size_t EP0_DATA_MAX = 4096;

std::atomic<int> g_next_gadget{ 0 };

Status write_text(const std::string &p_path, const std::string &p_text) {
	const int fd = ::open(p_path.c_str(), O_WRONLY | O_CLOEXEC);
	if (fd < 0) {
		return errno_status("open", p_path);
	}
	const ssize_t written = ::write(fd, p_text.data(), p_text.size());
	const int error = errno;
	::close(fd);
	if (written != static_cast<ssize_t>(p_text.size())) {
		errno = error;
		return errno_status("write", p_path);
	}
	return Status::success();
}

Status make_dir(const std::string &p_path) {
	if (::mkdir(p_path.c_str(), 0755) != 0 && errno != EEXIST) {
		return errno_status("mkdir", p_path);
	}
	return Status::success();
}

std::string hex16(uint16_t p_value) {
	char text[8];
	std::snprintf(text, sizeof(text), "0x%04x", p_value);
	return text;
}

std::string first_udc() {
	DIR *dir = ::opendir(UDC_CLASS);
	if (dir == nullptr) {
		return "";
	}
	std::string name;
	while (const dirent *entry = ::readdir(dir)) {
		if (entry->d_name[0] != '.') {
			name = entry->d_name;
			break;
		}
	}
	::closedir(dir);
	return name;
}

void put_u32(std::vector<uint8_t> &r_bytes, uint32_t p_value) {
	for (int shift = 0; shift < 32; shift += 8) {
		r_bytes.push_back(static_cast<uint8_t>(p_value >> shift));
	}
}

} // namespace

void add_interface(std::vector<uint8_t> &r_bytes, uint8_t p_endpoints, uint8_t p_class, uint8_t p_subclass,
		uint8_t p_protocol) {
	const uint8_t bytes[] = { USB_DT_INTERFACE_SIZE, USB_DT_INTERFACE, 0, 0, p_endpoints, p_class, p_subclass, p_protocol, 0 };
	r_bytes.insert(r_bytes.end(), std::begin(bytes), std::end(bytes));
}

void add_endpoint(std::vector<uint8_t> &r_bytes, uint8_t p_address, uint8_t p_attributes, uint16_t p_max_packet,
		uint8_t p_interval) {
	const uint8_t bytes[] = { USB_DT_ENDPOINT_SIZE, USB_DT_ENDPOINT, p_address, p_attributes,
		static_cast<uint8_t>(p_max_packet & 0xFF), static_cast<uint8_t>(p_max_packet >> 8), p_interval };
	r_bytes.insert(r_bytes.end(), std::begin(bytes), std::end(bytes));
}

UsbGadget::UsbGadget(GadgetHandler &p_handler) :
		handler_(p_handler) {}

UsbGadget::~UsbGadget() {
	destroy();
}

Status UsbGadget::create(const GadgetIdentity &p_identity, const GadgetFunction &p_function) {
	if (!name_.empty()) {
		return Status::error(StatusCode::INVALID_STATE, "gadget already created");
	}
	name_ = "haptics" + std::to_string(g_next_gadget++);
	configfs_ = std::string(GADGETS) + "/" + name_;
	mount_ = "/run/ffs-" + name_;
	const std::string function = configfs_ + "/functions/ffs." + name_;
	const std::string config = configfs_ + "/configs/c.1";
	Status status = make_dir(configfs_);
	const std::pair<const char *, std::string> attributes[] = {
		{ "idVendor", hex16(p_identity.vendor) },
		{ "idProduct", hex16(p_identity.product) },
		{ "bcdDevice", hex16(p_identity.device_release) },
		{ "bcdUSB", "0x0200" },
	};
	for (const auto &[attribute, value] : attributes) {
		status = status ? write_text(configfs_ + "/" + attribute, value) : status;
	}
	status = status ? make_dir(configfs_ + "/strings/0x409") : status;
	status = status ? write_text(configfs_ + "/strings/0x409/manufacturer", p_identity.manufacturer) : status;
	status = status ? write_text(configfs_ + "/strings/0x409/product", p_identity.product_name) : status;
	status = status ? write_text(configfs_ + "/strings/0x409/serialnumber", p_identity.serial) : status;
	status = status ? make_dir(config) : status;
	status = status ? write_text(config + "/MaxPower", "100") : status;
	status = status ? make_dir(function) : status;
	if (status && ::symlink(function.c_str(), (config + "/ffs." + name_).c_str()) != 0) {
		status = errno_status("link", function);
	}
	status = status ? make_dir(mount_) : status;
	if (status && ::mount(name_.c_str(), mount_.c_str(), "functionfs", 0, nullptr) != 0) {
		status = errno_status("mount functionfs on", mount_);
	}
	if (status) {
		ep0_ = ::open((mount_ + "/ep0").c_str(), O_RDWR | O_CLOEXEC);
		status = ep0_ >= 0 ? write_descriptors(p_function) : errno_status("open", mount_ + "/ep0");
	}
	// The endpoint files appear once ep0 has the descriptors. Non-blocking: a transfer on a
	// disabled endpoint fails at once (EAGAIN) instead of waiting for the host.
	for (uint32_t i = 1; status && i <= p_function.endpoint_count; ++i) {
		const std::string path = mount_ + "/ep" + std::to_string(i);
		const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NONBLOCK);
		status = fd >= 0 ? Status::success() : errno_status("open", path);
		endpoints_.push_back(fd);
	}
	if (status && ::pipe2(wake_, O_CLOEXEC) != 0) {
		status = errno_status("pipe");
	}
	if (!status) {
		destroy();
		return status;
	}
	thread_ = std::thread(&UsbGadget::run, this);
	return Status::success();
}

Status UsbGadget::write_descriptors(const GadgetFunction &p_function) {
	std::vector<uint8_t> blob;
	put_u32(blob, FUNCTIONFS_DESCRIPTORS_MAGIC_V2);
	put_u32(blob, 0); // Length, set below.
	put_u32(blob, FUNCTIONFS_HAS_FS_DESC | FUNCTIONFS_HAS_HS_DESC | FUNCTIONFS_ALL_CTRL_RECIP);
	put_u32(blob, p_function.full_speed_count);
	put_u32(blob, p_function.high_speed_count);
	blob.insert(blob.end(), p_function.full_speed.begin(), p_function.full_speed.end());
	blob.insert(blob.end(), p_function.high_speed.begin(), p_function.high_speed.end());
	const auto length = static_cast<uint32_t>(blob.size());
	std::memcpy(blob.data() + 4, &length, 4);
	if (::write(ep0_, blob.data(), blob.size()) != static_cast<ssize_t>(blob.size())) {
		return errno_status("write descriptors to", mount_ + "/ep0");
	}
	std::vector<uint8_t> strings;
	put_u32(strings, FUNCTIONFS_STRINGS_MAGIC);
	put_u32(strings, 16);
	put_u32(strings, 0); // No strings,
	put_u32(strings, 0); // in no language.
	if (::write(ep0_, strings.data(), strings.size()) != static_cast<ssize_t>(strings.size())) {
		return errno_status("write strings to", mount_ + "/ep0");
	}
	return Status::success();
}

Status UsbGadget::plug() {
	if (ep0_ < 0) {
		return Status::error(StatusCode::INVALID_STATE, "gadget not created");
	}
	const std::string udc = first_udc();
	if (udc.empty()) {
		return Status::error(StatusCode::NO_DEVICE, "no USB device controller in %s (is dummy_hcd loaded?)", UDC_CLASS);
	}
	const Status bound = write_text(configfs_ + "/UDC", udc);
	plugged_ = plugged_ || bound.ok();
	return bound;
}

Status UsbGadget::unplug() {
	if (!plugged_) {
		return Status::success();
	}
	plugged_ = false;
	enabled_ = false;
	return write_text(configfs_ + "/UDC", "\n");
}

void UsbGadget::destroy() {
	if (name_.empty()) {
		return;
	}
	(void)unplug();
	if (wake_[1] >= 0) {
		const char wake = 1;
		[[maybe_unused]] const ssize_t woke = ::write(wake_[1], &wake, 1);
	}
	if (thread_.joinable()) {
		thread_.join();
	}
	for (const int fd : endpoints_) {
		if (fd >= 0) {
			::close(fd);
		}
	}
	endpoints_.clear();
	for (int &fd : { std::ref(ep0_), std::ref(wake_[0]), std::ref(wake_[1]) }) {
		if (fd >= 0) {
			::close(fd);
		}
		fd = -1;
	}
	// configfs removes in the reverse order of making; each step may fail when create() did
	// not get that far.
	::umount(mount_.c_str());
	::rmdir(mount_.c_str());
	::unlink((configfs_ + "/configs/c.1/ffs." + name_).c_str());
	::rmdir((configfs_ + "/configs/c.1").c_str());
	::rmdir((configfs_ + "/functions/ffs." + name_).c_str());
	::rmdir((configfs_ + "/strings/0x409").c_str());
	::rmdir(configfs_.c_str());
	name_.clear();
}

int UsbGadget::endpoint(uint32_t p_index) const {
	return p_index >= 1 && p_index <= endpoints_.size() ? endpoints_[p_index - 1] : -1;
}

void UsbGadget::run() {
	usb_functionfs_event events[4];
	while (true) {
		const KernelDeviceWait waited = wait_kernel_device(ep0_, wake_[0]);
		if (waited == KernelDeviceWait::STOP) {
			return;
		}
		if (waited == KernelDeviceWait::IDLE) {
			continue;
		}
		const ssize_t got = ::read(ep0_, events, sizeof(events));
		for (ssize_t i = 0; got > 0 && i < got / static_cast<ssize_t>(sizeof(events[0])); ++i) {
			switch (events[i].type) {
				case FUNCTIONFS_ENABLE:
					enabled_ = true;
					handler_.on_enabled(true);
					break;
				case FUNCTIONFS_DISABLE:
				case FUNCTIONFS_UNBIND:
					enabled_ = false;
					handler_.on_enabled(false);
					break;
				case FUNCTIONFS_SETUP:
					++setups_;
					answer(events[i].u.setup);
					break;
				default:
					break;
			}
		}
	}
}

void UsbGadget::answer(const usb_ctrlrequest &p_request) {
	const size_t length = std::min<size_t>(p_request.wLength, EP0_DATA_MAX);
	std::vector<uint8_t> reply;
	if ((p_request.bRequestType & USB_DIR_IN) != 0) {
		// A read in the direction opposite to the request's stalls it.
		if (!handler_.on_setup(p_request, {}, reply)) {
			(void)::read(ep0_, nullptr, 0);
			return;
		}
		reply.resize(std::min(reply.size(), length));
		(void)::write(ep0_, reply.data(), reply.size());
		return;
	}
	uint8_t data[EP0_DATA_MAX];
	ssize_t got = 0;
	if (length > 0) {
		// The data stage; reading it also acknowledges the request, so a model cannot refuse
		// one with data (it logs what it rejects instead).
		got = ::read(ep0_, data, length);
		(void)handler_.on_setup(p_request, std::span<const uint8_t>(data, got > 0 ? static_cast<size_t>(got) : 0), reply);
		return;
	}
	if (handler_.on_setup(p_request, {}, reply)) {
		(void)::read(ep0_, nullptr, 0);
	} else {
		(void)::write(ep0_, nullptr, 0);
	}
}

} // namespace haptics::gadget
