#include "devices/sdl/sdl_runtime.h"

#include <cstdio>

namespace haptics::sdl {

std::string describe_sdl_features(const SdlHapticEntry &p_entry) {
	if (!p_entry.features_read) {
		return "features not read";
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
	if (started_ && api_.QuitSubSystem != nullptr) {
		api_.QuitSubSystem(SDL_INIT_HAPTIC);
	}
}

SdlRuntime *SdlRuntime::shared(std::string &r_reason) {
	// Loaded once, kept for the process (a static: initialised once, thread-safe).
	static SdlLibrary library;
	static const Status loaded = load_sdl_library("", library);
	static SdlRuntime *runtime = loaded ? new SdlRuntime(library.api) : nullptr;
	if (runtime == nullptr) {
		r_reason = loaded.message();
	}
	return runtime;
}

const char *SdlRuntime::error_text() const {
	const char *text = api_.GetError != nullptr ? api_.GetError() : nullptr;
	return text != nullptr && text[0] != '\0' ? text : "SDL gave no reason";
}

Status SdlRuntime::start_locked() {
	if (started_ && open_count_ == 0) {
		api_.QuitSubSystem(SDL_INIT_HAPTIC); // A fresh scan: see the header.
		started_ = false;
	}
	if (!started_) {
		if (!api_.InitSubSystem(SDL_INIT_HAPTIC)) {
			return Status::error(StatusCode::DEVICE_ERROR, "SDL's haptic subsystem did not start: %s", error_text());
		}
		started_ = true;
	}
	return Status::success();
}

Status SdlRuntime::list(bool p_read_features, std::vector<SdlHapticEntry> &r_entries) {
	std::lock_guard lock(mutex_);
	entries_.clear();
	const Status started = start_locked();
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
		int same = 0;
		for (const SdlHapticEntry &earlier : entries_) {
			same += earlier.name == entry.name ? 1 : 0;
		}
		entry.key = entry.name + "#" + std::to_string(same);
		if (p_read_features) {
			SDL_Haptic *haptic = api_.OpenHaptic(entry.id);
			if (haptic == nullptr) {
				entry.error = error_text();
			} else {
				entry.features_read = true;
				entry.features = api_.GetHapticFeatures(haptic);
				entry.axes = api_.GetNumHapticAxes(haptic);
				entry.max_effects = api_.GetMaxHapticEffects(haptic);
				api_.CloseHaptic(haptic);
			}
		}
		entries_.push_back(entry);
	}
	api_.Free(ids);
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

SDL_Haptic *SdlRuntime::open_haptic(const std::string &p_key, std::string &r_error) {
	if (!started_) {
		r_error = "SDL's haptic subsystem is not started (list the devices first)";
		return nullptr;
	}
	for (const SdlHapticEntry &entry : entries_) {
		if (entry.key != p_key) {
			continue;
		}
		SDL_Haptic *haptic = api_.OpenHaptic(entry.id);
		if (haptic == nullptr) {
			r_error = error_text();
			return nullptr;
		}
		++open_count_;
		return haptic;
	}
	r_error = "SDL no longer lists '" + p_key + "' (unplugged?)";
	return nullptr;
}

void SdlRuntime::close_haptic(SDL_Haptic *p_haptic) {
	if (p_haptic == nullptr) {
		return;
	}
	api_.CloseHaptic(p_haptic);
	--open_count_;
}

} // namespace haptics::sdl
