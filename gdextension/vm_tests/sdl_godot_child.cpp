// The child of GodotSdlProcess (sdl_godot.h): Debian's libSDL3 run for joypads the way Godot 4.6
// runs it. What Godot does is read from godotengine/godot drivers/sdl/joypad_sdl.cpp
// (JoypadSDL::initialize, process_events, close_joypad, ~JoypadSDL) and from what Debian's
// Godot 4.6.3 binary imports from libSDL3 (docs/linux-kernel.md, "Godot's SDL beside ours").
// Godot's mapping database (SDL_AddGamepadMappingsFromIO) is left out: it renames buttons and
// sends the device nothing.

#include "sdl_godot.h"

#include <SDL3/SDL_error.h>
#include <SDL3/SDL_events.h>
#include <SDL3/SDL_gamepad.h>
#include <SDL3/SDL_guid.h>
#include <SDL3/SDL_hints.h>
#include <SDL3/SDL_init.h>
#include <SDL3/SDL_joystick.h>
#include <SDL3/SDL_properties.h>
#include <SDL3/SDL_version.h>

#include <dlfcn.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace haptics::vm {

namespace {

constexpr int CHANNEL_FD = 3; // GodotSdlProcess's socket.
constexpr int FRAME_MS = 16; // Godot calls process_events() once a frame.

#define GODOT_SDL_FUNCTIONS(X) \
	X(SetHint) \
	X(Init) \
	X(Quit) \
	X(GetError) \
	X(GetVersion) \
	X(PollEvent) \
	X(IsGamepad) \
	X(OpenGamepad) \
	X(GetGamepadName) \
	X(GetGamepadJoystick) \
	X(GetGamepadSteamHandle) \
	X(OpenJoystick) \
	X(GetJoystickName) \
	X(GetJoystickGUID) \
	X(GUIDToString) \
	X(GetJoystickProperties) \
	X(GetBooleanProperty) \
	X(GetJoystickVendor) \
	X(GetJoystickProduct) \
	X(GetJoystickPlayerIndex) \
	X(RumbleJoystick) \
	X(CloseGamepad) \
	X(CloseJoystick)

struct Sdl {
#define GODOT_SDL_MEMBER(p_name) decltype(&SDL_##p_name) p_name = nullptr;
	GODOT_SDL_FUNCTIONS(GODOT_SDL_MEMBER)
#undef GODOT_SDL_MEMBER
};

struct Pad {
	SDL_JoystickID id = 0;
	SDL_Joystick *joystick = nullptr;
	SDL_Gamepad *gamepad = nullptr;
	uint16_t vendor = 0;
	uint16_t product = 0;
};

void say(const char *p_format, ...) {
	char line[512];
	va_list args;
	va_start(args, p_format);
	const int length = std::vsnprintf(line, sizeof(line) - 1, p_format, args);
	va_end(args);
	const size_t size = std::min(static_cast<size_t>(length < 0 ? 0 : length), sizeof(line) - 2);
	line[size] = '\n';
	(void)::send(CHANNEL_FD, line, size + 1, MSG_NOSIGNAL);
}

// Loads libSDL3 as the engine's loader would ($HAPTICS_SDL3_LIBRARY first, as our backend).
bool load(Sdl &r_sdl) {
	const char *env = std::getenv("HAPTICS_SDL3_LIBRARY");
	void *handle = ::dlopen(env != nullptr && env[0] != '\0' ? env : "libSDL3.so.0", RTLD_NOW | RTLD_LOCAL);
	if (handle == nullptr) {
		say("init-failed %s", ::dlerror());
		return false;
	}
#define GODOT_SDL_RESOLVE(p_name) \
	r_sdl.p_name = reinterpret_cast<decltype(&SDL_##p_name)>(::dlsym(handle, "SDL_" #p_name)); \
	if (r_sdl.p_name == nullptr) { \
		say("init-failed no SDL_" #p_name); \
		return false; \
	}
	GODOT_SDL_FUNCTIONS(GODOT_SDL_RESOLVE)
#undef GODOT_SDL_RESOLVE
	return true;
}

// JoypadSDL::process_events on SDL_EVENT_JOYSTICK_ADDED.
void open_pad(const Sdl &p_sdl, SDL_JoystickID p_id, std::vector<Pad> &r_pads) {
	Pad pad;
	pad.id = p_id;
	const char *name = nullptr;
	if (p_sdl.IsGamepad(p_id)) {
		pad.gamepad = p_sdl.OpenGamepad(p_id);
		if (pad.gamepad == nullptr) {
			say("open-failed %u %s", static_cast<unsigned>(p_id), p_sdl.GetError());
			return;
		}
		name = p_sdl.GetGamepadName(pad.gamepad);
		pad.joystick = p_sdl.GetGamepadJoystick(pad.gamepad);
	} else {
		pad.joystick = p_sdl.OpenJoystick(p_id);
		if (pad.joystick == nullptr) {
			say("open-failed %u %s", static_cast<unsigned>(p_id), p_sdl.GetError());
			return;
		}
		name = p_sdl.GetJoystickName(pad.joystick);
	}
	char guid_text[64] = {};
	const SDL_GUID guid = p_sdl.GetJoystickGUID(pad.joystick);
	p_sdl.GUIDToString(guid, guid_text, sizeof(guid_text));
	const SDL_PropertiesID properties = p_sdl.GetJoystickProperties(pad.joystick);
	const bool rumble = p_sdl.GetBooleanProperty(properties, SDL_PROP_JOYSTICK_CAP_RUMBLE_BOOLEAN, false);
	const bool light = p_sdl.GetBooleanProperty(properties, SDL_PROP_JOYSTICK_CAP_RGB_LED_BOOLEAN, false);
	pad.vendor = p_sdl.GetJoystickVendor(pad.joystick);
	pad.product = p_sdl.GetJoystickProduct(pad.joystick);
	(void)p_sdl.GetGamepadSteamHandle(pad.gamepad);
	const int player = p_sdl.GetJoystickPlayerIndex(pad.joystick);
	// SDL's GUID keeps its driver in byte 14: 'h' for HIDAPI (SDL_joystick.c).
	say("opened %04x %04x gamepad=%d hidapi=%d rumble=%d light=%d player=%d guid=%s %s", pad.vendor, pad.product,
			pad.gamepad != nullptr, guid.data[14] == 'h', rumble, light, player, guid_text, name != nullptr ? name : "");
	r_pads.push_back(pad);
}

void close_pad(const Sdl &p_sdl, const Pad &p_pad) {
	if (p_pad.gamepad != nullptr) {
		p_sdl.CloseGamepad(p_pad.gamepad);
	} else {
		p_sdl.CloseJoystick(p_pad.joystick);
	}
}

// "vibrate VVVV PPPP WEAK STRONG SECONDS": Input.start_joy_vibration as Godot hands it to SDL.
void vibrate(const Sdl &p_sdl, const std::vector<Pad> &p_pads, const char *p_arguments) {
	unsigned vendor = 0;
	unsigned product = 0;
	double weak = 0.0;
	double strong = 0.0;
	double seconds = 0.0;
	if (std::sscanf(p_arguments, "%x %x %lf %lf %lf", &vendor, &product, &weak, &strong, &seconds) != 5) {
		say("vibrated bad-command");
		return;
	}
	for (const Pad &pad : p_pads) {
		if (pad.vendor == vendor && pad.product == product) {
			const bool ok = p_sdl.RumbleJoystick(pad.joystick, static_cast<Uint16>(strong * UINT16_MAX),
					static_cast<Uint16>(weak * UINT16_MAX), static_cast<Uint32>(seconds * 1000.0));
			say("vibrated %04x %04x %s", vendor, product, ok ? "ok" : p_sdl.GetError());
			return;
		}
	}
	say("vibrated %04x %04x no-such-pad", vendor, product);
}

// Takes the commands that arrived within one frame; false on "quit" or a closed channel.
bool take_commands(const Sdl &p_sdl, const std::vector<Pad> &p_pads, std::string &r_pending) {
	pollfd channel{ CHANNEL_FD, POLLIN, 0 };
	if (::poll(&channel, 1, FRAME_MS) <= 0) {
		return true;
	}
	char buffer[256];
	const ssize_t got = ::recv(CHANNEL_FD, buffer, sizeof(buffer), 0);
	if (got <= 0) {
		return false;
	}
	r_pending.append(buffer, static_cast<size_t>(got));
	size_t end = 0;
	while ((end = r_pending.find('\n')) != std::string::npos) {
		const std::string line = r_pending.substr(0, end);
		r_pending.erase(0, end + 1);
		if (line == "quit") {
			return false;
		}
		if (line.rfind("vibrate ", 0) == 0) {
			vibrate(p_sdl, p_pads, line.c_str() + 8);
		}
	}
	return true;
}

} // namespace

int run_godot_sdl(int p_argc, char **p_argv) {
	Sdl sdl;
	if (!load(sdl)) {
		return 2;
	}
	// JoypadSDL::initialize.
	sdl.SetHint(SDL_HINT_JOYSTICK_THREAD, "1");
	sdl.SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
	for (int i = 0; i < p_argc; ++i) {
		const std::string hint = p_argv[i];
		const size_t equals = hint.find('=');
		if (equals != std::string::npos) {
			sdl.SetHint(hint.substr(0, equals).c_str(), hint.substr(equals + 1).c_str());
			say("hint %s", hint.c_str());
		}
	}
	if (!sdl.Init(SDL_INIT_JOYSTICK | SDL_INIT_GAMEPAD)) {
		say("init-failed %s", sdl.GetError());
		return 3;
	}
	const int version = sdl.GetVersion();
	say("sdl %d.%d.%d", SDL_VERSIONNUM_MAJOR(version), SDL_VERSIONNUM_MINOR(version), SDL_VERSIONNUM_MICRO(version));

	std::vector<Pad> pads;
	std::string pending;
	bool running = true;
	while (running) {
		running = take_commands(sdl, pads, pending);
		SDL_Event event;
		while (sdl.PollEvent(&event)) {
			if (event.type == SDL_EVENT_JOYSTICK_ADDED) {
				open_pad(sdl, event.jdevice.which, pads);
			} else if (event.type == SDL_EVENT_JOYSTICK_REMOVED) {
				for (size_t i = 0; i < pads.size(); ++i) {
					if (pads[i].id == event.jdevice.which) {
						close_pad(sdl, pads[i]);
						say("removed %04x %04x", pads[i].vendor, pads[i].product);
						pads.erase(pads.begin() + static_cast<std::ptrdiff_t>(i));
						break;
					}
				}
			}
		}
	}
	// ~JoypadSDL.
	for (const Pad &pad : pads) {
		close_pad(sdl, pad);
	}
	sdl.Quit();
	say("bye");
	return 0;
}

} // namespace haptics::vm
