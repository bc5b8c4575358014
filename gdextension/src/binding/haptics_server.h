// HapticsServer: the one class GDScript talks to. A thin adapter over the engine-free
// HapticsSystem (system/haptics_system.h) and the ports of the renderers that offer more
// than the servo (ConstraintPort, PongPort): it converts engine values to the core's plain
// structs and back (conversions.h) and reports rejected input through the engine's error
// printer, naming the offending field; a rejected call changes nothing. All behaviour lives
// below the binding.
//
// Vectors are in game axes (x right, y down). Lengths are metres, forces newtons.
#pragma once

#include <string>
#include <vector>

#include "binding/class_db.h"
#include "binding/containers.h"
#include "renderers/constraint/constraint_port.h"
#include "renderers/pong/pong_port.h"
#include "system/haptics_system.h"

namespace haptics::binding {

class HapticsServer : public gd::ExtensionObject {
public:
	static void bind_methods(gd::ClassBinder<HapticsServer> &r_binder);

	// --- Devices --- (haptics_server_devices.cpp)
	// Every device present: the simulated one first, then hidapi, libusb, evdev and
	// OpenHaptics devices, each a Dictionary (id, backend, vendor_id, product_id, path,
	// product, manufacturer, serial, usage_page, usage, known_haptic, model, driver,
	// openable, unavailable_reason).
	gd::Array list_devices();
	// The entry of list_devices() with this id; an empty Dictionary (and an error) if none.
	gd::Dictionary get_device(const std::string &p_id);
	// Why the last enumeration could not look everywhere (no USB bus, no permission...).
	gd::Array get_device_warnings() const;
	// The id of the simulated device, which every installation has ("simulated").
	std::string get_simulated_device_id() const;
	// Opens a device by id (get_simulated_device_id(), or an id from list_devices()). On
	// failure the current device stays open and rendering is untouched.
	bool open_device(const std::string &p_id);
	void close_device();
	std::string get_device_id() const;
	std::string get_device_name() const;
	// max_force_n, max_continuous_force_n, max_stiffness_n_per_m, workspace_radius_m.
	gd::Dictionary get_device_limits() const;
	// Limits plus input/output DOF, output kind, native rate, orientation, homing, buttons;
	// empty without a device.
	gd::Dictionary get_device_capabilities() const;
	// {io: "ok" | "disconnected" | "failed", reason}: the device's own account of a fault.
	gd::Dictionary get_device_status() const;
	bool calibrate();
	// Simulated device only: where its hand pulls the stylus, in metres (game axes).
	bool set_hand_target(gd::Vector2 p_target_m);
	gd::Vector2 get_hand_target() const;
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

	// --- Game -> servo --- (dictionary layouts: conversions.h)
	bool submit_frame(const gd::Dictionary &p_frame);
	bool push_impact(const gd::Dictionary &p_impact);

	// --- Servo -> game ---
	gd::Vector2 get_input_vector() const;
	gd::Vector2 get_device_position() const;
	// The active renderer's components by its names (movement and constraint: normal,
	// friction, weight, drag, inertia; Pong: contact, spin, effects), then continuous,
	// smoothed, impact, total: Vector2 N.
	gd::Dictionary get_forces() const;
	gd::Dictionary get_stats() const;
	// Up to p_max_samples samples of get_telemetry_stride() floats each, oldest first, in
	// DEVICE axes (y up); get_telemetry_columns() names the floats.
	gd::PackedFloat32Array drain_telemetry(int64_t p_max_samples);
	int64_t get_telemetry_stride() const;
	gd::Array get_telemetry_columns() const;

	// --- Constraint-based rendering (position control against a maze's walls) ---
	// RENDER_MODE_MOVEMENT (the default), RENDER_MODE_CONSTRAINT or RENDER_MODE_PONG.
	bool set_render_mode(int64_t p_mode);
	int64_t get_render_mode() const;
	// Walls as point pairs in maze units and how the maze maps onto the workspace
	// (conversions.h). On error the previous walls stay.
	bool set_constraint_geometry(const gd::PackedVector2Array &p_segments, const gd::Dictionary &p_mapping);
	// position (where to draw the avatar), goal (the device in maze units), constraints
	// (walls holding the proxy), placed, updates, geometry_segments.
	gd::Dictionary get_proxy_state() const;

	// --- Haptic Battle Pong (RENDER_MODE_PONG; haptics_server_pong.cpp) ---
	// World vectors are Godot's 3D world (Vector3, metres, y up) and pass straight through;
	// hand forces are the device player's device space. Layouts: pong_conversions.h.
	// The latest paddles and modes, every frame (in PONG mode also the watchdog's heartbeat).
	bool set_pong_input(const gd::Dictionary &p_input);
	// set_ball, effect or clear_effects, queued for the servo's next tick.
	bool pong_command(const gd::Dictionary &p_command);
	gd::Dictionary get_pong_state() const;
	// The events since the last drain, oldest first.
	gd::Array drain_pong_events();
	// Simulated device only: its hand target in DEVICE space (x right, y up, z toward the
	// user), metres, so the stylus can be moved in depth.
	bool set_hand_target_3d(gd::Vector3 p_target_m);

	// --- Configuration --- by section (system/config_table.h); only the keys given change.
	// get_config() returns every section with every key, get_config_fields() the table
	// itself (kinds, ranges, units, defaults).
	bool set_config(const std::string &p_section, const gd::Dictionary &p_values);
	gd::Dictionary get_config() const;
	gd::Array get_config_fields() const;

	std::string get_version() const;

private:
	bool report(const char *p_method, const Status &p_status) const;

	HapticsSystem system_;
	ConstraintPort constraint_{ system_.renderers().constraint.channels };
	PongPort pong_{ system_.renderers().pong.channels };
	std::string device_id_;
	gd::Vector2 hand_target_;
	std::vector<std::string> last_warnings_;
};

} // namespace haptics::binding
