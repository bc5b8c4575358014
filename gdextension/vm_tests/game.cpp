#include "game.h"

#include "engine/device_factory.h"
#include "ktest.h"

#include <chrono>
#include <thread>

namespace haptics::vm {

bool find_listed(uint16_t p_vendor, uint16_t p_product, std::string_view p_backend, DeviceInfo &r_info) {
	for (const DeviceInfo &info : list_all_devices().devices) {
		if (info.vendor_id == p_vendor && info.product_id == p_product && info.backend == p_backend) {
			r_info = info;
			return true;
		}
	}
	return false;
}

void stand_on_floor(HapticsEngine &p_engine, double p_seconds) {
	Frame frame;
	frame.add_contact(Vec3{ 0.0, 1.0, 0.0 });
	const int count = static_cast<int>(p_seconds * 50.0);
	for (int i = 0; i < count; ++i) {
		frame.sequence = static_cast<uint64_t>(i);
		(void)p_engine.submit_frame(frame);
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
}

bool servo_stops(const HapticsEngine &p_engine, double p_seconds) {
	return eventually([&] { return !p_engine.servo_status().ok(); }, p_seconds);
}

} // namespace haptics::vm
