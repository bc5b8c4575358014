#pragma once

// The Sony DualSense (and Edge) as a HapticDevice: no directional force, so it renders what
// it can (dualsense_mapping.h: transients -> rumble, continuous force -> adaptive-trigger
// resistance, status -> lightbar) and reads its left stick as the 2-D input vector.
//
// Open: the transport (hidapi or the scripted pad), the link (from the transport, else the
// first input report), the firmware's update version (feature report 0x20) for the rumble
// recipe, a lightbar-setup report so the firmware hands the lightbar over, then the I/O
// thread at the pad's rate. The servo side only copies through a DeviceExchange.
//
// Capabilities (the limits are FULL-SCALES of the mapping, not newtons the pad can push):
//  - output VIBRATION, output_dof 0; input_dof 2 (left stick), 19 buttons; physical.
//  - native rate: 250 Hz over USB (the pad's input-report rate, widely reported; not in our
//    sources: a real pad confirms it), 125 Hz over Bluetooth (half: each BT output report is
//    78 bytes over a shared radio link, and the motors' own time constants are tens of ms).
//  - max_continuous_force_n = continuous_full_scale_n (2 N: the force model's default
//    contact stiffness, 2 N per unit input, at full stick deflection -> trigger strength 8),
//    so the safety stage's continuous cap is exactly the trigger's full scale.
//  - max_force_n = impact + continuous full-scales (5 N by default), so the total clamp never
//    eats into the impact share while a contact is held.
//  - workspace_radius_m = the nominal stick radius (5 cm): full deflection is |input| = 1.
//  - max_stiffness_n_per_m = continuous full-scale / radius (40 N/m): a position-control
//    renderer at that stiffness reaches full trigger strength at full deflection.

#include "core/device/device.h"
#include "devices/device_exchange.h"
#include "devices/device_io_thread.h"
#include "devices/dualsense/dualsense_io.h"
#include "devices/dualsense/dualsense_mapping.h"
#include "devices/dualsense/dualsense_transport.h"
#include "devices/exchanged_device.h"

#include <memory>

namespace haptics::dualsense {

enum class DualSenseModel : int32_t {
	DUALSENSE = 0, // 054C:0CE6
	EDGE = 1, // 054C:0DF2
};

struct DualSenseConfig {
	MappingConfig mapping;
	double stick_radius_m = 0.05; // (0, 1].
	double usb_rate_hz = 250.0; // (0, 1000].
	double bluetooth_rate_hz = 125.0; // (0, 1000].
	// hidapi < 0.13 only: how long open() waits for the first input report to tell USB from
	// Bluetooth; [1, 2000] ms.
	int32_t bus_probe_timeout_ms = 250;
};

Status validate_dualsense_config(const DualSenseConfig &p_config);

class DualSenseDevice final : public ExchangedDevice {
public:
	// p_transport may be null: open() then fails with INVALID_ARGUMENT.
	DualSenseDevice(std::unique_ptr<DualSenseTransport> p_transport, DualSenseModel p_model,
			const DualSenseConfig &p_config = {});
	~DualSenseDevice() override;

	DualSenseDevice(const DualSenseDevice &) = delete;
	DualSenseDevice &operator=(const DualSenseDevice &) = delete;

	Status open() override;
	// Stops the I/O thread (which writes the off report while the pad is reachable).
	void close() override;
	// Nothing to home: the pad centres its own sticks. NO_DEVICE when not open.
	Status calibrate() override;
	DeviceCapabilities capabilities() const override;
	const char *name() const override { return name_; }

	DeviceIo write_force(const ForceCommand &p_command) override;

	// Diagnostics (game thread).
	Bus bus() const { return bus_; }
	DualSenseModel model() const { return model_; }
	uint16_t update_version() const { return update_version_; } // 0 = unknown.
	RumbleRecipe rumble_recipe_in_use() const { return recipe_; }
	DualSenseIoStats pad_io_stats() const { return io_.stats(); }

private:
	Status find_bus();
	void read_firmware_version();
	void set_name();

	std::unique_ptr<DualSenseTransport> transport_;
	DualSenseModel model_;
	DualSenseConfig config_;
	DualSenseIo io_;
	DeviceIoThread thread_;
	Bus bus_ = Bus::UNKNOWN;
	uint16_t update_version_ = 0;
	RumbleRecipe recipe_ = RumbleRecipe::IMPROVED;
	char name_[64] = {};
};

} // namespace haptics::dualsense
