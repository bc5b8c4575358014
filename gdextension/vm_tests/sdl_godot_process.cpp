// GodotSdlProcess (sdl_godot.h): starts this program again as the Godot-like SDL process and
// talks to it over a socket pair (fd 3 in the child; MSG_NOSIGNAL, so a child that died costs
// no SIGPIPE).

#include "sdl_godot.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>

namespace haptics::vm {

GodotSdlProcess::~GodotSdlProcess() {
	stop(5.0);
}

Status GodotSdlProcess::start(const std::vector<std::string> &p_hints) {
	if (pid_ > 0) {
		return Status::error(StatusCode::INVALID_STATE, "the Godot-like SDL process already runs");
	}
	int channel[2] = { -1, -1 };
	if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, channel) != 0) {
		return Status::error(StatusCode::DEVICE_ERROR, "socketpair: %s", std::strerror(errno));
	}
	// Everything the child needs is made before fork(): it only dups and execs.
	std::vector<std::string> arguments = { "haptics_vm_tests", GODOT_SDL_ARG };
	arguments.insert(arguments.end(), p_hints.begin(), p_hints.end());
	std::vector<char *> argv;
	for (std::string &argument : arguments) {
		argv.push_back(argument.data());
	}
	argv.push_back(nullptr);
	const pid_t pid = ::fork();
	if (pid == 0) {
		if (::dup2(channel[1], 3) < 0 || ::fcntl(3, F_SETFD, 0) < 0) {
			::_exit(126);
		}
		::execv("/proc/self/exe", argv.data());
		::_exit(127);
	}
	::close(channel[1]);
	if (pid < 0) {
		::close(channel[0]);
		return Status::error(StatusCode::DEVICE_ERROR, "fork: %s", std::strerror(errno));
	}
	pid_ = pid;
	channel_ = channel[0];
	reader_ = std::thread([this] { read_lines(); });
	return Status::success();
}

void GodotSdlProcess::read_lines() {
	std::string pending;
	char buffer[512];
	while (true) {
		const ssize_t got = ::recv(channel_, buffer, sizeof(buffer), 0);
		if (got <= 0) {
			if (got < 0 && errno == EINTR) {
				continue;
			}
			return;
		}
		pending.append(buffer, static_cast<size_t>(got));
		size_t end = 0;
		while ((end = pending.find('\n')) != std::string::npos) {
			std::lock_guard lock(mutex_);
			lines_.push_back(pending.substr(0, end));
			pending.erase(0, end + 1);
		}
	}
}

void GodotSdlProcess::send(const std::string &p_line) {
	if (channel_ < 0) {
		return;
	}
	const std::string line = p_line + "\n";
	(void)::send(channel_, line.data(), line.size(), MSG_NOSIGNAL);
}

bool GodotSdlProcess::opened(uint16_t p_vendor, uint16_t p_product, GodotSdlJoypad &r_joypad) const {
	char prefix[32];
	std::snprintf(prefix, sizeof(prefix), "opened %04x %04x ", p_vendor, p_product);
	std::lock_guard lock(mutex_);
	for (const std::string &line : lines_) {
		if (line.rfind(prefix, 0) != 0) {
			continue;
		}
		int gamepad = 0;
		int hidapi = 0;
		int rumble = 0;
		int light = 0;
		int player = -1;
		int name_at = 0;
		if (std::sscanf(line.c_str() + std::strlen(prefix), "gamepad=%d hidapi=%d rumble=%d light=%d player=%d guid=%*s %n",
					&gamepad, &hidapi, &rumble, &light, &player, &name_at) < 5) {
			continue;
		}
		r_joypad.vendor = p_vendor;
		r_joypad.product = p_product;
		r_joypad.gamepad = gamepad != 0;
		r_joypad.hidapi = hidapi != 0;
		r_joypad.rumble = rumble != 0;
		r_joypad.light = light != 0;
		r_joypad.player = player;
		r_joypad.name = line.substr(std::strlen(prefix) + static_cast<size_t>(name_at));
		return true;
	}
	return false;
}

bool GodotSdlProcess::initialised(std::string &r_version) const {
	std::lock_guard lock(mutex_);
	for (const std::string &line : lines_) {
		if (line.rfind("sdl ", 0) == 0) {
			r_version = line.substr(4);
			return true;
		}
	}
	return false;
}

void GodotSdlProcess::vibrate(uint16_t p_vendor, uint16_t p_product, double p_weak, double p_strong, double p_seconds) {
	char line[96];
	std::snprintf(line, sizeof(line), "vibrate %04x %04x %.3f %.3f %.3f", p_vendor, p_product, p_weak, p_strong, p_seconds);
	send(line);
}

bool GodotSdlProcess::stop(double p_seconds) {
	if (pid_ <= 0) {
		return true;
	}
	send("quit");
	int status = 0;
	bool exited = false;
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_seconds);
	while (!exited && std::chrono::steady_clock::now() < deadline) {
		exited = ::waitpid(pid_, &status, WNOHANG) == pid_;
		if (!exited) {
			std::this_thread::sleep_for(std::chrono::milliseconds(20));
		}
	}
	if (!exited) {
		::kill(pid_, SIGKILL); // Our own child, by its id.
		(void)::waitpid(pid_, &status, 0);
	}
	::shutdown(channel_, SHUT_RDWR);
	if (reader_.joinable()) {
		reader_.join();
	}
	::close(channel_);
	channel_ = -1;
	pid_ = -1;
	return exited && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::vector<std::string> GodotSdlProcess::lines() const {
	std::lock_guard lock(mutex_);
	return lines_;
}

} // namespace haptics::vm
