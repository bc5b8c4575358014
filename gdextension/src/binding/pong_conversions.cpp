#include "binding/pong_conversions.h"

#include <iterator>
#include <utility>

#include "binding/dictionary_reader.h"
#include "renderers/pong/pong_renderer.h"

namespace haptics::binding {

namespace {

Vec3 from_godot(const gd::Vector3 &p_v) {
	return { p_v.x, p_v.y, p_v.z };
}

gd::Vector3 to_godot(const Vec3 &p_v) {
	return { static_cast<float>(p_v.x), static_cast<float>(p_v.y), static_cast<float>(p_v.z) };
}

// A Vector3 read into a Vec3, leaving it untouched when the key is absent.
bool read_vec3(DictionaryReader &r_reader, const char *p_key, Vec3 &r_value, bool p_required = false) {
	gd::Vector3 value = to_godot(r_value);
	if (!r_reader.read_vector3(p_key, value, p_required)) {
		return false;
	}
	r_value = from_godot(value);
	return true;
}

// A player index (one of p_first..PONG_MAX_PLAYERS - 1), so a huge int never wraps into a
// valid one. The configured count is checked by the core's validation.
bool read_player(DictionaryReader &r_reader, const char *p_key, int64_t p_first, int32_t &r_player, bool p_required,
		std::string &r_error) {
	int64_t player = r_player;
	if (!r_reader.read_int(p_key, player, p_required)) {
		r_error = r_reader.error();
		return false;
	}
	if (player < p_first || player >= PONG_MAX_PLAYERS) {
		r_error = r_reader.path() + "." + p_key + " must be " + (p_first < 0 ? "-1 or " : "") + "0.." +
				std::to_string(PONG_MAX_PLAYERS - 1) + " (got " + std::to_string(player) + ")";
		return false;
	}
	r_player = static_cast<int32_t>(player);
	return true;
}

bool read_player_input(const gd::Dictionary &p_entry, const std::string &p_path, PongPlayerInput &r_player,
		std::string &r_error) {
	DictionaryReader reader(p_entry, p_path);
	const bool ok = reader.only_keys({ "avatar", "kinematic", "paddle_offset", "paddle_velocity", "normal", "spin",
							"gun", "active", "pose_age_s" }) &&
			read_vec3(reader, "avatar", r_player.avatar) && reader.read_bool("kinematic", r_player.kinematic) &&
			read_vec3(reader, "paddle_offset", r_player.paddle_offset) &&
			read_vec3(reader, "paddle_velocity", r_player.paddle_velocity) &&
			read_vec3(reader, "normal", r_player.normal) && reader.read_bool("spin", r_player.spin) &&
			reader.read_bool("gun", r_player.gun) && reader.read_bool("active", r_player.active) &&
			reader.read_number("pose_age_s", r_player.pose_age_s);
	if (!ok) {
		r_error = reader.error();
	}
	return ok;
}

// A name out of p_names (an enum's names in value order), as its index.
template <size_t N>
bool read_name(DictionaryReader &r_reader, const char *p_key, const char *const (&p_names)[N], int64_t &r_index,
		std::string &r_error) {
	std::string name;
	if (!r_reader.read_string(p_key, name, true)) {
		r_error = r_reader.error();
		return false;
	}
	r_index = name_index(name, p_names);
	if (r_index < 0) {
		std::string known;
		for (const char *candidate : p_names) {
			known += (known.empty() ? "\"" : ", \"") + std::string(candidate) + "\"";
		}
		r_error = r_reader.path() + "." + p_key + " must be one of " + known + " (got \"" + name + "\")";
		return false;
	}
	return true;
}

bool read_effect(DictionaryReader &r_reader, PongCommand &r_command, std::string &r_error) {
	if (!r_reader.only_keys({ "type", "player", "kind", "direction", "magnitude_n", "duration_s", "owner" })) {
		r_error = r_reader.error();
		return false;
	}
	if (!read_player(r_reader, "player", 0, r_command.player, true, r_error)) {
		return false;
	}
	int64_t kind = 0;
	if (!read_name(r_reader, "kind", PONG_EFFECT_NAMES, kind, r_error)) {
		return false;
	}
	r_command.kind = static_cast<PongEffectKind>(kind);
	const bool directed = r_command.kind == PongEffectKind::RECOIL || r_command.kind == PongEffectKind::HIT;
	r_command.use_default_magnitude = !r_reader.has("magnitude_n");
	r_command.use_default_duration = !r_reader.has("duration_s");
	r_command.owner = r_command.player ^ 1; // The opponent across the court, unless named.
	if (!read_vec3(r_reader, "direction", r_command.direction, directed) ||
			!r_reader.read_number("magnitude_n", r_command.magnitude_n) ||
			!r_reader.read_number("duration_s", r_command.duration_s)) {
		r_error = r_reader.error();
		return false;
	}
	return read_player(r_reader, "owner", 0, r_command.owner, false, r_error);
}

gd::Dictionary paddle_to_dictionary(const PongPaddleState &p_paddle) {
	gd::Dictionary d;
	d.set("paddle_center", to_godot(p_paddle.center));
	d.set("normal", to_godot(p_paddle.normal));
	d.set("paddle_velocity", to_godot(p_paddle.velocity));
	d.set("in_contact", p_paddle.in_contact);
	return d;
}

} // namespace

bool pong_input_from_dictionary(const gd::Dictionary &p_dictionary, PongInput &r_input, std::string &r_error) {
	PongInput input;
	DictionaryReader reader(p_dictionary, "pong_input");
	gd::Array players;
	if (!reader.only_keys({ "beginner", "local_player", "players" }) || !reader.read_bool("beginner", input.beginner) ||
			!reader.read_array("players", players)) {
		r_error = reader.error();
		return false;
	}
	if (!read_player(reader, "local_player", -1, input.local_player, false, r_error)) {
		return false;
	}
	if (reader.has("players")) {
		const int64_t count = players.size();
		if (count < PONG_DEFAULT_PLAYERS || count > PONG_MAX_PLAYERS) {
			r_error = "pong_input.players: " + std::to_string(count) + " entries, expected 2 to " +
					std::to_string(PONG_MAX_PLAYERS) + " (player 0 near +z, 1 far -z, 2 at +x, 3 at -x)";
			return false;
		}
		// Seats not given are empty: no paddle of theirs touches the ball.
		for (int p = static_cast<int>(count); p < PONG_MAX_PLAYERS; ++p) {
			input.players[p].active = false;
		}
		for (int p = 0; p < static_cast<int>(count); ++p) {
			const std::string path = "pong_input.players[" + std::to_string(p) + "]";
			gd::Variant entry = players.get(p);
			if (entry.get_type() != gd::VariantType::DICTIONARY) {
				r_error = path + ": expected a Dictionary, got " + variant_type_name(entry.get_type());
				return false;
			}
			if (!read_player_input(gd::Dictionary(std::move(entry)), path, input.players[p], r_error)) {
				return false;
			}
		}
	}
	r_input = input;
	return true;
}

bool pong_command_from_dictionary(const gd::Dictionary &p_dictionary, PongCommand &r_command, std::string &r_error) {
	PongCommand command;
	DictionaryReader reader(p_dictionary, "pong_command");
	int64_t type = 0;
	if (!read_name(reader, "type", PONG_COMMAND_NAMES, type, r_error)) {
		return false;
	}
	command.type = static_cast<PongCommandType>(type);
	bool ok = true;
	switch (command.type) {
		case PongCommandType::SET_BALL:
		case PongCommandType::CORRECT_BALL:
			ok = reader.only_keys({ "type", "position", "velocity", "spin" }) &&
					read_vec3(reader, "position", command.position, true) &&
					read_vec3(reader, "velocity", command.velocity) && read_vec3(reader, "spin", command.spin);
			break;
		case PongCommandType::EFFECT:
			if (!read_effect(reader, command, r_error)) {
				return false;
			}
			break;
		case PongCommandType::CLEAR_EFFECTS:
			ok = reader.only_keys({ "type" });
			break;
	}
	if (!ok) {
		r_error = reader.error();
		return false;
	}
	r_command = command;
	return true;
}

gd::Dictionary pong_state_to_dictionary(const PongState &p_state) {
	gd::Dictionary d;
	d.set("time_s", p_state.time_s);
	gd::Dictionary ball;
	ball.set("position", to_godot(p_state.ball.position));
	ball.set("velocity", to_godot(p_state.ball.velocity));
	ball.set("spin", to_godot(p_state.ball.spin));
	ball.set("correction", to_godot(p_state.ball_correction));
	ball.set("correction_step_max", p_state.correction_step_max_m);
	d.set("ball", ball.variant());
	d.set("territory", static_cast<int64_t>(p_state.territory));
	gd::Array players;
	for (int p = 0; p < p_state.player_count && p < PONG_MAX_PLAYERS; ++p) {
		players.append(paddle_to_dictionary(p_state.players[p]).variant());
	}
	d.set("players", players.variant());
	gd::Dictionary hand;
	hand.set(PONG_FORCE_NAMES[CONTACT_FORCE], to_godot(p_state.hand_force.contact));
	hand.set(PONG_FORCE_NAMES[SPIN_FORCE], to_godot(p_state.hand_force.spin));
	hand.set(PONG_FORCE_NAMES[EFFECTS_FORCE], to_godot(p_state.hand_force.effects));
	hand.set("total", to_godot(p_state.hand_force.total));
	d.set("hand_force", hand.variant());
	gd::Array effects;
	for (uint32_t e = 0; e < p_state.effect_count && e < PONG_MAX_ACTIVE_EFFECTS; ++e) {
		gd::Dictionary effect;
		effect.set("kind", PONG_EFFECT_NAMES[static_cast<size_t>(p_state.effects[e].kind)]);
		effect.set("remaining_s", p_state.effects[e].remaining_s);
		effects.append(effect.variant());
	}
	d.set("effects", effects.variant());
	d.set("paddle_contacts", static_cast<int64_t>(p_state.paddle_contacts));
	d.set("bounces", static_cast<int64_t>(p_state.bounces));
	d.set("events_dropped", static_cast<int64_t>(p_state.events_dropped));
	d.set("remote_work_j", p_state.remote_work_j);
	return d;
}

gd::Dictionary pong_event_to_dictionary(const PongEvent &p_event) {
	gd::Dictionary d;
	d.set("type", PONG_EVENT_NAMES[static_cast<size_t>(p_event.type)]);
	d.set("time_s", p_event.time_s);
	d.set("position", to_godot(p_event.position));
	d.set("speed", p_event.speed);
	d.set("territory", static_cast<int64_t>(p_event.territory));
	d.set("player", static_cast<int64_t>(p_event.player));
	const auto wall = static_cast<size_t>(p_event.wall);
	const bool is_wall = p_event.type == PongEventType::WALL && wall < std::size(COURT_WALL_NAMES);
	d.set("wall", is_wall ? COURT_WALL_NAMES[wall] : "");
	d.set("back_wall_of", static_cast<int64_t>(p_event.back_wall_of));
	return d;
}

} // namespace haptics::binding
