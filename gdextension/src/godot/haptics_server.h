// HapticsServer: the one class GDScript talks to. A thin adapter: it converts engine
// values to the core's plain structs and back, and reports bad input through the engine's
// error printer. All behaviour lives in the engine-free core.
#pragma once

#include <string>
#include <vector>

#include "godot/class_db.h"
#include "godot/containers.h"

namespace haptics::godot {

class HapticsServer : public gd::ExtensionObject {
public:
	static void bind_methods(gd::ClassBinder<HapticsServer> &r_binder);

	// Every device present: the simulated one first, then hidapi and libusb devices, each a
	// Dictionary (id, backend, vendor_id, product_id, path, product, manufacturer, serial,
	// usage_page, usage, known_haptic, model).
	gd::Array list_devices();
	// The entry of list_devices() with this id; an empty Dictionary (and an error) if none.
	gd::Dictionary get_device(const std::string &p_id);
	// Why the last enumeration could not look everywhere (no USB bus, no permission...).
	gd::Array get_device_warnings() const;
	std::string get_version() const;

private:
	std::vector<std::string> last_warnings_;
};

} // namespace haptics::godot
