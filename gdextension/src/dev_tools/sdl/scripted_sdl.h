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
//  - SDL_GetError is per thread, as SDL's;
//  - joysticks (SDL_joystick.h, scripted_sdl_joystick_api.cpp): SDL_InitSubSystem
//    (SDL_INIT_JOYSTICK) counts and scans like the haptics; a haptic with `joystick` set is also a
//    joystick whose haptic it is (DirectInput's force-feedback sticks: SDL_IsJoystickHaptic,
//    SDL_OpenHapticFromJoystick, which unlike SDL_OpenHaptic sets neither gain nor autocentre),
//    and a ScriptedJoystick is a joystick without one (an XInput pad: rumble through
//    SDL_RumbleJoystick); a gamepad is never a haptic's joystick, as in SDL_haptic.c.
// Every call is recorded with its arguments and the time it was made. One model is current at a
// time (the table's functions are plain C functions): constructing one makes it current.
// Thread-safe (one mutex): the device's I/O thread and the test share it.

#include "devices/sdl/sdl_api.h"

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace haptics::sdl {

struct ScriptedHaptic {
	std::string name = "Arduino LLC Arduino Leonardo";
	uint16_t vendor_id = 0x2341; // Its joystick's, when `joystick`.
	uint16_t product_id = 0x8036;
	bool joystick = false; // SDL lists it as a joystick too (Windows' DirectInput).
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

// A joystick SDL lists without a haptic.
struct ScriptedJoystick {
	std::string name = "Xbox 360 Controller";
	uint16_t vendor_id = 0x045e;
	uint16_t product_id = 0x028e;
	bool gamepad = true;
	bool rumble = true; // SDL_PROP_JOYSTICK_CAP_RUMBLE_BOOLEAN.
	std::string open_error; // Non-empty: SDL_OpenJoystick fails with it.
};

// An XInput pad as SDL 3 on Windows sees it: a gamepad with rumble and no haptic.
ScriptedJoystick scripted_sdl_xinput_pad();

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
		JOYSTICK_OPEN,
		JOYSTICK_CLOSE,
		JOYSTICK_RUMBLE,
		JOYSTICK_UPDATE,
		HAPTIC_FROM_JOYSTICK,
	};
	Kind kind = Kind::INIT;
	int haptic = -1; // Index in the script (JOYSTICK_*: in the joysticks, haptics' first).
	SdlEffectId effect = -1;
	SDL_HapticEffect data{}; // CREATE, UPDATE.
	int value = 0; // GAIN, AUTOCENTER, RUN (iterations), INIT and QUIT (the flags).
	uint16_t low = 0; // JOYSTICK_RUMBLE: the low-frequency (large) motor.
	uint16_t high = 0; // JOYSTICK_RUMBLE: the high-frequency (small) motor.
	float strength = 0.0f; // RUMBLE_PLAY.
	uint32_t length_ms = 0; // RUMBLE_PLAY, JOYSTICK_RUMBLE.
	bool ok = true;
	std::chrono::steady_clock::time_point when;

	// A record with one argument set (the rest default).
	static ScriptedSdlCall with_value(int p_value) {
		return with([&](ScriptedSdlCall &r_call) { r_call.value = p_value; });
	}
	static ScriptedSdlCall with_ok(bool p_ok) {
		return with([&](ScriptedSdlCall &r_call) { r_call.ok = p_ok; });
	}
	static ScriptedSdlCall with_data(const SDL_HapticEffect &p_data) {
		return with([&](ScriptedSdlCall &r_call) { r_call.data = p_data; });
	}
	static ScriptedSdlCall with_effect(SdlEffectId p_effect) {
		return with([&](ScriptedSdlCall &r_call) { r_call.effect = p_effect; });
	}
	template <typename Set>
	static ScriptedSdlCall with(Set p_set) {
		ScriptedSdlCall call;
		p_set(call);
		return call;
	}
};

class ScriptedSdl {
public:
	explicit ScriptedSdl(std::vector<ScriptedHaptic> p_haptics, std::vector<ScriptedJoystick> p_joysticks = {});
	~ScriptedSdl();
	ScriptedSdl(const ScriptedSdl &) = delete;
	ScriptedSdl &operator=(const ScriptedSdl &) = delete;

	// The table whose functions reach this model.
	static SdlApi api();

	// Unplugged: calls on its open handle fail (ENODEV's text); a later scan leaves it out.
	void set_plugged(size_t p_haptic, bool p_plugged);
	// The same for a ScriptedJoystick (its index in the constructor's list).
	void set_joystick_plugged(size_t p_joystick, bool p_plugged);
	// The next call of p_kind fails with p_text (once).
	void fail_next(ScriptedSdlCall::Kind p_kind, const std::string &p_text);

	std::vector<ScriptedSdlCall> calls() const;
	void clear_calls();
	// The effect p_effect of haptic p_haptic as last uploaded, and whether it plays.
	bool effect(size_t p_haptic, SdlEffectId p_effect, SDL_HapticEffect &r_data, bool &r_playing) const;
	int effects_in_use(size_t p_haptic) const;
	int open_references(size_t p_haptic) const;
	int gain(size_t p_haptic) const;
	int autocenter(size_t p_haptic) const;
	int subsystem_count() const;
	int joystick_subsystem_count() const;
	bool joystick_events() const;
	// SDL_SetHint's last value for p_name; empty when never set.
	std::string hint(const std::string &p_name) const;
	// A ScriptedJoystick's open references and its motors as last set.
	int joystick_references(size_t p_joystick) const;
	void joystick_rumble(size_t p_joystick, uint16_t &r_low, uint16_t &r_high) const;

private:
	friend struct ScriptedSdlAccess;
	friend struct ScriptedSdlJoystickAccess;
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
		SdlEffectId rumble = -1;
		SDL_HapticEffect rumble_data{};
	};

	size_t first_scripted_joystick() const; // mutex_ held.

	mutable std::mutex mutex_;
	struct Joystick {
		ScriptedJoystick script;
		int haptic = -1; // The device whose joystick it is; -1: a ScriptedJoystick.
		bool plugged = true; // A haptic's follows the haptic's.
		SDL_JoystickID id = 0;
		int references = 0;
		uint16_t low = 0;
		uint16_t high = 0;
	};

	std::vector<Device> devices_;
	std::vector<Joystick> joysticks_; // The haptics' joysticks first, then the ScriptedJoysticks.
	std::vector<ScriptedSdlCall> calls_;
	int subsystem_ = 0;
	int joystick_subsystem_ = 0;
	bool joystick_events_ = true; // SDL_SetJoystickEventsEnabled.
	std::map<std::string, std::string> hints_; // SDL_SetHint.
	SDL_HapticID next_id_ = 1;
	ScriptedSdlCall::Kind fail_kind_ = ScriptedSdlCall::Kind::INIT;
	std::string fail_text_;
};

// The model the table's functions reach (scripted_sdl_api.cpp); set by the constructor.
extern ScriptedSdl *scripted_sdl_current;
// SDL_SetError for the model's functions (per thread, as SDL's); returns false.
bool scripted_sdl_set_error(const std::string &p_text);
// Fills the joystick members of p_api (scripted_sdl_joystick_api.cpp).
void fill_scripted_joystick_api(SdlApi &r_api);

} // namespace haptics::sdl
