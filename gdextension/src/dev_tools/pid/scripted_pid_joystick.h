#pragma once

// A software PID joystick that answers like its firmware does, for tests, the benchmark and
// the game's "scripted:hid-pid" device. It decodes the host's reports with the firmware's
// own fixed byte layout (docs/devices/hid-pid.md, "Field layouts", for AJ;
// virtual_pid_descriptor.h for ours), NOT with
// our descriptor parser, so a layout the parser got wrong shows up as a wrong force here.
//
// AJ semantics [AJ PIDReportHandler.cpp, Joystick.cpp getEffectForce; docs/devices/hid-pid.md,
// "AJ's firmware behaviour"]: Create
// New Effect allocates the first free block (Block Load then answers Success with it, or
// Full); Block Free 0xFF frees all; a Pool GET frees all; Device Reset frees all; with only
// Direction Enable set, the effect pushes axis X by sin θ and axis Y by -cos θ (θ =
// dir·360/255° on AJ, dir/100° on ours), times magnitude/max, effect gain and device gain;
// an effect ends after its duration unless that is the firmware's infinite value (AJ:
// 0x7FFF only; ours: 0 or 0xFFFF).
//
// Scripting: stick axes and buttons (what the input reports carry), the next Block Load
// answers (Full / Error / garbage / silence instead of the firmware's), and unplugging
// (every transfer then fails DISCONNECTED, like hidraw's ENODEV, and the firmware restarts
// from power-on when plugged back). Every transfer is recorded (kind, bytes).
//
// Thread-safe (one mutex): the device's I/O thread calls the transport while a test
// scripts and inspects. The real transport has no such lock.

#include "devices/hid/hid_transport.h"
#include "devices/pid/pid_layout.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

namespace haptics::pid {

enum class ScriptedFirmware : uint8_t {
	AJ = 0, // compose_aj_descriptor(16 buttons) + AJ firmware behaviour.
	VIRTUAL = 1, // virtual_pid_descriptor(): OFB-like bitmask control, 16-bit direction.
	VIRTUAL_WHEEL = 2, // The same firmware with a one-axis (X) stick report.
	// AJ with a Start Delay in Set Effect (aj_start_delay_descriptor()): the layout Linux 6.1's
	// hid-pidff accepts, so the kernel drives it through evdev.
	AJ_START_DELAY = 3,
};

enum class TransferKind : uint8_t {
	OUTPUT,
	FEATURE_SET,
	FEATURE_GET, // bytes = the reply (empty when the device did not answer).
	INPUT,
};

struct ScriptedTransfer {
	TransferKind kind = TransferKind::OUTPUT;
	uint8_t length = 0;
	uint8_t bytes[PID_MAX_REPORT_BYTES] = {};
	std::vector<uint8_t> to_vector() const { return std::vector<uint8_t>(bytes, bytes + length); }
};

enum class BlockLoadAnswer : uint8_t {
	FIRMWARE, // What the firmware would answer.
	FULL,
	ERROR,
	GARBAGE, // Cycles: wrong report ID, status 0, Success with block index 0.
	SILENCE, // GET_REPORT fails (the device stalls / times out).
};

// The force the firmware currently drives, per HID axis, normalised to -1..1 (axis X
// grows to the right, axis Y toward the user, as the stick's own axes).
struct ScriptedForce {
	double x = 0.0;
	double y = 0.0;
	uint32_t playing_effects = 0;
};

struct ScriptedEffect {
	bool allocated = false;
	bool playing = false;
	uint8_t type = 0;
	uint16_t duration = 0;
	bool duration_infinite = false;
	uint8_t gain = 0;
	uint8_t enable_bits = 0; // AJ: bit0 X, bit1 Y, bit2 Direction Enable (ours the same).
	uint16_t direction = 0; // Raw: 0..255 (AJ) or 0..36000 (ours).
	int32_t magnitude = 0;
	uint8_t loop_count = 0;
};

struct ScriptedJoystickStats {
	uint64_t outputs = 0;
	uint64_t feature_sets = 0;
	uint64_t feature_gets = 0;
	uint64_t inputs = 0;
	uint64_t bytes_to_device = 0; // Output and feature SET reports.
	uint64_t bytes_from_device = 0; // Feature GET replies and input reports.
	uint64_t pool_reads = 0;
	uint64_t device_resets = 0;
	uint64_t malformed_reports = 0; // Too short or unknown: ignored, as firmware does.
	uint64_t records_dropped = 0; // Past the record capacity (counters still count).
};

class ScriptedPidJoystick {
public:
	static constexpr uint8_t MAX_EFFECTS = 40; // AJ and OFB.

	explicit ScriptedPidJoystick(ScriptedFirmware p_firmware = ScriptedFirmware::AJ, size_t p_record_capacity = 16384);

	ScriptedFirmware firmware() const { return firmware_; }
	std::span<const uint8_t> descriptor() const { return descriptor_; }

	// --- Scripting (any thread) --------------------------------------------------------
	void set_plugged(bool p_plugged);
	bool plugged() const;
	// HID axes in -1..1: x to the right, y toward the user (stick pulled back).
	void set_stick(double p_x, double p_y);
	void set_buttons(uint32_t p_buttons);
	// The next p_count Block Load GETs get p_answer instead of the firmware's reply.
	void script_block_load(BlockLoadAnswer p_answer, uint32_t p_count = 1);

	// --- Observation (any thread) ------------------------------------------------------
	std::vector<ScriptedTransfer> records() const;
	void clear_records();
	ScriptedJoystickStats stats() const;
	ScriptedForce rendered_force() const;
	ScriptedEffect effect(uint8_t p_block_index) const;
	uint32_t allocated_effects() const;
	bool actuators_enabled() const;
	uint8_t device_gain() const;

	// --- The device side of the transport (ScriptedHidTransport forwards here) ---------
	// r_error receives a reason on failure (at most ERROR_CAPACITY bytes with the NUL).
	static constexpr size_t ERROR_CAPACITY = 128;
	DeviceIo write_output(std::span<const uint8_t> p_report, char *r_error);
	DeviceIo send_feature(std::span<const uint8_t> p_report, char *r_error);
	DeviceIo get_feature(std::span<uint8_t> p_buffer, size_t &r_length, char *r_error);
	DeviceIo read_input(std::span<uint8_t> p_buffer, size_t &r_length, char *r_error);

	struct Profile; // The firmware's fixed byte layout (scripted_pid_joystick.cpp).

private:
	static constexpr uint8_t CONSTANT_FORCE_TYPE = 1; // First in both firmwares' type lists.
	static const Profile &profile_for(ScriptedFirmware p_firmware);
	void power_on();
	void record(TransferKind p_kind, std::span<const uint8_t> p_bytes);
	bool effect_active(const ScriptedEffect &p_effect, size_t p_index) const;
	void handle_output(std::span<const uint8_t> p_report);
	void handle_device_control(uint8_t p_value);
	void free_all();
	DeviceIo unplugged(char *r_error) const;

	const ScriptedFirmware firmware_;
	const Profile &profile_;
	std::vector<uint8_t> descriptor_;
	mutable std::mutex mutex_;
	bool plugged_ = true;
	double stick_x_ = 0.0;
	double stick_y_ = 0.0;
	uint32_t buttons_ = 0;
	std::vector<BlockLoadAnswer> block_load_script_;
	uint32_t garbage_variant_ = 0;
	// Firmware state.
	ScriptedEffect effects_[MAX_EFFECTS + 1]; // Index = block index; 0 unused.
	std::chrono::steady_clock::time_point started_[MAX_EFFECTS + 1];
	bool actuators_enabled_ = false;
	bool paused_ = false;
	uint8_t device_gain_ = 255;
	uint8_t pending_block_ = 0;
	uint8_t pending_status_ = 0;
	uint64_t input_sequence_ = 0;
	// Records.
	std::vector<ScriptedTransfer> records_;
	size_t record_capacity_;
	ScriptedJoystickStats stats_;
};

// A transport onto p_joystick (several may share one model, as reopen after replug does).
std::unique_ptr<hid::HidTransport> make_scripted_transport(std::shared_ptr<ScriptedPidJoystick> p_joystick);

} // namespace haptics::pid
