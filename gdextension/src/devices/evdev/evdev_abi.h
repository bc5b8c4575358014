#pragma once

// The slice of the Linux evdev ABI this backend speaks, as plain constants and byte
// offsets (docs/devices/evdev.md [UAPI]). Our own names (EVDEV_*) rather than <linux/input.h>'s macros,
// so that headers stay free of the system's macro namespace; evdev_abi_check.cpp
// static_asserts every number and offset here against the system header, so a mismatch
// fails the build instead of sending wrong bytes.
//
// The layouts are those of LP64 Linux (x86-64, aarch64): struct ff_effect is 48 bytes there
// because its union holds a pointer (ff_periodic_effect.custom_data) and so is aligned to 8,
// which puts the effect parameters at offset 16. A 32-bit build would get 44 bytes and a
// different EVIOCSFF number; the static_asserts stop such a build.

#include <cstddef>
#include <cstdint>

namespace haptics::evdev {

// Event types.
inline constexpr uint16_t EVDEV_EV_SYN = 0x00;
inline constexpr uint16_t EVDEV_EV_KEY = 0x01;
inline constexpr uint16_t EVDEV_EV_ABS = 0x03;
inline constexpr uint16_t EVDEV_EV_FF = 0x15;
inline constexpr uint16_t EVDEV_EV_MAX = 0x1f;

// EV_SYN codes.
inline constexpr uint16_t EVDEV_SYN_REPORT = 0;
inline constexpr uint16_t EVDEV_SYN_DROPPED = 3; // The client's buffer overflowed: resync.

// EV_ABS codes.
inline constexpr uint16_t EVDEV_ABS_X = 0x00;
inline constexpr uint16_t EVDEV_ABS_Y = 0x01;
inline constexpr uint16_t EVDEV_ABS_WHEEL = 0x08;
inline constexpr uint16_t EVDEV_ABS_MAX = 0x3f;

// EV_KEY codes (buttons start at BTN_MISC; codes below are keyboard keys).
inline constexpr uint16_t EVDEV_BTN_MISC = 0x100;
inline constexpr uint16_t EVDEV_BTN_JOYSTICK = 0x120; // == BTN_TRIGGER
inline constexpr uint16_t EVDEV_BTN_TRIGGER = 0x120;
inline constexpr uint16_t EVDEV_BTN_THUMB = 0x121;
inline constexpr uint16_t EVDEV_BTN_GAMEPAD = 0x130; // == BTN_SOUTH
inline constexpr uint16_t EVDEV_BTN_SOUTH = 0x130;
inline constexpr uint16_t EVDEV_BTN_TRIGGER_HAPPY = 0x2c0;
inline constexpr uint16_t EVDEV_KEY_MAX = 0x2ff;

// EV_FF codes [docs/devices/evdev.md].
inline constexpr uint16_t EVDEV_FF_RUMBLE = 0x50;
inline constexpr uint16_t EVDEV_FF_PERIODIC = 0x51;
inline constexpr uint16_t EVDEV_FF_CONSTANT = 0x52;
inline constexpr uint16_t EVDEV_FF_RAMP = 0x57;
inline constexpr uint16_t EVDEV_FF_SQUARE = 0x58;
inline constexpr uint16_t EVDEV_FF_TRIANGLE = 0x59;
inline constexpr uint16_t EVDEV_FF_SINE = 0x5a;
inline constexpr uint16_t EVDEV_FF_GAIN = 0x60;
inline constexpr uint16_t EVDEV_FF_AUTOCENTER = 0x61;
inline constexpr uint16_t EVDEV_FF_MAX = 0x7f;

// Bitmap sizes the kernel keeps (whole longs: BITS_TO_LONGS(*_CNT) * 8 on LP64).
inline constexpr size_t EVDEV_EV_BITS_BYTES = 8;
inline constexpr size_t EVDEV_ABS_BITS_BYTES = 8;
inline constexpr size_t EVDEV_KEY_BITS_BYTES = 96;
inline constexpr size_t EVDEV_FF_BITS_BYTES = 16;

// struct ff_effect [docs/devices/evdev.md]: type u16 @0, id s16 @2, direction u16 @4,
// trigger {button u16 @6, interval u16 @8}, replay {length u16 @10, delay u16 @12},
// union @16; FF_CONSTANT: level s16 @16, envelope {attack_length @18, attack_level @20,
// fade_length @22, fade_level @24}.
inline constexpr size_t FF_EFFECT_SIZE = 48;
inline constexpr size_t FF_EFFECT_TYPE_OFFSET = 0;
inline constexpr size_t FF_EFFECT_ID_OFFSET = 2;
inline constexpr size_t FF_EFFECT_DIRECTION_OFFSET = 4;
inline constexpr size_t FF_EFFECT_TRIGGER_BUTTON_OFFSET = 6;
inline constexpr size_t FF_EFFECT_TRIGGER_INTERVAL_OFFSET = 8;
inline constexpr size_t FF_EFFECT_REPLAY_LENGTH_OFFSET = 10;
inline constexpr size_t FF_EFFECT_REPLAY_DELAY_OFFSET = 12;
inline constexpr size_t FF_EFFECT_UNION_OFFSET = 16;
inline constexpr size_t FF_CONSTANT_LEVEL_OFFSET = 16;
inline constexpr size_t FF_CONSTANT_ENVELOPE_OFFSET = 18; // 4 x u16, all zero here.
// FF_RUMBLE: strong_magnitude u16 @16, weak_magnitude u16 @18. FF_PERIODIC: waveform u16 @16,
// period u16 @18, magnitude s16 @20, offset s16 @22, phase u16 @24, envelope @26.
inline constexpr size_t FF_RUMBLE_STRONG_OFFSET = 16;
inline constexpr size_t FF_RUMBLE_WEAK_OFFSET = 18;
inline constexpr size_t FF_PERIODIC_WAVEFORM_OFFSET = 16;
inline constexpr size_t FF_PERIODIC_PERIOD_OFFSET = 18;
inline constexpr size_t FF_PERIODIC_MAGNITUDE_OFFSET = 20;

// struct input_event [docs/devices/evdev.md]: struct timeval (16 bytes) then type u16 @16,
// code u16 @18, value s32 @20.
inline constexpr size_t INPUT_EVENT_SIZE = 24;
inline constexpr size_t INPUT_EVENT_TYPE_OFFSET = 16;
inline constexpr size_t INPUT_EVENT_CODE_OFFSET = 18;
inline constexpr size_t INPUT_EVENT_VALUE_OFFSET = 20;

// struct input_absinfo: value, minimum, maximum, fuzz, flat, resolution (s32 each).
inline constexpr size_t INPUT_ABSINFO_SIZE = 24;
// struct input_id: bustype, vendor, product, version (u16 each).
inline constexpr size_t INPUT_ID_SIZE = 8;

// ioctl numbers: _IOC(dir, type, nr, size) = dir << 30 | size << 16 | type << 8 | nr.
inline constexpr uint32_t IOC_WRITE = 1;
inline constexpr uint32_t IOC_READ = 2;

constexpr uint32_t ioc(uint32_t p_dir, uint32_t p_type, uint32_t p_nr, uint32_t p_size) {
	return (p_dir << 30) | ((p_size & 0x3fffu) << 16) | (p_type << 8) | p_nr;
}
constexpr uint32_t ioc_dir(uint32_t p_request) {
	return p_request >> 30;
}
constexpr uint32_t ioc_size(uint32_t p_request) {
	return (p_request >> 16) & 0x3fffu;
}
constexpr uint32_t ioc_type(uint32_t p_request) {
	return (p_request >> 8) & 0xffu;
}
constexpr uint32_t ioc_nr(uint32_t p_request) {
	return p_request & 0xffu;
}

inline constexpr uint32_t EVDEV_IOC_TYPE = 'E';
inline constexpr uint32_t EVDEV_EVIOCGID = ioc(IOC_READ, EVDEV_IOC_TYPE, 0x02, INPUT_ID_SIZE);
inline constexpr uint32_t EVDEV_EVIOCSFF = ioc(IOC_WRITE, EVDEV_IOC_TYPE, 0x80, FF_EFFECT_SIZE); // 0x40304580
// The kernel takes the effect id BY VALUE as the ioctl argument (evdev.c casts the
// pointer back to an int), not through a pointer; the size field still says int.
inline constexpr uint32_t EVDEV_EVIOCRMFF = ioc(IOC_WRITE, EVDEV_IOC_TYPE, 0x81, 4); // 0x40044581
inline constexpr uint32_t EVDEV_EVIOCGEFFECTS = ioc(IOC_READ, EVDEV_IOC_TYPE, 0x84, 4); // 0x80044584

inline constexpr uint32_t EVIOCGNAME_NR = 0x06;
inline constexpr uint32_t EVIOCGKEY_NR = 0x18;
inline constexpr uint32_t EVIOCGBIT_NR = 0x20; // + event type
inline constexpr uint32_t EVIOCGABS_NR = 0x40; // + axis

constexpr uint32_t evdev_eviocgname(uint32_t p_len) {
	return ioc(IOC_READ, EVDEV_IOC_TYPE, EVIOCGNAME_NR, p_len);
}
constexpr uint32_t evdev_eviocgkey(uint32_t p_len) {
	return ioc(IOC_READ, EVDEV_IOC_TYPE, EVIOCGKEY_NR, p_len);
}
constexpr uint32_t evdev_eviocgbit(uint32_t p_event_type, uint32_t p_len) {
	return ioc(IOC_READ, EVDEV_IOC_TYPE, EVIOCGBIT_NR + p_event_type, p_len);
}
constexpr uint32_t evdev_eviocgabs(uint32_t p_axis) {
	return ioc(IOC_READ, EVDEV_IOC_TYPE, EVIOCGABS_NR + p_axis, INPUT_ABSINFO_SIZE);
}

static_assert(EVDEV_EVIOCSFF == 0x40304580u, "docs/devices/evdev.md: EVIOCSFF on x86-64");
static_assert(EVDEV_EVIOCRMFF == 0x40044581u, "docs/devices/evdev.md: EVIOCRMFF");
static_assert(EVDEV_EVIOCGEFFECTS == 0x80044584u, "docs/devices/evdev.md: EVIOCGEFFECTS");

// Little-endian field access for the byte layouts above (evdev is host-endian; every LP64
// Linux target we build for is little-endian, checked in evdev_abi_check.cpp).
inline void put_u16(uint8_t *r_bytes, size_t p_offset, uint16_t p_value) {
	r_bytes[p_offset] = static_cast<uint8_t>(p_value & 0xffu);
	r_bytes[p_offset + 1] = static_cast<uint8_t>(p_value >> 8);
}
inline void put_s32(uint8_t *r_bytes, size_t p_offset, int32_t p_value) {
	const uint32_t value = static_cast<uint32_t>(p_value);
	for (size_t i = 0; i < 4; ++i) {
		r_bytes[p_offset + i] = static_cast<uint8_t>((value >> (8 * i)) & 0xffu);
	}
}
inline uint16_t get_u16(const uint8_t *p_bytes, size_t p_offset) {
	return static_cast<uint16_t>(p_bytes[p_offset] | (p_bytes[p_offset + 1] << 8));
}
inline int16_t get_s16(const uint8_t *p_bytes, size_t p_offset) {
	return static_cast<int16_t>(get_u16(p_bytes, p_offset));
}
inline int32_t get_s32(const uint8_t *p_bytes, size_t p_offset) {
	uint32_t value = 0;
	for (size_t i = 0; i < 4; ++i) {
		value |= static_cast<uint32_t>(p_bytes[p_offset + i]) << (8 * i);
	}
	return static_cast<int32_t>(value);
}

// Bit p_bit of a kernel bitmap as EVIOCGBIT returns it (bytes of little-endian longs, so
// bit b lives in byte b / 8). False beyond p_size.
inline bool test_bit(const uint8_t *p_bits, size_t p_size, uint32_t p_bit) {
	const size_t byte = p_bit / 8;
	return byte < p_size && (p_bits[byte] >> (p_bit % 8)) & 1u;
}
inline void set_bit(uint8_t *r_bits, size_t p_size, uint32_t p_bit) {
	const size_t byte = p_bit / 8;
	if (byte < p_size) {
		r_bits[byte] = static_cast<uint8_t>(r_bits[byte] | (1u << (p_bit % 8)));
	}
}

} // namespace haptics::evdev
