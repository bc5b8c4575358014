#pragma once

// The Novint Falcon as a HapticDevice: a 3-DOF directional device behind an FTDI bridge,
// driven from the host at 1 kHz (the firmware has no control loop of its own,
// docs/devices/falcon.md).
//
// open() (game thread): opens the USB transport, purges, switches the bridge to normal mode
// and checks for running firmware (a correctly framed reply); if there is none, uploads the
// user's firmware image (falcon_firmware_loader.h, up to firmware_attempts times) and checks
// again. Then it starts a DeviceIoThread at 1 kHz. Each I/O cycle:
//   newest servo force -> torques at the last position (J^T F, falcon_kinematics.h) ->
//   16-byte command -> bulk OUT; bulk IN (64) -> reassemble frames -> newest reply ->
//   encoders -> forward kinematics -> device space -> publish_state.
// The servo's calls only copy through the DeviceExchange: no USB in the servo tick.
//
// Axes: falcon_axes.h (a translation by the workspace centre; x right, y up, z toward the
// user). Velocity: the positions' difference, low-passed at 40 Hz (encoder steps are
// ~0.06 mm, which a raw 1 kHz difference turns into 0.06 m/s of noise).
//
// Homing: every command carries the homing flag (what libnifalcon's examples do); the
// firmware sets three homing bits once the user has pulled the grip all the way out and
// pushed it back in. Until all three are set DeviceState::ready is false, the servo holds
// zero force and the I/O cycle sends zero torques whatever it is given. The LED tells the
// user: RED while not homed, GREEN once homed. (Blue is unused.)
//
// Safety: zero torques are sent by io_stop() (close, stop), whenever the position or the
// force is not usable (FK failed, NaN force: the cycle counts it and sends zero), and on
// every cycle before homing. A write or read failure ends the I/O thread with the USB error
// as the device's status reason (DISCONNECTED for LIBUSB_ERROR_NO_DEVICE), so the servo
// stops at its next tick. Silence (no valid frame for silence_timeout_s) is a failure too.
//
// Limits: 8 N peak and 3000 N/m (CHAI3D's cFalconDevice table; Novint's spec sheet says
// "over 2 lbs", 8.9 N), 4 N continuous (no public continuous rating: half the peak, our
// conservative choice), workspace radius 0.04 m (CHAI3D; the model reaches 0.05 m around the
// centre, the advertised workspace is a 4-inch cube).

#include "core/device/device.h"
#include "devices/device_exchange.h"
#include "devices/device_io_thread.h"
#include "devices/exchanged_device.h"
#include "devices/falcon/falcon_codec.h"
#include "devices/falcon/falcon_firmware_loader.h"
#include "devices/usb/usb_transport.h"

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace haptics::falcon {

inline constexpr const char *FALCON_MODEL_NAME = "Novint Falcon";

struct FalconDeviceConfig {
	std::string firmware_path; // The user's file, read only when the Falcon needs firmware.
	std::vector<uint8_t> firmware_image; // If not empty, used instead of the file (tests).
	int32_t firmware_attempts = 3; // libnifalcon's findfalcons tries 10.
	FirmwareLoadOptions firmware;
	int32_t firmware_probe_attempts = 20; // Exchanges to see a framed reply.
	double io_rate_hz = 1000.0;
	uint32_t write_timeout_ms = 50;
	uint32_t read_timeout_ms = 2; // The bridge's latency timer is 1 ms in normal mode.
	double silence_timeout_s = 0.25;
	double velocity_cutoff_hz = 40.0;
	int32_t io_priority = 45; // DeviceIoThreadOptions::realtime_priority.
};

// I/O-thread counters, readable any time.
struct FalconIoCounters {
	uint64_t cycles = 0;
	uint64_t frames = 0;
	uint64_t malformed_frames = 0;
	uint64_t dropped_bytes = 0;
	uint64_t read_timeouts = 0;
	uint64_t fk_failures = 0; // Encoders the model maps to no position: last position kept.
	uint64_t torque_failures = 0; // Force not finite or position singular: zero torques sent.
	uint64_t bytes_written = 0;
	uint64_t bytes_read = 0;
};

using UsbTransportOpener = std::function<Status(std::unique_ptr<usb::UsbTransport> &r_transport)>;

class FalconDevice final : public ExchangedDevice, private DeviceIoWorker {
public:
	FalconDevice(UsbTransportOpener p_opener, FalconDeviceConfig p_config);
	~FalconDevice() override;

	FalconDevice(const FalconDevice &) = delete;
	FalconDevice &operator=(const FalconDevice &) = delete;

	// Idempotent while open.
	Status open() override;
	void close() override;
	// The Falcon homes when the user moves the grip; this only reports whether it has.
	Status calibrate() override;
	DeviceCapabilities capabilities() const override;
	const char *name() const override { return FALCON_MODEL_NAME; }

	const FirmwareLoadReport &firmware_report() const { return firmware_report_; }
	bool firmware_uploaded() const { return firmware_uploaded_; } // By the last open().
	FalconIoCounters io_counters() const;

private:
	DeviceIo io_cycle(DeviceExchange &r_exchange, double p_dt_s) override;
	void io_stop() override;

	Status ensure_firmware();
	void reset_io_state();
	DeviceIo send_command(DeviceExchange &r_exchange, const Vec3 &p_force_kinematic);
	void take_replies(double p_dt_s);

	UsbTransportOpener opener_;
	FalconDeviceConfig config_;
	std::unique_ptr<usb::UsbTransport> transport_;
	DeviceIoThread io_thread_;
	FirmwareLoadReport firmware_report_;
	bool firmware_uploaded_ = false;

	// I/O thread only (reset in open() before the thread starts).
	FalconStreamAssembler assembler_;
	Vec3 position_kinematic_;
	Vec3 velocity_;
	bool have_position_ = false;
	bool homed_ = false;
	uint8_t buttons_ = 0;
	double since_frame_s_ = 0.0;
	double since_position_s_ = 0.0;
	uint8_t in_buffer_[64] = {};

	struct AtomicCounters {
		std::atomic<uint64_t> cycles{ 0 };
		std::atomic<uint64_t> read_timeouts{ 0 };
		std::atomic<uint64_t> fk_failures{ 0 };
		std::atomic<uint64_t> torque_failures{ 0 };
		std::atomic<uint64_t> bytes_written{ 0 };
		std::atomic<uint64_t> bytes_read{ 0 };
		std::atomic<uint64_t> frames{ 0 };
		std::atomic<uint64_t> malformed_frames{ 0 };
		std::atomic<uint64_t> dropped_bytes{ 0 };
	};
	AtomicCounters counters_;
};

} // namespace haptics::falcon
