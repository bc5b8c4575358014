#pragma once

// Loading Novint's firmware into a freshly powered Falcon, and telling whether it is
// already running. The Falcon boots into a loader behind its FTDI bridge; the host must
// upload the firmware image at every power-up. The sequence is docs/devices/falcon.md,
// "Loading the firmware" (libnifalcon's
// libusb backend, in its exact order):
//
//   FIRMWARE_MODE  purge RX, purge TX, latency 16 ms, baud 0x4138 (9600), 8N1, flow off,
//                  RTS low, DTR low, DTR high
//   HANDSHAKE      up to 100 tries: send 0A 43 0D, expect 00 0A 44 2C 0D ("Apple", 7 bytes
//                  with the FTDI status) or 0A 44 2C 0D ("Linux", 6 bytes)
//   UPLOAD_START   DTR low, baud 0x0015 (~140 kBd), send 'A', expect 'A' back
//   UPLOAD         the image in 62-byte chunks; the loader echoes every byte, which must
//                  match (the echo may arrive split across several reads)
//   NORMAL_MODE    latency 1 ms, baud 0x0002 (1.5 MBd), purge RX, purge TX
//
// FirmwareLoader is that sequence as a state machine over the USB seam: step() runs one
// stage (one chunk in UPLOAD), so the caller, a test or a progress bar, sees where it is.
// Every failure names its stage and the USB error.
//
// The firmware image is the USER's file: Novint's license does not let us ship it
// (docs/devices/falcon.md, "Loading the firmware").

#include "core/base/status.h"
#include "devices/usb/usb_transport.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace haptics::falcon {

inline constexpr size_t FIRMWARE_CHUNK_SIZE = 62; // One 64-byte USB packet minus the 2 status bytes.
// Novint's images are 7-9 KB (docs/devices/falcon.md); anything this large is not one.
inline constexpr size_t FIRMWARE_MAX_SIZE = 64 * 1024;
inline constexpr const char *FIRMWARE_ENV_VAR = "HAPTICS_FALCON_FIRMWARE";

enum class FirmwareStage : int32_t {
	FIRMWARE_MODE = 0,
	HANDSHAKE,
	UPLOAD_START,
	UPLOAD,
	NORMAL_MODE,
	DONE,
	FAILED,
};

const char *firmware_stage_name(FirmwareStage p_stage);

struct FirmwareLoadOptions {
	int32_t handshake_tries = 100; // docs/devices/falcon.md, "Loading the firmware".
	uint32_t handshake_read_timeout_ms = 100; // Per try: 100 tries stay within ~10 s.
	uint32_t bulk_timeout_ms = 1000;
	// IN transfers carrying only the FTDI status bytes (the chip sends one every 40 ms when
	// idle) before an expected reply is given up on.
	int32_t max_empty_reads = 50;
};

struct FirmwareLoadReport {
	FirmwareStage stage = FirmwareStage::FIRMWARE_MODE;
	int32_t handshake_tries = 0; // Tries used (1 = the first try answered).
	bool apple_reply = false; // Which of the two handshake replies came.
	size_t bytes_sent = 0; // Image bytes uploaded and echoed correctly.
	size_t chunks_sent = 0;
};

class FirmwareLoader {
public:
	// p_image must outlive the loader.
	FirmwareLoader(usb::UsbTransport &r_transport, const uint8_t *p_image, size_t p_size,
			const FirmwareLoadOptions &p_options = {});

	// Runs the current stage; on error the stage becomes FAILED and stays there.
	Status step();
	// Steps until DONE (success) or an error.
	Status run();
	const FirmwareLoadReport &report() const { return report_; }

private:
	Status enter_firmware_mode();
	Status handshake();
	Status start_upload();
	Status upload_chunk();
	Status fail_transfer(const char *p_what, const usb::UsbTransfer &p_transfer);
	// Reads until a transfer with payload arrives (skipping status-only ones); r_length is
	// the payload length.
	Status read_payload(const char *p_what, uint32_t p_timeout_ms, uint8_t *r_payload, size_t p_capacity, size_t &r_length);

	usb::UsbTransport &transport_;
	const uint8_t *image_;
	size_t size_;
	FirmwareLoadOptions options_;
	FirmwareLoadReport report_;
};

// The four requests that switch the bridge to 1 kHz I/O (the last stage above; also run
// when opening a Falcon whose firmware is already loaded).
Status falcon_set_normal_mode(usb::UsbTransport &r_transport);
// Purge RX then TX: what NIF does right after claiming the interface.
Status falcon_purge(usb::UsbTransport &r_transport);

// Sends zero-force commands and reads for up to p_attempts exchanges: any correctly framed
// reply means the firmware runs (NIF's isFirmwareLoaded). A transfer error is an error;
// r_loaded false is not.
Status falcon_probe_firmware(usb::UsbTransport &r_transport, int32_t p_attempts, uint32_t p_read_timeout_ms,
		bool &r_loaded);

// Checks a firmware image's size: errors for empty or larger than FIRMWARE_MAX_SIZE.
Status check_firmware_image(const std::string &p_origin, size_t p_size);
// Reads the user's firmware file. p_path empty: "not set". Errors tell the user what to do.
Status read_firmware_file(const std::string &p_path, std::vector<uint8_t> &r_image);

} // namespace haptics::falcon
