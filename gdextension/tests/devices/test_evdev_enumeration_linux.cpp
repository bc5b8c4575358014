// Enumeration over a fake sysfs tree built in a temporary folder (removed afterwards, also
// when a check fails): which event nodes are listed (FF_CONSTANT or FF_RUMBLE), the DeviceInfo
// fields, stable ids, the HID directory for pairing with hidraw, and probe() through the
// REAL syscalls on files that are not evdev nodes.

#include "devices/evdev/evdev_backend.h"
#include "devices/evdev/evdev_enumeration.h"

#include "scratch_dir.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace haptics;
using namespace haptics::evdev;
namespace fs = std::filesystem;

namespace {

class FakeSysfs {
public:
	FakeSysfs() {
		fs::create_directories(class_input());
		fs::create_directories(dev_input());
		fs::create_directories(root_ / "sys/bus/hid");
		fs::create_directories(root_ / "sys/class/input_subsystem");
	}

	fs::path class_input() const { return root_ / "sys/class/input"; }
	fs::path dev_input() const { return root_ / "dev/input"; }
	fs::path root() const { return root_; }

	// An input device below p_parent (relative to sys/devices) with one event node, linked
	// the way the kernel links them. Returns the input device's directory.
	fs::path add(const std::string &p_parent, const std::string &p_input, const std::string &p_event, const char *p_ff,
			const std::string &p_name, const std::string &p_phys, const char *p_vendor = "2341", const char *p_product = "8036") {
		const fs::path input = root_ / "sys/devices" / p_parent / "input" / p_input;
		fs::create_directories(input / p_event);
		fs::create_directories(input / "id");
		fs::create_directories(input / "capabilities");
		if (p_ff) {
			write(input / "capabilities/ff", p_ff);
		}
		write(input / "name", p_name);
		write(input / "phys", p_phys);
		write(input / "uniq", "");
		write(input / "id/vendor", p_vendor);
		write(input / "id/product", p_product);
		fs::create_directory_symlink(fs::path("../../") / p_input, input / p_event / "device");
		fs::create_directory_symlink(fs::relative(input / p_event, class_input()), class_input() / p_event);
		return input;
	}
	// Marks a directory as a HID device (its `subsystem` link ends in bus/hid).
	void mark_hid(const fs::path &p_dir) {
		fs::create_directories(p_dir);
		fs::create_directory_symlink(root_ / "sys/bus/hid", p_dir / "subsystem");
	}
	void add_dev_file(const std::string &p_event) { write(dev_input() / p_event, ""); }

	static void write(const fs::path &p_path, const std::string &p_text) {
		std::ofstream file(p_path);
		file << p_text << "\n";
	}

private:
	testing::ScratchDir dir_{ "haptics-evdev" };
	fs::path root_ = dir_.root();
};

constexpr const char *HID_PARENT = "pci0000:00/0000:00:14.0/usb1/1-2/1-2:1.0/0003:2341:8036.0001";

} // namespace

TEST_CASE("evdev enumeration: lists FF_CONSTANT and FF_RUMBLE nodes, in event order, with sysfs fields") {
	FakeSysfs sysfs;
	sysfs.mark_hid(sysfs.root() / "sys/devices" / HID_PARENT);
	sysfs.add(HID_PARENT, "input5", "event7", "1077e0000 0", "Arduino LLC Arduino Leonardo",
			"usb-0000:00:14.0-2/input0");
	// A rumble gamepad (no FF_CONSTANT), a keyboard (no ff file), a garbled capability, a node
	// whose driver offers only the gain (nothing to render with).
	sysfs.add("pci0000:00/usb1/1-3/1-3:1.0/0003:045E:028E.0002", "input6", "event3", "107030000 0", "Pad", "usb-3", "045e",
			"028e");
	sysfs.add("virtual", "input7", "event5", "100000000 0", "Gain only", "");
	sysfs.add("platform/i8042/serio0", "input1", "event0", nullptr, "AT keyboard", "isa0060/serio0/input0");
	sysfs.add("virtual/broken", "input9", "event4", "zz 0", "Broken", "");
	// A virtual (uinput) wheel: constant force, no phys, not on HID.
	sysfs.add("virtual", "input20", "event12", "300040000 0", "Virtual wheel", "", "1209", "ffb0");
	sysfs.add_dev_file("event7");

	std::vector<DeviceInfo> devices;
	std::vector<std::string> warnings;
	enumerate_evdev_devices(devices, warnings, sysfs.class_input().string(), sysfs.dev_input().string());
	REQUIRE(devices.size() == 3);
	REQUIRE(warnings.size() == 1);
	CHECK(warnings[0] == "evdev: event4 capabilities/ff: 'z' in 'zz' is not a hex digit");

	const DeviceInfo &pad = devices[0]; // event3: rumble renders the impacts.
	CHECK(pad.id == "evdev:usb-3");
	CHECK(pad.vendor_id == 0x045e);
	CHECK(pad.product_id == 0x028e);
	CHECK(pad.driver == "evdev");

	const DeviceInfo &stick = devices[1];
	CHECK(stick.id == "evdev:usb-0000:00:14.0-2/input0");
	CHECK(stick.backend == "evdev");
	CHECK(stick.driver == "evdev");
	CHECK(stick.path == (sysfs.dev_input() / "event7").string());
	CHECK(stick.vendor_id == 0x2341);
	CHECK(stick.product_id == 0x8036);
	CHECK(stick.product == "Arduino LLC Arduino Leonardo");
	CHECK(stick.known_haptic);
	// probe() through the real syscalls: a regular file opens but is no evdev node.
	CHECK_FALSE(stick.openable);
	CHECK(stick.unavailable_reason.find("EVIOCGBIT(EV_FF) failed") != std::string::npos);
	CHECK(stick.unavailable_reason.find("not an evdev node?") != std::string::npos);

	const DeviceInfo &wheel = devices[2];
	CHECK(wheel.id == "evdev:event12"); // No phys: the node's name.
	CHECK(wheel.vendor_id == 0x1209);
	CHECK(wheel.product_id == 0xffb0);
	CHECK_FALSE(wheel.openable);
	CHECK(wheel.unavailable_reason == (sysfs.dev_input() / "event12").string() + " is not present (ENOENT): the device is unplugged or the path is stale");
}

TEST_CASE("evdev enumeration: ids are stable across calls - without phys, udev's by-path name") {
	FakeSysfs sysfs;
	sysfs.add(HID_PARENT, "input5", "event7", "300040000 0", "Stick", "usb-0000:00:14.0-2/input0");
	sysfs.add("virtual", "input20", "event12", "300040000 0", "Virtual wheel", "");
	fs::create_directories(sysfs.dev_input() / "by-path");
	fs::create_symlink("../event12", sysfs.dev_input() / "by-path/platform-vhci-event-joystick");
	fs::create_symlink("../event5", sysfs.dev_input() / "by-path/pci-0000:00:14.0-usb-0:9:1.0-event");
	std::vector<DeviceInfo> first;
	std::vector<DeviceInfo> second;
	std::vector<std::string> warnings;
	enumerate_evdev_devices(first, warnings, sysfs.class_input().string(), sysfs.dev_input().string());
	enumerate_evdev_devices(second, warnings, sysfs.class_input().string(), sysfs.dev_input().string());
	REQUIRE(first.size() == 2);
	REQUIRE(second.size() == 2);
	CHECK(first[0].id == "evdev:usb-0000:00:14.0-2/input0");
	CHECK(first[1].id == "evdev:platform-vhci-event-joystick");
	CHECK(first[0].id == second[0].id);
	CHECK(first[1].id == second[1].id);
	CHECK(first[0].id != first[1].id);
	CHECK(warnings.empty());
}

TEST_CASE("evdev enumeration: the HID device directory above the event node, for pairing with hidraw") {
	FakeSysfs sysfs;
	const fs::path hid = sysfs.root() / "sys/devices" / HID_PARENT;
	sysfs.mark_hid(hid);
	sysfs.add(HID_PARENT, "input5", "event7", "300040000 0", "Stick", "usb-2");
	sysfs.add("virtual", "input20", "event12", "300040000 0", "Virtual wheel", "");
	// Named like a HID device but without a subsystem link: still recognised by its name.
	sysfs.add("usb1/1-4/1-4:1.0/0003:046D:C24F.0003", "input8", "event8", "300040000 0", "Wheel", "usb-4");

	CHECK(evdev_hid_device_sysfs_dir(sysfs.class_input().string(), "event7") == fs::canonical(hid).string());
	CHECK(evdev_hid_device_sysfs_dir(sysfs.class_input().string(), "event8") ==
			fs::canonical(sysfs.root() / "sys/devices/usb1/1-4/1-4:1.0/0003:046D:C24F.0003").string());
	CHECK(evdev_hid_device_sysfs_dir(sysfs.class_input().string(), "event12").empty());
	CHECK(evdev_hid_device_sysfs_dir(sysfs.class_input().string(), "event99").empty());
	CHECK(evdev_hid_device_sysfs_dir("/nonexistent/sysfs", "event7").empty());
}

TEST_CASE("evdev enumeration: a missing sysfs root is a warning, not an error") {
	std::vector<DeviceInfo> devices;
	std::vector<std::string> warnings;
	enumerate_evdev_devices(devices, warnings, "/nonexistent/haptics/sys/class/input", "/dev/input");
	CHECK(devices.empty());
	REQUIRE(warnings.size() == 1);
	CHECK(warnings[0].rfind("evdev: cannot list /nonexistent/haptics/sys/class/input (", 0) == 0);
	// And the real root on this machine (no input devices in this container) never throws.
	enumerate_evdev_devices(devices, warnings);
	CHECK(devices.empty());
}
