#include "devices/dualsense/dualsense_device.h"

#include <cmath>
#include <cstdio>

namespace haptics::dualsense {

namespace {

Status check_range(const char *p_name, double p_value, double p_min, double p_max) {
	if (!std::isfinite(p_value) || !(p_value > p_min) || !(p_value <= p_max)) {
		return Status::error(std::isfinite(p_value) ? StatusCode::OUT_OF_RANGE : StatusCode::INVALID_ARGUMENT,
				"dualsense.%s must be in (%g, %g] (got %g)", p_name, p_min, p_max, p_value);
	}
	return Status::success();
}

StatusCode status_code_for(TransportIo p_io) {
	return p_io == TransportIo::DISCONNECTED ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR;
}

} // namespace

Status validate_dualsense_config(const DualSenseConfig &p_config) {
	Status status = validate_mapping_config(p_config.mapping);
	if (status) {
		status = check_range("stick_radius_m", p_config.stick_radius_m, 0.0, 1.0);
	}
	if (status) {
		status = check_range("usb_rate_hz", p_config.usb_rate_hz, 0.0, 1000.0);
	}
	if (status) {
		status = check_range("bluetooth_rate_hz", p_config.bluetooth_rate_hz, 0.0, 1000.0);
	}
	if (status && (p_config.bus_probe_timeout_ms < 1 || p_config.bus_probe_timeout_ms > 2000)) {
		status = Status::error(StatusCode::OUT_OF_RANGE, "dualsense.bus_probe_timeout_ms must be in [1, 2000] (got %d)",
				p_config.bus_probe_timeout_ms);
	}
	return status;
}

DualSenseDevice::DualSenseDevice(std::unique_ptr<DualSenseTransport> p_transport, DualSenseModel p_model,
		const DualSenseConfig &p_config) :
		transport_(std::move(p_transport)),
		model_(p_model),
		config_(p_config),
		io_(transport_.get(), p_config.mapping, p_config.stick_radius_m) {
	set_name();
}

DualSenseDevice::~DualSenseDevice() {
	close();
}

void DualSenseDevice::set_name() {
	const char *model = model_ == DualSenseModel::EDGE ? "Sony DualSense Edge" : "Sony DualSense";
	if (bus_ == Bus::UNKNOWN) {
		std::snprintf(name_, sizeof(name_), "%s", model);
	} else {
		std::snprintf(name_, sizeof(name_), "%s (%s)", model, bus_name(bus_));
	}
}

Status DualSenseDevice::find_bus() {
	bus_ = transport_->bus();
	if (bus_ != Bus::UNKNOWN) {
		return Status::success();
	}
	// hidapi < 0.13: the first input report tells (USB 0x01/64, BT 0x31/78 or short 0x01).
	uint8_t report[DualSenseIo::INPUT_BUFFER_SIZE];
	size_t size = 0;
	const TransportIo read = transport_->read_input(report, sizeof(report), size, config_.bus_probe_timeout_ms);
	if (read != TransportIo::OK && read != TransportIo::NO_DATA) {
		return Status::error(status_code_for(read), "DualSense at %s: cannot read an input report (%s)", transport_->location(),
				transport_->error_text());
	}
	bus_ = bus_from_input_report(report, size);
	if (bus_ == Bus::UNKNOWN) {
		return Status::error(StatusCode::DEVICE_ERROR,
				"DualSense at %s: no recognisable input report within %d ms (got %zu bytes, ID 0x%02X), cannot tell USB from Bluetooth",
				transport_->location(), config_.bus_probe_timeout_ms, size, size > 0 ? report[0] : 0u);
	}
	return Status::success();
}

void DualSenseDevice::read_firmware_version() {
	// Unknown (0) when the report is missing or garbled: SDL then assumes an updated pad,
	// and so the improved rumble recipe (dualsense_report.h).
	update_version_ = 0;
	uint8_t report[FEATURE_FIRMWARE_INFO_SIZE];
	size_t size = 0;
	if (transport_->get_feature(FEATURE_FIRMWARE_INFO_ID, report, sizeof(report), size) == TransportIo::OK) {
		uint16_t version = 0;
		if (parse_firmware_info(report, size, bus_, version) == FirmwareInfoParse::OK) {
			update_version_ = version;
		}
	}
	recipe_ = rumble_recipe(update_version_, model_ == DualSenseModel::EDGE);
}

Status DualSenseDevice::open() {
	close();
	if (!transport_) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "DualSense: no transport");
	}
	const Status valid = validate_dualsense_config(config_);
	if (!valid) {
		return valid;
	}
	Status status = transport_->open();
	if (status) {
		status = find_bus();
	}
	if (!status) {
		transport_->close();
		return status;
	}
	read_firmware_version();
	io_.begin(bus_, recipe_);
	// Take the lightbar from the firmware first (PS-K dualsense_reset_leds); also switches a
	// Bluetooth pad to full input reports. The first I/O cycle then sends the whole state.
	const TransportIo setup = io_.send(OutputPlanner::off_state(), FIELD_LIGHTBAR_SETUP);
	if (setup != TransportIo::OK) {
		status = Status::error(status_code_for(setup), "DualSense at %s: the first output report failed (%s)",
				transport_->location(), transport_->error_text());
		transport_->close();
		return status;
	}
	DeviceState initial;
	initial.ready = false;
	exchange_.reset(initial);
	DeviceIoThreadOptions options;
	options.rate_hz = bus_ == Bus::BLUETOOTH ? config_.bluetooth_rate_hz : config_.usb_rate_hz;
	status = thread_.start(io_, exchange_, options);
	if (!status) {
		io_.send_off();
		transport_->close();
		return status;
	}
	set_name();
	open_ = true;
	return Status::success();
}

void DualSenseDevice::close() {
	if (!open_) {
		return;
	}
	thread_.stop(); // Runs io_stop() (off report) unless the cycle had failed.
	open_ = false;
	transport_->close();
}

Status DualSenseDevice::calibrate() {
	if (!open_) {
		return Status::error(StatusCode::NO_DEVICE, "cannot calibrate '%s': device not open", name_);
	}
	return Status::success();
}

DeviceCapabilities DualSenseDevice::capabilities() const {
	const MappingConfig &mapping = config_.mapping;
	DeviceCapabilities capabilities;
	capabilities.input_dof = 2;
	capabilities.output_dof = 0;
	capabilities.output = ForceOutput::VIBRATION;
	capabilities.limits.max_force_n = mapping.impact_full_scale_n + mapping.continuous_full_scale_n;
	capabilities.limits.max_continuous_force_n = mapping.continuous_full_scale_n;
	capabilities.limits.max_stiffness_n_per_m = mapping.continuous_full_scale_n / config_.stick_radius_m;
	capabilities.limits.workspace_radius_m = config_.stick_radius_m;
	capabilities.native_rate_hz = bus_ == Bus::BLUETOOTH ? config_.bluetooth_rate_hz : config_.usb_rate_hz;
	capabilities.has_orientation = false;
	capabilities.needs_homing = false;
	capabilities.physical = true;
	capabilities.button_count = static_cast<int32_t>(BUTTON_COUNT);
	return capabilities;
}

DeviceIo DualSenseDevice::write_force(const ForceCommand &p_command) {
	if (open_) {
		io_.offer_impact(p_command.impact_n); // The transients' peak, for the rumble.
	}
	return ExchangedDevice::write_force(p_command);
}

} // namespace haptics::dualsense
