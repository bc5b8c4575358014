// SystemObject, registered as HapticsSystem: the one native class, which GDScript reaches
// through the Haptics door's native backend only. A thin adapter over the engine-free HapticsSystem (system/haptics_system.h)
// and its renderers' ports: values cross as the bytes of their schema (wire_values.h), so it
// names no game and converts no field by hand; rejected input is reported through the
// engine's error printer, naming the field, and a rejected call changes nothing. All
// behaviour lives below the binding.
//
// Vectors the 2D door reads every frame are in game axes (x right, y down); the hand target
// is device space. Lengths are metres, forces newtons.
#pragma once

#include <string>
#include <vector>

#include "binding/class_db.h"
#include "binding/containers.h"
#include "system/device_open.gen.h"
#include "system/haptics_system.h"

namespace haptics::binding {

class SystemObject : public gd::ExtensionObject {
public:
	static void bind_methods(gd::ClassBinder<SystemObject> &r_binder);

	// --- Devices --- (system_object_devices.cpp)
	// Every device present (the simulated one first, then hidapi, libusb, evdev and
	// OpenHaptics devices) and why the enumeration could not look everywhere: a
	// HapticDeviceList.
	gd::PackedByteArray list_devices();
	// The id of the simulated device, which every installation has ("simulated").
	std::string get_simulated_device_id() const;
	// Opens a device by id (get_simulated_device_id(), or an id from list_devices()). On
	// failure the current device stays open and rendering is untouched.
	bool open_device(const std::string &p_id);
	// A HapticDeviceOpenOptions: what the next open_device may change on the device. A refused
	// one is reported and leaves the options as they were.
	bool set_device_open_options(const gd::PackedByteArray &p_options);
	void close_device();
	std::string get_device_id() const;
	std::string get_device_name() const;
	// A HapticDeviceCapabilities (its limits inside; all zero limits without a device).
	gd::PackedByteArray get_device_capabilities() const;
	// A HapticDeviceStatus: the device's own account of a fault.
	gd::PackedByteArray get_device_status() const;
	bool calibrate();
	// Simulated device only: where its hand pulls the stylus, in metres, device space (x right,
	// y up, z toward the user).
	bool set_hand_target(gd::Vector3 p_target_m);
	gd::Vector3 get_hand_target() const;
	// Devices in software only (HapticDevice::software_cable): unplug (false) or replug it, to
	// exercise disconnect handling.
	bool set_simulated_plugged(bool p_plugged);

	// --- Rendering ---
	// p_spin_us: the busy-wait before each deadline in microseconds, [0, half a period]
	// (max_spin_ns), or SPIN_US_SERVO_DEFAULT for ServoOptions' own.
	bool start(double p_rate_hz, double p_spin_us);
	static constexpr double SPIN_US_SERVO_DEFAULT = -1.0;
	void stop();
	bool is_running() const;
	// Manual mode: one servo tick of p_dt seconds on the calling thread (deterministic).
	bool step(double p_dt);
	// "" while rendering is healthy, else why it stopped (e.g. the device was unplugged).
	std::string get_servo_status() const;

	// --- Game -> servo --- (each a HapticFrame's or HapticImpact's encode(), or their 3D
	// forms': a 3D frame tells the servo the game is 3D)
	bool submit_frame(const gd::PackedByteArray &p_frame);
	bool push_impact(const gd::PackedByteArray &p_impact);

	// --- Servo -> game ---
	gd::Vector2 get_input_vector() const;
	gd::Vector2 get_device_position() const;
	// A HapticForces: the active renderer's components (its force enum names them), then
	// continuous, smoothed, impact, total; game axes, N.
	gd::PackedByteArray get_forces() const;
	// The same three in a 3D game's view axes (x right, y up, z toward the viewer); the forces
	// as a HapticForces3D.
	gd::Vector3 get_input_vector_3d() const;
	gd::Vector3 get_device_position_3d() const;
	gd::PackedByteArray get_forces_3d() const;
	// A HapticServoStats.
	gd::PackedByteArray get_stats() const;
	// Up to p_max_samples samples of get_telemetry_stride() floats each, oldest first, in
	// DEVICE axes (y up); get_telemetry_columns() names the floats.
	gd::PackedFloat32Array drain_telemetry(int64_t p_max_samples);
	int64_t get_telemetry_stride() const;
	gd::PackedStringArray get_telemetry_columns() const;

	// --- Renderers ---
	// The renderers by name, in render-mode order (a mode is its name's index; the first is
	// the default).
	gd::PackedStringArray get_renderer_names() const;
	bool set_render_mode(int64_t p_mode);
	int64_t get_render_mode() const;
	// --- What one renderer offers of its own (core/render/renderer_port.h) ---
	// p_message: a value of that renderer's schema it takes (its encode()); refused ones are
	// reported by name and change nothing.
	bool renderer_send(int64_t p_mode, const gd::PackedByteArray &p_message);
	// The value of layout p_value_id it gives (its SCHEMA_ID); empty, and reported, when it
	// gives no such value.
	gd::PackedByteArray renderer_read(int64_t p_mode, int64_t p_value_id);

	// --- Settings --- (HapticServoSettings; each renderer's own, e.g. HapticMovementSettings)
	// Whole values: read, change a copy, hand it back; a refused one is reported by field and
	// changes nothing (any time, also while rendering).
	gd::PackedByteArray get_servo_settings() const;
	bool set_servo_settings(const gd::PackedByteArray &p_settings);
	gd::PackedByteArray get_renderer_settings(int64_t p_mode) const;
	bool set_renderer_settings(int64_t p_mode, const gd::PackedByteArray &p_settings);

	std::string get_version() const;

private:
	bool report(const char *p_method, const Status &p_status) const;

	RendererPort *port_of(const char *p_method, int64_t p_mode);

	HapticsSystem system_;
	std::string device_id_;
	gd::Vector3 hand_target_;
	DeviceOpenOptions open_options_;
};

} // namespace haptics::binding
