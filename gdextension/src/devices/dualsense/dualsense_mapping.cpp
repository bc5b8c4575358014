#include "devices/dualsense/dualsense_mapping.h"

#include <algorithm>
#include <cmath>

namespace haptics::dualsense {

namespace {

Status check_range(const char *p_name, double p_value, double p_min, double p_max, bool p_min_exclusive,
		bool p_max_exclusive = false) {
	const bool below = p_min_exclusive ? !(p_value > p_min) : !(p_value >= p_min);
	const bool above = p_max_exclusive ? !(p_value < p_max) : !(p_value <= p_max);
	if (!std::isfinite(p_value) || below || above) {
		return Status::error(std::isfinite(p_value) ? StatusCode::OUT_OF_RANGE : StatusCode::INVALID_ARGUMENT,
				"dualsense.%s must be in %s%g, %g%s (got %g)", p_name, p_min_exclusive ? "(" : "[", p_min, p_max,
				p_max_exclusive ? ")" : "]", p_value);
	}
	return Status::success();
}

double stick_axis(uint8_t p_raw) {
	return std::clamp((static_cast<double>(p_raw) - STICK_CENTRE) / 127.0, -1.0, 1.0);
}

uint8_t to_byte(double p_fraction) {
	return static_cast<uint8_t>(std::lround(std::clamp(p_fraction, 0.0, 1.0) * 255.0));
}

double finite_or_zero(double p_value) {
	return std::isfinite(p_value) ? p_value : 0.0;
}

} // namespace

Status validate_mapping_config(const MappingConfig &p_config) {
	Status status = check_range("impact_full_scale_n", p_config.impact_full_scale_n, 0.0, 100.0, true);
	if (status) {
		status = check_range("continuous_full_scale_n", p_config.continuous_full_scale_n, 0.0, 100.0, true);
	}
	if (status) {
		status = check_range("rumble_release_s", p_config.rumble_release_s, 0.0, 1.0, false);
	}
	if (status) {
		status = check_range("rumble_floor", p_config.rumble_floor, 0.0, 0.5, false, true);
	}
	if (status) {
		status = check_range("strong_motor_knee", p_config.strong_motor_knee, 0.0, 1.0, false);
	}
	if (status) {
		status = check_range("keep_alive_s", p_config.keep_alive_s, 0.0, 10.0, true);
	}
	if (status && (p_config.trigger_start_zone < 0 || p_config.trigger_start_zone >= TRIGGER_ZONES)) {
		status = Status::error(StatusCode::OUT_OF_RANGE, "dualsense.trigger_start_zone must be in [0, %d] (got %d)",
				TRIGGER_ZONES - 1, p_config.trigger_start_zone);
	}
	return status;
}

Vec3 stick_position_m(const PadInput &p_input, double p_radius_m) {
	return Vec3{ stick_axis(p_input.left_x) * p_radius_m, -stick_axis(p_input.left_y) * p_radius_m, 0.0 };
}

RumbleLevels RumbleMapper::update(double p_peak_n, double p_dt_s) {
	const double input = std::min(std::fabs(finite_or_zero(p_peak_n)) / config_.impact_full_scale_n, 1.0);
	const double kept = config_.rumble_release_s > 0.0 ? level_ * std::exp(-p_dt_s / config_.rumble_release_s) : 0.0;
	level_ = std::max(input, kept);
	if (level_ < config_.rumble_floor) {
		level_ = 0.0;
	}
	RumbleLevels levels;
	levels.right = to_byte(level_);
	const double knee = config_.strong_motor_knee;
	levels.left = knee < 1.0 ? to_byte((level_ - knee) / (1.0 - knee)) : 0;
	return levels;
}

int TriggerMapper::update(double p_continuous_n) {
	const double steps = std::fabs(finite_or_zero(p_continuous_n)) / config_.continuous_full_scale_n * TRIGGER_MAX_STRENGTH;
	// Only move when the force is clearly in another step: |steps - current| beyond half a
	// step plus the hysteresis.
	if (std::fabs(steps - strength_) > 0.5 + TRIGGER_HYSTERESIS_STEPS) {
		strength_ = steps < 0.5 ? 0 : static_cast<int>(std::clamp(std::lround(steps), 1L, static_cast<long>(TRIGGER_MAX_STRENGTH)));
	}
	return strength_;
}

OutputPlanner::OutputPlanner(const MappingConfig &p_config) {
	configure(p_config);
}

void OutputPlanner::configure(const MappingConfig &p_config) {
	config_ = p_config;
	rumble_.configure(p_config);
	trigger_.configure(p_config);
}

void OutputPlanner::reset() {
	rumble_.reset();
	trigger_.reset();
	sent_ = OutputState{};
	have_sent_ = false;
	since_sent_s_ = 0.0;
	stops_left_ = 0;
}

OutputState OutputPlanner::off_state() {
	OutputState state;
	state.right_trigger = trigger_off();
	state.left_trigger = trigger_off();
	state.lightbar = LIGHTBAR_IDLE;
	state.player_leds = 0;
	return state;
}

uint32_t OutputPlanner::plan(const ForceCommand &p_command, double p_impact_peak_n, double p_dt_s, OutputState &r_state) {
	const RumbleLevels levels = rumble_.update(p_impact_peak_n, p_dt_s);
	const int strength = trigger_.update(length(p_command.force_n - p_command.impact_n));

	OutputState next;
	next.motor_left = levels.left;
	next.motor_right = levels.right;
	TriggerEffect effect = trigger_off();
	if (strength > 0) {
		// Cannot fail: start zone validated by the config, strength in 1..8.
		trigger_feedback(config_.trigger_start_zone, strength, effect);
	}
	next.right_trigger = config_.right_trigger ? effect : trigger_off();
	next.left_trigger = config_.left_trigger ? effect : trigger_off();
	next.lightbar = strength > 0 ? LIGHTBAR_CONTACT : LIGHTBAR_IDLE;
	next.player_leds = PLAYER_LEDS_SESSION;
	r_state = next;

	since_sent_s_ += p_dt_s;
	uint32_t fields = 0;
	const bool motors_changed = next.motor_left != sent_.motor_left || next.motor_right != sent_.motor_right;
	if (!have_sent_ || since_sent_s_ >= config_.keep_alive_s) {
		fields = FIELDS_HELD;
	} else {
		if (!(next.right_trigger == sent_.right_trigger)) {
			fields |= FIELD_RIGHT_TRIGGER;
		}
		if (!(next.left_trigger == sent_.left_trigger)) {
			fields |= FIELD_LEFT_TRIGGER;
		}
		if (!(next.lightbar == sent_.lightbar)) {
			fields |= FIELD_LIGHTBAR;
		}
		if (next.player_leds != sent_.player_leds) {
			fields |= FIELD_PLAYER_LEDS;
		}
	}
	// Our rumble rides on every report while it is on, and the one that ends it states 0, as
	// does the keep-alive after it (a lost Bluetooth report would leave the pad rumbling);
	// otherwise the motor bits stay clear so a rumble of Godot's SDL is left alone.
	const bool rumbling = next.motor_left != 0 || next.motor_right != 0;
	if (motors_changed) {
		stops_left_ = rumbling ? 0 : STOP_REPORTS;
	}
	if (motors_changed || (fields != 0 && (rumbling || stops_left_ > 0))) {
		fields |= FIELD_RUMBLE;
		if (!rumbling && stops_left_ > 0) {
			--stops_left_;
		}
	}
	if (fields != 0) {
		sent_ = next;
		have_sent_ = true;
		since_sent_s_ = 0.0;
	}
	return fields;
}

} // namespace haptics::dualsense
