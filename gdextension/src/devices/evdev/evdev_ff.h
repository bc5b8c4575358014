#pragma once

// The force-feedback protocol of evdev, as bytes (docs/devices/evdev.md [UAPI, ff.rst]): the FF_CONSTANT
// struct ff_effect that EVIOCSFF uploads, the 24-byte input_event written to play, stop or
// set the gain, and the mapping from our device-space force to (direction, level).
//
// Direction (docs/devices/hid-pid.md, "Direction"): a u16 angle, 0x4000 = 90 degrees. hid-pidff passes it on to the
// device scaled, and the open PID firmwares (AJ, OFB) render per-axis factors
// X = sin(theta), Y = -cos(theta) in the stick's AXIS frame (the frame ABS_X/ABS_Y report:
// +X right, +Y toward the user). So on such a device
//     0x4000 -> +X,   0xC000 -> -X,   0x8000 -> +Y (toward the user),   0x0000 -> -Y.
// Our device space has y UP = away from the user (the input side negates ABS_Y, see
// evdev_input.h), so a device-space force (x, y) is the axis-frame force (x, -y):
//     device +x -> 0x4000, device -x -> 0xC000, device -y -> 0x8000, device +y -> 0x0000.
// Documentation disagrees on the physical sign (the uapi comment calls 0x4000 "left",
// meaning where the force comes from; SDL and the kernel's K-new name it EAST), so each
// axis has an invert flag that one hardware check per device family settles.
//
// Level: |F| / max_force_n * 0x7FFF, rounded, clamped to 0x7FFF: the kernel API has no unit;
// 0x7FFF is "the device's strongest", so our newtons are nominal (EvdevDeviceConfig).
// A wheel has one axis: it renders the x component with the fixed steering direction 0x4000
// (SDL's SDL_HAPTIC_STEERING_AXIS, K-new's wheel direction) and a signed level.

#include "core/base/vec3.h"
#include "devices/evdev/evdev_abi.h"

#include <array>
#include <cstdint>

namespace haptics::evdev {

// How long an uploaded constant force lasts, and how often it is played again before it ends.
// Not 0 (ff.rst's "infinite"): hid-pidff before Linux 6.15 hands 0 to the device's Duration,
// which PID firmwares read as "ends at once" (docs/devices/evdev.md, "Finite effects"); a
// finite effect renewed in time works on every kernel, and one left behind stops by itself.
inline constexpr uint16_t CONSTANT_EFFECT_LENGTH_MS = 1000;
inline constexpr double CONSTANT_EFFECT_RENEW_S = 0.25;

struct FfConstantEffect {
	int16_t id = -1; // -1: the kernel allocates one at upload and writes it back.
	uint16_t direction = 0;
	int16_t level = 0;
	uint16_t replay_length_ms = CONSTANT_EFFECT_LENGTH_MS; // 0 would be infinite (ff.rst).
	uint16_t replay_delay_ms = 0;
};

using FfEffectBytes = std::array<uint8_t, FF_EFFECT_SIZE>;
using InputEventBytes = std::array<uint8_t, INPUT_EVENT_SIZE>;

// Explicit bytes: what EVIOCSFF is given. Trigger and envelope are zero.
void encode_constant_effect(const FfConstantEffect &p_effect, FfEffectBytes &r_bytes);
// The same built with <linux/input.h>'s struct ff_effect (evdev_abi_check.cpp): the tests
// compare both, so our offsets are checked against the compiler's, not only a comment.
void encode_constant_effect_kernel_struct(const FfConstantEffect &p_effect, FfEffectBytes &r_bytes);

// FF_RUMBLE: two motors, 0..0xFFFF each (ff.rst: "strong" the low-frequency one). Direction
// is unused.
struct FfRumbleEffect {
	int16_t id = -1;
	uint16_t strong_magnitude = 0;
	uint16_t weak_magnitude = 0;
	uint16_t replay_length_ms = 0; // 0 = infinite.
};
void encode_rumble_effect(const FfRumbleEffect &p_effect, FfEffectBytes &r_bytes);

// Every field of an ff_effect this backend or the scripted kernel looks at; the union's
// fields are decoded for every type (only the effect's own type's are meaningful).
struct FfEffectFields {
	uint16_t type = 0;
	int16_t id = 0;
	uint16_t direction = 0;
	uint16_t trigger_button = 0;
	uint16_t trigger_interval = 0;
	uint16_t replay_length_ms = 0;
	uint16_t replay_delay_ms = 0;
	int16_t constant_level = 0;
	uint16_t rumble_strong = 0;
	uint16_t rumble_weak = 0;
	uint16_t periodic_waveform = 0;
	uint16_t periodic_period_ms = 0;
	int16_t periodic_magnitude = 0;
};
FfEffectFields decode_ff_effect(const FfEffectBytes &p_bytes);

// An input_event to write: the kernel ignores (and stamps) the time, so it is zero.
void encode_input_event(uint16_t p_type, uint16_t p_code, int32_t p_value, InputEventBytes &r_bytes);

struct InputEvent {
	int64_t time_s = 0;
	int64_t time_us = 0;
	uint16_t type = 0;
	uint16_t code = 0;
	int32_t value = 0;
};
// Reads exactly INPUT_EVENT_SIZE bytes from p_bytes.
InputEvent decode_input_event(const uint8_t *p_bytes);

enum class EvdevShape : int32_t {
	JOYSTICK = 0, // ABS_X + ABS_Y, 2-DOF force.
	WHEEL = 1, // One steering axis (ABS_WHEEL or ABS_X), force along x only.
};

struct FfForceMapping {
	double max_force_n = 5.0; // The force sent as level 0x7FFF; > 0 and finite.
	EvdevShape shape = EvdevShape::JOYSTICK;
	bool invert_x = false;
	bool invert_y = false;
};

// What one constant effect renders: compared to decide whether to upload.
struct FfConstantForce {
	uint16_t direction = 0;
	int16_t level = 0;
	bool operator==(const FfConstantForce &p_other) const = default;
};

inline constexpr uint16_t FF_DIRECTION_STEERING = 0x4000;
inline constexpr int16_t FF_LEVEL_MAX = 0x7fff;

// Device-space newtons -> (direction, level). Non-finite components count as zero; z is
// ignored (no evdev device pushes along it); a zero level always has direction 0 so that
// resting produces no uploads. Never allocates.
FfConstantForce map_force_to_constant(const Vec3 &p_force_n, const FfForceMapping &p_mapping);

} // namespace haptics::evdev
