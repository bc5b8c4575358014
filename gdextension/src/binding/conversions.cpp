#include "binding/conversions.h"

#include <iterator>
#include <utility>

#include "binding/dictionary_reader.h"
#include "core/base/coordinates.h"

namespace haptics::binding {

namespace {

Vec3 direction_from(const gd::Vector2 &p_game) {
	return game_to_device_direction(p_game.x, p_game.y);
}

// Velocities arrive in m/s already: only the axes change.
Vec3 velocity_from(const gd::Vector2 &p_game) {
	return game_to_device_scaled(p_game.x, p_game.y, 1.0);
}

bool read_contact(const gd::Dictionary &p_entry, const std::string &p_path, Contact &r_contact,
		std::string &r_error) {
	DictionaryReader reader(p_entry, p_path);
	reader.accept_old_key("stiffness", "stiffness_n");
	reader.accept_old_key("damping", "friction_n");
	gd::Vector2 normal;
	const bool has_material = reader.has("stiffness_n") || reader.has("friction_n");
	r_contact.use_default_material = !has_material;
	bool ok = reader.only_keys({ "normal", "stiffness_n", "friction_n" }) &&
			reader.read_vector2("normal", normal, true) &&
			reader.read_number("stiffness_n", r_contact.material.stiffness, has_material) &&
			reader.read_number("friction_n", r_contact.material.friction, has_material);
	r_contact.normal = direction_from(normal);
	if (!ok) {
		r_error = reader.error();
	}
	return ok;
}

bool read_resting(const gd::Dictionary &p_entry, const std::string &p_path, Frame &r_frame,
		std::string &r_error) {
	DictionaryReader reader(p_entry, p_path);
	reader.accept_old_key("mass", "mass_kg");
	gd::Vector2 normal;
	double mass = 0.0;
	if (!reader.only_keys({ "normal", "mass_kg" }) || !reader.read_vector2("normal", normal, true) ||
			!reader.read_number("mass_kg", mass, true)) {
		r_error = reader.error();
		return false;
	}
	r_frame.add_resting(direction_from(normal), mass);
	return true;
}

template <typename F>
bool read_list(DictionaryReader &r_reader, const char *p_key, size_t p_capacity, F &&p_read_one,
		std::string &r_error) {
	gd::Array list;
	if (!r_reader.read_array(p_key, list)) {
		r_error = r_reader.error();
		return false;
	}
	const int64_t count = list.size();
	const std::string path = r_reader.path() + "." + p_key;
	if (count > static_cast<int64_t>(p_capacity)) {
		r_error = path + ": " + std::to_string(count) + " entries, at most " +
				std::to_string(p_capacity);
		return false;
	}
	for (int64_t i = 0; i < count; ++i) {
		const std::string entry_path = path + "[" + std::to_string(i) + "]";
		gd::Variant entry = list.get(i);
		if (entry.get_type() != gd::VariantType::DICTIONARY) {
			r_error = entry_path + ": expected a Dictionary, got " + variant_type_name(entry.get_type());
			return false;
		}
		if (!p_read_one(gd::Dictionary(std::move(entry)), entry_path)) {
			return false;
		}
	}
	return true;
}

} // namespace

bool frame_from_dictionary(const gd::Dictionary &p_dictionary, Frame &r_frame, std::string &r_error) {
	Frame frame;
	DictionaryReader reader(p_dictionary, "frame");
	reader.accept_old_key("velocity", "velocity_m_per_s");
	reader.accept_old_key("time", "time_s");
	if (!reader.only_keys({ "contacts", "resting", "water", "velocity_m_per_s", "sequence", "time_s" })) {
		r_error = reader.error();
		return false;
	}
	const bool contacts_ok = read_list(
			reader, "contacts", MAX_CONTACTS,
			[&](const gd::Dictionary &p_entry, const std::string &p_path) {
				Contact &contact = frame.contacts[frame.contact_count];
				if (!read_contact(p_entry, p_path, contact, r_error)) {
					return false;
				}
				++frame.contact_count;
				return true;
			},
			r_error);
	const bool resting_ok = contacts_ok &&
			read_list(
					reader, "resting", MAX_RESTING_OBJECTS,
					[&](const gd::Dictionary &p_entry, const std::string &p_path) {
						return read_resting(p_entry, p_path, frame, r_error);
					},
					r_error);
	if (!resting_ok) {
		return false;
	}

	gd::Dictionary water;
	gd::Vector2 velocity;
	int64_t sequence = 0;
	if (!reader.read_dictionary("water", water) || !reader.read_vector2("velocity_m_per_s", velocity) ||
			!reader.read_int("sequence", sequence) || !reader.read_number("time_s", frame.timestamp_s)) {
		r_error = reader.error();
		return false;
	}
	DictionaryReader water_reader(water, "frame.water");
	water_reader.accept_old_key("drag", "drag_n_s_per_m");
	water_reader.accept_old_key("inertia", "inertia_n");
	if (!water_reader.only_keys({ "inside", "drag_n_s_per_m", "inertia_n" }) ||
			!water_reader.read_bool("inside", frame.water.inside) ||
			!water_reader.read_number("drag_n_s_per_m", frame.water.drag) ||
			!water_reader.read_number("inertia_n", frame.water.inertia)) {
		r_error = water_reader.error();
		return false;
	}
	frame.player_velocity = velocity_from(velocity);
	frame.sequence = static_cast<uint64_t>(sequence);
	r_frame = frame;
	return true;
}

bool impact_from_dictionary(const gd::Dictionary &p_dictionary, ImpactEvent &r_event,
		std::string &r_error) {
	ImpactEvent event;
	DictionaryReader reader(p_dictionary, "impact");
	reader.accept_old_key("speed", "speed_m_per_s");
	reader.accept_old_key("gain", "gain_n_s_per_m");
	reader.accept_old_key("frequency", "frequency_hz");
	reader.accept_old_key("decay", "decay_s");
	const bool has_material = reader.has("gain_n_s_per_m") || reader.has("frequency_hz") || reader.has("decay_s");
	gd::Vector2 direction;
	event.use_default_material = !has_material;
	const bool ok = reader.only_keys({ "direction", "speed_m_per_s", "gain_n_s_per_m", "frequency_hz", "decay_s" }) &&
			reader.read_vector2("direction", direction, true) &&
			reader.read_number("speed_m_per_s", event.speed, true) &&
			reader.read_number("gain_n_s_per_m", event.material.gain, has_material) &&
			reader.read_number("frequency_hz", event.material.frequency_hz, has_material) &&
			reader.read_number("decay_s", event.material.decay_s, has_material);
	if (!ok) {
		r_error = reader.error();
		return false;
	}
	event.direction = direction_from(direction);
	r_event = event;
	return true;
}

bool segments_from_points(const gd::PackedVector2Array &p_points, std::vector<Segment2> &r_segments,
		std::string &r_error) {
	const int64_t count = p_points.size();
	if (count % 2 != 0) {
		r_error = "segments: " + std::to_string(count) + " points; walls are point pairs, so it must be even";
		return false;
	}
	const gd::Vector2 *points = p_points.ptr();
	r_segments.clear();
	r_segments.reserve(static_cast<size_t>(count / 2));
	for (int64_t i = 0; i + 1 < count; i += 2) {
		r_segments.push_back({ { points[i].x, points[i].y }, { points[i + 1].x, points[i + 1].y } });
	}
	return true;
}

bool mapping_from_dictionary(const gd::Dictionary &p_dictionary, MazeMapping &r_mapping,
		std::string &r_error) {
	MazeMapping mapping;
	DictionaryReader reader(p_dictionary, "mapping");
	reader.accept_old_key("half_extent", "half_extent_m");
	reader.accept_old_key("centre", "centre_m");
	gd::Vector2 maze_min;
	gd::Vector2 maze_max;
	gd::Vector2 centre;
	if (!reader.only_keys({ "maze_min", "maze_max", "workspace", "half_extent_m", "centre_m" }) ||
			!reader.read_vector2("maze_min", maze_min, true) || !reader.read_vector2("maze_max", maze_max, true) ||
			!reader.read_number("half_extent_m", mapping.workspace_half_extent_m) ||
			!reader.read_vector2("centre_m", centre)) {
		r_error = reader.error();
		return false;
	}
	gd::Variant shape;
	if (p_dictionary.get(gd::Variant("workspace"), shape)) {
		int64_t index = -1; // The enum's value, or its name.
		if (shape.get_type() == gd::VariantType::INT) {
			index = shape.as_int();
		} else if (shape.get_type() == gd::VariantType::STRING) {
			index = name_index(shape.as_string(), WORKSPACE_SHAPE_NAMES);
		}
		if (index < 0 || index >= static_cast<int64_t>(std::size(WORKSPACE_SHAPE_NAMES))) {
			r_error = "mapping.workspace must be WORKSPACE_DISC, WORKSPACE_SQUARE, \"disc\" or \"square\" (got " +
					shape.stringify() + ")";
			return false;
		}
		mapping.workspace_shape = static_cast<WorkspaceShape>(index);
	}
	mapping.maze_min = { maze_min.x, maze_min.y };
	mapping.maze_max = { maze_max.x, maze_max.y };
	mapping.maze_y_down = true;
	// The centre is a device-plane point given in game axes like every other vector here.
	mapping.workspace_centre_m = { centre.x, -static_cast<double>(centre.y) };
	r_mapping = mapping;
	return true;
}

gd::Dictionary proxy_state_to_dictionary(const ProxyState &p_state) {
	gd::Dictionary d;
	d.set("position", gd::Vector2{ static_cast<float>(p_state.proxy.x), static_cast<float>(p_state.proxy.y) });
	d.set("goal", gd::Vector2{ static_cast<float>(p_state.goal.x), static_cast<float>(p_state.goal.y) });
	d.set("constraints", static_cast<int64_t>(p_state.constraints));
	d.set("placed", p_state.placed);
	d.set("updates", static_cast<int64_t>(p_state.updates));
	d.set("geometry_segments", static_cast<int64_t>(p_state.geometry_segments));
	return d;
}

gd::Vector2 to_game(const Vec3 &p_device) {
	const GameVec2 game = device_to_game(p_device);
	return { static_cast<float>(game.x), static_cast<float>(game.y) };
}

gd::Dictionary forces_to_dictionary(const ForceComponents &p_forces, std::span<const char *const> p_names) {
	gd::Dictionary d;
	for (size_t part = 0; part < p_names.size() && part < MAX_FORCE_PARTS; ++part) {
		d.set(p_names[part], to_game(p_forces.parts[part]));
	}
	d.set("continuous", to_game(p_forces.continuous));
	d.set("smoothed", to_game(p_forces.smoothed));
	d.set("impact", to_game(p_forces.impact));
	d.set("total", to_game(p_forces.total));
	return d;
}

// Stable lowercase names for scripts.
static const char *scheduler_script_name(SchedulerKind p_kind) {
	switch (p_kind) {
		case SchedulerKind::MANUAL:
			return "manual";
		case SchedulerKind::REALTIME_FIFO:
			return "realtime_fifo";
		case SchedulerKind::REALTIME_RR:
			return "realtime_rr";
		case SchedulerKind::MMCSS_PRO_AUDIO:
			return "mmcss_pro_audio";
		case SchedulerKind::MMCSS_GAMES:
			return "mmcss_games";
		case SchedulerKind::NORMAL:
			break;
	}
	return "normal";
}

gd::Dictionary stats_to_dictionary(const ServoStats &p_stats) {
	constexpr double MS = 1e3;
	constexpr double US = 1e6;
	gd::Dictionary d;
	d.set("running", p_stats.running);
	d.set("scheduler", scheduler_script_name(p_stats.scheduler));
	d.set("realtime", is_realtime_kind(p_stats.scheduler));
	d.set("realtime_priority", static_cast<int64_t>(p_stats.realtime_priority));
	// What RealtimeKit was asked and gave: "not asked", "realtime", "high priority",
	// "refused", "unavailable"; the nice level it granted; why, in words.
	d.set("realtime_kit", rtkit_outcome_name(p_stats.realtime_kit.outcome));
	d.set("realtime_kit_nice", static_cast<int64_t>(p_stats.realtime_kit.nice));
	d.set("realtime_kit_reason", p_stats.realtime_kit.reason);
	d.set("memory_locked", p_stats.memory_locked);
	d.set("cpu_latency_held", p_stats.cpu_latency_held);
	d.set("pinned_cpu", static_cast<int64_t>(p_stats.pinned_cpu));
	d.set("stack_prefaulted_kb", static_cast<int64_t>(p_stats.stack_prefaulted_kb));
	d.set("timer_slack_minimised", p_stats.timer_slack_minimised);
	d.set("spin_us", p_stats.spin_s * US);
	d.set("servo_cpu_percent", p_stats.thread_cpu_fraction * 100.0);
	d.set("nominal_rate_hz", p_stats.nominal_rate_hz);
	d.set("rate_hz", p_stats.achieved_rate_hz);
	d.set("ticks", static_cast<int64_t>(p_stats.ticks));
	d.set("period_mean_ms", p_stats.period_mean_s * MS);
	d.set("period_p50_ms", p_stats.period_p50_s * MS);
	d.set("period_p99_ms", p_stats.period_p99_s * MS);
	d.set("period_p999_ms", p_stats.period_p999_s * MS);
	d.set("period_max_ms", p_stats.period_max_s * MS);
	d.set("jitter_p99_us", p_stats.jitter_p99_s * US);
	d.set("latency_p99_us", p_stats.latency_p99_s * US);
	d.set("latency_max_us", p_stats.latency_max_s * US);
	d.set("late_ticks", static_cast<int64_t>(p_stats.late_ticks));
	d.set("missed_deadlines", static_cast<int64_t>(p_stats.missed_deadlines));
	d.set("tick_cost_p50_us", p_stats.tick_cost_p50_s * US);
	d.set("tick_cost_p99_us", p_stats.tick_cost_p99_s * US);
	d.set("frames_received", static_cast<int64_t>(p_stats.frames_received));
	d.set("frames_rejected", static_cast<int64_t>(p_stats.frames_rejected));
	d.set("frame_age_ms", p_stats.frame_age_s < 0.0 ? -1.0 : p_stats.frame_age_s * MS);
	d.set("watchdog_tripped", p_stats.watchdog_tripped);
	d.set("transient_drops", static_cast<int64_t>(p_stats.transient_drops));
	d.set("telemetry_drops", static_cast<int64_t>(p_stats.telemetry_drops));
	d.set("clamped_ticks", static_cast<int64_t>(p_stats.clamped_ticks));
	d.set("non_finite_ticks", static_cast<int64_t>(p_stats.non_finite_ticks));
	d.set("device_io_cycles", static_cast<int64_t>(p_stats.device_io_cycles));
	d.set("device_command_age_mean_ms", p_stats.device_command_age_mean_s * MS);
	d.set("device_command_age_max_ms", p_stats.device_command_age_max_s * MS);
	return d;
}

gd::Dictionary capabilities_to_dictionary(const DeviceCapabilities &p_capabilities) {
	gd::Dictionary d = limits_to_dictionary(p_capabilities.limits);
	d.set("input_dof", static_cast<int64_t>(p_capabilities.input_dof));
	d.set("output_dof", static_cast<int64_t>(p_capabilities.output_dof));
	const char *output = p_capabilities.output == ForceOutput::DIRECTIONAL ? "directional"
			: p_capabilities.output == ForceOutput::VIBRATION			   ? "vibration"
																		   : "none";
	d.set("output", output);
	d.set("native_rate_hz", p_capabilities.native_rate_hz);
	d.set("has_orientation", p_capabilities.has_orientation);
	d.set("needs_homing", p_capabilities.needs_homing);
	d.set("physical", p_capabilities.physical);
	d.set("button_count", static_cast<int64_t>(p_capabilities.button_count));
	return d;
}

gd::Dictionary device_status_to_dictionary(const DeviceStatus &p_status) {
	gd::Dictionary d;
	const char *io = p_status.io == DeviceIo::OK ? "ok" : p_status.io == DeviceIo::DISCONNECTED ? "disconnected"
																								: "failed";
	d.set("io", io);
	d.set("reason", std::string(p_status.reason));
	return d;
}

gd::Dictionary limits_to_dictionary(const DeviceLimits &p_limits) {
	gd::Dictionary d;
	d.set("max_force_n", p_limits.max_force_n);
	d.set("max_continuous_force_n", p_limits.max_continuous_force_n);
	d.set("max_stiffness_n_per_m", p_limits.max_stiffness_n_per_m);
	d.set("workspace_radius_m", p_limits.workspace_radius_m);
	return d;
}

} // namespace haptics::binding
