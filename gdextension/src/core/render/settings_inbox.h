#pragma once

// The servo's end of a renderer's settings channel: the game writes the renderer's whole
// Config into a seqlock (HapticsSystem::configure), and the renderer takes it from there in
// Renderer::pick_up_settings, only when it is newer than what it last took. No allocation.

#include "core/base/seqlock.h"

#include <cstdint>

namespace haptics {

template <typename T>
class SettingsInbox {
public:
	explicit SettingsInbox(const Seqlock<T> &p_channel) :
			channel_(p_channel) {}

	// Into r_settings: the latest settings when the game wrote newer ones since the last take;
	// with p_restart (a new session) the latest whatever was taken before. False when nothing
	// was taken: nothing new, or the game is mid-write (taken next tick).
	bool take(T &r_settings, bool p_restart) {
		if (p_restart) {
			// A session starts with the latest settings; if the game is writing again right
			// now, the version stays 0 and the next tick takes that too.
			r_settings = channel_.load();
			version_ = 0;
			channel_.try_load(r_settings, &version_);
			return true;
		}
		if (channel_.version() == version_) {
			return false;
		}
		uint64_t version = 0;
		if (!channel_.try_load(r_settings, &version)) {
			return false;
		}
		version_ = version;
		return true;
	}

private:
	const Seqlock<T> &channel_;
	uint64_t version_ = 0;
};

} // namespace haptics
