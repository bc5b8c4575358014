#include "godot/conversions.h"

#include <utility>

#include "core/coordinates.h"
#include "godot/dictionary_reader.h"

namespace haptics::godot {

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
	gd::Vector2 normal;
	const bool has_material = reader.has("stiffness") || reader.has("damping");
	r_contact.use_default_material = !has_material;
	bool ok = reader.only_keys({ "normal", "stiffness", "damping" }) &&
			reader.read_vector2("normal", normal, true) &&
			reader.read_number("stiffness", r_contact.material.stiffness, has_material) &&
			reader.read_number("damping", r_contact.material.damping, has_material);
	r_contact.normal = direction_from(normal);
	if (!ok) {
		r_error = reader.error();
	}
	return ok;
}

bool read_resting(const gd::Dictionary &p_entry, const std::string &p_path, Frame &r_frame,
		std::string &r_error) {
	DictionaryReader reader(p_entry, p_path);
	gd::Vector2 normal;
	double mass = 0.0;
	if (!reader.only_keys({ "normal", "mass" }) || !reader.read_vector2("normal", normal, true) ||
			!reader.read_number("mass", mass, true)) {
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
	if (!reader.only_keys({ "contacts", "resting", "water", "velocity", "sequence", "time" })) {
		r_error = reader.error();
		return false;
	}
	const bool contacts_ok = read_list(reader, "contacts", MAX_CONTACTS,
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
			read_list(reader, "resting", MAX_RESTING_OBJECTS,
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
	if (!reader.read_dictionary("water", water) || !reader.read_vector2("velocity", velocity) ||
			!reader.read_int("sequence", sequence) || !reader.read_number("time", frame.timestamp_s)) {
		r_error = reader.error();
		return false;
	}
	DictionaryReader water_reader(water, "frame.water");
	if (!water_reader.only_keys({ "inside", "drag", "inertia" }) ||
			!water_reader.read_bool("inside", frame.water.inside) ||
			!water_reader.read_number("drag", frame.water.drag) ||
			!water_reader.read_number("inertia", frame.water.inertia)) {
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
	gd::Vector2 direction;
	const bool has_material = reader.has("gain") || reader.has("frequency") || reader.has("decay");
	event.use_default_material = !has_material;
	const bool ok = reader.only_keys({ "direction", "speed", "gain", "frequency", "decay" }) &&
			reader.read_vector2("direction", direction, true) &&
			reader.read_number("speed", event.speed, true) &&
			reader.read_number("gain", event.material.gain, has_material) &&
			reader.read_number("frequency", event.material.frequency_hz, has_material) &&
			reader.read_number("decay", event.material.decay_s, has_material);
	if (!ok) {
		r_error = reader.error();
		return false;
	}
	event.direction = direction_from(direction);
	r_event = event;
	return true;
}

namespace {

struct NumberField {
	const char *section;
	const char *key;
	double &(*field)(RenderConfig &);
};

// The numeric settings by section and name, as GDScript sees them.
const NumberField NUMBER_FIELDS[] = {
	{ "force_model", "dead_zone", [](RenderConfig &c) -> double & { return c.force_model.dead_zone; } },
	{ "force_model", "gravity", [](RenderConfig &c) -> double & { return c.force_model.gravity; } },
	{ "force_model", "input_radius", [](RenderConfig &c) -> double & { return c.force_model.input_radius_m; } },
	{ "force_model", "contact_stiffness", [](RenderConfig &c) -> double & { return c.force_model.default_contact.stiffness; } },
	{ "force_model", "contact_damping", [](RenderConfig &c) -> double & { return c.force_model.default_contact.damping; } },
	{ "force_model", "impact_gain", [](RenderConfig &c) -> double & { return c.force_model.default_impact.gain; } },
	{ "force_model", "impact_frequency", [](RenderConfig &c) -> double & { return c.force_model.default_impact.frequency_hz; } },
	{ "force_model", "impact_decay", [](RenderConfig &c) -> double & { return c.force_model.default_impact.decay_s; } },
	{ "smoothing", "cutoff_hz", [](RenderConfig &c) -> double & { return c.smoothing.cutoff_hz; } },
	{ "safety", "max_force", [](RenderConfig &c) -> double & { return c.safety.max_force_n; } },
	{ "safety", "max_impact_force", [](RenderConfig &c) -> double & { return c.safety.max_impact_force_n; } },
	{ "safety", "slew_rate", [](RenderConfig &c) -> double & { return c.safety.slew_rate_n_per_s; } },
	{ "safety", "startup_ramp", [](RenderConfig &c) -> double & { return c.safety.startup_ramp_s; } },
	{ "safety", "watchdog_timeout", [](RenderConfig &c) -> double & { return c.safety.watchdog_timeout_s; } },
	{ "safety", "watchdog_fade", [](RenderConfig &c) -> double & { return c.safety.watchdog_fade_s; } },
};

// An integer setting within [p_min, p_max]; false with r_error set when out of range or
// not an integer (the reader's message).
bool read_count(DictionaryReader &r_reader, const char *p_key, int64_t p_min, int64_t p_max,
		uint32_t &r_value, std::string &r_error) {
	int64_t value = r_value;
	if (!r_reader.read_int(p_key, value)) {
		return false;
	}
	if (value < p_min || value > p_max) {
		r_error = r_reader.path() + "." + p_key + " must be in [" + std::to_string(p_min) + ", " +
				std::to_string(p_max) + "] (got " + std::to_string(value) + ")";
		return false;
	}
	r_value = static_cast<uint32_t>(value);
	return true;
}

} // namespace

bool apply_config_section(const std::string &p_section, const gd::Dictionary &p_values,
		RenderConfig &r_config, std::string &r_error) {
	DictionaryReader reader(p_values, p_section);
	const gd::Array keys = p_values.keys();
	for (int64_t i = 0; i < keys.size(); ++i) {
		const std::string key = keys.get(i).as_string();
		bool handled = false;
		for (const NumberField &field : NUMBER_FIELDS) {
			if (p_section == field.section && key == field.key) {
				handled = true;
				if (!reader.read_number(field.key, field.field(r_config))) {
					r_error = reader.error();
					return false;
				}
			}
		}
		if (p_section == "constraint" && key == "stiffness") {
			handled = reader.read_number("stiffness", r_config.constraint.stiffness_n_per_m);
		} else if (p_section == "constraint" && key == "proxy_radius") {
			handled = reader.read_number("proxy_radius", r_config.constraint.proxy_radius);
		} else if (p_section == "constraint" && key == "max_iterations") {
			handled = read_count(reader, "max_iterations", 1, 16, r_config.constraint.max_iterations, r_error);
		} else if (p_section == "constraint" && key == "update") {
			gd::Variant value;
			p_values.get(gd::Variant("update"), value);
			const std::string mode = value.as_string();
			if (value.get_type() != gd::VariantType::STRING || (mode != "servo" && mode != "frame")) {
				r_error = "constraint.update must be \"servo\" or \"frame\" (got " + value.stringify() + ")";
				return false;
			}
			r_config.constraint.update = mode == "servo" ? ProxyUpdate::SERVO_RATE : ProxyUpdate::FRAME_RATE;
			handled = true;
		} else if (p_section == "smoothing" && key == "enabled") {
			bool enabled = r_config.smoothing.type != SmoothingType::OFF;
			handled = reader.read_bool("enabled", enabled);
			r_config.smoothing.type = enabled ? SmoothingType::BUTTERWORTH2 : SmoothingType::OFF;
		} else if (p_section == "telemetry" && key == "enabled") {
			handled = reader.read_bool("enabled", r_config.telemetry.enabled);
		} else if (p_section == "telemetry" && key == "decimation") {
			handled = read_count(reader, "decimation", 1, 1000, r_config.telemetry.decimation, r_error);
		}
		if (!handled) {
			if (r_error.empty()) {
				r_error = reader.error().empty() ? p_section + ": unknown setting '" + key + "'" : reader.error();
			}
			return false;
		}
	}
	return true;
}

gd::Dictionary config_to_dictionary(const RenderConfig &p_config) {
	RenderConfig config = p_config;
	gd::Dictionary sections;
	for (const char *section : { "force_model", "smoothing", "safety", "telemetry", "constraint" }) {
		gd::Dictionary values;
		for (const NumberField &field : NUMBER_FIELDS) {
			if (std::string(field.section) == section) {
				values.set(field.key, field.field(config));
			}
		}
		if (std::string(section) == "smoothing") {
			values.set("enabled", config.smoothing.type != SmoothingType::OFF);
		} else if (std::string(section) == "telemetry") {
			values.set("enabled", config.telemetry.enabled);
			values.set("decimation", static_cast<int64_t>(config.telemetry.decimation));
		} else if (std::string(section) == "constraint") {
			values.set("stiffness", config.constraint.stiffness_n_per_m);
			values.set("proxy_radius", config.constraint.proxy_radius);
			values.set("max_iterations", static_cast<int64_t>(config.constraint.max_iterations));
			values.set("update", config.constraint.update == ProxyUpdate::SERVO_RATE ? "servo" : "frame");
		}
		sections.set(section, values.variant());
	}
	return sections;
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
	gd::Vector2 maze_min;
	gd::Vector2 maze_max;
	gd::Vector2 centre;
	if (!reader.only_keys({ "maze_min", "maze_max", "workspace", "half_extent", "centre" }) ||
			!reader.read_vector2("maze_min", maze_min, true) || !reader.read_vector2("maze_max", maze_max, true) ||
			!reader.read_number("half_extent", mapping.workspace_half_extent_m) ||
			!reader.read_vector2("centre", centre)) {
		r_error = reader.error();
		return false;
	}
	gd::Variant shape;
	if (p_dictionary.get(gd::Variant("workspace"), shape)) {
		const std::string name = shape.as_string();
		if (shape.get_type() != gd::VariantType::STRING || (name != "disc" && name != "square")) {
			r_error = "mapping.workspace must be \"disc\" or \"square\" (got " + shape.stringify() + ")";
			return false;
		}
		mapping.workspace_shape = name == "disc" ? WorkspaceShape::DISC : WorkspaceShape::SQUARE;
	}
	mapping.maze_min = { maze_min.x, maze_min.y };
	mapping.maze_max = { maze_max.x, maze_max.y };
	mapping.maze_y_down = true;
	// The centre is a device-plane point given in game axes like every other vector here.
	mapping.workspace_centre_m = { centre.x, -static_cast<double>(centre.y) };
	r_mapping = mapping;
	return true;
}

gd::Dictionary proxy_state_to_dictionary(const ServoOutput &p_output) {
	gd::Dictionary d;
	d.set("position", gd::Vector2{ static_cast<float>(p_output.proxy_maze.x), static_cast<float>(p_output.proxy_maze.y) });
	d.set("goal", gd::Vector2{ static_cast<float>(p_output.goal_maze.x), static_cast<float>(p_output.goal_maze.y) });
	d.set("constraints", static_cast<int64_t>(p_output.proxy_constraints));
	d.set("placed", p_output.proxy_placed);
	d.set("updates", static_cast<int64_t>(p_output.proxy_updates));
	d.set("geometry_segments", static_cast<int64_t>(p_output.geometry_segments));
	return d;
}

gd::Vector2 to_game(const Vec3 &p_device) {
	const GameVec2 game = device_to_game(p_device);
	return { static_cast<float>(game.x), static_cast<float>(game.y) };
}

gd::Dictionary forces_to_dictionary(const ForceComponents &p_forces) {
	gd::Dictionary d;
	d.set("normal", to_game(p_forces.normal));
	d.set("friction", to_game(p_forces.friction));
	d.set("weight", to_game(p_forces.weight));
	d.set("drag", to_game(p_forces.drag));
	d.set("inertia", to_game(p_forces.inertia));
	d.set("continuous", to_game(p_forces.continuous));
	d.set("smoothed", to_game(p_forces.smoothed));
	d.set("impact", to_game(p_forces.impact));
	d.set("total", to_game(p_forces.total));
	return d;
}

gd::Dictionary stats_to_dictionary(const ServoStats &p_stats) {
	constexpr double MS = 1e3;
	constexpr double US = 1e6;
	gd::Dictionary d;
	d.set("running", p_stats.running);
	// Stable lowercase names for scripts: manual, normal, realtime_fifo.
	const char *scheduler = p_stats.scheduler == SchedulerKind::MANUAL ? "manual"
			: p_stats.scheduler == SchedulerKind::REALTIME_FIFO                ? "realtime_fifo"
																				: "normal";
	d.set("scheduler", scheduler);
	d.set("realtime", p_stats.scheduler == SchedulerKind::REALTIME_FIFO);
	d.set("realtime_priority", static_cast<int64_t>(p_stats.realtime_priority));
	d.set("nominal_rate_hz", p_stats.nominal_rate_hz);
	d.set("rate_hz", p_stats.achieved_rate_hz);
	d.set("ticks", static_cast<int64_t>(p_stats.ticks));
	d.set("period_mean_ms", p_stats.period_mean_s * MS);
	d.set("period_p50_ms", p_stats.period_p50_s * MS);
	d.set("period_p99_ms", p_stats.period_p99_s * MS);
	d.set("period_p999_ms", p_stats.period_p999_s * MS);
	d.set("period_max_ms", p_stats.period_max_s * MS);
	d.set("jitter_p99_us", p_stats.jitter_p99_s * US);
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
	return d;
}

gd::Dictionary limits_to_dictionary(const DeviceLimits &p_limits) {
	gd::Dictionary d;
	d.set("max_force", p_limits.max_force_n);
	d.set("max_continuous_force", p_limits.max_continuous_force_n);
	d.set("max_stiffness", p_limits.max_stiffness_n_per_m);
	d.set("workspace_radius", p_limits.workspace_radius_m);
	return d;
}

} // namespace haptics::godot
