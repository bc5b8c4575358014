#pragma once

// A second process that runs Debian's libSDL3 for joypads the way Godot 4.6 does
// (drivers/sdl/joypad_sdl.cpp; docs/linux-kernel.md, "Godot's SDL beside ours"): hints
// SDL_JOYSTICK_THREAD=1 and SDL_NO_SIGNAL_HANDLERS=1, SDL_Init(JOYSTICK | GAMEPAD) with SDL's
// defaults otherwise (HIDAPI drivers on), every joypad opened as it is added (a gamepad with
// SDL_OpenGamepad, anything else with SDL_OpenJoystick), its properties read, events pumped
// once a frame (60 Hz), SDL_RumbleJoystick for Input.start_joy_vibration(), and at exit every
// joypad closed and SDL_Quit. The VM test program runs it as itself with GODOT_SDL_ARG
// (main.cpp); GodotSdlProcess starts it and talks to it over two pipes, a line each way.

#include "core/base/status.h"

#include <sys/types.h>

#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace haptics::vm {

inline constexpr char GODOT_SDL_ARG[] = "--godot-sdl";

// The child's main: p_argv are extra "NAME=VALUE" hints set before SDL_Init (the hints a game
// or an addon could set in the same libSDL3). Reads commands on fd 0, writes lines on fd 3.
int run_godot_sdl(int p_argc, char **p_argv);

// A joypad the child opened, as it said.
struct GodotSdlJoypad {
	uint16_t vendor = 0;
	uint16_t product = 0;
	bool gamepad = false; // SDL_IsGamepad: opened with SDL_OpenGamepad.
	bool hidapi = false; // SDL's HIDAPI driver has it (the GUID's driver byte is 'h').
	bool rumble = false; // SDL_PROP_JOYSTICK_CAP_RUMBLE_BOOLEAN: Godot will send it vibration.
	bool light = false; // SDL_PROP_JOYSTICK_CAP_RGB_LED_BOOLEAN.
	int player = -1;
	std::string name;
};

class GodotSdlProcess {
public:
	GodotSdlProcess() = default;
	~GodotSdlProcess(); // stop(), then SIGKILL if it is still there.
	GodotSdlProcess(const GodotSdlProcess &) = delete;
	GodotSdlProcess &operator=(const GodotSdlProcess &) = delete;

	// Starts the child (this program, /proc/self/exe, with GODOT_SDL_ARG and p_hints).
	Status start(const std::vector<std::string> &p_hints = {});
	bool running() const { return pid_ > 0; }
	// The joypad with these ids the child opened, if it said so yet; the "sdl" line (SDL's
	// version) once SDL_Init returned.
	bool opened(uint16_t p_vendor, uint16_t p_product, GodotSdlJoypad &r_joypad) const;
	bool initialised(std::string &r_version) const;
	// What Godot does for Input.start_joy_vibration(device, p_weak, p_strong, p_seconds):
	// SDL_RumbleJoystick(strong * 0xFFFF, weak * 0xFFFF, seconds * 1000).
	void vibrate(uint16_t p_vendor, uint16_t p_product, double p_weak, double p_strong, double p_seconds);
	// Asks it to close its joypads and quit SDL as Godot does at exit, and waits up to
	// p_seconds for it to exit; true when it exited with status 0.
	bool stop(double p_seconds = 10.0);
	// Everything it said, oldest first.
	std::vector<std::string> lines() const;

private:
	void read_lines();
	void send(const std::string &p_line);

	pid_t pid_ = -1;
	int channel_ = -1; // Our end of the socket pair.
	std::thread reader_;
	mutable std::mutex mutex_;
	std::vector<std::string> lines_;
};

} // namespace haptics::vm
