#include "dev_tools/sdl/scripted_sdl.h"

#include <cstdlib>
#include <cstring>

// The joystick functions of the scripted SDL's table (scripted_sdl.h), over the current model.

namespace haptics::sdl {

struct ScriptedSdlJoystickAccess {
	using Joystick = ScriptedSdl::Joystick;
	using Kind = ScriptedSdlCall::Kind;

	static std::unique_lock<std::mutex> lock() { return std::unique_lock<std::mutex>(scripted_sdl_current->mutex_); }

	static void record(Kind p_kind, const Joystick *p_joystick, ScriptedSdlCall p_call = {}) {
		p_call.kind = p_kind;
		p_call.haptic = p_joystick != nullptr ? static_cast<int>(p_joystick - scripted_sdl_current->joysticks_.data()) : -1;
		p_call.when = std::chrono::steady_clock::now();
		scripted_sdl_current->calls_.push_back(p_call);
	}

	static bool plugged(const Joystick &p_joystick) {
		return p_joystick.haptic >= 0 ? scripted_sdl_current->devices_[p_joystick.haptic].plugged : p_joystick.plugged;
	}

	static Joystick *listed(SDL_JoystickID p_id) {
		for (Joystick &joystick : scripted_sdl_current->joysticks_) {
			if (joystick.id != 0 && joystick.id == p_id) {
				return &joystick;
			}
		}
		scripted_sdl_set_error("Joystick " + std::to_string(p_id) + " not found");
		return nullptr;
	}

	static Joystick *opened(SDL_Joystick *p_joystick) {
		for (Joystick &joystick : scripted_sdl_current->joysticks_) {
			if (reinterpret_cast<SDL_Joystick *>(&joystick) == p_joystick && joystick.references > 0) {
				return &joystick;
			}
		}
		scripted_sdl_set_error("Parameter 'joystick' is invalid");
		return nullptr;
	}

	static bool SDLCALL SetHint(const char *p_name, const char *p_value) {
		auto held = lock();
		scripted_sdl_current->hints_[p_name] = p_value != nullptr ? p_value : "";
		return true;
	}

	static SDL_JoystickID *SDLCALL GetJoysticks(int *r_count) {
		auto held = lock();
		auto *ids = static_cast<SDL_JoystickID *>(std::calloc(scripted_sdl_current->joysticks_.size() + 1, sizeof(SDL_JoystickID)));
		int count = 0;
		for (const Joystick &joystick : scripted_sdl_current->joysticks_) {
			if (joystick.id != 0) {
				ids[count++] = joystick.id;
			}
		}
		*r_count = count;
		return ids;
	}

	static const char *SDLCALL GetJoystickNameForID(SDL_JoystickID p_id) {
		auto held = lock();
		const Joystick *joystick = listed(p_id);
		return joystick != nullptr ? joystick->script.name.c_str() : nullptr;
	}

	static Uint16 SDLCALL GetJoystickVendorForID(SDL_JoystickID p_id) {
		auto held = lock();
		const Joystick *joystick = listed(p_id);
		return joystick != nullptr ? joystick->script.vendor_id : 0;
	}

	static Uint16 SDLCALL GetJoystickProductForID(SDL_JoystickID p_id) {
		auto held = lock();
		const Joystick *joystick = listed(p_id);
		return joystick != nullptr ? joystick->script.product_id : 0;
	}

	static SDL_Joystick *SDLCALL OpenJoystick(SDL_JoystickID p_id) {
		auto held = lock();
		Joystick *joystick = listed(p_id);
		if (joystick == nullptr) {
			return nullptr;
		}
		if (!plugged(*joystick) || !joystick->script.open_error.empty()) {
			scripted_sdl_set_error(joystick->script.open_error.empty() ? "Joystick not connected" : joystick->script.open_error);
			record(Kind::JOYSTICK_OPEN, joystick, ScriptedSdlCall::with_ok(false));
			return nullptr;
		}
		if (joystick->references++ == 0) {
			record(Kind::JOYSTICK_OPEN, joystick);
		}
		return reinterpret_cast<SDL_Joystick *>(joystick);
	}

	static void SDLCALL CloseJoystick(SDL_Joystick *p_joystick) {
		auto held = lock();
		Joystick *joystick = opened(p_joystick);
		if (joystick != nullptr && --joystick->references == 0) {
			record(Kind::JOYSTICK_CLOSE, joystick);
		}
	}

	static bool SDLCALL JoystickConnected(SDL_Joystick *p_joystick) {
		auto held = lock();
		const Joystick *joystick = opened(p_joystick);
		return joystick != nullptr && plugged(*joystick);
	}

	static void SDLCALL UpdateJoysticks() {
		auto held = lock();
		record(Kind::JOYSTICK_UPDATE, nullptr);
	}

	static void SDLCALL SetJoystickEventsEnabled(bool p_enabled) {
		auto held = lock();
		scripted_sdl_current->joystick_events_ = p_enabled;
	}

	// A joystick's properties are its index + 1: only the rumble capability is modelled.
	static SDL_PropertiesID SDLCALL GetJoystickProperties(SDL_Joystick *p_joystick) {
		auto held = lock();
		const Joystick *joystick = opened(p_joystick);
		return joystick != nullptr ? static_cast<SDL_PropertiesID>(joystick - scripted_sdl_current->joysticks_.data() + 1) : 0;
	}

	static bool SDLCALL GetBooleanProperty(SDL_PropertiesID p_properties, const char *p_name, bool p_default) {
		auto held = lock();
		const auto &joysticks = scripted_sdl_current->joysticks_;
		if (p_properties == 0 || p_properties > joysticks.size() || std::strcmp(p_name, SDL_PROP_JOYSTICK_CAP_RUMBLE_BOOLEAN) != 0) {
			return p_default;
		}
		return joysticks[p_properties - 1].script.rumble;
	}

	static bool SDLCALL RumbleJoystick(SDL_Joystick *p_joystick, Uint16 p_low, Uint16 p_high, Uint32 p_duration_ms) {
		auto held = lock();
		Joystick *joystick = opened(p_joystick);
		if (joystick == nullptr) {
			return false;
		}
		bool ok = true;
		if (!joystick->script.rumble) {
			ok = scripted_sdl_set_error("That operation is not supported");
		} else if (!plugged(*joystick)) {
			ok = scripted_sdl_set_error("XInputSetState() failed"); // SDL's XInput driver's text.
		} else {
			joystick->low = p_low;
			joystick->high = p_high;
		}
		ScriptedSdlCall call = ScriptedSdlCall::with_ok(ok);
		call.low = p_low;
		call.high = p_high;
		call.length_ms = p_duration_ms;
		record(Kind::JOYSTICK_RUMBLE, joystick, call);
		return ok;
	}

	static bool SDLCALL IsJoystickHaptic(SDL_Joystick *p_joystick) {
		auto held = lock();
		const Joystick *joystick = opened(p_joystick);
		return joystick != nullptr && joystick->haptic >= 0 && !joystick->script.gamepad;
	}

	// As SDL's: the haptic, opened (or one more reference), without setting gain or autocentre.
	static SDL_Haptic *SDLCALL OpenHapticFromJoystick(SDL_Joystick *p_joystick) {
		auto held = lock();
		const Joystick *joystick = opened(p_joystick);
		if (joystick == nullptr || joystick->haptic < 0 || joystick->script.gamepad) {
			scripted_sdl_set_error("Haptic: Joystick isn't a haptic device.");
			return nullptr;
		}
		auto &device = scripted_sdl_current->devices_[joystick->haptic];
		if (device.references++ == 0) {
			device.effects.assign(static_cast<size_t>(device.script.max_effects), {});
			device.rumble = -1;
		}
		record(Kind::HAPTIC_FROM_JOYSTICK, joystick);
		return reinterpret_cast<SDL_Haptic *>(&device);
	}

	static SDL_HapticID SDLCALL GetHapticID(SDL_Haptic *p_haptic) {
		auto held = lock();
		for (const auto &device : scripted_sdl_current->devices_) {
			if (reinterpret_cast<SDL_Haptic *>(const_cast<ScriptedSdl::Device *>(&device)) == p_haptic && device.references > 0) {
				return device.id;
			}
		}
		scripted_sdl_set_error("Parameter 'haptic' is invalid");
		return 0;
	}
};

void fill_scripted_joystick_api(SdlApi &r_api) {
#define HAPTICS_SCRIPTED_SDL(p_name) r_api.p_name = ScriptedSdlJoystickAccess::p_name;
	HAPTICS_SDL_JOYSTICK_FUNCTIONS(HAPTICS_SCRIPTED_SDL)
#undef HAPTICS_SCRIPTED_SDL
}

} // namespace haptics::sdl
