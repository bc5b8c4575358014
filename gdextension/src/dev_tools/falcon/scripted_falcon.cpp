#include "dev_tools/falcon/scripted_falcon.h"

#include "devices/falcon/falcon_axes.h"
#include "devices/falcon/falcon_ftdi.h"
#include "devices/falcon/falcon_kinematics.h"

#include <algorithm>

namespace haptics::falcon {

namespace {

constexpr uint8_t FTDI_STATUS[2] = { 0x31, 0x60 }; // Modem status (CTS, DSR, B0), line status (THRE, TEMT).
constexpr size_t RECORD_LIMIT = 400000; // Per list: ~7 minutes at 1 kHz; then counters only.

class ScriptedFalconTransport final : public usb::UsbTransport {
public:
	explicit ScriptedFalconTransport(std::shared_ptr<ScriptedFalcon> p_model) :
			model_(std::move(p_model)) {}

	const char *describe() const override { return "scripted Falcon"; }

private:
	usb::UsbTransfer raw_control_transfer(uint8_t p_request_type, uint8_t p_request, uint16_t p_value, uint16_t p_index,
			uint8_t *p_data, uint16_t p_length, uint32_t p_timeout_ms) override {
		(void)p_data;
		(void)p_length;
		(void)p_timeout_ms;
		return model_->control_transfer(p_request_type, p_request, p_value, p_index);
	}
	usb::UsbTransfer raw_bulk_write(uint8_t p_endpoint, const uint8_t *p_bytes, int32_t p_length, uint32_t p_timeout_ms) override {
		(void)p_timeout_ms;
		return model_->bulk_write(p_endpoint, p_bytes, p_length);
	}
	usb::UsbTransfer raw_bulk_read(uint8_t p_endpoint, uint8_t *r_buffer, int32_t p_length, uint32_t p_timeout_ms) override {
		(void)p_timeout_ms;
		return model_->bulk_read(p_endpoint, r_buffer, p_length);
	}

	std::shared_ptr<ScriptedFalcon> model_;
};

} // namespace

ScriptedFalcon::ScriptedFalcon(const ScriptedFalconOptions &p_options) :
		options_(p_options) {
	power_up();
	set_position(FALCON_KINEMATIC_CENTRE);
}

void ScriptedFalcon::power_up() {
	mode_ = options_.firmware_loaded ? Mode::RUNNING : Mode::LOADER_IDLE;
	baud_value_ = 0;
	dtr_low_seen_ = false;
	handshake_answers_ = 0;
	in_queue_.clear();
	command_stream_.clear();
	homed_ = homed_scripted_ ? homed_ : 0;
	homing_commands_seen_ = 0;
}

Status ScriptedFalcon::open_transport(std::unique_ptr<usb::UsbTransport> &r_transport) {
	if (!plugged()) {
		return Status::error(StatusCode::NO_DEVICE, "Novint Falcon 0403:cb48 not present (scripted Falcon unplugged)");
	}
	r_transport = std::make_unique<ScriptedFalconTransport>(shared_from_this());
	return Status::success();
}

void ScriptedFalcon::set_position(const Vec3 &p_kinematic_m) {
	FalconAngles angles;
	const std::lock_guard lock(mutex_);
	if (!falcon_inverse_kinematics(p_kinematic_m, angles)) {
		return; // Unreachable: the mechanism stops where it was.
	}
	position_kinematic_ = p_kinematic_m;
	for (int i = 0; i < 3; ++i) {
		encoders_[i] = theta_rad_to_encoder(angles.leg[i].theta1);
	}
}

void ScriptedFalcon::set_device_position(const Vec3 &p_device_m) {
	set_position(device_to_falcon_position(p_device_m));
}

void ScriptedFalcon::set_buttons(uint8_t p_buttons) {
	const std::lock_guard lock(mutex_);
	buttons_ = static_cast<uint8_t>(p_buttons & 0x0F);
}

void ScriptedFalcon::set_homed(uint8_t p_bits) {
	const std::lock_guard lock(mutex_);
	homed_ = static_cast<uint8_t>(p_bits & FALCON_HOMED_ALL);
	homed_scripted_ = true;
}

void ScriptedFalcon::set_options(const ScriptedFalconOptions &p_options) {
	const std::lock_guard lock(mutex_);
	options_ = p_options;
}

void ScriptedFalcon::unplug() {
	const std::lock_guard lock(mutex_);
	plugged_ = false;
}

void ScriptedFalcon::replug() {
	const std::lock_guard lock(mutex_);
	plugged_ = true;
	const bool keep = options_.keep_firmware_on_replug && mode_ == Mode::RUNNING;
	power_up();
	if (keep) {
		mode_ = Mode::RUNNING;
	}
}

bool ScriptedFalcon::plugged() const {
	const std::lock_guard lock(mutex_);
	return plugged_;
}

bool ScriptedFalcon::firmware_running() const {
	const std::lock_guard lock(mutex_);
	return mode_ == Mode::RUNNING;
}

std::vector<ControlRecord> ScriptedFalcon::control_transfers() const {
	const std::lock_guard lock(mutex_);
	return controls_;
}

std::vector<BulkRecord> ScriptedFalcon::bulk_writes() const {
	const std::lock_guard lock(mutex_);
	return writes_;
}

std::vector<BulkRecord> ScriptedFalcon::bulk_reads() const {
	const std::lock_guard lock(mutex_);
	return reads_;
}

std::vector<uint8_t> ScriptedFalcon::uploaded_image() const {
	const std::lock_guard lock(mutex_);
	return uploaded_;
}

ScriptedFalconCounters ScriptedFalcon::counters() const {
	const std::lock_guard lock(mutex_);
	return counters_;
}

bool ScriptedFalcon::has_command() const {
	const std::lock_guard lock(mutex_);
	return has_command_;
}

FalconCommand ScriptedFalcon::last_command() const {
	const std::lock_guard lock(mutex_);
	return last_command_;
}

Vec3 ScriptedFalcon::last_force_device() const {
	const std::lock_guard lock(mutex_);
	Vec3 force;
	if (!falcon_motor_words_to_force(position_kinematic_, last_command_.torque, force)) {
		return Vec3{};
	}
	return falcon_to_device_direction(force);
}

void ScriptedFalcon::clear_record() {
	const std::lock_guard lock(mutex_);
	controls_.clear();
	writes_.clear();
	reads_.clear();
	counters_ = ScriptedFalconCounters{};
}

void ScriptedFalcon::record_bulk(std::vector<BulkRecord> &r_list, uint8_t p_endpoint, const uint8_t *p_bytes,
		size_t p_length, usb::UsbResult p_result) {
	if (options_.record && r_list.size() < RECORD_LIMIT) {
		r_list.push_back(BulkRecord{ p_endpoint, std::vector<uint8_t>(p_bytes, p_bytes + p_length), p_result });
	}
}

void ScriptedFalcon::queue(std::vector<uint8_t> p_bytes, bool p_boundary_after) {
	if (!p_bytes.empty()) {
		in_queue_.push_back(Piece{ std::move(p_bytes), p_boundary_after });
	}
}

usb::UsbTransfer ScriptedFalcon::control_transfer(uint8_t p_request_type, uint8_t p_request, uint16_t p_value,
		uint16_t p_index) {
	const std::lock_guard lock(mutex_);
	const usb::UsbResult result = plugged_ ? usb::UsbResult::OK : usb::UsbResult::NO_DEVICE;
	if (options_.record && controls_.size() < RECORD_LIMIT) {
		controls_.push_back(ControlRecord{ p_request_type, p_request, p_value, p_index, result });
	}
	if (result != usb::UsbResult::OK) {
		return { result, 0 };
	}
	if (p_request == FTDI_REQUEST_RESET && p_value == FTDI_PURGE_RX) {
		in_queue_.clear(); // Whatever the chip held for the host is gone.
	} else if (p_request == FTDI_REQUEST_SET_BAUD_RATE) {
		baud_value_ = p_value;
		if (p_value == FTDI_BAUD_NORMAL.value && mode_ == Mode::UPLOADING && !uploaded_.empty()) {
			mode_ = Mode::RUNNING; // The loader jumps into the uploaded firmware.
			command_stream_.clear();
		}
	} else if (p_request == FTDI_REQUEST_MODEM_CTRL && p_value == FTDI_DTR_LOW) {
		dtr_low_seen_ = true;
	} else if (p_request == FTDI_REQUEST_MODEM_CTRL && p_value == FTDI_DTR_HIGH && dtr_low_seen_ &&
			baud_value_ == FTDI_BAUD_BOOTSTRAP.value) {
		mode_ = Mode::LOADER_HANDSHAKE; // DTR pulses the microcontroller's reset: back to its loader.
		uploaded_.clear();
		handshake_answers_ = 0;
		dtr_low_seen_ = false;
	}
	return { usb::UsbResult::OK, 0 };
}

usb::UsbTransfer ScriptedFalcon::bulk_write(uint8_t p_endpoint, const uint8_t *p_bytes, int32_t p_length) {
	const std::lock_guard lock(mutex_);
	const size_t length = p_bytes && p_length > 0 ? static_cast<size_t>(p_length) : 0;
	const usb::UsbResult result = !plugged_ ? usb::UsbResult::NO_DEVICE
											: (p_endpoint != FALCON_ENDPOINT_OUT ? usb::UsbResult::PIPE : usb::UsbResult::OK);
	record_bulk(writes_, p_endpoint, p_bytes, length, result);
	if (result != usb::UsbResult::OK) {
		return { result, 0 };
	}
	counters_.bytes_written += length;
	switch (mode_) {
		case Mode::LOADER_IDLE:
			break; // Nobody listens before the DTR pulse.
		case Mode::LOADER_HANDSHAKE: {
			const uint8_t query[] = { 0x0A, 0x43, 0x0D };
			if (length == sizeof(query) && std::equal(query, query + sizeof(query), p_bytes)) {
				const bool answer = options_.handshake_failures >= 0 && handshake_answers_ >= options_.handshake_failures;
				++handshake_answers_;
				if (!answer) {
					queue({ 0x0A, 0x45 }); // Not the reply the host waits for.
				} else if (options_.handshake_reply == HandshakeReply::APPLE) {
					queue({ 0x00, 0x0A, 0x44, 0x2C, 0x0D });
					mode_ = Mode::LOADER_READY;
				} else {
					queue({ 0x0A, 0x44, 0x2C, 0x0D });
					mode_ = Mode::LOADER_READY;
				}
			}
			break;
		}
		case Mode::LOADER_READY:
			if (length == 1 && p_bytes[0] == 0x41 && baud_value_ == FTDI_BAUD_FIRMWARE_UPLOAD.value) {
				queue({ 0x41 });
				mode_ = Mode::UPLOADING;
			}
			break;
		case Mode::UPLOADING: {
			const size_t offset = uploaded_.size();
			uploaded_.insert(uploaded_.end(), p_bytes, p_bytes + length);
			std::vector<uint8_t> echo(p_bytes, p_bytes + length);
			if (options_.echo == EchoMode::CORRUPT && options_.corrupt_at >= offset && options_.corrupt_at < offset + length) {
				echo[options_.corrupt_at - offset] ^= 0xFF;
			}
			if (options_.echo == EchoMode::SPLIT && options_.echo_split_at > 0 && options_.echo_split_at < length) {
				queue(std::vector<uint8_t>(echo.begin(), echo.begin() + static_cast<std::ptrdiff_t>(options_.echo_split_at)), true);
				queue(std::vector<uint8_t>(echo.begin() + static_cast<std::ptrdiff_t>(options_.echo_split_at), echo.end()), true);
			} else if (options_.echo != EchoMode::SILENT && options_.echo != EchoMode::TIMEOUT) {
				queue(std::move(echo), true);
			}
			break;
		}
		case Mode::RUNNING:
			command_stream_.insert(command_stream_.end(), p_bytes, p_bytes + length);
			take_commands();
			break;
	}
	return { usb::UsbResult::OK, static_cast<int32_t>(length) };
}

void ScriptedFalcon::take_commands() {
	size_t start = 0;
	while (true) {
		while (start < command_stream_.size() && command_stream_[start] != FALCON_FRAME_START) {
			++start;
		}
		if (command_stream_.size() - start < FALCON_PACKET_SIZE) {
			break;
		}
		FalconCommand command;
		if (!decode_falcon_command(command_stream_.data() + start, FALCON_PACKET_SIZE, command)) {
			++counters_.bad_commands;
			++start;
			continue;
		}
		start += FALCON_PACKET_SIZE;
		++counters_.commands;
		has_command_ = true;
		last_command_ = command;
		if ((command.flags & FALCON_FLAG_HOMING) && !homed_scripted_ && options_.homing_commands >= 0 &&
				homed_ != FALCON_HOMED_ALL && ++homing_commands_seen_ > options_.homing_commands) {
			homed_ = FALCON_HOMED_ALL;
		}
		FalconReply reply;
		for (int i = 0; i < 3; ++i) {
			reply.encoder[i] = encoders_[i];
		}
		reply.homed = homed_;
		reply.buttons = buttons_;
		FalconPacket packet;
		encode_falcon_reply(reply, packet);
		queue(std::vector<uint8_t>(packet, packet + FALCON_PACKET_SIZE));
		++counters_.replies;
	}
	command_stream_.erase(command_stream_.begin(), command_stream_.begin() + static_cast<std::ptrdiff_t>(start));
}

usb::UsbTransfer ScriptedFalcon::bulk_read(uint8_t p_endpoint, uint8_t *r_buffer, int32_t p_length) {
	const std::lock_guard lock(mutex_);
	usb::UsbResult result = usb::UsbResult::OK;
	if (!plugged_) {
		result = usb::UsbResult::NO_DEVICE;
	} else if (p_endpoint != FALCON_ENDPOINT_IN || r_buffer == nullptr || p_length < FTDI_STATUS_BYTES) {
		result = usb::UsbResult::INVALID_PARAM;
	} else if (mode_ == Mode::UPLOADING && options_.echo == EchoMode::TIMEOUT && in_queue_.empty()) {
		result = usb::UsbResult::TIMEOUT;
	}
	if (result != usb::UsbResult::OK) {
		record_bulk(reads_, p_endpoint, nullptr, 0, result);
		return { result, 0 };
	}
	const size_t packet_payload = static_cast<size_t>(std::min<int32_t>(p_length, FTDI_PACKET_SIZE) - FTDI_STATUS_BYTES);
	const size_t limit = std::min(packet_payload, std::clamp<size_t>(options_.max_reply_payload, 1, 62));
	r_buffer[0] = FTDI_STATUS[0];
	r_buffer[1] = FTDI_STATUS[1];
	size_t length = FTDI_STATUS_BYTES;
	while (!in_queue_.empty() && length - FTDI_STATUS_BYTES < limit) {
		Piece &piece = in_queue_.front();
		const size_t take = std::min(piece.bytes.size(), limit - (length - FTDI_STATUS_BYTES));
		std::copy(piece.bytes.begin(), piece.bytes.begin() + static_cast<std::ptrdiff_t>(take), r_buffer + length);
		length += take;
		piece.bytes.erase(piece.bytes.begin(), piece.bytes.begin() + static_cast<std::ptrdiff_t>(take));
		if (!piece.bytes.empty()) {
			break;
		}
		const bool boundary = piece.boundary_after;
		in_queue_.pop_front();
		if (boundary) {
			break;
		}
	}
	counters_.bytes_read += length;
	record_bulk(reads_, p_endpoint, r_buffer, length, result);
	return { result, static_cast<int32_t>(length) + options_.overstated_read_bytes };
}

} // namespace haptics::falcon
