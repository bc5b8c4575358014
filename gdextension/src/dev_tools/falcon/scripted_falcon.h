#pragma once

// A Falcon without hardware: the FTDI bridge and the Falcon's loader and firmware, modelled
// at the level of USB transfers, for the tests, the benchmark and the headless game test.
//
//  - FTDI: records every control transfer; tracks baud and DTR; purge RX drops pending IN
//    data; every IN transfer starts with two status bytes (31 60) and carries at most 62
//    payload bytes (fewer with max_reply_payload, to split frames across reads); with
//    nothing pending it returns the status bytes alone, as the chip does.
//  - Loader (after power-up): answers 0A 43 0D at 9600 Bd after a DTR low-high with the
//    "Linux" or "Apple" reply (or not, for handshake_failures tries), 'A' at the upload baud
//    with 'A', then echoes every firmware byte: whole, split in two, with one byte
//    corrupted, not at all (status-only reads) or with TIMEOUT errors. Switching to the
//    normal baud after an upload starts the firmware.
//  - Firmware: for every 16-byte command returns a 16-byte reply whose encoders come from the
//    scripted end-effector position through the inverse kinematics, so the device's forward
//    kinematics recovers it; homing bits and buttons as scripted; the motor words and flags
//    of the last command are kept, with the force they render at the scripted position.
//  - overstated_read_bytes: IN transfers report more bytes than they wrote (a broken
//    transport), which the USB seam must refuse.
//  - unplug(): every transfer fails with NO_DEVICE until replug(), which powers the model
//    up again (firmware gone, unless keep_firmware_on_replug).
//
// Thread-safe: the device's I/O thread calls the transport while a test scripts the model.
// The mutex and the record's allocations stand in for the bus; the device's own I/O cycle
// neither locks nor allocates.

#include "core/base/vec3.h"
#include "devices/falcon/falcon_codec.h"
#include "devices/usb/usb_transport.h"

#include <deque>
#include <memory>
#include <mutex>
#include <vector>

namespace haptics::falcon {

enum class HandshakeReply : int32_t {
	LINUX = 0, // 0A 44 2C 0D
	APPLE = 1, // 00 0A 44 2C 0D
};

enum class EchoMode : int32_t {
	WHOLE = 0,
	SPLIT, // Each chunk's echo in two reads, split at echo_split_at.
	CORRUPT, // The byte at image offset corrupt_at is echoed with its bits flipped.
	SILENT, // No echo: reads bring only status bytes.
	TIMEOUT, // Reads fail with LIBUSB_ERROR_TIMEOUT while uploading.
};

struct ScriptedFalconOptions {
	bool firmware_loaded = false; // Power up with the firmware already running.
	bool keep_firmware_on_replug = false;
	HandshakeReply handshake_reply = HandshakeReply::LINUX;
	int32_t handshake_failures = 0; // Tries answered with garbage first; < 0: never answer.
	EchoMode echo = EchoMode::WHOLE;
	size_t echo_split_at = 30;
	size_t corrupt_at = 100;
	size_t max_reply_payload = 62; // Payload bytes per IN transfer (1..62).
	// Commands carrying the homing flag before all three homing bits come up (0: the first).
	// < 0: never by itself (set_homed() decides).
	int32_t homing_commands = 0;
	bool record = true; // Keep every transfer (tests); false keeps counters only (benchmark).
	// Added to the length every successful IN transfer reports (the bytes written stay as
	// they were): a broken transport claiming more than the buffer holds.
	int32_t overstated_read_bytes = 0;
};

struct ControlRecord {
	uint8_t request_type = 0;
	uint8_t request = 0;
	uint16_t value = 0;
	uint16_t index = 0;
	usb::UsbResult result = usb::UsbResult::OK;
};

struct BulkRecord {
	uint8_t endpoint = 0;
	std::vector<uint8_t> bytes; // Written, or read including the status bytes.
	usb::UsbResult result = usb::UsbResult::OK;
};

struct ScriptedFalconCounters {
	uint64_t bytes_written = 0;
	uint64_t bytes_read = 0; // Including status bytes.
	uint64_t commands = 0; // Valid 16-byte commands the firmware took.
	uint64_t bad_commands = 0;
	uint64_t replies = 0;
};

class ScriptedFalcon : public std::enable_shared_from_this<ScriptedFalcon> {
public:
	explicit ScriptedFalcon(const ScriptedFalconOptions &p_options = {});

	// A transport bound to this model (what "opening the USB device" gives). Fails with
	// NO_DEVICE while unplugged, like the real open.
	Status open_transport(std::unique_ptr<usb::UsbTransport> &r_transport);

	// --- Script ---------------------------------------------------------------------------
	void set_position(const Vec3 &p_kinematic_m); // Kinematic frame (falcon_kinematics.h).
	void set_device_position(const Vec3 &p_device_m); // Device space (falcon_axes.h).
	void set_buttons(uint8_t p_buttons);
	void set_homed(uint8_t p_bits); // Overrides homing_commands from now on.
	void set_options(const ScriptedFalconOptions &p_options); // Takes effect at once.
	void unplug();
	void replug();

	// --- Record ---------------------------------------------------------------------------
	bool plugged() const;
	bool firmware_running() const;
	std::vector<ControlRecord> control_transfers() const;
	std::vector<BulkRecord> bulk_writes() const;
	std::vector<BulkRecord> bulk_reads() const;
	std::vector<uint8_t> uploaded_image() const;
	ScriptedFalconCounters counters() const;
	bool has_command() const;
	FalconCommand last_command() const;
	// What the last command's motor words render at the scripted position, device space, N.
	Vec3 last_force_device() const;
	void clear_record();

	// --- Transport (called by the transport it handed out) ---------------------------------
	usb::UsbTransfer control_transfer(uint8_t p_request_type, uint8_t p_request, uint16_t p_value, uint16_t p_index);
	usb::UsbTransfer bulk_write(uint8_t p_endpoint, const uint8_t *p_bytes, int32_t p_length);
	usb::UsbTransfer bulk_read(uint8_t p_endpoint, uint8_t *r_buffer, int32_t p_length);

private:
	enum class Mode : int32_t {
		LOADER_IDLE, // Powered, waiting for the DTR pulse.
		LOADER_HANDSHAKE, // Answers 0A 43 0D.
		LOADER_READY, // Handshake done: waits for 'A'.
		UPLOADING,
		RUNNING,
	};
	struct Piece {
		std::vector<uint8_t> bytes;
		bool boundary_after = false; // A read stops here (split echoes).
	};

	void power_up();
	void queue(std::vector<uint8_t> p_bytes, bool p_boundary_after = false);
	void take_commands();
	void record_bulk(std::vector<BulkRecord> &r_list, uint8_t p_endpoint, const uint8_t *p_bytes, size_t p_length,
			usb::UsbResult p_result);

	mutable std::mutex mutex_;
	ScriptedFalconOptions options_;
	bool plugged_ = true;
	Mode mode_ = Mode::LOADER_IDLE;
	uint16_t baud_value_ = 0;
	bool dtr_low_seen_ = false;
	int32_t handshake_answers_ = 0;
	std::deque<Piece> in_queue_;
	std::vector<uint8_t> command_stream_;
	Vec3 position_kinematic_;
	int16_t encoders_[3] = {};
	uint8_t buttons_ = 0;
	uint8_t homed_ = 0;
	bool homed_scripted_ = false;
	int32_t homing_commands_seen_ = 0;
	bool has_command_ = false;
	FalconCommand last_command_;
	std::vector<ControlRecord> controls_;
	std::vector<BulkRecord> writes_;
	std::vector<BulkRecord> reads_;
	std::vector<uint8_t> uploaded_;
	ScriptedFalconCounters counters_;
};

} // namespace haptics::falcon
