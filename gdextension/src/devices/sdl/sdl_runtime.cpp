#include "devices/sdl/sdl_runtime.h"

#include "devices/dynamic_library.h"

#include <cstdio>

namespace haptics::sdl {

std::string describe_sdl_features(const SdlHapticEntry &p_entry) {
	if (!p_entry.features_read) {
		return "features not read";
	}
	if (p_entry.kind == SdlEntryKind::JOYSTICK) {
		return p_entry.rumble ? "a joystick with rumble" : "a joystick without rumble";
	}
	static constexpr struct {
		uint32_t bit;
		const char *name;
	} NAMES[] = {
		{ SDL_HAPTIC_CONSTANT, "constant" },
		{ SDL_HAPTIC_SINE, "sine" },
		{ SDL_HAPTIC_SQUARE, "square" },
		{ SDL_HAPTIC_TRIANGLE, "triangle" },
		{ SDL_HAPTIC_SAWTOOTHUP, "sawtoothup" },
		{ SDL_HAPTIC_SAWTOOTHDOWN, "sawtoothdown" },
		{ SDL_HAPTIC_RAMP, "ramp" },
		{ SDL_HAPTIC_SPRING, "spring" },
		{ SDL_HAPTIC_DAMPER, "damper" },
		{ SDL_HAPTIC_INERTIA, "inertia" },
		{ SDL_HAPTIC_FRICTION, "friction" },
		{ SDL_HAPTIC_LEFTRIGHT, "leftright" },
		{ SDL_HAPTIC_CUSTOM, "custom" },
		{ SDL_HAPTIC_GAIN, "gain" },
		{ SDL_HAPTIC_AUTOCENTER, "autocenter" },
		{ SDL_HAPTIC_STATUS, "status" },
		{ SDL_HAPTIC_PAUSE, "pause" },
	};
	std::string text;
	for (const auto &name : NAMES) {
		if ((p_entry.features & name.bit) != 0) {
			text += text.empty() ? "" : " ";
			text += name.name;
		}
	}
	char counts[64];
	std::snprintf(counts, sizeof(counts), "%s%d axes, %d effects", text.empty() ? "" : ", ", p_entry.axes,
			p_entry.max_effects);
	return (text.empty() ? "no effects" : text) + counts;
}

SdlRuntime::~SdlRuntime() {
	std::lock_guard lock(mutex_);
	if (api_.QuitSubSystem != nullptr) {
		// The haptics first: SDL's haptic code uses its joysticks (SDL_haptic.c).
		if ((started_ & SDL_INIT_HAPTIC) != 0) {
			api_.QuitSubSystem(SDL_INIT_HAPTIC);
		}
		if ((started_ & SDL_INIT_JOYSTICK) != 0) {
			api_.QuitSubSystem(SDL_INIT_JOYSTICK);
		}
	}
}

SdlRuntime *SdlRuntime::shared(std::string &r_reason) {
	// Opened once, kept for the process (a static: initialised once, thread-safe).
	static SdlLibrary library;
	static const Status opened = open_process_sdl(library);
	static SdlRuntime *runtime = opened ? new SdlRuntime(library.api) : nullptr;
	if (runtime == nullptr) {
		r_reason = opened.message();
	}
	return runtime;
}

const char *SdlRuntime::error_text() const {
	const char *text = api_.GetError != nullptr ? api_.GetError() : nullptr;
	return text != nullptr && text[0] != '\0' ? text : "SDL gave no reason";
}

Status SdlRuntime::start_locked(bool p_joysticks, std::string &r_warning) {
	if (started_ != 0 && open_count_ == 0) {
		// A fresh scan: see the header. Haptics before joysticks, as in the destructor.
		if ((started_ & SDL_INIT_HAPTIC) != 0) {
			api_.QuitSubSystem(SDL_INIT_HAPTIC);
		}
		if ((started_ & SDL_INIT_JOYSTICK) != 0) {
			api_.QuitSubSystem(SDL_INIT_JOYSTICK);
		}
		started_ = 0;
	}
	if (p_joysticks && (started_ & SDL_INIT_JOYSTICK) == 0) {
		// No RawInput: Windows keeps one raw-input registration per device class for the whole
		// process, so ours would take the game pads' from the engine (its own SDL), and quitting
		// would remove it. XInput, DirectInput and SDL's HIDAPI reach the same pads.
		api_.SetHint(SDL_HINT_JOYSTICK_RAWINPUT, "0");
		if (api_.InitSubSystem(SDL_INIT_JOYSTICK)) {
			started_ |= SDL_INIT_JOYSTICK;
			// Nothing pumps this SDL's event queue: its joystick events would only fill it.
			api_.SetJoystickEventsEnabled(false);
		} else {
			r_warning = std::string("SDL's joystick subsystem did not start (no rumble pads listed): ") + error_text();
		}
	}
	if ((started_ & SDL_INIT_HAPTIC) == 0) {
		if (!api_.InitSubSystem(SDL_INIT_HAPTIC)) {
			return Status::error(StatusCode::DEVICE_ERROR, "SDL's haptic subsystem did not start: %s", error_text());
		}
		started_ |= SDL_INIT_HAPTIC;
	}
	// SDL loads XInput for both subsystems and frees it when a scan quits them. Wine's XInput
	// runs a thread that outlives the library: it faulted there in 2 of 4 runs of the Windows
	// suite. Kept loaded for the process, as it is anyway while SDL is up.
	for (const char *xinput : { "xinput1_4.dll", "xinput1_3.dll", "xinput9_1_0.dll" }) {
		pin_loaded_library(xinput);
	}
	return Status::success();
}

void SdlRuntime::read_haptic_locked(SdlHapticEntry &r_entry) {
	SDL_Haptic *haptic = api_.OpenHaptic(r_entry.id);
	if (haptic == nullptr) {
		r_entry.error = error_text();
		return;
	}
	r_entry.features_read = true;
	r_entry.features = api_.GetHapticFeatures(haptic);
	r_entry.axes = api_.GetNumHapticAxes(haptic);
	r_entry.max_effects = api_.GetMaxHapticEffects(haptic);
	api_.CloseHaptic(haptic);
}

Status SdlRuntime::list(const SdlListOptions &p_options, std::vector<SdlHapticEntry> &r_entries, std::string &r_warning) {
	std::lock_guard lock(mutex_);
	entries_.clear();
	const Status started = start_locked(p_options.joysticks, r_warning);
	if (!started) {
		return started;
	}
	int count = 0;
	SDL_HapticID *ids = api_.GetHaptics(&count);
	if (ids == nullptr) {
		return Status::error(StatusCode::DEVICE_ERROR, "SDL could not list its haptics: %s", error_text());
	}
	for (int i = 0; i < count; ++i) {
		SdlHapticEntry entry;
		entry.id = ids[i];
		const char *name = api_.GetHapticNameForID(ids[i]);
		entry.name = name != nullptr ? name : "unnamed haptic";
		entries_.push_back(entry);
	}
	api_.free(ids);
	if ((started_ & SDL_INIT_JOYSTICK) != 0) {
		list_joysticks_locked(p_options);
	}
	for (size_t i = 0; i < entries_.size(); ++i) {
		SdlHapticEntry &entry = entries_[i];
		int same = 0;
		for (size_t j = 0; j < i; ++j) {
			same += entries_[j].name == entry.name ? 1 : 0;
		}
		entry.key = entry.name + "#" + std::to_string(same);
		if (p_options.read && entry.kind == SdlEntryKind::HAPTIC && entry.claimed_by.empty()) {
			read_haptic_locked(entry);
		}
	}
	r_entries = entries_;
	return Status::success();
}

bool SdlRuntime::entry(const std::string &p_key, SdlHapticEntry &r_entry) {
	std::lock_guard lock(mutex_);
	for (const SdlHapticEntry &entry : entries_) {
		if (entry.key == p_key) {
			r_entry = entry;
			return true;
		}
	}
	return false;
}

bool SdlRuntime::open(const std::string &p_key, SdlOpened &r_opened, std::string &r_error) {
	if (started_ == 0) {
		r_error = "SDL is not started (list the devices first)";
		return false;
	}
	for (const SdlHapticEntry &entry : entries_) {
		if (entry.key != p_key) {
			continue;
		}
		SdlOpened opened;
		if (entry.kind == SdlEntryKind::JOYSTICK) {
			opened.joystick = api_.OpenJoystick(entry.joystick);
		} else {
			opened.haptic = api_.OpenHaptic(entry.id);
		}
		if (opened.haptic == nullptr && opened.joystick == nullptr) {
			r_error = error_text();
			return false;
		}
		++open_count_;
		r_opened = opened;
		return true;
	}
	r_error = "SDL no longer lists '" + p_key + "' (unplugged?)";
	return false;
}

void SdlRuntime::close(SdlOpened &r_opened) {
	if (r_opened.haptic == nullptr && r_opened.joystick == nullptr) {
		return;
	}
	if (r_opened.haptic != nullptr) {
		api_.CloseHaptic(r_opened.haptic);
	}
	if (r_opened.joystick != nullptr) {
		api_.CloseJoystick(r_opened.joystick);
	}
	r_opened = SdlOpened{};
	--open_count_;
}

} // namespace haptics::sdl
