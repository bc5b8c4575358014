#include "devices/pid/pid_effect.h"

#include <chrono>
#include <thread>

namespace haptics::pid {

namespace {

StatusCode code_for(DeviceIo p_io) {
	return p_io == DeviceIo::DISCONNECTED ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR;
}

Status write_report(hid::HidTransport &r_transport, const PidReport &p_report, const char *p_what) {
	const DeviceIo io = r_transport.write_output(p_report.view());
	if (io != DeviceIo::OK) {
		return Status::error(code_for(io), "PID %s report failed: %s", p_what, r_transport.last_error());
	}
	return Status::success();
}

} // namespace

Status send_device_command(hid::HidTransport &r_transport, const PidLayout &p_layout, DeviceCommand p_command) {
	PidReport report;
	if (!encode_device_control(p_layout, p_command, report)) {
		return Status::error(StatusCode::UNSUPPORTED, "PID device has no Device Control '%s'", device_command_name(p_command));
	}
	return write_report(r_transport, report, device_command_name(p_command));
}

Status send_device_gain(hid::HidTransport &r_transport, const PidLayout &p_layout, uint16_t p_gain) {
	PidReport report;
	if (!encode_device_gain(p_layout, p_gain, report)) {
		return Status::error(StatusCode::DEVICE_ERROR, "PID Device Gain %u does not fit its field", p_gain);
	}
	return write_report(r_transport, report, "Device Gain");
}

Status initialize_device(hid::HidTransport &r_transport, const PidLayout &p_layout, uint16_t p_gain) {
	const DeviceCommand sequence[] = { DeviceCommand::RESET, DeviceCommand::RESET, DeviceCommand::STOP_ALL_EFFECTS,
		DeviceCommand::ENABLE_ACTUATORS };
	for (const DeviceCommand command : sequence) {
		const Status status = send_device_command(r_transport, p_layout, command);
		if (!status) {
			return status;
		}
	}
	return send_device_gain(r_transport, p_layout, p_gain);
}

Status ConstantForceEffect::upload(hid::HidTransport &r_transport, const PidLayout &p_layout, uint16_t p_direction,
		int16_t p_level, const PidEffectOptions &p_options) {
	layout_ = nullptr;
	PidReport report;
	if (!encode_create_constant_effect(p_layout, report)) {
		return Status::error(StatusCode::DEVICE_ERROR, "PID Create New Effect: the constant-force type does not fit its field");
	}
	DeviceIo io = r_transport.send_feature(report.view());
	if (io != DeviceIo::OK) {
		return Status::error(code_for(io), "PID Create New Effect failed: %s", r_transport.last_error());
	}

	// Block Load: the device answers Success with the block index it allocated, or Full or
	// Error; anything else (no answer, garbage) is asked again, 60 times as Linux.
	const hid::Report &load = p_layout.report(p_layout.block_load.report);
	BlockLoadResult result = BlockLoadResult::GARBAGE;
	bool answered = false;
	uint8_t block_index = 0;
	for (uint32_t attempt = 0; attempt < p_options.block_load_attempts; ++attempt) {
		PidReport reply;
		reply.length = static_cast<uint16_t>(load.byte_length);
		reply.bytes[0] = load.id;
		size_t received = 0;
		io = r_transport.get_feature(reply.data(), received);
		if (io == DeviceIo::DISCONNECTED) {
			return Status::error(StatusCode::DEVICE_DISCONNECTED, "PID Block Load failed: %s", r_transport.last_error());
		}
		if (io == DeviceIo::OK) {
			answered = true;
			result = decode_block_load(p_layout, reply.view().first(received < reply.length ? received : reply.length), block_index);
			if (result != BlockLoadResult::GARBAGE) {
				break;
			}
		}
		if (p_options.block_load_retry_delay_us > 0) {
			std::this_thread::sleep_for(std::chrono::microseconds(p_options.block_load_retry_delay_us));
		}
	}
	switch (result) {
		case BlockLoadResult::SUCCESS:
			break;
		case BlockLoadResult::FULL:
			return Status::error(StatusCode::DEVICE_ERROR, "PID device has no free effect slot (Block Load: Full)");
		case BlockLoadResult::ERROR:
			return Status::error(StatusCode::DEVICE_ERROR, "PID device refused the effect (Block Load: Error)");
		case BlockLoadResult::GARBAGE:
			return Status::error(StatusCode::DEVICE_ERROR,
					"PID device did not confirm the effect in %u Block Load requests (%s)", p_options.block_load_attempts,
					answered ? "its replies were not a valid Block Load report" : r_transport.last_error());
	}

	block_index_ = block_index;
	Status status = encode_set_effect(p_layout, block_index_, p_direction, report)
			? write_report(r_transport, report, "Set Effect")
			: Status::error(StatusCode::DEVICE_ERROR, "PID Set Effect: block index %u does not fit its field", block_index_);
	if (status) {
		status = encode_set_constant_force(p_layout, block_index_, p_level, report)
				? write_report(r_transport, report, "Set Constant Force")
				: Status::error(StatusCode::DEVICE_ERROR, "PID Set Constant Force: a value does not fit its field");
	}
	if (!status) {
		if (status.code() != StatusCode::DEVICE_DISCONNECTED && encode_block_free(p_layout, block_index_, report)) {
			(void)r_transport.write_output(report.view()); // Best effort: give the slot back.
		}
		return status;
	}
	layout_ = &p_layout;
	loop_count_ = 0;
	direction_value_ = pid::direction_value(p_layout, p_direction);
	magnitude_value_ = pid::magnitude_value(p_layout, p_level);
	reports_sent_ = 0; // Counts what play/update/stop/erase send afterwards.
	bytes_sent_ = 0;
	return Status::success();
}

DeviceIo ConstantForceEffect::send(hid::HidTransport &r_transport, const PidReport &p_report) {
	const DeviceIo io = r_transport.write_output(p_report.view());
	if (io == DeviceIo::OK) {
		++reports_sent_;
		bytes_sent_ += p_report.length;
	}
	return io;
}

DeviceIo ConstantForceEffect::play(hid::HidTransport &r_transport, uint8_t p_loop_count) {
	if (!layout_ || !encode_effect_operation(*layout_, block_index_, EffectOperation::START, p_loop_count, scratch_)) {
		return DeviceIo::FAILED;
	}
	loop_count_ = p_loop_count;
	return send(r_transport, scratch_);
}

DeviceIo ConstantForceEffect::update(hid::HidTransport &r_transport, uint16_t p_direction, int16_t p_level,
		PidUpdateResult *r_result) {
	if (!layout_) {
		return DeviceIo::FAILED;
	}
	const int64_t direction = pid::direction_value(*layout_, p_direction);
	const int64_t magnitude = pid::magnitude_value(*layout_, p_level);
	PidUpdateResult result;
	// Linux's order for an update: Set Effect, then the type-specific block.
	if (direction != direction_value_) {
		if (!encode_set_effect(*layout_, block_index_, p_direction, scratch_)) {
			return DeviceIo::FAILED;
		}
		const DeviceIo io = send(r_transport, scratch_);
		if (io != DeviceIo::OK) {
			return io;
		}
		direction_value_ = direction;
		result.sent_set_effect = true;
	}
	if (magnitude != magnitude_value_) {
		if (!encode_set_constant_force(*layout_, block_index_, p_level, scratch_)) {
			return DeviceIo::FAILED;
		}
		const DeviceIo io = send(r_transport, scratch_);
		if (io != DeviceIo::OK) {
			return io;
		}
		magnitude_value_ = magnitude;
		result.sent_set_constant = true;
	}
	if (r_result) {
		*r_result = result;
	}
	return DeviceIo::OK;
}

DeviceIo ConstantForceEffect::stop(hid::HidTransport &r_transport) {
	if (!layout_ || !encode_effect_operation(*layout_, block_index_, EffectOperation::STOP, loop_count_, scratch_)) {
		return DeviceIo::FAILED;
	}
	return send(r_transport, scratch_);
}

DeviceIo ConstantForceEffect::erase(hid::HidTransport &r_transport) {
	if (!layout_) {
		return DeviceIo::OK;
	}
	const DeviceIo io = stop(r_transport);
	if (io == DeviceIo::DISCONNECTED) {
		layout_ = nullptr;
		return io;
	}
	const DeviceIo freed = free_block(r_transport);
	return io == DeviceIo::OK ? freed : io;
}

DeviceIo ConstantForceEffect::free_block(hid::HidTransport &r_transport) {
	if (!layout_) {
		return DeviceIo::OK;
	}
	const DeviceIo io = encode_block_free(*layout_, block_index_, scratch_) ? send(r_transport, scratch_) : DeviceIo::FAILED;
	layout_ = nullptr;
	return io;
}

} // namespace haptics::pid
