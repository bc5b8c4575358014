#pragma once

// How a pad without directional force renders what the servo computes. The servo hands the
// device a ForceCommand each tick (force_n = continuous + transients, impact_n = the
// transients' share); the DualSense can make two things the player feels:
//
// 1. IMPACT TRANSIENTS -> RUMBLE. The transients are decaying sinusoids (transients.h,
//    150 Hz by default), so their instantaneous value swings through zero; what the hand
//    should feel is their ENVELOPE. The servo records the peak |impact_n| of its ticks
//    (1 kHz) and each I/O cycle takes that peak (a 250 Hz cycle sees about 4 ticks, enough to
//    catch the crest of any transient above ~125 Hz; slower ones are felt as the pulsing
//    they are). A release filter (time constant rumble_release_s) smooths the step between
//    windows; below rumble_floor the level is exactly zero, so a hit always ends in silence.
//    level u = envelope / impact_full_scale_n, clamped to 1. The full-scale defaults to the
//    servo's impact cap (SafetyConfig::max_impact_force_n, 3 N), so the strongest impact
//    the servo can render is full rumble.
//    Motors: the RIGHT (weak, high-frequency) motor gets u for every hit: the transients
//    are short, high-frequency knocks, which is what that motor renders crisply. The LEFT
//    (strong, low-frequency) motor joins only above strong_motor_knee:
//    (u - knee) / (1 - knee). It spins up slowly (a heavy eccentric mass), which smears a
//    small tap into a buzz, but it gives a big crash its thud. The impact's frequency is not
//    in the command, so magnitude decides; "large" stands in for "large and slow".
//
// 2. CONTINUOUS FORCE -> ADAPTIVE-TRIGGER RESISTANCE. |force_n - impact_n| (the contact and
//    weight forces the stylus would push back with) sets a feedback-mode resistance
//    (dualsense_triggers.h) from trigger_start_zone to the end of the travel, strength
//    1..8 = round(8 |F| / continuous_full_scale_n), off (mode 0x05) below half a step. A
//    0.15-step hysteresis stops a force hovering at a boundary from flipping the level (and
//    sending a report) every cycle. Both triggers by default: the player's index fingers
//    rest on L2/R2 while the thumb steers the stick, so the resistance is felt whichever
//    trigger is held; either can be turned off. The start zone (2 of 0..9 by default) leaves
//    the first fifth of the pull free, so the resistance reads as meeting a surface rather
//    than as a uniformly heavy trigger.
//
// 3. STATUS ON THE LIGHTBAR: dim blue while idle, orange while a contact force is rendered
//    (trigger resistance on); the centre player LED while the haptics session is open.
//
// Reports: the pad holds what it was told, so a report goes out only when a motor level, a
// trigger block or the lightbar changed, or every keep_alive_s (re-asserting everything in
// case a Bluetooth report was lost). Trigger and light fields go only when they changed or at
// the keep-alive, so a rumble decay does not re-apply the trigger effect 250 times a second
// (whether re-sending an unchanged effect restarts it is unknown: a real pad would tell).
// The motors are shared: Godot's SDL (HIDAPI PS5 driver) writes its own reports to the same
// pad for Input.start_joy_vibration (docs/linux-kernel.md, "Godot's SDL beside ours"). So
// the rumble bits ride on our reports only while our own rumble is non-zero, and on the
// report that ends it and the next keep-alive (stating 0, to stop what we started);
// otherwise they stay clear and the pad keeps whatever rumble SDL set.
//
// INPUT: the left stick is the input vector. x = (raw - 128) / 127, y = -(raw - 128) / 127
// (the pad's y grows downward, ours up), clamped to [-1, 1], times the nominal radius, so
// full deflection is the workspace edge (|input| = 1 in the force model).

#include "core/base/status.h"
#include "core/base/vec3.h"
#include "core/device/device.h"
#include "devices/dualsense/dualsense_input.h"
#include "devices/dualsense/dualsense_report.h"

#include <cstdint>

namespace haptics::dualsense {

struct MappingConfig {
	double impact_full_scale_n = 3.0; // |impact| giving full rumble; (0, 100].
	double continuous_full_scale_n = 2.0; // |continuous| giving trigger strength 8; (0, 100].
	double rumble_release_s = 0.015; // Envelope release time constant; [0, 1].
	double rumble_floor = 0.01; // Fraction of full scale below which the motors stop; [0, 0.5).
	double strong_motor_knee = 0.5; // Level where the strong motor joins; [0, 1] (1: never).
	int32_t trigger_start_zone = 2; // 0..9.
	bool right_trigger = true; // R2 resists.
	bool left_trigger = true; // L2 resists.
	double keep_alive_s = 0.5; // Re-send everything at least this often; (0, 10].
};

Status validate_mapping_config(const MappingConfig &p_config);

inline constexpr Rgb LIGHTBAR_IDLE{ 0, 0, 64 };
inline constexpr Rgb LIGHTBAR_CONTACT{ 255, 64, 0 };
inline constexpr uint8_t PLAYER_LEDS_SESSION = 0x04; // The centre LED of five.
inline constexpr double TRIGGER_HYSTERESIS_STEPS = 0.15;

// Stick deflection -> device-space position (z = 0).
Vec3 stick_position_m(const PadInput &p_input, double p_radius_m);

struct RumbleLevels {
	uint8_t left = 0; // Strong, low-frequency.
	uint8_t right = 0; // Weak, high-frequency.
};

class RumbleMapper {
public:
	void configure(const MappingConfig &p_config) { config_ = p_config; }
	void reset() { level_ = 0.0; }
	// p_peak_n: the largest |impact| since the previous call (non-finite counts as 0).
	RumbleLevels update(double p_peak_n, double p_dt_s);
	double level() const { return level_; } // 0..1 after the floor.

private:
	MappingConfig config_;
	double level_ = 0.0;
};

class TriggerMapper {
public:
	void configure(const MappingConfig &p_config) { config_ = p_config; }
	void reset() { strength_ = 0; }
	// p_continuous_n: |continuous force| (non-finite counts as 0). Returns 0 (off) .. 8.
	int update(double p_continuous_n);
	int strength() const { return strength_; }

private:
	MappingConfig config_;
	int strength_ = 0;
};

// Decides, once per I/O cycle, what the pad should be told and whether to send it.
class OutputPlanner {
public:
	explicit OutputPlanner(const MappingConfig &p_config = {});
	void configure(const MappingConfig &p_config);
	// Forget what the pad holds: the next plan() sends every field (used at open).
	void reset();
	// p_impact_peak_n: the largest |impact_n| the servo rendered since the previous cycle.
	// Returns the OutputFields to send now, 0 when nothing changed and no keep-alive is due;
	// r_state is the state to send. The planner assumes a report it asked for is sent (a
	// failed send ends the session, and the next one starts with reset()).
	uint32_t plan(const ForceCommand &p_command, double p_impact_peak_n, double p_dt_s, OutputState &r_state);
	// Motors off, both triggers off, lightbar idle, player LEDs off: what close, io_stop and
	// errors leave the pad with.
	static OutputState off_state();
	// Whether the pad holds a non-zero rumble of ours (the last motor levels we sent): the
	// closing report then stops it; otherwise it leaves the motors alone.
	bool rumble_on_pad() const { return sent_.motor_left != 0 || sent_.motor_right != 0; }

	const RumbleMapper &rumble() const { return rumble_; }
	const TriggerMapper &trigger() const { return trigger_; }

private:
	MappingConfig config_;
	RumbleMapper rumble_;
	TriggerMapper trigger_;
	OutputState sent_;
	bool have_sent_ = false;
	// Reports that state our rumble's end: the one that stops it and the next keep-alive.
	static constexpr int STOP_REPORTS = 2;
	int stops_left_ = 0;
	double since_sent_s_ = 0.0;
};

} // namespace haptics::dualsense
