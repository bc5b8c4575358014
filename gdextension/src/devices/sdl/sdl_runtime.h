#pragma once

// SDL's haptic subsystem as this process uses it: one table of SDL functions (sdl_api.h), the
// mutex every call through it holds (SDL_haptic.c keeps its device list and open devices in
// globals without locks), the subsystem's initialisation, and the haptics SDL lists.
//
// Listing. SDL scans for haptics when its haptic subsystem starts; later plugs reach its list
// only through udev events that SDL's joystick code pumps. So while no haptic of ours is open,
// each listing restarts the subsystem (SDL_QuitSubSystem, SDL_InitSubSystem: a fresh scan);
// while one is open, SDL's list is kept as it is. SDL's instance ids change at every scan, so
// a haptic is named by a key that does not: "<SDL's name>#<k>", k counting the haptics of the
// same name in SDL's order (on Linux, /dev/input/event order): stable while the same devices
// stay plugged.
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

struct SdlHapticEntry {
	std::string key; // "<name>#<k>"
	std::string name; // SDL_GetHapticNameForID.
	SDL_HapticID id = 0; // Valid until the next rescan.
	bool features_read = false; // Opened to read what follows.
	uint32_t features = 0; // SDL_GetHapticFeatures.
	int32_t axes = 0; // SDL_GetNumHapticAxes.
	int32_t max_effects = 0;
	std::string error; // Why it could not be opened to read them (SDL_GetError).
};

// "constant sine leftright gain autocenter, 2 axes, 16 effects": for logs and the player.
std::string describe_sdl_features(const SdlHapticEntry &p_entry);

class SdlRuntime {
public:
	explicit SdlRuntime(const SdlApi &p_api) :
			api_(p_api) {}
	~SdlRuntime(); // Quits the haptic subsystem if it started it.

	SdlRuntime(const SdlRuntime &) = delete;
	SdlRuntime &operator=(const SdlRuntime &) = delete;

	// The process's, over libSDL3 loaded on first use (load_sdl_library); null, with the reason,
	// when it cannot be loaded. Later calls return the same (or the same reason, without
	// loading again).
	static SdlRuntime *shared(std::string &r_reason);

	const SdlApi &api() const { return api_; }
	// Held for every call through api(): the game thread lists, I/O threads update effects.
	std::mutex &mutex() { return mutex_; }

	// Starts the haptic subsystem (restarting it first when no haptic of ours is open) and
	// lists SDL's haptics; with p_read_features, opens each to read its features (and closes it
	// again). Game thread. The list is kept for entry().
	Status list(bool p_read_features, std::vector<SdlHapticEntry> &r_entries);
	// The last listing's entry with p_key; false when it had none.
	bool entry(const std::string &p_key, SdlHapticEntry &r_entry);

	// With mutex() held: opens the haptic the last listing named p_key. Null with the reason
	// when it is gone or SDL refuses; counts it open until close_haptic().
	SDL_Haptic *open_haptic(const std::string &p_key, std::string &r_error);
	void close_haptic(SDL_Haptic *p_haptic);
	int32_t open_count() const { return open_count_; }

	// SDL_GetError() now (mutex() held), never null.
	const char *error_text() const;

private:
	Status start_locked();

	SdlApi api_;
	std::mutex mutex_;
	bool started_ = false;
	int32_t open_count_ = 0;
	std::vector<SdlHapticEntry> entries_;
};

} // namespace haptics::sdl
