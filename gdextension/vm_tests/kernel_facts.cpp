// What the real ff-core does that the scripted evdev kernel (dev_tools/evdev) models, checked
// side by side on the same script: a client of the uinput stick and a client of a scripted
// kernel make the same calls, and what each device ends up with must agree.
//  - EV_FF bits: ff-core adds FF_RUMBLE to a device with FF_PERIODIC;
//  - a rumble upload reaches such a device as ff-core's compat sine (50 ms, 2/3 strong +
//    1/3 weak, halved);
//  - closing the node stops and erases the client's effects.

#include "dev_tools/evdev/scripted_evdev_kernel.h"
#include "dev_tools/uinput/uinput_ff_device.h"
#include "devices/evdev/evdev_effect.h"
#include "ktest.h"
#include "scenarios.h"

#include <cstdio>
#include <cstring>

namespace haptics::vm {

namespace {

using evdev::EvdevSyscalls;

int upload(EvdevSyscalls &r_sys, int p_fd, evdev::FfEffectBytes &r_bytes) {
	const int result = r_sys.ioctl(p_fd, evdev::EVDEV_EVIOCSFF, r_bytes.data());
	return result < 0 ? result : evdev::get_s16(r_bytes.data(), evdev::FF_EFFECT_ID_OFFSET);
}

void play(EvdevSyscalls &r_sys, int p_fd, int p_id, int32_t p_count) {
	evdev::InputEventBytes event;
	evdev::encode_input_event(evdev::EVDEV_EV_FF, static_cast<uint16_t>(p_id), p_count, event);
	(void)r_sys.write(p_fd, event.data(), event.size());
}

} // namespace

void check_kernel_facts(Report &r_report, uinput::UinputFfDevice &p_stick) {
	const evdev::ScriptedEvdevScript script = evdev::scripted_joystick_script();
	const std::shared_ptr<EvdevSyscalls> real = evdev::linux_evdev_syscalls();
	evdev::ScriptedEvdevKernel scripted(script);
	const int real_fd = real->open_device(p_stick.event_path().c_str());
	const int scripted_fd = scripted.open_device(script.path.c_str());
	if (!r_report.check(real_fd >= 0 && scripted_fd >= 0, "facts: a client opens the stick's node and the scripted kernel's")) {
		return;
	}

	uint8_t real_bits[evdev::EVDEV_FF_BITS_BYTES] = {};
	uint8_t scripted_bits[evdev::EVDEV_FF_BITS_BYTES] = {};
	const uint32_t get_ff_bits = evdev::evdev_eviocgbit(evdev::EVDEV_EV_FF, sizeof(real_bits));
	(void)real->ioctl(real_fd, get_ff_bits, real_bits);
	(void)scripted.ioctl(scripted_fd, get_ff_bits, scripted_bits);
	const evdev::EvdevFfFeatures real_features = evdev::ff_features_from_bits(real_bits, sizeof(real_bits));
	r_report.wire("facts: EVIOCGBIT(EV_FF) of the real kernel", real_bits);
	r_report.wire("facts: EVIOCGBIT(EV_FF) of the scripted kernel", scripted_bits);
	r_report.check(real_features.rumble && real_features.periodic && std::memcmp(real_bits, scripted_bits, sizeof(real_bits)) == 0,
			"facts: the kernel offers FF_RUMBLE on a device created without it but with FF_PERIODIC (" +
					evdev::describe_ff_features(real_features) + "); the scripted kernel's bits are the same");

	p_stick.clear_records();
	evdev::FfEffectBytes bytes;
	const evdev::FfRumbleEffect rumble{ -1, 0x6000, 0x3000, 0 };
	evdev::encode_rumble_effect(rumble, bytes);
	const int real_rumble = upload(*real, real_fd, bytes);
	evdev::encode_rumble_effect(rumble, bytes);
	const int scripted_rumble = upload(scripted, scripted_fd, bytes);
	play(scripted, scripted_fd, scripted_rumble, 1);
	uinput::UinputRecord got;
	const bool reached = p_stick.last_upload(evdev::EVDEV_FF_PERIODIC, got);
	const int16_t compat = static_cast<int16_t>(rumble.strong_magnitude / 3 + rumble.weak_magnitude / 6);
	const evdev::ScriptedRenderedForce scripted_force = scripted.rendered();
	char text[240];
	std::snprintf(text, sizeof(text),
			"facts: FF_RUMBLE (strong 0x%04x, weak 0x%04x) reaches the device as FF_PERIODIC waveform 0x%02x period %u "
			"magnitude %d (ff-core's sine: %d); the scripted kernel stores magnitude %d",
			rumble.strong_magnitude, rumble.weak_magnitude, got.effect.periodic_waveform, got.effect.periodic_period_ms,
			got.effect.periodic_magnitude, compat, scripted_force.periodic_magnitude);
	r_report.wire("facts: the ff_effect the device got for a rumble upload", got.bytes);
	r_report.check(real_rumble >= 0 && reached && got.effect.periodic_waveform == evdev::EVDEV_FF_SINE &&
					got.effect.periodic_period_ms == 50 && got.effect.periodic_magnitude == compat &&
					scripted_force.periodic_playing == 1 && scripted_force.periodic_magnitude == compat,
			text);

	// A constant force playing beside it, then the client goes away without erasing anything.
	evdev::FfConstantEffect constant;
	constant.direction = 0x4000;
	constant.level = 0x2000;
	evdev::encode_constant_effect(constant, bytes);
	const int real_constant = upload(*real, real_fd, bytes);
	play(*real, real_fd, real_constant, 1);
	evdev::encode_constant_effect(constant, bytes);
	play(scripted, scripted_fd, upload(scripted, scripted_fd, bytes), 1);
	const bool playing = eventually([&] { return p_stick.rendered().playing == 1 && p_stick.effects_in_use() == 2; }, 2.0);
	(void)real->close(real_fd);
	(void)scripted.close(scripted_fd);
	int erased = 0;
	int stopped = 0;
	for (const uinput::UinputRecord &record : p_stick.records()) {
		erased += record.kind == uinput::UinputRecord::Kind::ERASE ? 1 : 0;
		stopped += record.kind == uinput::UinputRecord::Kind::PLAY && record.id == real_constant && record.value == 0 ? 1 : 0;
	}
	std::snprintf(text, sizeof(text),
			"facts: closing the node stopped (%d) and erased (%d of 2) the client's effects; the device holds %d, the scripted kernel %d",
			stopped, erased, p_stick.effects_in_use(), scripted.effects_in_use());
	r_report.check(playing && erased == 2 && stopped >= 1 && p_stick.effects_in_use() == 0 && scripted.effects_in_use() == 0,
			text);
}

} // namespace haptics::vm
