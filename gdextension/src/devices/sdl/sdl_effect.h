#pragma once

// What the SDL backend asks SDL to play, as SDL_HapticEffect values (docs/devices/sdl.md):
//
// CONSTANT FORCE. One SDL_HAPTIC_CONSTANT effect of finite length SDL_EFFECT_LENGTH_MS, run
// again every SDL_EFFECT_RENEW_S so it never ends while the device is driven and stops by
// itself within a length if the game dies (the evdev backend's rule, docs/devices/evdev.md,
// "Finite effects": SDL hands its SDL_HAPTIC_INFINITY to Linux as length 0, which hid-pidff
// before 6.15 passes to PID firmwares as "end at once").
//  - A stick (2 axes or more): direction SDL_HAPTIC_POLAR, level |F| / max_force_n * 0x7FFF.
//    The angle is the force's own direction in hundredths of a degree clockwise from device +y
//    (north, away from the user): +x 9000, -y 18000, -x 27000. SDL documents its direction as
//    where the force comes from, but on Linux it hands the angle on unchanged (polar * 0x8000 /
//    18000 = the evdev direction, src/haptic/linux/SDL_syshaptic.c) and the PID firmwares
//    behind hid-pidff render X = sin(theta), Y = -cos(theta) toward it, so these are the very
//    angles our evdev backend sends (evdev_ff.h) and the bytes on the wire are the servo's force
//    (the VM test checks it). invert_x / invert_y flip a family whose motors disagree.
//  - A wheel (1 axis): direction SDL_HAPTIC_STEERING_AXIS and a signed level from the x
//    component. SDL reports 2 axes for every Linux device unless the player's
//    SDL_JOYSTICK_HAPTIC_AXES hint says otherwise ("0xVID/0xPID/1").
//  Non-finite components count as zero; the level is clamped to 0x7FFF, so whatever the servo
//  hands over, SDL gets a finite value within the device's full scale.
//
// RUMBLE (a device with no constant force). Impacts as the evdev and DualSense backends render
// them: the peak |impact| of the servo's ticks since the last cycle, over a release filter,
// u = peak / impact_full_scale_n; the small (high-frequency) motor gets u, the large one
// (u - knee) / (1 - knee) above the knee. With SDL_HAPTIC_LEFTRIGHT (XInput pads, Linux
// FF_RUMBLE) both motors are set, magnitudes 0..0x7FFF (SDL's Linux driver doubles them to the
// kernel's 0..0xFFFE; XInput's likewise); otherwise SDL's simple rumble plays u on whatever
// SDL chose (SDL_InitHapticRumble: a sine where offered).

#include "core/base/vec3.h"

#include <SDL3/SDL_haptic.h>

#include <cstdint>

namespace haptics::sdl {

inline constexpr uint32_t SDL_EFFECT_LENGTH_MS = 1000;
inline constexpr double SDL_EFFECT_RENEW_S = 0.25;
inline constexpr int16_t SDL_LEVEL_MAX = 0x7fff;

struct SdlForceMapping {
	double max_force_n = 5.0; // Sent as level 0x7FFF; > 0 and finite.
	bool steering = false; // One axis: a wheel.
	bool invert_x = false;
	bool invert_y = false;
};

// What one constant effect renders, compared to decide whether to update it.
struct SdlConstantForce {
	uint8_t direction_type = SDL_HAPTIC_POLAR;
	int32_t direction = 0; // Hundredths of a degree (polar); 0 for the steering axis.
	int16_t level = 0;
	bool operator==(const SdlConstantForce &p_other) const = default;
};

// Device-space newtons -> (direction, level); z ignored; zero level has direction 0.
SdlConstantForce map_force_to_sdl(const Vec3 &p_force_n, const SdlForceMapping &p_mapping);
// The SDL_HAPTIC_CONSTANT effect playing p_force for SDL_EFFECT_LENGTH_MS.
SDL_HapticEffect constant_effect(const SdlConstantForce &p_force);
// The force a device renders for p_effect (an SDL_HAPTIC_CONSTANT), in device space and
// newtons at p_max_force_n full scale: the inverse of the mapping, for tests and the VM.
Vec3 constant_effect_force_n(const SDL_HapticEffect &p_effect, double p_max_force_n);

struct SdlRumbleMapping {
	double impact_full_scale_n = 3.0; // The servo's impact cap: its strongest hit is full rumble.
	double release_s = 0.015;
	double floor = 0.01; // Below this fraction of full scale both motors stop.
	double large_motor_knee = 0.5; // Where the large (strong) motor joins; 1: never.
};

struct SdlRumbleLevels {
	uint16_t large = 0; // 0..0x7FFF
	uint16_t small = 0; // 0..0x7FFF
	bool operator==(const SdlRumbleLevels &p_other) const = default;
};

class SdlRumbleEnvelope {
public:
	void reset() { level_ = 0.0; }
	// p_peak_n: the largest |impact| since the previous call (non-finite counts as 0).
	SdlRumbleLevels update(double p_peak_n, double p_dt_s, const SdlRumbleMapping &p_mapping);
	double level() const { return level_; } // 0..1 after the floor: SDL's simple rumble strength.

private:
	double level_ = 0.0;
};

// The SDL_HAPTIC_LEFTRIGHT effect for p_levels, SDL_EFFECT_LENGTH_MS long.
SDL_HapticEffect leftright_effect(const SdlRumbleLevels &p_levels);

} // namespace haptics::sdl
