#include "dev_tools/sdl/scripted_sdl.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

// The C functions of the scripted SDL's table (scripted_sdl.h), over the current model.

namespace haptics::sdl {

ScriptedSdl *scripted_sdl_current = nullptr;

namespace {

thread_local std::string error_text;

bool set_error(const std::string &p_text) {
	return scripted_sdl_set_error(p_text);
}

// SDL's Linux driver appends strerror(errno) to its messages.
std::string enodev(const char *p_prefix) {
	return std::string(p_prefix) + ": " + std::strerror(ENODEV);
}

uint32_t feature_of(const SDL_HapticEffect &p_effect) {
	switch (p_effect.type) {
		case SDL_HAPTIC_CONSTANT:
		case SDL_HAPTIC_SINE:
		case SDL_HAPTIC_LEFTRIGHT:
			return p_effect.type;
		default:
			return 0;
	}
}

} // namespace

bool scripted_sdl_set_error(const std::string &p_text) {
	error_text = p_text;
	return false;
}

struct ScriptedSdlAccess {
	using Device = ScriptedSdl::Device;
	using Kind = ScriptedSdlCall::Kind;

	static std::unique_lock<std::mutex> lock() { return std::unique_lock<std::mutex>(scripted_sdl_current->mutex_); }

	static int index_of(const Device *p_device) { return static_cast<int>(p_device - scripted_sdl_current->devices_.data()); }

	static void record(Kind p_kind, const Device *p_device, ScriptedSdlCall p_call = {}) {
		p_call.kind = p_kind;
		p_call.haptic = p_device != nullptr ? index_of(p_device) : -1;
		p_call.when = std::chrono::steady_clock::now();
		scripted_sdl_current->calls_.push_back(p_call);
	}

	// The scripted failure for p_kind, once; true when it fires.
	static bool scripted_failure(Kind p_kind) {
		if (scripted_sdl_current->fail_text_.empty() || scripted_sdl_current->fail_kind_ != p_kind) {
			return false;
		}
		set_error(scripted_sdl_current->fail_text_);
		scripted_sdl_current->fail_text_.clear();
		return true;
	}

	static Device *device(SDL_Haptic *p_haptic) {
		for (Device &device : scripted_sdl_current->devices_) {
			if (reinterpret_cast<SDL_Haptic *>(&device) == p_haptic && device.references > 0) {
				return &device;
			}
		}
		set_error("Parameter 'haptic' is invalid");
		return nullptr;
	}

	static Device *listed(SDL_HapticID p_id) {
		for (Device &device : scripted_sdl_current->devices_) {
			if (device.id != 0 && device.id == p_id) {
				return &device;
			}
		}
		set_error("Haptic device " + std::to_string(p_id) + " not found");
		return nullptr;
	}

	static int SDLCALL GetVersion() { return SDL_VERSIONNUM(3, 4, 18); }

	static bool SDLCALL InitSubSystem(SDL_InitFlags p_flags) {
		auto held = lock();
		record(Kind::INIT, nullptr, ScriptedSdlCall::with_value(static_cast<int>(p_flags)));
		if (scripted_failure(Kind::INIT)) {
			return false;
		}
		ScriptedSdl &sdl = *scripted_sdl_current;
		if ((p_flags & SDL_INIT_HAPTIC) != 0 && sdl.subsystem_++ == 0) {
			for (Device &device : sdl.devices_) {
				device.id = device.plugged ? sdl.next_id_++ : 0;
			}
		}
		if ((p_flags & SDL_INIT_JOYSTICK) != 0 && sdl.joystick_subsystem_++ == 0) {
			for (ScriptedSdl::Joystick &joystick : sdl.joysticks_) {
				const bool plugged = joystick.haptic >= 0 ? sdl.devices_[joystick.haptic].plugged : joystick.plugged;
				joystick.id = plugged ? sdl.next_id_++ : 0;
			}
		}
		return true;
	}

	static void SDLCALL QuitSubSystem(SDL_InitFlags p_flags) {
		auto held = lock();
		ScriptedSdl &sdl = *scripted_sdl_current;
		if ((p_flags & SDL_INIT_HAPTIC) != 0 && sdl.subsystem_ > 0 && --sdl.subsystem_ == 0) {
			for (Device &device : sdl.devices_) {
				device.id = 0;
			}
		}
		if ((p_flags & SDL_INIT_JOYSTICK) != 0 && sdl.joystick_subsystem_ > 0 && --sdl.joystick_subsystem_ == 0) {
			for (ScriptedSdl::Joystick &joystick : sdl.joysticks_) {
				joystick.id = 0;
			}
		}
		record(Kind::QUIT, nullptr, ScriptedSdlCall::with_value(static_cast<int>(p_flags)));
	}

	static const char *SDLCALL GetError() { return error_text.c_str(); }

	static void SDLCALL free(void *p_memory) { std::free(p_memory); }

	static SDL_HapticID *SDLCALL GetHaptics(int *r_count) {
		auto held = lock();
		auto *ids = static_cast<SDL_HapticID *>(std::calloc(scripted_sdl_current->devices_.size() + 1, sizeof(SDL_HapticID)));
		int count = 0;
		for (const Device &device : scripted_sdl_current->devices_) {
			if (device.id != 0) {
				ids[count++] = device.id;
			}
		}
		*r_count = count;
		return ids;
	}

	static const char *SDLCALL GetHapticNameForID(SDL_HapticID p_id) {
		auto held = lock();
		const Device *device = listed(p_id);
		return device != nullptr ? device->script.name.c_str() : nullptr;
	}

	static SDL_Haptic *SDLCALL OpenHaptic(SDL_HapticID p_id) {
		auto held = lock();
		Device *device = listed(p_id);
		if (device == nullptr) {
			return nullptr;
		}
		if (device->references > 0) {
			++device->references;
			return reinterpret_cast<SDL_Haptic *>(device);
		}
		if (!device->plugged || !device->script.open_error.empty() || scripted_failure(Kind::OPEN)) {
			if (!device->plugged) {
				set_error(std::string("Haptic: Unable to open /dev/input/event7: ") + std::strerror(ENOENT));
			} else if (!device->script.open_error.empty()) {
				set_error(device->script.open_error);
			}
			record(Kind::OPEN, device, ScriptedSdlCall::with_ok(false));
			return nullptr;
		}
		device->references = 1;
		device->effects.assign(static_cast<size_t>(device->script.max_effects), {});
		device->rumble = -1;
		record(Kind::OPEN, device);
		// SDL_OpenHaptic: "Disable autocenter and set gain to max."
		if ((device->script.features & SDL_HAPTIC_GAIN) != 0) {
			device->gain = 100;
			record(Kind::GAIN, device, ScriptedSdlCall::with_value(100));
		}
		if ((device->script.features & SDL_HAPTIC_AUTOCENTER) != 0) {
			device->autocenter = 0;
			record(Kind::AUTOCENTER, device, ScriptedSdlCall::with_value(0));
		}
		return reinterpret_cast<SDL_Haptic *>(device);
	}

	static void SDLCALL CloseHaptic(SDL_Haptic *p_haptic) {
		auto held = lock();
		Device *device = ScriptedSdlAccess::device(p_haptic);
		if (device == nullptr || --device->references > 0) {
			return;
		}
		device->effects.clear();
		record(Kind::CLOSE, device);
	}

	static Uint32 SDLCALL GetHapticFeatures(SDL_Haptic *p_haptic) {
		auto held = lock();
		const Device *device = ScriptedSdlAccess::device(p_haptic);
		return device != nullptr ? device->script.features : 0;
	}

	static int SDLCALL GetNumHapticAxes(SDL_Haptic *p_haptic) {
		auto held = lock();
		const Device *device = ScriptedSdlAccess::device(p_haptic);
		return device != nullptr ? device->script.axes : -1;
	}

	static int SDLCALL GetMaxHapticEffects(SDL_Haptic *p_haptic) {
		auto held = lock();
		const Device *device = ScriptedSdlAccess::device(p_haptic);
		return device != nullptr ? device->script.max_effects : -1;
	}

	// The effect p_id of p_device when it is in use; null with SDL's error otherwise.
	static ScriptedSdl::Effect *slot(Device *p_device, SdlEffectId p_id) {
		if (p_id < 0 || p_id >= static_cast<int>(p_device->effects.size()) || !p_device->effects[p_id].in_use) {
			set_error("Haptic: Invalid effect identifier.");
			return nullptr;
		}
		return &p_device->effects[p_id];
	}

	static SdlEffectId SDLCALL CreateHapticEffect(SDL_Haptic *p_haptic, const SDL_HapticEffect *p_effect) {
		auto held = lock();
		Device *device = ScriptedSdlAccess::device(p_haptic);
		if (device == nullptr) {
			return -1;
		}
		ScriptedSdlCall call = ScriptedSdlCall::with_data(*p_effect);
		bool ok = true;
		if ((device->script.features & feature_of(*p_effect)) == 0) {
			ok = set_error("Haptic: Effect not supported by haptic device.");
		} else if (!device->plugged) {
			ok = set_error(enodev("Haptic: Error uploading effect to the device"));
		} else if (scripted_failure(Kind::CREATE)) {
			ok = false;
		}
		for (size_t i = 0; ok && i < device->effects.size(); ++i) {
			if (!device->effects[i].in_use) {
				device->effects[i] = ScriptedSdl::Effect{ true, false, *p_effect };
				call.effect = static_cast<SdlEffectId>(i);
				record(Kind::CREATE, device, call);
				return call.effect;
			}
		}
		if (ok) {
			set_error("Haptic: Device has no free space left.");
		}
		call.ok = false;
		record(Kind::CREATE, device, call);
		return -1;
	}

	// UPDATE, RUN, STOP: the effect's checks and the unplugged device's failure.
	static ScriptedSdl::Effect *effect_call(Kind p_kind, SDL_Haptic *p_haptic, SdlEffectId p_id, const char *p_what,
			ScriptedSdlCall p_call, Device *&r_device) {
		r_device = ScriptedSdlAccess::device(p_haptic);
		if (r_device == nullptr) {
			return nullptr;
		}
		p_call.effect = p_id;
		ScriptedSdl::Effect *effect = slot(r_device, p_id);
		if (effect != nullptr && !r_device->plugged) {
			effect = nullptr;
			set_error(enodev(p_what));
		} else if (effect != nullptr && scripted_failure(p_kind)) {
			effect = nullptr;
		}
		p_call.ok = effect != nullptr;
		record(p_kind, r_device, p_call);
		return effect;
	}

	static bool SDLCALL UpdateHapticEffect(SDL_Haptic *p_haptic, SdlEffectId p_id, const SDL_HapticEffect *p_data) {
		auto held = lock();
		Device *device = nullptr;
		ScriptedSdl::Effect *effect = effect_call(Kind::UPDATE, p_haptic, p_id, "Haptic: Error updating the effect",
				ScriptedSdlCall::with_data(*p_data), device);
		if (effect == nullptr) {
			return false;
		}
		if (effect->data.type != p_data->type) {
			return set_error("Haptic: Updating effect type is illegal.");
		}
		effect->data = *p_data;
		return true;
	}

	static bool SDLCALL RunHapticEffect(SDL_Haptic *p_haptic, SdlEffectId p_id, Uint32 p_iterations) {
		auto held = lock();
		Device *device = nullptr;
		ScriptedSdl::Effect *effect = effect_call(Kind::RUN, p_haptic, p_id, "Haptic: Unable to run the effect",
				ScriptedSdlCall::with_value(static_cast<int>(p_iterations)), device);
		if (effect != nullptr) {
			effect->playing = p_iterations > 0;
		}
		return effect != nullptr;
	}

	static bool SDLCALL StopHapticEffect(SDL_Haptic *p_haptic, SdlEffectId p_id) {
		auto held = lock();
		Device *device = nullptr;
		ScriptedSdl::Effect *effect = effect_call(Kind::STOP, p_haptic, p_id, "Haptic: Unable to stop the effect", ScriptedSdlCall(), device);
		if (effect != nullptr) {
			effect->playing = false;
		}
		return effect != nullptr;
	}

	static void SDLCALL DestroyHapticEffect(SDL_Haptic *p_haptic, SdlEffectId p_id) {
		auto held = lock();
		Device *device = ScriptedSdlAccess::device(p_haptic);
		if (device == nullptr) {
			return;
		}
		if (ScriptedSdl::Effect *effect = slot(device, p_id)) {
			*effect = ScriptedSdl::Effect{};
			record(Kind::DESTROY, device, ScriptedSdlCall::with_effect(p_id));
		}
	}

	static bool SDLCALL SetHapticAutocenter(SDL_Haptic *p_haptic, int p_autocenter) {
		auto held = lock();
		Device *device = ScriptedSdlAccess::device(p_haptic);
		if (device == nullptr) {
			return false;
		}
		if ((device->script.features & SDL_HAPTIC_AUTOCENTER) == 0) {
			return set_error("Haptic: Device does not support setting autocenter.");
		}
		device->autocenter = p_autocenter;
		record(Kind::AUTOCENTER, device, ScriptedSdlCall::with_value(p_autocenter));
		return true;
	}

	static bool SDLCALL InitHapticRumble(SDL_Haptic *p_haptic) {
		auto held = lock();
		Device *device = ScriptedSdlAccess::device(p_haptic);
		if (device == nullptr) {
			return false;
		}
		if ((device->script.features & (SDL_HAPTIC_SINE | SDL_HAPTIC_LEFTRIGHT)) == 0) {
			return set_error("Device doesn't support rumble");
		}
		record(Kind::RUMBLE_INIT, device);
		device->rumble = 0;
		return true;
	}

	static bool SDLCALL PlayHapticRumble(SDL_Haptic *p_haptic, float p_strength, Uint32 p_length) {
		auto held = lock();
		Device *device = ScriptedSdlAccess::device(p_haptic);
		if (device == nullptr || device->rumble < 0) {
			return device != nullptr && set_error("Haptic: Rumble effect not initialized on haptic device");
		}
		const bool ok = device->plugged || set_error(enodev("Haptic: Error updating the effect"));
		ScriptedSdlCall call = ScriptedSdlCall::with_ok(ok);
		call.strength = p_strength;
		call.length_ms = p_length;
		record(Kind::RUMBLE_PLAY, device, call);
		return ok;
	}

	static bool SDLCALL StopHapticRumble(SDL_Haptic *p_haptic) {
		auto held = lock();
		Device *device = ScriptedSdlAccess::device(p_haptic);
		if (device == nullptr) {
			return false;
		}
		const bool ok = device->plugged || set_error(enodev("Haptic: Unable to stop the effect"));
		record(Kind::RUMBLE_STOP, device, ScriptedSdlCall::with_ok(ok));
		return ok;
	}
};

SdlApi ScriptedSdl::api() {
	SdlApi api;
#define HAPTICS_SCRIPTED_SDL(p_name) api.p_name = ScriptedSdlAccess::p_name;
	HAPTICS_SDL_HAPTIC_FUNCTIONS(HAPTICS_SCRIPTED_SDL)
#undef HAPTICS_SCRIPTED_SDL
	fill_scripted_joystick_api(api);
	return api;
}

} // namespace haptics::sdl
