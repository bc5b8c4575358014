#include "binding/system_object.h"

#include <algorithm>
#include <cmath>

#include "binding/log.h"
#include "binding/version.h"
#include "binding/wire_values.h"
#include "core/base/coordinates.h"
#include "core/servo/telemetry.h"
#include "system/device_factory.h"
#include "system/renderer_registry.h"
#include "system/settings_validation.h"

namespace haptics::binding {

namespace {

constexpr int64_t NS_PER_US = 1000;

// Device space (y up) to the 2D game's axes (y down): the input vector and the device's
// position, which 2D games read every frame.
gd::Vector2 to_game(const Vec3 &p_device) {
	const GameVec2 game = device_to_game(p_device);
	return { static_cast<float>(game.x), static_cast<float>(game.y) };
}

// Device space to a 3D game's view axes: the same axes (core/base/coordinates.h).
gd::Vector3 to_space(const Vec3 &p_device) {
	return { static_cast<float>(p_device.x), static_cast<float>(p_device.y), static_cast<float>(p_device.z) };
}

} // namespace

void SystemObject::bind_methods(gd::ClassBinder<SystemObject> &r_binder) {
	using S = SystemObject;
	r_binder.bind_method("list_devices", &S::list_devices);
	r_binder.bind_method("get_simulated_device_id", &S::get_simulated_device_id);
	r_binder.bind_method("open_device", &S::open_device, { "id" });
	r_binder.bind_method("set_device_open_options", &S::set_device_open_options, { "options" });
	r_binder.bind_method("close_device", &S::close_device);
	r_binder.bind_method("get_device_id", &S::get_device_id);
	r_binder.bind_method("get_device_name", &S::get_device_name);
	r_binder.bind_method("get_device_capabilities", &S::get_device_capabilities);
	r_binder.bind_method("get_device_status", &S::get_device_status);
	r_binder.bind_method("calibrate", &S::calibrate);
	r_binder.bind_method("set_hand_target", &S::set_hand_target, { "target_m" });
	r_binder.bind_method("get_hand_target", &S::get_hand_target);
	r_binder.bind_method("set_simulated_plugged", &S::set_simulated_plugged, { "plugged" });
	r_binder.bind_method("start", &S::start, { "rate_hz", "spin_us" },
			{ gd::Variant(DEFAULT_RATE_HZ), gd::Variant(SPIN_US_SERVO_DEFAULT) });
	r_binder.bind_method("stop", &S::stop);
	r_binder.bind_method("is_running", &S::is_running);
	r_binder.bind_method("step", &S::step, { "dt" });
	r_binder.bind_method("get_servo_status", &S::get_servo_status);
	r_binder.bind_method("submit_frame", &S::submit_frame, { "frame" });
	r_binder.bind_method("push_impact", &S::push_impact, { "impact" });
	r_binder.bind_method("get_input_vector", &S::get_input_vector);
	r_binder.bind_method("get_device_position", &S::get_device_position);
	r_binder.bind_method("get_forces", &S::get_forces);
	r_binder.bind_method("get_input_vector_3d", &S::get_input_vector_3d);
	r_binder.bind_method("get_device_position_3d", &S::get_device_position_3d);
	r_binder.bind_method("get_forces_3d", &S::get_forces_3d);
	r_binder.bind_method("get_stats", &S::get_stats);
	r_binder.bind_method("drain_telemetry", &S::drain_telemetry, { "max_samples" },
			{ gd::Variant(static_cast<int64_t>(TELEMETRY_QUEUE_CAPACITY)) });
	r_binder.bind_method("get_telemetry_stride", &S::get_telemetry_stride);
	r_binder.bind_method("get_telemetry_columns", &S::get_telemetry_columns);
	r_binder.bind_method("get_renderer_names", &S::get_renderer_names);
	r_binder.bind_method("set_render_mode", &S::set_render_mode, { "mode" });
	r_binder.bind_method("get_render_mode", &S::get_render_mode);
	r_binder.bind_method("renderer_send", &S::renderer_send, { "mode", "message" });
	r_binder.bind_method("renderer_read", &S::renderer_read, { "mode", "value_id" });
	r_binder.bind_method("get_servo_settings", &S::get_servo_settings);
	r_binder.bind_method("set_servo_settings", &S::set_servo_settings, { "settings" });
	r_binder.bind_method("get_renderer_settings", &S::get_renderer_settings, { "mode" });
	r_binder.bind_method("set_renderer_settings", &S::set_renderer_settings, { "mode", "settings" });
	r_binder.bind_method("get_version", &S::get_version);
}

bool SystemObject::report(const char *p_method, const Status &p_status) const {
	if (!p_status.ok()) {
		gd::print_error(std::string(p_method) + ": " + p_status.message(), p_method, __FILE__, __LINE__);
	}
	return p_status.ok();
}

bool SystemObject::start(double p_rate_hz, double p_spin_us) {
	ServoOptions options;
	options.rate_hz = p_rate_hz;
	if (p_spin_us != SPIN_US_SERVO_DEFAULT) {
		// The spin's bound depends on the rate: a bad rate is reported as itself.
		const Status rate = validate_rate(p_rate_hz);
		if (!rate) {
			return report("start", rate);
		}
		const double max_spin_us = static_cast<double>(max_spin_ns(p_rate_hz)) / NS_PER_US;
		if (!(p_spin_us >= 0.0 && p_spin_us <= max_spin_us)) { // NaN fails both.
			return report("start",
					Status::error(std::isfinite(p_spin_us) ? StatusCode::OUT_OF_RANGE : StatusCode::INVALID_ARGUMENT,
							"spin_us must be in [0, %g] (half a period at %g Hz), or %g for the servo's default (got %g)",
							max_spin_us, p_rate_hz, SPIN_US_SERVO_DEFAULT, p_spin_us));
		}
		options.spin_ns = std::llround(p_spin_us * NS_PER_US);
	}
	return report("start", system_.start(options));
}

void SystemObject::stop() {
	system_.stop();
}

bool SystemObject::is_running() const {
	return system_.is_running();
}

bool SystemObject::step(double p_dt) {
	return report("step", system_.step(p_dt));
}

std::string SystemObject::get_servo_status() const {
	return system_.servo_status().message();
}

bool SystemObject::submit_frame(const gd::PackedByteArray &p_frame) {
	Frame frame;
	GameSpace space = GameSpace::PLANE;
	if (!decode_argument("submit_frame", p_frame, frame, &space)) {
		system_.count_rejected_frame();
		return false;
	}
	return report("submit_frame", system_.submit_frame(frame, space));
}

bool SystemObject::push_impact(const gd::PackedByteArray &p_impact) {
	ImpactEvent event;
	return decode_argument("push_impact", p_impact, event) && report("push_impact", system_.push_impact(event));
}

gd::Vector2 SystemObject::get_input_vector() const {
	return to_game(system_.input_vector());
}

gd::Vector2 SystemObject::get_device_position() const {
	return to_game(system_.device_position());
}

gd::PackedByteArray SystemObject::get_forces() const {
	return encode_result(system_.forces());
}

gd::Vector3 SystemObject::get_input_vector_3d() const {
	return to_space(system_.input_vector());
}

gd::Vector3 SystemObject::get_device_position_3d() const {
	return to_space(system_.device_position());
}

gd::PackedByteArray SystemObject::get_forces_3d() const {
	return encode_result(system_.forces(), GameSpace::SPACE);
}

gd::PackedByteArray SystemObject::get_stats() const {
	return encode_result(system_.stats());
}

gd::PackedFloat32Array SystemObject::drain_telemetry(int64_t p_max_samples) {
	gd::PackedFloat32Array out;
	if (p_max_samples <= 0) {
		return out;
	}
	const size_t max_samples =
			std::min(static_cast<size_t>(p_max_samples), static_cast<size_t>(TELEMETRY_QUEUE_CAPACITY));
	if (!out.resize(static_cast<int64_t>(max_samples * TELEMETRY_STRIDE))) {
		return gd::PackedFloat32Array();
	}
	const size_t count = system_.drain_telemetry(out.ptrw(), max_samples);
	out.resize(static_cast<int64_t>(count * TELEMETRY_STRIDE));
	return out;
}

int64_t SystemObject::get_telemetry_stride() const {
	return static_cast<int64_t>(TELEMETRY_STRIDE);
}

gd::PackedStringArray SystemObject::get_telemetry_columns() const {
	// The force parts' columns are named after the default renderer's components (the
	// movement renderer's five); other renderers fill them in their own order.
	const std::span<const char *const> parts = registered_renderers()[0].info->force_names;
	std::vector<std::string> vectors = { "input", "position" };
	for (size_t part = 0; part < MAX_FORCE_PARTS; ++part) {
		vectors.push_back(part < parts.size() ? parts[part] : "part" + std::to_string(part));
	}
	vectors.insert(vectors.end(), { "smoothed", "impact", "total" });
	gd::PackedStringArray names;
	names.append("t");
	for (const std::string &vector : vectors) {
		for (const char *axis : { "_x", "_y", "_z" }) {
			names.append(vector + axis);
		}
	}
	names.append("flags");
	return names;
}

gd::PackedStringArray SystemObject::get_renderer_names() const {
	gd::PackedStringArray names;
	for (const RegisteredRenderer &renderer : registered_renderers()) {
		names.append(renderer.name);
	}
	return names;
}

gd::PackedByteArray SystemObject::get_servo_settings() const {
	return encode_result(static_cast<const ServoSettings &>(system_.config().servo));
}

bool SystemObject::set_servo_settings(const gd::PackedByteArray &p_settings) {
	RenderConfig config = system_.config();
	ServoSettings &settings = config.servo;
	return decode_argument("set_servo_settings", p_settings, settings) &&
			report("set_servo_settings", system_.configure(config));
}

gd::PackedByteArray SystemObject::get_renderer_settings(int64_t p_mode) const {
	gd::PackedByteArray out;
	const RenderConfig &config = system_.config();
	if (!visit_renderer_settings(config, p_mode, [&](const auto &p_settings) { out = encode_result(p_settings); })) {
		HAPTICS_ERROR("get_renderer_settings: no renderer has mode " + std::to_string(p_mode));
	}
	return out;
}

bool SystemObject::set_renderer_settings(int64_t p_mode, const gd::PackedByteArray &p_settings) {
	RenderConfig config = system_.config();
	bool decoded = false;
	if (!visit_renderer_settings(config, p_mode,
				[&](auto &r_settings) { decoded = decode_argument("set_renderer_settings", p_settings, r_settings); })) {
		HAPTICS_ERROR("set_renderer_settings: no renderer has mode " + std::to_string(p_mode));
		return false;
	}
	return decoded && report("set_renderer_settings", system_.configure(config));
}

bool SystemObject::set_render_mode(int64_t p_mode) {
	const std::span<const RegisteredRenderer> renderers = registered_renderers();
	if (p_mode < 0 || p_mode >= static_cast<int64_t>(renderers.size())) {
		std::string modes; // "0 movement, 1 constraint, 2 pong"
		for (size_t mode = 0; mode < renderers.size(); ++mode) {
			modes += (mode == 0 ? "" : ", ") + std::to_string(mode) + " " + renderers[mode].name;
		}
		HAPTICS_ERROR("set_render_mode: unknown mode " + std::to_string(p_mode) + " (" + modes +
				"); the current mode stays.");
		return false;
	}
	RenderConfig config = system_.config();
	config.servo.render_mode = static_cast<int32_t>(p_mode);
	return report("set_render_mode", system_.configure(config));
}

int64_t SystemObject::get_render_mode() const {
	return static_cast<int64_t>(system_.config().servo.render_mode);
}

RendererPort *SystemObject::port_of(const char *p_method, int64_t p_mode) {
	const auto &ports = system_.renderers().all_ports;
	if (p_mode < 0 || p_mode >= static_cast<int64_t>(ports.size())) {
		HAPTICS_ERROR(std::string(p_method) + ": no renderer has mode " + std::to_string(p_mode) + " (0.." +
				std::to_string(ports.size() - 1) + ", get_renderer_names())");
		return nullptr;
	}
	return ports[static_cast<size_t>(p_mode)];
}

bool SystemObject::renderer_send(int64_t p_mode, const gd::PackedByteArray &p_message) {
	RendererPort *port = port_of("renderer_send", p_mode);
	return port && report("renderer_send", port->receive(bytes_of(p_message)));
}

gd::PackedByteArray SystemObject::renderer_read(int64_t p_mode, int64_t p_value_id) {
	RendererPort *port = port_of("renderer_read", p_mode);
	std::vector<uint8_t> bytes;
	if (!port || !report("renderer_read", port->give(static_cast<uint32_t>(p_value_id), bytes))) {
		return gd::PackedByteArray();
	}
	return to_packed(bytes);
}

std::string SystemObject::get_version() const {
	return std::string("haptics ") + EXTENSION_VERSION + " (Godot " +
			std::to_string(gd::api.version_major) + "." + std::to_string(gd::api.version_minor) +
			"." + std::to_string(gd::api.version_patch) + ")";
}

} // namespace haptics::binding
