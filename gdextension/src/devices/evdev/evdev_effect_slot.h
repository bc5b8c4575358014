#pragma once

// One force-feedback effect's life on an evdev node, whatever its type, in ff.rst's order
// (docs/devices/evdev.md, "Using an effect"): start = gain 0xFFFF and autocentre off where the game allows (EvdevTakeover), upload with
// id -1 (the kernel answers with the id), play; an update is one EVIOCSFF with that id; stop
// = stop, erase. The effect types (evdev_effect.h's constant force, evdev_rumble.h's rumble)
// encode their struct into bytes() and keep what the device plays.
//
// upload() and write_event() run on the device's I/O thread: no allocation, no lock; errors
// come back as -errno.

#include "core/base/status.h"
#include "devices/evdev/evdev_ff.h"
#include "devices/evdev/evdev_syscalls.h"

#include <cstdint>

namespace haptics::evdev {

struct EvdevFfFeatures;

// What the game lets an effect's start change on the device: its gain (to full) and its
// centring spring (off). Both are the player's settings otherwise, and evdev cannot read them
// back, so nothing is put back on close (HapticDeviceOpenOptions says so to the game).
struct EvdevTakeover {
	bool gain = false;
	bool spring = true;
};

class EvdevEffectSlot {
public:
	// Gain to full and autocentre off where p_takeover allows and the driver offers them,
	// upload of bytes() (id -1), play. On failure nothing stays uploaded. p_what names the
	// effect and p_path the device in messages.
	Status start(EvdevSyscalls &r_sys, int p_fd, const EvdevFfFeatures &p_features, const EvdevTakeover &p_takeover,
			const char *p_what, const char *p_path);
	// EVIOCSFF of bytes() with the started id: 0 or -errno.
	int upload();
	// Plays the started effect again from its start (its length counts anew): 0 or -errno.
	int replay();
	// Best effort, idempotent: stop, erase; returns p_first_error if it is one, else the
	// first error of these (0 if none). The caller zeroes its effect first.
	int stop_and_erase(int p_first_error = 0);

	// Where the effect type encodes its next ff_effect.
	FfEffectBytes &bytes() { return bytes_; }
	bool started() const { return started_; }
	int16_t id() const { return id_; }
	uint64_t uploads() const { return uploads_; } // EVIOCSFF calls that succeeded.

private:
	int send_upload();
	int write_event(uint16_t p_code, int32_t p_value);

	EvdevSyscalls *sys_ = nullptr;
	int fd_ = -1;
	int16_t id_ = -1;
	bool started_ = false;
	uint64_t uploads_ = 0;
	FfEffectBytes bytes_{};
	InputEventBytes event_{};
};

} // namespace haptics::evdev
