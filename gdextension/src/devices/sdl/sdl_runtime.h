#pragma once

// SDL as this process uses it: one table of SDL functions (sdl_api.h), the mutex every call
// through it holds (SDL_haptic.c keeps its device list and open devices in globals without
// locks), the subsystems' start, and the devices SDL lists.
//
// Listing. SDL scans for haptics and joysticks when their subsystems start; later plugs reach its
// lists only through events SDL's joystick code pumps. So while nothing of ours is open, each
// listing restarts the subsystems (SDL_QuitSubSystem, SDL_InitSubSystem: a fresh scan); while
// something is, SDL's lists are kept as they are. SDL's instance ids change at every scan, so an
// entry is named by a key that does not: "<SDL's name>#<k>", k counting the entries of the same
// name before it (haptics in SDL's order, on Linux /dev/input/event order, then joysticks):
// stable while the same devices stay plugged.
//
// Entries. Every haptic SDL lists (SDL_GetHaptics); with SdlListOptions::joysticks (Windows, where
// XInput pads are joysticks with rumble but no haptic in SDL 3) every joystick too, except one
// whose haptic SDL lists (SDL_IsJoystickHaptic: the haptic entry stands for it and takes its USB
// ids). A joystick whose USB ids a claim names (another backend drives that device:
// sdl_backend.h) is not opened at all, nor is a haptic whose name is that joystick's: SDL's
// DirectInput open resets a device's force feedback, and its HIDAPI drivers send a pad its
// set-up reports.
//
// Opening. SDL_OpenHaptic itself sets a device's gain to 100 and its autocentre to 0 where it
// offers them (SDL_haptic.c), before the caller can say otherwise: reading a haptic's features
// means opening it, so a listing that reads them does so too (sdl_backend.h decides when).

#include "core/base/status.h"
#include "devices/sdl/sdl_api.h"

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace haptics::sdl {

enum class SdlEntryKind : int32_t {
	HAPTIC = 0, // SDL_GetHaptics: force feedback or rumble through SDL_haptic.h.
	JOYSTICK = 1, // A joystick without a haptic: rumble through SDL_RumbleJoystick, or nothing.
};

// A device another backend drives, by its USB ids (sdl_claims(), sdl_backend.h).
struct SdlClaim {
	uint16_t vendor_id = 0;
	uint16_t product_id = 0;
	std::string reason; // The entry's verdict: "driven by the hid-pid backend here (...)".
};

struct SdlHapticEntry {
	std::string key; // "<name>#<k>"
	std::string name; // SDL_GetHapticNameForID or SDL_GetJoystickNameForID.
	SdlEntryKind kind = SdlEntryKind::HAPTIC;
	SDL_HapticID id = 0; // HAPTIC; valid until the next rescan.
	SDL_JoystickID joystick = 0; // JOYSTICK; valid until the next rescan.
	uint16_t vendor_id = 0; // From SDL's joystick; 0 when unknown (a haptic no joystick led to).
	uint16_t product_id = 0;
	bool features_read = false; // Opened to read what follows.
	uint32_t features = 0; // HAPTIC: SDL_GetHapticFeatures.
	int32_t axes = 0; // HAPTIC: SDL_GetNumHapticAxes.
	int32_t max_effects = 0;
	bool rumble = false; // JOYSTICK: SDL_PROP_JOYSTICK_CAP_RUMBLE_BOOLEAN.
	std::string claimed_by; // Non-empty: another backend drives it (SdlClaim::reason); never opened.
	std::string error; // Why it could not be opened to read them (SDL_GetError).
};

// "constant sine leftright gain autocenter, 2 axes, 16 effects": for logs and the player.
std::string describe_sdl_features(const SdlHapticEntry &p_entry);

struct SdlListOptions {
	bool read = false; // Open each entry to read what it offers (where SDL drives).
	bool joysticks = false; // List SDL's joysticks too.
	std::vector<SdlClaim> claims;
};

// What an open entry holds: a haptic, or a joystick for its rumble.
struct SdlOpened {
	SDL_Haptic *haptic = nullptr;
	SDL_Joystick *joystick = nullptr;
};

class SdlRuntime {
public:
	explicit SdlRuntime(const SdlApi &p_api) :
			api_(p_api) {}
	~SdlRuntime(); // Quits the subsystems it started.

	SdlRuntime(const SdlRuntime &) = delete;
	SdlRuntime &operator=(const SdlRuntime &) = delete;

	// The process's, over the process's SDL (open_process_sdl: linked in, or loaded on first
	// use); null, with the reason, when there is none. Later calls return the same (or the same
	// reason, without loading again).
	static SdlRuntime *shared(std::string &r_reason);

	const SdlApi &api() const { return api_; }
	// Held for every call through api(): the game thread lists, I/O threads update effects.
	std::mutex &mutex() { return mutex_; }

	// Starts the subsystems (restarting them first when nothing of ours is open) and lists
	// SDL's devices as p_options says (see the header). Game thread. The list is kept for entry().
	// A joystick subsystem that does not start is a warning in r_warning, not a failure.
	Status list(const SdlListOptions &p_options, std::vector<SdlHapticEntry> &r_entries, std::string &r_warning);
	// The last listing's entry with p_key; false when it had none.
	bool entry(const std::string &p_key, SdlHapticEntry &r_entry);

	// With mutex() held: opens the entry the last listing named p_key (its haptic, or its
	// joystick). False with the reason when it is gone or SDL refuses; counts it open until
	// close().
	bool open(const std::string &p_key, SdlOpened &r_opened, std::string &r_error);
	void close(SdlOpened &r_opened);
	int32_t open_count() const { return open_count_; }

	// SDL_GetError() now (mutex() held), never null.
	const char *error_text() const;

private:
	Status start_locked(bool p_joysticks, std::string &r_warning);
	void list_joysticks_locked(const SdlListOptions &p_options);
	void read_haptic_locked(SdlHapticEntry &r_entry);

	SdlApi api_;
	std::mutex mutex_;
	SDL_InitFlags started_ = 0;
	int32_t open_count_ = 0;
	std::vector<SdlHapticEntry> entries_;
};

} // namespace haptics::sdl
