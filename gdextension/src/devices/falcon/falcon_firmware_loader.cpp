#include "devices/falcon/falcon_firmware_loader.h"

#include "devices/falcon/falcon_codec.h"
#include "devices/falcon/falcon_ftdi.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace haptics::falcon {

namespace {

constexpr uint8_t HANDSHAKE_QUERY[] = { 0x0A, 0x43, 0x0D };
constexpr uint8_t HANDSHAKE_REPLY_APPLE[] = { 0x00, 0x0A, 0x44, 0x2C, 0x0D };
constexpr uint8_t HANDSHAKE_REPLY_LINUX[] = { 0x0A, 0x44, 0x2C, 0x0D };
constexpr uint8_t UPLOAD_START_BYTE = 0x41; // 'A'

StatusCode code_for(usb::UsbResult p_result) {
	return p_result == usb::UsbResult::NO_DEVICE ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR;
}

Status send_all(usb::UsbTransport &r_transport, const FtdiRequest *p_requests, size_t p_count, const char *p_stage) {
	for (size_t i = 0; i < p_count; ++i) {
		const usb::UsbTransfer sent = ftdi_send(r_transport, p_requests[i]);
		if (!sent.ok()) {
			return Status::error(code_for(sent.result), "Falcon %s: FTDI request 0x%02X (wValue 0x%04X) failed: %s", p_stage,
					p_requests[i].request, p_requests[i].value, usb::usb_result_name(sent.result));
		}
	}
	return Status::success();
}

bool payload_equals(const uint8_t *p_payload, size_t p_length, const uint8_t *p_expected, size_t p_expected_length) {
	return p_length == p_expected_length && std::memcmp(p_payload, p_expected, p_length) == 0;
}

} // namespace

const char *firmware_stage_name(FirmwareStage p_stage) {
	switch (p_stage) {
		case FirmwareStage::FIRMWARE_MODE:
			return "firmware mode";
		case FirmwareStage::HANDSHAKE:
			return "loader handshake";
		case FirmwareStage::UPLOAD_START:
			return "upload start";
		case FirmwareStage::UPLOAD:
			return "firmware upload";
		case FirmwareStage::NORMAL_MODE:
			return "normal mode";
		case FirmwareStage::DONE:
			return "done";
		case FirmwareStage::FAILED:
			break;
	}
	return "failed";
}

FirmwareLoader::FirmwareLoader(usb::UsbTransport &r_transport, const uint8_t *p_image, size_t p_size,
		const FirmwareLoadOptions &p_options) :
		transport_(r_transport), image_(p_image), size_(p_size), options_(p_options) {}

Status FirmwareLoader::step() {
	Status status;
	switch (report_.stage) {
		case FirmwareStage::FIRMWARE_MODE:
			status = check_firmware_image("image", image_ ? size_ : 0);
			if (status) {
				status = enter_firmware_mode();
			}
			break;
		case FirmwareStage::HANDSHAKE:
			status = handshake();
			break;
		case FirmwareStage::UPLOAD_START:
			status = start_upload();
			break;
		case FirmwareStage::UPLOAD:
			status = upload_chunk();
			break;
		case FirmwareStage::NORMAL_MODE:
			status = falcon_set_normal_mode(transport_);
			if (status) {
				report_.stage = FirmwareStage::DONE;
			}
			break;
		case FirmwareStage::DONE:
			return Status::success();
		case FirmwareStage::FAILED:
			return Status::error(StatusCode::INVALID_STATE, "Falcon firmware load already failed");
	}
	if (!status) {
		report_.stage = FirmwareStage::FAILED;
	}
	return status;
}

Status FirmwareLoader::run() {
	while (report_.stage != FirmwareStage::DONE) {
		const Status status = step();
		if (!status) {
			return status;
		}
	}
	return Status::success();
}

Status FirmwareLoader::fail_transfer(const char *p_what, const usb::UsbTransfer &p_transfer) {
	return Status::error(code_for(p_transfer.result), "Falcon %s: %s failed: %s", firmware_stage_name(report_.stage), p_what,
			usb::usb_result_name(p_transfer.result));
}

Status FirmwareLoader::read_payload(const char *p_what, uint32_t p_timeout_ms, uint8_t *r_payload, size_t p_capacity,
		size_t &r_length) {
	uint8_t transfer[FTDI_PACKET_SIZE];
	for (int32_t empty = 0; empty < options_.max_empty_reads; ++empty) {
		const usb::UsbTransfer read = transport_.bulk_read(FALCON_ENDPOINT_IN, transfer, FTDI_PACKET_SIZE, p_timeout_ms);
		if (!read.ok()) {
			return fail_transfer(p_what, read);
		}
		r_length = ftdi_strip_status(transfer, static_cast<size_t>(read.transferred), r_payload, p_capacity);
		if (r_length > 0) {
			return Status::success();
		}
	}
	return Status::error(StatusCode::DEVICE_ERROR, "Falcon %s: no reply to %s after %d empty reads",
			firmware_stage_name(report_.stage), p_what, options_.max_empty_reads);
}

Status FirmwareLoader::enter_firmware_mode() {
	const FtdiRequest requests[] = {
		{ FTDI_REQUEST_RESET, FTDI_PURGE_RX, 0 },
		{ FTDI_REQUEST_RESET, FTDI_PURGE_TX, 0 },
		{ FTDI_REQUEST_SET_LATENCY_TIMER, FTDI_LATENCY_FIRMWARE_MS, 0 },
		{ FTDI_REQUEST_SET_BAUD_RATE, FTDI_BAUD_BOOTSTRAP.value, FTDI_BAUD_BOOTSTRAP.index },
		{ FTDI_REQUEST_SET_DATA, FTDI_DATA_8N1, 0 },
		{ FTDI_REQUEST_SET_FLOW_CTRL, FTDI_FLOW_NONE, 0 },
		{ FTDI_REQUEST_MODEM_CTRL, FTDI_RTS_LOW, 0 },
		{ FTDI_REQUEST_MODEM_CTRL, FTDI_DTR_LOW, 0 },
		{ FTDI_REQUEST_MODEM_CTRL, FTDI_DTR_HIGH, 0 },
	};
	const Status sent = send_all(transport_, requests, sizeof(requests) / sizeof(requests[0]), "firmware mode");
	if (sent) {
		report_.stage = FirmwareStage::HANDSHAKE;
	}
	return sent;
}

Status FirmwareLoader::handshake() {
	uint8_t transfer[FTDI_PACKET_SIZE];
	uint8_t payload[FTDI_PACKET_SIZE];
	while (report_.handshake_tries < options_.handshake_tries) {
		++report_.handshake_tries;
		const usb::UsbTransfer sent = transport_.bulk_write(FALCON_ENDPOINT_OUT, HANDSHAKE_QUERY, sizeof(HANDSHAKE_QUERY),
				options_.bulk_timeout_ms);
		if (!sent.ok()) {
			return fail_transfer("sending 0A 43 0D", sent);
		}
		const usb::UsbTransfer read = transport_.bulk_read(FALCON_ENDPOINT_IN, transfer, FTDI_PACKET_SIZE,
				options_.handshake_read_timeout_ms);
		if (!read.ok() && read.result != usb::UsbResult::TIMEOUT) {
			return fail_transfer("reading the handshake reply", read); // A timeout is just a failed try.
		}
		const size_t length = ftdi_strip_status(transfer, read.ok() ? static_cast<size_t>(read.transferred) : 0, payload,
				sizeof(payload));
		const bool apple = payload_equals(payload, length, HANDSHAKE_REPLY_APPLE, sizeof(HANDSHAKE_REPLY_APPLE));
		if (apple || payload_equals(payload, length, HANDSHAKE_REPLY_LINUX, sizeof(HANDSHAKE_REPLY_LINUX))) {
			report_.apple_reply = apple;
			report_.stage = FirmwareStage::UPLOAD_START;
			return Status::success();
		}
	}
	return Status::error(StatusCode::DEVICE_ERROR,
			"Falcon loader handshake: no '0A 44 2C 0D' reply in %d tries (is the Falcon powered? its power supply is separate from USB)",
			options_.handshake_tries);
}

Status FirmwareLoader::start_upload() {
	const FtdiRequest requests[] = {
		{ FTDI_REQUEST_MODEM_CTRL, FTDI_DTR_LOW, 0 },
		{ FTDI_REQUEST_SET_BAUD_RATE, FTDI_BAUD_FIRMWARE_UPLOAD.value, FTDI_BAUD_FIRMWARE_UPLOAD.index },
	};
	const Status switched = send_all(transport_, requests, sizeof(requests) / sizeof(requests[0]), "upload start");
	if (!switched) {
		return switched;
	}
	const uint8_t start = UPLOAD_START_BYTE;
	const usb::UsbTransfer sent = transport_.bulk_write(FALCON_ENDPOINT_OUT, &start, 1, options_.bulk_timeout_ms);
	if (!sent.ok()) {
		return fail_transfer("sending 'A'", sent);
	}
	uint8_t payload[FTDI_PACKET_SIZE];
	size_t length = 0;
	const Status read = read_payload("'A'", options_.bulk_timeout_ms, payload, sizeof(payload), length);
	if (!read) {
		return read;
	}
	if (length != 1 || payload[0] != UPLOAD_START_BYTE) {
		return Status::error(StatusCode::DEVICE_ERROR, "Falcon upload start: expected 'A' (41) back, got %zu bytes starting 0x%02X",
				length, payload[0]);
	}
	report_.stage = FirmwareStage::UPLOAD;
	return Status::success();
}

Status FirmwareLoader::upload_chunk() {
	const size_t offset = report_.bytes_sent;
	const size_t chunk = size_ - offset < FIRMWARE_CHUNK_SIZE ? size_ - offset : FIRMWARE_CHUNK_SIZE;
	const usb::UsbTransfer sent = transport_.bulk_write(FALCON_ENDPOINT_OUT, image_ + offset, static_cast<int32_t>(chunk),
			options_.bulk_timeout_ms);
	if (!sent.ok()) {
		return fail_transfer("writing a chunk", sent);
	}
	if (static_cast<size_t>(sent.transferred) != chunk) {
		return Status::error(StatusCode::DEVICE_ERROR, "Falcon firmware upload: chunk at byte %zu: wrote %d of %zu bytes", offset,
				sent.transferred, chunk);
	}
	// The loader echoes every byte; the echo may come in pieces.
	size_t echoed = 0;
	while (echoed < chunk) {
		uint8_t payload[FTDI_PACKET_SIZE];
		size_t length = 0;
		const Status read = read_payload("a chunk's echo", options_.bulk_timeout_ms, payload, sizeof(payload), length);
		if (!read) {
			return read;
		}
		for (size_t i = 0; i < length; ++i) {
			if (echoed + i >= chunk) {
				return Status::error(StatusCode::DEVICE_ERROR,
						"Falcon firmware upload: checksum mismatch: %zu bytes echoed for a %zu-byte chunk at byte %zu", echoed + length,
						chunk, offset);
			}
			const uint8_t expected = image_[offset + echoed + i];
			if (payload[i] != expected) {
				return Status::error(StatusCode::DEVICE_ERROR,
						"Falcon firmware upload: checksum mismatch at image byte %zu (sent 0x%02X, echoed 0x%02X)", offset + echoed + i,
						expected, payload[i]);
			}
		}
		echoed += length;
	}
	report_.bytes_sent += chunk;
	++report_.chunks_sent;
	if (report_.bytes_sent == size_) {
		report_.stage = FirmwareStage::NORMAL_MODE;
	}
	return Status::success();
}

Status falcon_set_normal_mode(usb::UsbTransport &r_transport) {
	// NIF sends the baud request here with timeout 0, which libusb reads as "forever"; ours
	// keeps the 1 s control timeout.
	const FtdiRequest requests[] = {
		{ FTDI_REQUEST_SET_LATENCY_TIMER, FTDI_LATENCY_NORMAL_MS, 0 },
		{ FTDI_REQUEST_SET_BAUD_RATE, FTDI_BAUD_NORMAL.value, FTDI_BAUD_NORMAL.index },
		{ FTDI_REQUEST_RESET, FTDI_PURGE_RX, 0 },
		{ FTDI_REQUEST_RESET, FTDI_PURGE_TX, 0 },
	};
	return send_all(r_transport, requests, sizeof(requests) / sizeof(requests[0]), "normal mode");
}

Status falcon_purge(usb::UsbTransport &r_transport) {
	const FtdiRequest requests[] = {
		{ FTDI_REQUEST_RESET, FTDI_PURGE_RX, 0 },
		{ FTDI_REQUEST_RESET, FTDI_PURGE_TX, 0 },
	};
	return send_all(r_transport, requests, sizeof(requests) / sizeof(requests[0]), "open");
}

Status falcon_probe_firmware(usb::UsbTransport &r_transport, int32_t p_attempts, uint32_t p_read_timeout_ms,
		bool &r_loaded) {
	r_loaded = false;
	FalconPacket command;
	encode_falcon_command(FalconCommand{}, command);
	FalconStreamAssembler assembler;
	uint8_t transfer[FTDI_PACKET_SIZE];
	for (int32_t attempt = 0; attempt < p_attempts; ++attempt) {
		const usb::UsbTransfer sent = r_transport.bulk_write(FALCON_ENDPOINT_OUT, command, FALCON_PACKET_SIZE, 100);
		if (!sent.ok()) {
			return Status::error(code_for(sent.result), "Falcon firmware check: write failed: %s",
					usb::usb_result_name(sent.result));
		}
		const usb::UsbTransfer read = r_transport.bulk_read(FALCON_ENDPOINT_IN, transfer, FTDI_PACKET_SIZE, p_read_timeout_ms);
		if (!read.ok() && read.result != usb::UsbResult::TIMEOUT) {
			return Status::error(code_for(read.result), "Falcon firmware check: read failed: %s",
					usb::usb_result_name(read.result));
		}
		assembler.push_transfer(transfer, read.ok() ? static_cast<size_t>(read.transferred) : 0);
		FalconReply reply;
		if (assembler.pop_reply(reply)) {
			r_loaded = true;
			return Status::success();
		}
	}
	return Status::success();
}

Status check_firmware_image(const std::string &p_origin, size_t p_size) {
	if (p_size == 0) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon firmware %.120s is empty", p_origin.c_str());
	}
	if (p_size > FIRMWARE_MAX_SIZE) {
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"Falcon firmware %.100s is larger than %zu bytes: not a Falcon image (Novint's are 7-9 KB)", p_origin.c_str(),
				FIRMWARE_MAX_SIZE);
	}
	return Status::success();
}

Status read_firmware_file(const std::string &p_path, std::vector<uint8_t> &r_image) {
	if (p_path.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"Falcon firmware file not set: set %s to Novint's firmware file (not shipped with this game)", FIRMWARE_ENV_VAR);
	}
	// A folder opens on Linux and fails at the first read; Windows refuses to open it at all.
	// Either way the player is told it is a folder.
	std::error_code ignored;
	const bool folder = std::filesystem::is_directory(p_path, ignored);
	std::FILE *file = folder ? nullptr : std::fopen(p_path.c_str(), "rb");
	if (!file && !folder) {
		const int error = errno;
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"Falcon firmware file '%.80s' not found or unreadable (%s): set %s to Novint's firmware file (not shipped with this game)",
				p_path.c_str(), std::strerror(error), FIRMWARE_ENV_VAR);
	}
	std::vector<uint8_t> image;
	uint8_t buffer[4096];
	bool read_error = folder;
	while (file && image.size() <= FIRMWARE_MAX_SIZE) {
		const size_t got = std::fread(buffer, 1, sizeof(buffer), file);
		image.insert(image.end(), buffer, buffer + got);
		if (got < sizeof(buffer)) {
			read_error = std::ferror(file) != 0;
			break;
		}
	}
	if (file) {
		std::fclose(file);
	}
	if (read_error) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon firmware file '%.80s' could not be read (a folder?)",
				p_path.c_str());
	}
	const Status size = check_firmware_image("file '" + p_path.substr(0, 80) + "'", image.size());
	if (!size) {
		return size;
	}
	r_image = std::move(image);
	return Status::success();
}

} // namespace haptics::falcon
