#pragma once

// A USB HID PID force-feedback stick (2-DOF joystick, or 1-DOF wheel when the descriptor
// has no Y axis) as a HapticDevice, over any HidTransport (hidapi, or the scripted joystick).
//
// Input: the stick deflection, normalised to -1..1 by the descriptor's logical ranges, IS
// the position: position_m = (x, -y, 0) * workspace_radius_m (HID Y grows toward the user,
// device y grows up), so the renderers' input vector is the deflection. Buttons from the
// Button page. Velocity is not estimated (zero).
//
// Output: one constant-force effect whose direction and level follow the rendered force
// (pid_force_mapping.h). PID has no physical units: the full PID magnitude is declared as
// max_force_n (default 4 N: a nominal figure for desktop FFB sticks; DIY AJ sticks vary),
// and the default continuous cap is half of it (hobby motors heat up at full scale).
//
// Rate: the device's I/O runs on its own thread (DeviceIoThread + DeviceExchange), never in
// the servo tick. Default 250 Hz: on hidraw each Output report is one synchronous interrupt
// OUT transfer, and a full-speed endpoint with bInterval 1 ms drains one report per 1 ms
// frame (docs/devices/hid-pid.md, "How fast reports drain": two per 1 ms tick already queue). A cycle sends at most two reports
// (direction + level changed), usually one or none, since only changed quantised values go
// out, so 4 ms leave the bus half idle for the input reports.
//
// Lifecycle: open = descriptor -> layout -> Reset, Reset, Stop All, Enable Actuators, Gain ->
// create the effect (Block Load) -> Start. The effect is re-started every
// restart_interval_s so a device that reads our "infinite" duration as finite never drops
// the force (docs/devices/hid-pid.md, "Infinite duration"). io_stop writes level 0 and stops the effect; close frees
// it. A failed transfer stops rendering with DISCONNECTED (unplugged) or FAILED and the
// transport's reason.

#include "devices/device_io_thread.h"
#include "devices/exchanged_device.h"
#include "devices/hid/hid_transport.h"
#include "devices/hid/joystick_input.h"
#include "devices/pid/pid_effect.h"
#include "devices/pid/pid_force_mapping.h"
#include "devices/pid/pid_layout.h"

#include <atomic>
#include <memory>
#include <string>

namespace haptics::pid {

enum class InfiniteDurationChoice : uint8_t {
	AUTO = 0, // PidLayout's per-device choice.
	ALL_ONES = 1,
	LOGICAL_MAX = 2,
};

struct PidDeviceConfig {
	double max_force_n = 4.0;
	double max_continuous_force_n = 2.0;
	double max_stiffness_n_per_m = 400.0; // Full force at 1 cm of the 5 cm deflection.
	double workspace_radius_m = 0.05; // Deflection 1 = 5 cm at the grip.
	double io_rate_hz = 250.0; // (0, 1000]
	bool invert_force_x = false;
	bool invert_force_y = false;
	InfiniteDurationChoice infinite_duration = InfiniteDurationChoice::AUTO;
	double restart_interval_s = 20.0; // < 32.7 s: AJ's longest finite duration.
	uint16_t device_gain = 0xFFFF;
	PidEffectOptions effect;
	uint32_t max_input_reports_per_cycle = 16; // Drained each cycle; the newest wins.
};

// Checks ranges; the message names the field.
Status validate_pid_device_config(const PidDeviceConfig &p_config);

// What the I/O thread did (game thread, any time).
struct PidDeviceCounters {
	uint64_t reports_sent = 0; // Output reports after open (updates, restarts, stop).
	uint64_t bytes_sent = 0;
	uint64_t input_reports = 0; // Stick reports decoded.
	uint64_t other_input_reports = 0; // Other report IDs (PID State) or undecodable.
};

class PidDevice final : public ExchangedDevice, private DeviceIoWorker {
public:
	PidDevice(std::unique_ptr<hid::HidTransport> p_transport, std::string p_name, const PidDeviceConfig &p_config = {});
	~PidDevice() override;

	Status open() override;
	void close() override;
	Status calibrate() override;
	DeviceCapabilities capabilities() const override;
	const char *name() const override { return name_.c_str(); }

	// Valid while open.
	const PidLayout &layout() const { return layout_; }
	const hid::JoystickInputLayout &input_layout() const { return input_; }
	PidDeviceCounters counters() const;

private:
	DeviceIo io_cycle(DeviceExchange &r_exchange, double p_dt_s) override;
	void io_stop() override;
	Status open_session();
	DeviceIo read_inputs(DeviceExchange &r_exchange);

	std::unique_ptr<hid::HidTransport> transport_;
	std::string name_;
	PidDeviceConfig config_;
	PidLayout layout_;
	hid::JoystickInputLayout input_;
	PidForceMapping mapping_;
	ConstantForceEffect effect_;
	DeviceIoThread io_thread_;
	// I/O-thread state.
	PidForce last_force_;
	uint64_t cycles_since_start_ = 0;
	uint64_t restart_cycles_ = 0;
	bool stopped_cleanly_ = false;
	DeviceState state_;
	std::atomic<uint64_t> input_reports_{ 0 };
	std::atomic<uint64_t> other_input_reports_{ 0 };
	std::atomic<uint64_t> reports_sent_{ 0 };
	std::atomic<uint64_t> bytes_sent_{ 0 };
};

} // namespace haptics::pid
