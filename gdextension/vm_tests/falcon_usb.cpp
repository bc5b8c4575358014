// The Falcon through libusb, end to end against the real kernel: the Falcon's model (the FTDI
// bridge, its loader and its firmware) is a USB gadget with the Falcon's ids on dummy_hcd;
// list_all_devices() finds it through libusb and the real sysfs, the factory opens it, claims
// the interface, uploads the firmware image over real bulk transfers, and the servo runs the
// 16-byte exchange. A hand pressed into a floor gets the servo's force from the motor words
// on the wire. Then the cable is pulled (the gadget unbound) and plugged back: the Falcon
// powers up without firmware and the reopen uploads it again.

#include "dev_tools/falcon/scripted_falcon_device.h"
#include "dev_tools/gadget/falcon_gadget.h"
#include "rig.h"
#include "scenarios.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <thread>

namespace haptics::vm {

namespace {

constexpr uint16_t FTDI_VENDOR = 0x0403;
constexpr uint16_t FALCON_PRODUCT = 0xCB48;
constexpr const char *FIRMWARE_PATH = "/tmp/falcon-test-firmware.bin";

void press_into_floor(Report &r_report, falcon::ScriptedFalcon &p_falcon, HapticsSystem &r_system, const std::string &p_when) {
	DeviceInfo info;
	if (!r_report.check(find_listed(FTDI_VENDOR, FALCON_PRODUCT, BACKEND_LIBUSB, info), p_when + ": list_all_devices() finds the Falcon")) {
		return;
	}
	r_report.info(p_when + ": " + info.id + " " + info.path + ", driver '" + info.driver + "', " +
			(info.openable ? "openable" : "not openable: " + info.unavailable_reason));
	r_report.check(info.driver == DRIVER_FALCON && info.openable, p_when + ": the Falcon backend drives it");
	p_falcon.set_device_position(Vec3{ 0.0, 0.0, 0.0 });
	const auto opening = std::chrono::steady_clock::now();
	double max_force_n = 0.0;
	if (!open_and_run(r_report, info, r_system, max_force_n, p_when)) {
		return;
	}
	const double open_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - opening).count();
	char text[200];
	std::snprintf(text, sizeof(text), "%s: opened in %.2f s, firmware uploaded (%zu bytes echoed back)", p_when.c_str(), open_s,
			p_falcon.uploaded_image().size());
	r_report.info(text);
	r_report.check(p_falcon.uploaded_image() == falcon::make_test_firmware_image(), p_when + ": the firmware on the device is the file's");
	stand_on_floor(r_system, 0.5);
	p_falcon.set_device_position(Vec3{ 0.0, -0.02, 0.0 }); // 2 cm down into the floor.
	const uint64_t commands_before = p_falcon.counters().commands;
	const auto start = std::chrono::steady_clock::now();
	stand_on_floor(r_system, 1.0);
	const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	std::snprintf(text, sizeof(text), "%s: %.0f exchanges/s of 16 bytes each way over the bus", p_when.c_str(),
			static_cast<double>(p_falcon.counters().commands - commands_before) / seconds);
	r_report.info(text);
	const std::vector<falcon::BulkRecord> writes = p_falcon.bulk_writes();
	if (!writes.empty()) {
		r_report.wire(p_when + ": last command", writes.back().bytes);
	}
	const Vec3 servo = r_system.forces().total;
	r_report.check(servo.y > 0.3, p_when + ": the floor pushes the hand up");
	// The motor words are 16-bit and the kinematics exact: 2 % of full scale.
	same_force(r_report, servo, p_falcon.last_force_device(), 0.02 * max_force_n, p_when);
}

} // namespace

int run_falcon_usb() {
	Report report("falcon-usb");
	{
		const std::vector<uint8_t> image = falcon::make_test_firmware_image();
		std::ofstream(FIRMWARE_PATH, std::ios::binary).write(reinterpret_cast<const char *>(image.data()), static_cast<std::streamsize>(image.size()));
	}
	// Where a player points the game at Novint's file.
	::setenv("HAPTICS_FALCON_FIRMWARE", FIRMWARE_PATH, 1);
	falcon::ScriptedFalconOptions options;
	options.record = true;
	auto model = std::make_shared<falcon::ScriptedFalcon>(options);
	gadget::FalconGadget falcon(model);
	gadget::GadgetIdentity identity;
	identity.vendor = FTDI_VENDOR;
	identity.product = FALCON_PRODUCT;
	identity.manufacturer = "Novint Technologies Inc.";
	identity.product_name = "FALCON HAPTIC";
	const Status created = falcon.create(identity);
	const Status plugged = created ? falcon.plug() : created;
	if (!report.check(plugged.ok(), std::string("the Falcon is a USB gadget ") + plugged.message())) {
		return report.failed();
	}
	HapticsSystem system;
	press_into_floor(report, *model, system, "plugged");

	(void)falcon.unplug();
	expect_unplugged(report, system, "unplugged");
	system.close_device();

	model->clear_record();
	const Status replugged = falcon.plug();
	if (report.check(replugged.ok(), std::string("replugged ") + replugged.message())) {
		report.check(!model->firmware_running(), "replugged: the Falcon powered up without firmware");
		press_into_floor(report, *model, system, "replugged");
	}
	system.stop();
	system.close_device();
	falcon.destroy();
	return report.failed();
}

} // namespace haptics::vm
