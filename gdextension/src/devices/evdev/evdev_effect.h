#pragma once

// One FF_CONSTANT effect driven through evdev, in the order ff.rst prescribes
// (docs/devices/evdev.md, "Using an effect"):
//
//   start:  write {EV_FF, FF_GAIN, 0xFFFF}        if the game asks and the driver offers it
//           write {EV_FF, FF_AUTOCENTER, 0}        likewise (the game's default: asked)
//           EVIOCSFF {FF_CONSTANT, id -1, level 0, length CONSTANT_EFFECT_LENGTH_MS}
//           write {EV_FF, id, 1}                   play (value = repeat count)
//   update: EVIOCSFF with the SAME id, only when the quantised (direction, level) changed;
//           a playing effect is updated in place ("normally not stopped and restarted"),
//           so an update is one ioctl and no re-play.
//   renew:  write {EV_FF, id, 1} every CONSTANT_EFFECT_RENEW_S, so the finite effect never
//           reaches its end (evdev_ff.h says why it is finite).
//   stop:   EVIOCSFF level 0, write {EV_FF, id, 0}, EVIOCRMFF id.
//
// Why the gain is left alone unless the game asks: it is the player's, set in a wheel's
// control panel or Oversteer, and scales every effect (a game that promises newtons can take
// it to full, HapticDeviceOpenOptions.take_gain). Why autocentre is turned off unless the game
// says not to: wheels and some sticks run a spring toward centre in the driver/firmware,
// which adds to (and fights) the game's own forces. Neither is restored on stop: evdev cannot
// read the previous value; the driver's default returns when the device is plugged in again.
//
// update() runs on the device's I/O thread: no allocation, no lock, no formatting; errors
// come back as -errno for the caller to report.

#include "core/base/status.h"
#include "devices/evdev/evdev_effect_slot.h"
#include "devices/evdev/evdev_ff.h"
#include "devices/evdev/evdev_syscalls.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace haptics::evdev {

// What the kernel says the device offers, as EVIOCGBIT(EV_FF) and sysfs show it: the
// input device's bits, to which ff-core adds FF_RUMBLE wherever the driver offers
// FF_PERIODIC (it turns an uploaded rumble into a sine for the driver) and ff-memless adds
// FF_PERIODIC with its waveforms and FF_GAIN wherever the driver offers FF_RUMBLE.
struct EvdevFfFeatures {
	bool constant = false;
	bool periodic = false;
	bool rumble = false;
	bool gain = false;
	bool autocenter = false;
	int32_t max_effects = 0; // EVIOCGEFFECTS; 0 when unknown.
};

// From an EVIOCGBIT(EV_FF) bitmap (either spelling, see evdev_bits.h).
EvdevFfFeatures ff_features_from_bits(const uint8_t *p_bits, size_t p_size);
// "constant periodic rumble gain, 16 effects": for logs and the player's device details.
std::string describe_ff_features(const EvdevFfFeatures &p_features);

// How a device renders the servo: the force itself (FF_CONSTANT), or where the driver offers
// only rumble, the impacts as vibration (evdev_rumble.h).
enum class EvdevOutput : int32_t {
	CONSTANT = 0,
	RUMBLE = 1,
};
// CONSTANT when the driver offers FF_CONSTANT, else RUMBLE when it offers FF_RUMBLE; else
// UNSUPPORTED: "the kernel driver offers neither constant force nor rumble on this device".
Status choose_ff_output(const EvdevFfFeatures &p_features, const char *p_path, EvdevOutput &r_output);

// EVIOCGBIT(EV_FF) and EVIOCGEFFECTS on an open fd. Errors name p_path; a driver without
// FF_CONSTANT is UNSUPPORTED: "the kernel driver offers no constant force on this device".
Status query_ff_features(EvdevSyscalls &r_sys, int p_fd, const char *p_path, EvdevFfFeatures &r_features);
Status require_constant_force(const EvdevFfFeatures &p_features, const char *p_path);

class EvdevConstantForce {
public:
	// Gain and autocentre as p_takeover allows, upload, play (the header's sequence). On
	// failure nothing stays uploaded. p_path only names the device in messages.
	Status start(EvdevSyscalls &r_sys, int p_fd, const EvdevFfFeatures &p_features, const char *p_path,
			const EvdevTakeover &p_takeover = {});
	// One EVIOCSFF with the started id when p_force differs from what the device renders;
	// 0, or -errno (the device keeps the previous force).
	int update(const FfConstantForce &p_force);
	// Plays the effect again before its finite length ends (CONSTANT_EFFECT_RENEW_S): 0 or
	// -errno.
	int renew() { return slot_.replay(); }
	// Best effort, idempotent: zero, stop, erase; returns the first error (0 if none).
	int stop_and_erase();

	bool started() const { return slot_.started(); }
	int16_t id() const { return slot_.id(); }
	FfConstantForce current() const { return { effect_.direction, effect_.level }; }
	uint64_t uploads() const { return slot_.uploads(); } // EVIOCSFF calls that succeeded.

private:
	EvdevEffectSlot slot_;
	FfConstantEffect effect_;
};

} // namespace haptics::evdev
