#pragma once

// Vibration for the evdev nodes whose driver offers rumble but no constant force: most
// gamepads (xpad, hid-playstation, hid-sony: ff-memless FF_RUMBLE), and through ff-core any
// FF_PERIODIC device (the kernel advertises FF_RUMBLE there and hands an uploaded rumble to
// the driver as a 50 ms sine; docs/devices/evdev.md, "What ff-core adds"). Such a device
// cannot push the hand, so it renders
// the servo's IMPACT TRANSIENTS the way the DualSense backend renders them on its motors
// (dualsense_mapping.h, the same rule and defaults): each I/O cycle takes the peak |impact_n|
// the servo rendered since the previous one (offer_impact, every tick: the transients swing
// through zero faster than the cycle samples), u = peak / impact_full_scale_n clamped to 1,
// held by a release filter, exactly 0 below the floor; the weak (high-frequency) motor gets u,
// the strong one (u - knee) / (1 - knee) above the knee. The continuous force is not felt: a
// steady buzz while standing on a floor would be noise, not contact.
//
// The effect, in ff.rst's order as the constant force (evdev_effect.h): gain 0xFFFF where
// offered, one FF_RUMBLE uploaded (id -1, both motors off, infinite) and played; an update is
// one EVIOCSFF with the same id, only when a 16-bit magnitude changed; stop = zero, stop,
// erase. update() and render() run on the I/O thread: no allocation, errors as -errno.

#include "core/base/status.h"
#include "core/base/vec3.h"
#include "devices/evdev/evdev_effect.h"

#include <atomic>
#include <cstdint>

namespace haptics::evdev {

struct RumbleMapping {
	double impact_full_scale_n = 3.0; // The servo's impact cap: its strongest hit is full rumble.
	double release_s = 0.015; // Release time constant of the level; 0: none.
	double floor = 0.01; // Fraction of full scale below which both motors stop.
	double strong_motor_knee = 0.5; // Level where the strong motor joins; 1: never.
};

struct FfRumbleLevels {
	uint16_t strong = 0;
	uint16_t weak = 0;
	bool operator==(const FfRumbleLevels &p_other) const = default;
};

class RumbleEnvelope {
public:
	void reset() { level_ = 0.0; }
	// p_peak_n: the largest |impact| since the previous call (non-finite counts as 0).
	FfRumbleLevels update(double p_peak_n, double p_dt_s, const RumbleMapping &p_mapping);
	double level() const { return level_; } // 0..1 after the floor.

private:
	double level_ = 0.0;
};

class EvdevRumble {
public:
	// The gain where the game asks (p_take_gain), upload, play. On failure nothing stays
	// uploaded; p_path only names the device.
	Status start(EvdevSyscalls &r_sys, int p_fd, const EvdevFfFeatures &p_features, const char *p_path,
			bool p_take_gain = false);
	// The servo's thread, each tick (an atomic max; never blocks).
	void offer_impact(const Vec3 &p_impact_n);
	// One I/O cycle: takes the peak offered since the last one and updates the effect.
	int render(double p_dt_s);
	// One EVIOCSFF with the started id when p_levels differ from the playing ones; 0 or -errno.
	int update(const FfRumbleLevels &p_levels);
	// Best effort, idempotent: zero, stop, erase; the first error (0 if none).
	int stop_and_erase();

	bool started() const { return slot_.started(); }
	int16_t id() const { return slot_.id(); }
	FfRumbleLevels current() const { return { effect_.strong_magnitude, effect_.weak_magnitude }; }
	uint64_t uploads() const { return slot_.uploads(); }
	const RumbleMapping &mapping() const { return mapping_; }

private:
	EvdevEffectSlot slot_;
	FfRumbleEffect effect_;
	RumbleMapping mapping_;
	RumbleEnvelope envelope_;
	std::atomic<double> peak_n_{ 0.0 };
};

} // namespace haptics::evdev
