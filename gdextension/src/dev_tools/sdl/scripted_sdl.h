#pragma once

// A software model of SDL 3's haptic API as its Linux driver behaves (SDL_haptic.c and
// src/haptic/linux/SDL_syshaptic.c), behind the SDL backend's seam (devices/sdl/sdl_api.h), so
// the backend is tested without SDL or a device:
//  - SDL_InitSubSystem(SDL_INIT_HAPTIC) counts; the first one scans: every plugged haptic gets
//    a new instance id (SDL_GetNextObjectID); the last SDL_QuitSubSystem forgets the list;
//  - SDL_OpenHaptic of an open haptic returns the same handle (its reference count grows);
//    a fresh open sets the gain to 100 and the autocentre to 0 where the haptic offers them,
//    as SDL does, and each is recorded as a call;
//  - effects are checked against the haptic's features and its effect count, an update keeps
//    the type, and a run plays the effect (SDL_HAPTIC_INFINITY or a finite length);
//  - an unplugged haptic's calls fail with the text SDL's Linux driver gives for ENODEV
//    ("Haptic: Error updating the effect: No such device"), and it is gone from the next scan;
//  - SDL_GetError is per thread, as SDL's.
// Every call is recorded with its arguments and the time it was made. One model is current at a
// time (the table's functions are plain C functions): constructing one makes it current.
// Thread-safe (one mutex): the device's I/O thread and the test share it.

#include "devices/sdl/sdl_api.h"

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace haptics::sdl {

struct ScriptedHaptic {
	std::string name = "Arduino LLC Arduino Leonardo";
	uint32_t features = SDL_HAPTIC_CONSTANT | SDL_HAPTIC_SINE | SDL_HAPTIC_GAIN | SDL_HAPTIC_AUTOCENTER;
	int axes = 2;
	int max_effects = 16;
	std::string open_error; // Non-empty: SDL_OpenHaptic fails with it (e.g. permissions).
};

// A joystick with AJ's PID firmware under hid-pidff as SDL sees it (the default above), a wheel
// (1 axis: the SDL_JOYSTICK_HAPTIC_AXES hint), and an XInput-like pad (rumble only).
ScriptedHaptic scripted_sdl_stick();
ScriptedHaptic scripted_sdl_wheel();
ScriptedHaptic scripted_sdl_pad();

struct ScriptedSdlCall {
	enum class Kind : int32_t {
		INIT,
		QUIT,
		OPEN,
		CLOSE,
		GAIN,
		AUTOCENTER,
		CREATE,
		UPDATE,
		RUN,
		STOP,
		DESTROY,
		RUMBLE_INIT,
		RUMBLE_PLAY,
		RUMBLE_STOP,
	};
	Kind kind = Kind::INIT;
	int haptic = -1; // Index in the script.
	SDL_HapticEffectID effect = -1;
	SDL_HapticEffect data{}; // CREATE, UPDATE.
	int value = 0; // GAIN, AUTOCENTER, RUN (iterations).
	float strength = 0.0f; // RUMBLE_PLAY.
	uint32_t length_ms = 0; // RUMBLE_PLAY.
	bool ok = true;
	std::chrono::steady_clock::time_point when;
};

class ScriptedSdl {
public:
	explicit ScriptedSdl(std::vector<ScriptedHaptic> p_haptics);
	~ScriptedSdl();
	ScriptedSdl(const ScriptedSdl &) = delete;
	ScriptedSdl &operator=(const ScriptedSdl &) = delete;

	// The table whose functions reach this model.
	static SdlApi api();

	// Unplugged: calls on its open handle fail (ENODEV's text); a later scan leaves it out.
	void set_plugged(size_t p_haptic, bool p_plugged);
	// The next call of p_kind fails with p_text (once).
	void fail_next(ScriptedSdlCall::Kind p_kind, const std::string &p_text);

	std::vector<ScriptedSdlCall> calls() const;
	void clear_calls();
	// The effect p_effect of haptic p_haptic as last uploaded, and whether it plays.
	bool effect(size_t p_haptic, SDL_HapticEffectID p_effect, SDL_HapticEffect &r_data, bool &r_playing) const;
	int effects_in_use(size_t p_haptic) const;
	int open_references(size_t p_haptic) const;
	int gain(size_t p_haptic) const;
	int autocenter(size_t p_haptic) const;
	int subsystem_count() const;

private:
	friend struct ScriptedSdlAccess;
	struct Effect {
		bool in_use = false;
		bool playing = false;
		SDL_HapticEffect data{};
	};
	struct Device {
		ScriptedHaptic script;
		bool plugged = true;
		SDL_HapticID id = 0; // 0: not in SDL's list.
		int references = 0;
		int gain = -1; // -1: never set.
		int autocenter = -1;
		std::vector<Effect> effects;
		SDL_HapticEffectID rumble = -1;
		SDL_HapticEffect rumble_data{};
	};

	mutable std::mutex mutex_;
	std::vector<Device> devices_;
	std::vector<ScriptedSdlCall> calls_;
	int subsystem_ = 0;
	SDL_HapticID next_id_ = 1;
	ScriptedSdlCall::Kind fail_kind_ = ScriptedSdlCall::Kind::INIT;
	std::string fail_text_;
};

// The model the table's functions reach (scripted_sdl_api.cpp); set by the constructor.
extern ScriptedSdl *scripted_sdl_current;

} // namespace haptics::sdl
