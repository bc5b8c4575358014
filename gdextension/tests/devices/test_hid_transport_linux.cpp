// The real-transport side as far as a machine without USB allows: the sysfs helpers on a
// fake /sys tree (descriptor, HID device dir, kernel force-feedback detection), hidapi on a
// path that does not exist (a clean Status, no crash), and the backend's probe/open_device
// verdicts for devices it does and does not drive.

#include "devices/hid/hidapi_transport.h"
#include "devices/hid/hidraw_sysfs.h"
#include "devices/pid/aj_descriptor.h"
#include "devices/pid/pid_backend.h"

#include "scratch_dir.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace haptics;
namespace fs = std::filesystem;

namespace {

// A throwaway /sys: class/hidraw/hidraw7/device -> devices/.../0003:2341:8036.0001 holding a
// report_descriptor and input/input12/capabilities/ff.
struct FakeSysfs {
	testing::ScratchDir dir{ "haptics-sysfs" };
	fs::path root = dir.root();

	FakeSysfs() {
		const fs::path device = root / "devices/pci0000:00/usb1/1-1/1-1:1.0/0003:2341:8036.0001";
		fs::create_directories(device / "input/input12/capabilities");
		fs::create_directories(root / "class/hidraw/hidraw7");
		fs::create_directory_symlink(device, root / "class/hidraw/hidraw7/device");
		const std::vector<uint8_t> descriptor = pid::compose_aj_descriptor(16);
		std::ofstream(device / "report_descriptor", std::ios::binary)
				.write(reinterpret_cast<const char *>(descriptor.data()), static_cast<std::streamsize>(descriptor.size()));
		set_ff("0");
	}
	void set_ff(const char *p_bitmap) {
		std::ofstream(root / "class/hidraw/hidraw7/device/input/input12/capabilities/ff") << p_bitmap << "\n";
	}
};

} // namespace

TEST_CASE("hid sysfs: hidraw paths, the HID device dir, the descriptor and kernel force feedback") {
	CHECK(hid::hidraw_index("/dev/hidraw0") == 0);
	CHECK(hid::hidraw_index("/dev/hidraw17") == 17);
	CHECK(hid::hidraw_index("/dev/hidraw") == -1);
	CHECK(hid::hidraw_index("/dev/hidraw1x") == -1);
	CHECK(hid::hidraw_index("/dev/usb/hiddev0") == -1);
	CHECK(hid::hidraw_index("1-1:1.0") == -1); // A libusb-style path (other hidapi backends).

	FakeSysfs sysfs;
	const std::string root = sysfs.root.string();
	const std::string dir = hid::hidraw_hid_device_sysfs_dir("/dev/hidraw7", root);
	CHECK(dir.find("0003:2341:8036.0001") != std::string::npos);
	CHECK(dir.find("class/hidraw") == std::string::npos); // Resolved, not the link.
	CHECK(hid::hidraw_hid_device_sysfs_dir("/dev/hidraw8", root).empty());

	std::vector<uint8_t> bytes;
	REQUIRE(hid::read_hidraw_report_descriptor("/dev/hidraw7", bytes, root).ok());
	CHECK(bytes == pid::compose_aj_descriptor(16));
	const Status missing = hid::read_hidraw_report_descriptor("/dev/hidraw8", bytes, root);
	CHECK(missing.code() == StatusCode::NO_DEVICE);
	CHECK(std::string(missing.message()).find("hidraw8/device/report_descriptor") != std::string::npos);
	CHECK(hid::read_hidraw_report_descriptor("hidraw7", bytes, root).code() == StatusCode::INVALID_ARGUMENT);

	CHECK_FALSE(hid::kernel_ff_bound("/dev/hidraw7", root));
	sysfs.set_ff("0 0 0");
	CHECK_FALSE(hid::kernel_ff_bound("/dev/hidraw7", root));
	sysfs.set_ff("107030000 0"); // What hid-pidff advertises: FF_CONSTANT, FF_PERIODIC, ...
	CHECK(hid::kernel_ff_bound("/dev/hidraw7", root));
	CHECK_FALSE(hid::kernel_ff_bound("/dev/hidraw8", root));
}

TEST_CASE("hid sysfs: a character device is hidraw only when its sysfs subsystem says so") {
	std::string reason;
	CHECK_FALSE(hid::is_hidraw_node("/dev/null", &reason));
	CHECK(reason == "/dev/null is not a hidraw device");
	CHECK_FALSE(hid::is_hidraw_node("/dev/hidraw-does-not-exist", &reason));
	CHECK(reason.find("No such file") != std::string::npos);
	// A fake /sys in which /dev/null's numbers (1:3) belong to the hidraw class.
	FakeSysfs sysfs;
	fs::create_directories(sysfs.root / "class/hidraw");
	fs::create_directories(sysfs.root / "dev/char/1:3");
	fs::create_directory_symlink(sysfs.root / "class/hidraw", sysfs.root / "dev/char/1:3/subsystem");
	CHECK(hid::is_hidraw_node("/dev/null", &reason, sysfs.root.string()));
}

TEST_CASE("hid transport: hidapi never sees a node that is not hidraw (hidapi 0.13.1 would crash)") {
	hid::HidapiTransport transport("/dev/null");
	const Status status = transport.open();
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(std::string(status.message()) == "hid-pid: '/dev/null' is not a hidraw device node");
}

TEST_CASE("hid transport: hidapi on a device that is not there fails cleanly") {
	hid::HidapiTransport transport("/dev/hidraw-does-not-exist");
	const Status status = transport.open();
	CHECK_FALSE(status.ok());
	CHECK(std::string(status.message()).find("/dev/hidraw-does-not-exist") != std::string::npos);
	CHECK_FALSE(transport.is_open());
	const uint8_t report[2] = { 0x0C, 0x01 };
	CHECK(transport.write_output(report) != DeviceIo::OK);
	CHECK(std::string(transport.last_error()).find("hid_write") != std::string::npos);
	uint8_t buffer[8] = { 0x06 };
	size_t length = 99;
	CHECK(transport.get_feature(buffer, length) != DeviceIo::OK);
	CHECK(length == 0);
	CHECK(transport.read_input(buffer, length) == DeviceIo::DISCONNECTED); // The node is gone.
	std::vector<uint8_t> descriptor;
	CHECK_FALSE(transport.report_descriptor(descriptor).ok());
	transport.close();
}

TEST_CASE("pid backend: probe and open_device say which devices are ours and why one cannot open") {
	DeviceInfo info;
	info.backend = std::string(BACKEND_LIBUSB);
	info.path = "1-1";
	info.usage_page = 0x0F;
	CHECK_FALSE(pid::probe(info).handled);

	info.backend = std::string(BACKEND_HIDAPI);
	info.path = "/dev/hidraw-does-not-exist";
	info.usage_page = 0x01; // A joystick whose descriptor we cannot read: not ours.
	CHECK_FALSE(pid::probe(info).handled);

	info.usage_page = 0x0F;
	const DeviceAvailability availability = pid::probe(info);
	CHECK(availability.handled);
	CHECK_FALSE(availability.openable);
	CHECK(availability.reason.find("no device at '/dev/hidraw-does-not-exist'") != std::string::npos);

	// An AJ stick: hidapi sees a joystick (usage page 1), its descriptor holds the PID reports.
	FakeSysfs sysfs;
	info.path = "/dev/hidraw7";
	info.usage_page = 0x01;
	DeviceAvailability aj = pid::probe_with_sysfs(info, sysfs.root.string());
	CHECK(aj.handled);
	CHECK_FALSE(aj.openable);
	CHECK(aj.reason == "hid-pid: no device at '/dev/hidraw7' (No such file or directory)"); // No such node here.
	sysfs.set_ff("107030000 0");
	aj = pid::probe_with_sysfs(info, sysfs.root.string());
	CHECK(aj.handled);
	CHECK_FALSE(aj.openable);
	CHECK(aj.reason == "the kernel's force-feedback driver owns it: use its evdev entry");

	std::unique_ptr<HapticDevice> device;
	info.path = "/dev/hidraw-does-not-exist";
	info.product = "FFB Stick";
	REQUIRE(pid::open_device(info, device).ok());
	REQUIRE(device);
	CHECK(std::string(device->name()) == "FFB Stick");
	const Status opened = device->open();
	CHECK_FALSE(opened.ok());
	CHECK(std::string(opened.message()).find("cannot open 'FFB Stick'") != std::string::npos);
	info.backend = std::string(BACKEND_SIMULATED);
	CHECK(pid::open_device(info, device).code() == StatusCode::INVALID_ARGUMENT);
}
