#pragma once

// A DualSense in software, behind the same DualSenseTransport as the real one: what the
// backend is tested against (no hardware here), and what a demo or CI run can drive.
//
// It behaves like the pad as far as docs/devices/dualsense.md describes it:
//  - Output reports are checked the way the pad would: USB 0x02 of 48 or 63 bytes; BT 0x31 of
//    78 bytes with the tag 0x10 and a valid seed-0xA2 CRC. A report that fails is REJECTED
//    (counted, not applied) but the write itself succeeds, as a real write does: only the pad
//    knows. An accepted report is applied field by field per its valid-flag bits, so held()
//    is what the pad would be doing: motor bytes as on the wire, trigger blocks, lightbar.
//  - Input reports come from the scripted stick and buttons: USB 0x01 (64 bytes); BT 0x31
//    (78 bytes, CRC seed 0xA1), or the short 0x01 "simple" report until the first BT output
//    report arrives (SDL: any output report switches the pad to full reports). Each poll
//    returns reports_per_poll reports, then one NO_DATA, so a reader that drains the queue
//    is exercised the way hidraw's queue would.
//  - Feature reports, as hid-playstation reads them when it binds the pad (PS-K
//    dualsense_create; each must be exactly its size, on BT with a seed-0xA3 CRC in the last
//    4 bytes): 0x09 pairing info (20 bytes, the MAC at 1..6, least significant byte first),
//    0x20 firmware info (64 bytes: hardware and firmware versions at 24 and 28, the scripted
//    update version at 44..45; fails when scripted to) and 0x05 IMU calibration (41 bytes,
//    scripted_dualsense_features.cpp). Any other ID fails as a stalled request does.
//  - The BT sequence nibble is checked within a session (from a transport's open): a new
//    host process starts its own count, so a jump between sessions is not an error.
//  - unplug(): every call then fails as hidapi does on hidraw (DISCONNECTED, its texts), and
//    open() fails until replug().
//
// Threading: the script setters, counters and held() may be used from any thread while a
// device's I/O thread drives the pad. history() and inject_input() only while no I/O thread
// runs (tests that call io_cycle themselves, or after close).

#include "core/base/seqlock.h"
#include "devices/dualsense/dualsense_input.h"
#include "devices/dualsense/dualsense_report.h"
#include "devices/dualsense/dualsense_transport.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace haptics::dualsense {

struct ScriptedDualSenseOptions {
	Bus bus = Bus::USB;
	bool edge = false; // A DualSense Edge (054C:0DF2).
	uint16_t update_version = 0x0224; // Firmware-info bytes 44..45.
	bool firmware_info_fails = false;
	// Pairing info: hid-playstation names the pad by it and refuses a second pad with the
	// same one ("Duplicate device found for MAC address").
	uint8_t mac_address[6] = { 0x5a, 0x3e, 0x21, 0x7c, 0x4b, 0xa0 }; // As shown: A0:4B:7C:21:3E:5A.
	// False: the transport reports Bus::UNKNOWN, like hidapi < 0.13, so the backend must
	// infer the link from the first input report.
	bool transport_knows_bus = true;
	uint32_t reports_per_poll = 1;
};

// What the pad currently does (applied fields), plus the newest report it accepted.
struct ScriptedPadHeld {
	uint8_t motor_left = 0; // As on the wire (halved under the legacy recipe).
	uint8_t motor_right = 0;
	bool improved_rumble = false; // The last rumble came with flag2 bit 2.
	TriggerEffect right_trigger;
	TriggerEffect left_trigger;
	Rgb lightbar;
	uint8_t player_leds = 0;
	bool lightbar_taken = false; // Saw the lightbar-setup (LIGHT_OUT) request.
	bool full_reports = false; // BT: switched from the simple 0x01 report.
	uint8_t last_report[MAX_OUTPUT_SIZE] = {};
	size_t last_report_size = 0;
};

// The feature reports the pad answers besides firmware info (dualsense_input.h), with the
// sizes hid-playstation asks for (PS-K DS_FEATURE_REPORT_*).
inline constexpr uint8_t FEATURE_CALIBRATION_ID = 0x05;
inline constexpr size_t FEATURE_CALIBRATION_SIZE = 41;
inline constexpr uint8_t FEATURE_PAIRING_INFO_ID = 0x09;
inline constexpr size_t FEATURE_PAIRING_INFO_SIZE = 20;
inline constexpr size_t FEATURE_MAX_SIZE = 64;

struct ScriptedPadCounters {
	uint64_t reports_accepted = 0;
	uint64_t bytes_accepted = 0;
	uint64_t reports_rejected = 0; // Bad CRC, tag, size or ID: not applied.
	uint64_t sequence_errors = 0; // BT: byte 1 not the previous sequence + 1 (mod 16).
	uint64_t input_reports = 0;
	uint64_t feature_reads = 0;
	uint32_t max_motor = 0; // Largest motor byte applied (either motor, as on the wire).
	uint32_t max_trigger_strength = 0; // Largest feedback strength applied (either trigger).
};

class ScriptedDualSense {
public:
	static constexpr size_t HISTORY_CAPACITY = 1024;

	struct Recorded {
		uint8_t bytes[MAX_OUTPUT_SIZE] = {};
		size_t size = 0;
		bool accepted = false;
	};

	explicit ScriptedDualSense(const ScriptedDualSenseOptions &p_options = {});

	const ScriptedDualSenseOptions &options() const { return options_; }

	// --- Script (any thread) ----------------------------------------------------------------
	void set_stick(uint8_t p_x, uint8_t p_y); // Raw: 0x80 centre, y grows downward.
	// Our convention: x right, y UP, each in [-1, 1].
	void set_stick_deflection(double p_x, double p_y);
	void set_buttons(uint32_t p_buttons); // Button bits (dualsense_input.h).
	void set_battery(uint8_t p_tenths); // 0..10.
	void unplug() { plugged_.store(false, std::memory_order_release); }
	void replug() { plugged_.store(true, std::memory_order_release); }
	bool plugged() const { return plugged_.load(std::memory_order_acquire); }

	// --- Record (any thread) ----------------------------------------------------------------
	ScriptedPadHeld held() const { return held_.load(); }
	ScriptedPadCounters counters() const;

	// --- Only while no I/O thread runs --------------------------------------------------------
	// The next reads return these raw reports (up to 8 queued), before any scripted one.
	void inject_input(const uint8_t *p_report, size_t p_size);
	// Oldest first; at most HISTORY_CAPACITY (the newest), accepted and rejected.
	size_t history_size() const;
	const Recorded &history(size_t p_index) const;
	void clear_history();

	// --- The pad's side of the transport (dualsense_transport.h) ------------------------------
	// A transport opened the pad: a new host session (the BT sequence check starts over).
	void begin_session();
	TransportIo receive_output(const uint8_t *p_report, size_t p_size, const char *&r_error);
	TransportIo produce_input(uint8_t *r_buffer, size_t p_capacity, size_t &r_size, const char *&r_error);
	TransportIo produce_feature(uint8_t p_report_id, uint8_t *r_buffer, size_t p_capacity, size_t &r_size,
			const char *&r_error);

private:
	bool accept(const uint8_t *p_report, size_t p_size);
	void apply(const uint8_t *p_common, ScriptedPadHeld &r_held) const;
	size_t build_input(uint8_t *r_buffer, size_t p_capacity);
	// The report p_report_id without its BT CRC; 0 for an ID the pad does not answer.
	size_t build_feature(uint8_t p_report_id, uint8_t (&r_report)[FEATURE_MAX_SIZE]) const;
	void record(const uint8_t *p_report, size_t p_size, bool p_accepted);

	ScriptedDualSenseOptions options_;
	std::atomic<bool> plugged_{ true };
	std::atomic<uint32_t> stick_{ 0x8080 }; // x | y << 8.
	std::atomic<uint32_t> buttons_{ 0 };
	std::atomic<uint32_t> battery_{ 10 };
	Seqlock<ScriptedPadHeld> held_;
	std::atomic<uint64_t> reports_accepted_{ 0 };
	std::atomic<uint64_t> bytes_accepted_{ 0 };
	std::atomic<uint64_t> reports_rejected_{ 0 };
	std::atomic<uint64_t> sequence_errors_{ 0 };
	std::atomic<uint64_t> input_reports_{ 0 };
	std::atomic<uint64_t> feature_reads_{ 0 };
	std::atomic<uint32_t> max_motor_{ 0 };
	std::atomic<uint32_t> max_trigger_strength_{ 0 };
	// Touched by the transport's caller only (one thread at a time).
	ScriptedPadHeld working_;
	bool have_sequence_ = false;
	uint8_t last_sequence_ = 0;
	uint32_t poll_burst_ = 0;
	uint8_t input_sequence_ = 0;
	struct Injected {
		uint8_t bytes[128] = {};
		size_t size = 0;
	};
	Injected injected_[8];
	size_t injected_count_ = 0;
	size_t injected_next_ = 0;
	std::unique_ptr<Recorded[]> history_;
	size_t history_count_ = 0; // Total recorded; the ring keeps the newest.
};

// A transport onto a shared scripted pad: several devices can be made over one pad in turn
// (open, unplug, replug, reopen), as with one physical controller.
std::unique_ptr<DualSenseTransport> make_scripted_transport(std::shared_ptr<ScriptedDualSense> p_pad);

} // namespace haptics::dualsense
