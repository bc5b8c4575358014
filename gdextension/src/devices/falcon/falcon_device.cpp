#include "devices/falcon/falcon_device.h"

#include "devices/falcon/falcon_axes.h"
#include "devices/falcon/falcon_ftdi.h"
#include "devices/falcon/falcon_kinematics.h"

#include <cmath>
#include <numbers>

namespace haptics::falcon {

namespace {

constexpr uint32_t FIRMWARE_PROBE_READ_TIMEOUT_MS = 10;

} // namespace

FalconDevice::FalconDevice(UsbTransportOpener p_opener, FalconDeviceConfig p_config) :
		opener_(std::move(p_opener)), config_(std::move(p_config)) {}

FalconDevice::~FalconDevice() {
	close();
}

Status FalconDevice::open() {
	if (open_) {
		return Status::success();
	}
	if (!opener_) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon: no USB transport to open");
	}
	std::unique_ptr<usb::UsbTransport> transport;
	Status status = opener_(transport);
	if (!status) {
		return status;
	}
	transport_ = std::move(transport);
	firmware_uploaded_ = false;
	firmware_report_ = FirmwareLoadReport{};
	// NIF's open(): purge, normal mode; then the firmware check (docs/devices/falcon.md,
	// "Loading the firmware").
	status = falcon_purge(*transport_);
	if (status) {
		status = falcon_set_normal_mode(*transport_);
	}
	if (status) {
		status = ensure_firmware();
	}
	if (status) {
		reset_io_state();
		DeviceState initial;
		initial.ready = false;
		exchange_.reset(initial);
		DeviceIoThreadOptions options;
		options.rate_hz = config_.io_rate_hz;
		options.realtime_priority = config_.io_priority;
		status = io_thread_.start(*this, exchange_, options);
	}
	if (!status) {
		transport_.reset();
		return status;
	}
	open_ = true;
	return Status::success();
}

void FalconDevice::close() {
	io_thread_.stop(); // Runs io_stop(): zero torques while the Falcon is reachable.
	transport_.reset();
	open_ = false;
}

Status FalconDevice::ensure_firmware() {
	bool loaded = false;
	Status status = falcon_probe_firmware(*transport_, config_.firmware_probe_attempts, FIRMWARE_PROBE_READ_TIMEOUT_MS, loaded);
	if (!status || loaded) {
		return status;
	}
	std::vector<uint8_t> file;
	if (config_.firmware_image.empty()) {
		status = read_firmware_file(config_.firmware_path, file);
		if (!status) {
			return status;
		}
	}
	const std::vector<uint8_t> &image = config_.firmware_image.empty() ? file : config_.firmware_image;
	for (int32_t attempt = 0; attempt < config_.firmware_attempts; ++attempt) {
		FirmwareLoader loader(*transport_, image.data(), image.size(), config_.firmware);
		status = loader.run();
		firmware_report_ = loader.report();
		if (status) {
			status = falcon_probe_firmware(*transport_, config_.firmware_probe_attempts, FIRMWARE_PROBE_READ_TIMEOUT_MS, loaded);
			if (status && loaded) {
				firmware_uploaded_ = true;
				return status;
			}
			if (status) {
				status = Status::error(StatusCode::DEVICE_ERROR,
						"Falcon firmware uploaded (%zu bytes) but the Falcon does not answer: is it Novint's firmware file?",
						image.size());
			}
		}
		if (status.code() == StatusCode::DEVICE_DISCONNECTED) {
			break;
		}
	}
	return status;
}

Status FalconDevice::calibrate() {
	if (!open_) {
		return Status::error(StatusCode::NO_DEVICE, "cannot calibrate '%s': device not open", name());
	}
	DeviceState state;
	if (exchange_.read_state(state) != DeviceIo::OK) {
		return Status::error(StatusCode::DEVICE_DISCONNECTED, "cannot calibrate '%s': %s", name(), exchange_.status().reason.c_str());
	}
	if (!state.ready) {
		return Status::error(StatusCode::DEVICE_ERROR,
				"'%s' not homed yet: pull the grip all the way out, then push it in (the LED turns from red to green)", name());
	}
	return Status::success();
}

DeviceCapabilities FalconDevice::capabilities() const {
	DeviceCapabilities capabilities;
	capabilities.input_dof = 3;
	capabilities.output_dof = 3;
	capabilities.output = ForceOutput::DIRECTIONAL;
	capabilities.limits.max_force_n = 8.0;
	capabilities.limits.max_continuous_force_n = 4.0;
	capabilities.limits.max_stiffness_n_per_m = 3000.0;
	capabilities.limits.workspace_radius_m = 0.04;
	capabilities.native_rate_hz = config_.io_rate_hz;
	capabilities.has_orientation = false;
	capabilities.needs_homing = true;
	capabilities.physical = true;
	capabilities.button_count = 4;
	return capabilities;
}

FalconIoCounters FalconDevice::io_counters() const {
	FalconIoCounters counters;
	counters.cycles = counters_.cycles.load(std::memory_order_relaxed);
	counters.frames = counters_.frames.load(std::memory_order_relaxed);
	counters.malformed_frames = counters_.malformed_frames.load(std::memory_order_relaxed);
	counters.dropped_bytes = counters_.dropped_bytes.load(std::memory_order_relaxed);
	counters.read_timeouts = counters_.read_timeouts.load(std::memory_order_relaxed);
	counters.fk_failures = counters_.fk_failures.load(std::memory_order_relaxed);
	counters.torque_failures = counters_.torque_failures.load(std::memory_order_relaxed);
	counters.bytes_written = counters_.bytes_written.load(std::memory_order_relaxed);
	counters.bytes_read = counters_.bytes_read.load(std::memory_order_relaxed);
	return counters;
}

void FalconDevice::reset_io_state() {
	assembler_.clear();
	position_kinematic_ = FALCON_KINEMATIC_CENTRE;
	velocity_ = Vec3{};
	have_position_ = false;
	homed_ = false;
	buttons_ = 0;
	since_frame_s_ = 0.0;
	since_position_s_ = 0.0;
	counters_.cycles.store(0, std::memory_order_relaxed);
	counters_.read_timeouts.store(0, std::memory_order_relaxed);
	counters_.fk_failures.store(0, std::memory_order_relaxed);
	counters_.torque_failures.store(0, std::memory_order_relaxed);
	counters_.bytes_written.store(0, std::memory_order_relaxed);
	counters_.bytes_read.store(0, std::memory_order_relaxed);
	counters_.frames.store(0, std::memory_order_relaxed);
	counters_.malformed_frames.store(0, std::memory_order_relaxed);
	counters_.dropped_bytes.store(0, std::memory_order_relaxed);
}

DeviceIo FalconDevice::send_command(DeviceExchange &r_exchange, const Vec3 &p_force_kinematic) {
	FalconCommand command;
	command.flags = static_cast<uint8_t>(FALCON_FLAG_HOMING | (homed_ ? FALCON_LED_GREEN : FALCON_LED_RED));
	if (homed_ && have_position_) {
		MotorWords words;
		if (falcon_force_to_motor_words(position_kinematic_, p_force_kinematic, words)) {
			for (int i = 0; i < 3; ++i) {
				command.torque[i] = words.word[i];
			}
		} else {
			counters_.torque_failures.fetch_add(1, std::memory_order_relaxed);
		}
	}
	FalconPacket packet;
	encode_falcon_command(command, packet);
	const usb::UsbTransfer sent = transport_->bulk_write(FALCON_ENDPOINT_OUT, packet, FALCON_PACKET_SIZE, config_.write_timeout_ms);
	if (!sent.ok()) {
		r_exchange.fail(usb::usb_result_io(sent.result), "Falcon USB write failed: %s%s", usb::usb_result_name(sent.result),
				sent.result == usb::UsbResult::NO_DEVICE ? " (unplugged?)" : "");
		return usb::usb_result_io(sent.result);
	}
	counters_.bytes_written.fetch_add(FALCON_PACKET_SIZE, std::memory_order_relaxed);
	return DeviceIo::OK;
}

void FalconDevice::take_replies(double p_dt_s) {
	since_frame_s_ += p_dt_s;
	since_position_s_ += p_dt_s;
	FalconReply reply;
	FalconReply newest;
	bool got = false;
	while (assembler_.pop_reply(reply)) {
		newest = reply;
		got = true;
	}
	const FalconStreamAssembler::Counters &stream = assembler_.counters();
	counters_.frames.store(stream.frames, std::memory_order_relaxed);
	counters_.malformed_frames.store(stream.malformed_frames, std::memory_order_relaxed);
	counters_.dropped_bytes.store(stream.dropped_bytes, std::memory_order_relaxed);
	if (!got) {
		return;
	}
	since_frame_s_ = 0.0;
	homed_ = newest.all_homed();
	buttons_ = newest.buttons;
	const double theta[3] = { encoder_to_theta_rad(newest.encoder[0]), encoder_to_theta_rad(newest.encoder[1]),
		encoder_to_theta_rad(newest.encoder[2]) };
	Vec3 position;
	if (!falcon_forward_kinematics(theta, have_position_ ? position_kinematic_ : FALCON_KINEMATIC_CENTRE, position)) {
		counters_.fk_failures.fetch_add(1, std::memory_order_relaxed);
		return;
	}
	if (have_position_ && since_position_s_ > 0.0) {
		const Vec3 raw = (position - position_kinematic_) / since_position_s_;
		const double alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * config_.velocity_cutoff_hz * since_position_s_);
		velocity_ += (raw - velocity_) * alpha;
	}
	position_kinematic_ = position;
	have_position_ = true;
	since_position_s_ = 0.0;
}

DeviceIo FalconDevice::io_cycle(DeviceExchange &r_exchange, double p_dt_s) {
	counters_.cycles.fetch_add(1, std::memory_order_relaxed);
	const ForceCommand command = r_exchange.latest_command();
	const DeviceIo sent = send_command(r_exchange, device_to_falcon_direction(command.force_n));
	if (sent != DeviceIo::OK) {
		return sent;
	}
	const usb::UsbTransfer read = transport_->bulk_read(FALCON_ENDPOINT_IN, in_buffer_, FTDI_PACKET_SIZE, config_.read_timeout_ms);
	if (read.ok()) {
		counters_.bytes_read.fetch_add(static_cast<uint64_t>(read.transferred), std::memory_order_relaxed);
		assembler_.push_transfer(in_buffer_, static_cast<size_t>(read.transferred));
	} else if (read.result == usb::UsbResult::TIMEOUT) {
		counters_.read_timeouts.fetch_add(1, std::memory_order_relaxed); // The reply comes next cycle.
	} else {
		const char *hint = "";
		if (read.result == usb::UsbResult::NO_DEVICE) {
			hint = " (unplugged?)";
		} else if (read.result == usb::UsbResult::OVERFLOW) {
			hint = " (the transfer claimed more bytes than its buffer holds)";
		}
		r_exchange.fail(usb::usb_result_io(read.result), "Falcon USB read failed: %s%s", usb::usb_result_name(read.result), hint);
		return usb::usb_result_io(read.result);
	}
	take_replies(p_dt_s);
	if (since_frame_s_ > config_.silence_timeout_s) {
		r_exchange.fail(DeviceIo::FAILED, "Falcon stopped answering: no valid reply for %.0f ms (%llu malformed frames)",
				since_frame_s_ * 1000.0, static_cast<unsigned long long>(assembler_.counters().malformed_frames));
		return DeviceIo::FAILED;
	}
	DeviceState state;
	state.position_m = falcon_to_device_position(position_kinematic_);
	state.velocity_m_per_s = falcon_to_device_direction(velocity_);
	state.buttons = buttons_;
	state.ready = homed_ && have_position_;
	r_exchange.publish_state(state);
	return DeviceIo::OK;
}

void FalconDevice::io_stop() {
	// Zero torques, keeping the homing flag and the LED as they were.
	FalconCommand command;
	command.flags = static_cast<uint8_t>(FALCON_FLAG_HOMING | (homed_ ? FALCON_LED_GREEN : FALCON_LED_RED));
	FalconPacket packet;
	encode_falcon_command(command, packet);
	if (transport_->bulk_write(FALCON_ENDPOINT_OUT, packet, FALCON_PACKET_SIZE, config_.write_timeout_ms).ok()) {
		counters_.bytes_written.fetch_add(FALCON_PACKET_SIZE, std::memory_order_relaxed);
	}
}

} // namespace haptics::falcon
