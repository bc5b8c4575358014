#include "devices/sdl/sdl_runtime.h"

#include <cctype>

// SdlRuntime's listing of SDL's joysticks (sdl_runtime.h, "Entries"): which joystick is a
// haptic's, which is a pad with rumble only, and which another backend drives.

namespace haptics::sdl {

namespace {

// SDL names a DirectInput haptic by DirectInput's product name and its joystick by the same
// name tidied (SDL_CreateJoystickName: spacing, repeated vendor words): compared without case
// or spaces.
std::string folded(const std::string &p_name) {
	std::string text;
	for (const char c : p_name) {
		if (!std::isspace(static_cast<unsigned char>(c))) {
			text += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
		}
	}
	return text;
}

const SdlClaim *claim_for(const std::vector<SdlClaim> &p_claims, uint16_t p_vendor, uint16_t p_product) {
	for (const SdlClaim &claim : p_claims) {
		if (p_vendor != 0 && claim.vendor_id == p_vendor && claim.product_id == p_product) {
			return &claim;
		}
	}
	return nullptr;
}

} // namespace

void SdlRuntime::list_joysticks_locked(const SdlListOptions &p_options) {
	// Devices SDL's drivers add after their start (RawInput's arrivals) reach its list here.
	api_.UpdateJoysticks();
	int count = 0;
	SDL_JoystickID *ids = api_.GetJoysticks(&count);
	if (ids == nullptr) {
		return;
	}
	const size_t haptics = entries_.size();
	for (int i = 0; i < count; ++i) {
		SdlHapticEntry entry;
		entry.kind = SdlEntryKind::JOYSTICK;
		entry.joystick = ids[i];
		const char *name = api_.GetJoystickNameForID(ids[i]);
		entry.name = name != nullptr ? name : "unnamed joystick";
		entry.vendor_id = api_.GetJoystickVendorForID(ids[i]);
		entry.product_id = api_.GetJoystickProductForID(ids[i]);
		if (const SdlClaim *claim = claim_for(p_options.claims, entry.vendor_id, entry.product_id)) {
			// Not opened. Its haptic, if SDL lists one, is found by name: SDL says which haptic
			// is a joystick's only once the joystick is open.
			bool haptic = false;
			for (size_t h = 0; h < haptics; ++h) {
				if (entries_[h].vendor_id == 0 && entries_[h].claimed_by.empty() && folded(entries_[h].name) == folded(entry.name)) {
					entries_[h].claimed_by = claim->reason;
					entries_[h].vendor_id = entry.vendor_id;
					entries_[h].product_id = entry.product_id;
					haptic = true;
					break;
				}
			}
			if (!haptic) {
				entry.claimed_by = claim->reason;
				entries_.push_back(entry);
			}
			continue;
		}
		if (!p_options.read) {
			entries_.push_back(entry);
			continue;
		}
		SDL_Joystick *joystick = api_.OpenJoystick(ids[i]);
		if (joystick == nullptr) {
			entry.error = error_text();
			entries_.push_back(entry);
			continue;
		}
		bool haptic = false;
		if (api_.IsJoystickHaptic(joystick)) {
			if (SDL_Haptic *opened = api_.OpenHapticFromJoystick(joystick)) {
				const SDL_HapticID id = api_.GetHapticID(opened);
				for (size_t h = 0; h < haptics; ++h) {
					if (entries_[h].id == id) {
						entries_[h].vendor_id = entry.vendor_id;
						entries_[h].product_id = entry.product_id;
						haptic = true;
					}
				}
				api_.CloseHaptic(opened);
			}
		}
		if (!haptic) {
			entry.features_read = true;
			entry.rumble = api_.GetBooleanProperty(api_.GetJoystickProperties(joystick), SDL_PROP_JOYSTICK_CAP_RUMBLE_BOOLEAN, false);
			entries_.push_back(entry);
		}
		api_.CloseJoystick(joystick);
	}
	api_.free(ids);
}

} // namespace haptics::sdl
