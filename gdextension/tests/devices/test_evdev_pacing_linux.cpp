// Pacing evdev updates to the interrupt OUT endpoint (evdev_pacing.h): the interval read from
// a sysfs tree shaped like the real one (the VM tests' Linux 6.1 under dummy_hcd), the hold
// each kind of update costs, and the device sending no faster than that while still ending
// on the last command.

#include "dev_tools/evdev/scripted_evdev_device.h"
#include "devices/evdev/evdev_device.h"
#include "devices/evdev/evdev_pacing.h"
#include "evdev_test_support.h"
#include "scratch_dir.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

using namespace haptics;
using namespace haptics::evdev;

namespace {

void write_file(const std::filesystem::path &p_path, const std::string &p_text) {
	std::filesystem::create_directories(p_path.parent_path());
	std::ofstream(p_path) << p_text << "\n";
}

// <root>/class/input/<event>/device -> the input device under a HID device under a USB
// interface with an interrupt IN and, when p_out_interval is not empty, OUT endpoint.
void fake_usb_tree(const std::filesystem::path &p_root, const std::string &p_event, const std::string &p_out_interval,
		bool p_usb = true) {
	const std::filesystem::path interface = p_root / "devices/platform/dummy_hcd.0/usb1/1-1/1-1:1.0";
	const std::filesystem::path input = interface / "0003:2341:8036.0003/input/input4";
	std::filesystem::create_directories(input);
	if (p_usb) {
		write_file(interface / "bInterfaceNumber", "00");
		write_file(interface / "ep_81/direction", "in");
		write_file(interface / "ep_81/type", "Interrupt");
		write_file(interface / "ep_81/interval", "1ms");
	}
	if (p_usb && !p_out_interval.empty()) {
		write_file(interface / "ep_02/direction", "out");
		write_file(interface / "ep_02/type", "Interrupt");
		write_file(interface / "ep_02/interval", p_out_interval);
	}
	std::filesystem::create_directories(p_root / "class/input" / p_event);
	std::filesystem::create_directory_symlink(input, p_root / "class/input" / p_event / "device");
}

} // namespace

TEST_CASE("evdev pacing: the interrupt OUT endpoint's interval from sysfs, else one report per frame") {
	{
		testing::ScratchDir sys("haptics-pacing");
		fake_usb_tree(sys.root(), "event4", "8ms");
		CHECK(output_report_interval_s("/dev/input/event4", sys.root().string()) == doctest::Approx(0.008));
	}
	{
		testing::ScratchDir sys("haptics-pacing");
		fake_usb_tree(sys.root(), "event4", "125us");
		CHECK(output_report_interval_s("/dev/input/event4", sys.root().string()) == doctest::Approx(125e-6));
	}
	{
		// No OUT endpoint (reports go as control transfers), not on USB, no such node, no path.
		testing::ScratchDir sys("haptics-pacing");
		fake_usb_tree(sys.root(), "event4", "");
		CHECK(output_report_interval_s("/dev/input/event4", sys.root().string()) == DEFAULT_REPORT_INTERVAL_S);
		CHECK(output_report_interval_s("/dev/input/event9", sys.root().string()) == DEFAULT_REPORT_INTERVAL_S);
		CHECK(output_report_interval_s("event4", sys.root().string()) == DEFAULT_REPORT_INTERVAL_S);
	}
	{
		testing::ScratchDir sys("haptics-pacing");
		fake_usb_tree(sys.root(), "event4", "8ms", false);
		CHECK(output_report_interval_s("/dev/input/event4", sys.root().string()) == DEFAULT_REPORT_INTERVAL_S);
	}
	{
		testing::ScratchDir sys("haptics-pacing");
		fake_usb_tree(sys.root(), "event4", "garbage");
		CHECK(output_report_interval_s("/dev/input/event4", sys.root().string()) == DEFAULT_REPORT_INTERVAL_S);
	}
}

TEST_CASE("evdev pacing: a new direction costs two reports, a new level one, nothing new none") {
	const FfConstantForce from{ 0x8000, 1000 };
	CHECK(update_hold_s(from, { 0x4000, 2000 }, 0.001) == doctest::Approx(2 * 0.001 * PACING_MARGIN));
	CHECK(update_hold_s(from, { 0x8000, 2000 }, 0.001) == doctest::Approx(0.001 * PACING_MARGIN));
	CHECK(update_hold_s(from, from, 0.001) == 0.0);
}

TEST_CASE("evdev pacing: a force turning every cycle is sent no faster than the endpoint drains, and the last one arrives") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	testing::ScratchDir sys("haptics-pacing");
	const std::string event = std::filesystem::path(kernel->script().path).filename().string();
	fake_usb_tree(sys.root(), event, "8ms"); // A slow endpoint: 24 ms per turning update.
	EvdevDeviceConfig config;
	config.sysfs_root = sys.root().string();
	auto device = make_scripted_device(kernel, config);
	REQUIRE(device->open().ok());
	const uint64_t uploads_before = kernel->counters().uploads;
	const auto start = std::chrono::steady_clock::now();
	double elapsed = 0.0;
	for (int i = 0; elapsed < 0.5; ++i) {
		// Direction and level both change: two reports per update.
		const double angle = 0.3 * i;
		const double magnitude = 2.0 + std::sin(1.7 * i);
		REQUIRE(device->write_force({ Vec3(magnitude * std::sin(angle), magnitude * std::cos(angle), 0.0), {} }) == DeviceIo::OK);
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
		elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	}
	REQUIRE(device->write_force({ Vec3(1.5, -2.0, 0.0), {} }) == DeviceIo::OK);
	// At most one update per 24 ms over the loop (plus the one at its start and the last);
	// unpaced, the 500 Hz I/O thread sends one per cycle (about 250).
	const uint64_t paced = kernel->counters().uploads - uploads_before;
	CHECK(paced <= static_cast<uint64_t>(elapsed / (2 * 0.008 * PACING_MARGIN)) + 3);
	CHECK(paced >= 2);
	CHECK(evdev_test::wait_until([&] { return std::fabs(kernel->rendered().axis_y - 0.4) < 1e-3; }));
	CHECK(kernel->rendered().axis_x == doctest::Approx(0.3).epsilon(1e-3));
	device->close();
}
