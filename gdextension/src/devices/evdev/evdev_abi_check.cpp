// Our byte layouts and ioctl numbers (evdev_abi.h) against the system's <linux/input.h>:
// any difference fails the build. Also the struct-built effect the tests compare with our
// explicit bytes.

#include "devices/evdev/evdev_abi.h"
#include "devices/evdev/evdev_ff.h"

#include <cstddef>
#include <cstring>
#include <linux/input.h>

namespace haptics::evdev {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "evdev_abi.h writes little-endian fields");

static_assert(sizeof(struct ff_effect) == FF_EFFECT_SIZE, "docs/devices/evdev.md: struct ff_effect is 48 bytes on LP64");
static_assert(offsetof(struct ff_effect, type) == FF_EFFECT_TYPE_OFFSET);
static_assert(offsetof(struct ff_effect, id) == FF_EFFECT_ID_OFFSET);
static_assert(offsetof(struct ff_effect, direction) == FF_EFFECT_DIRECTION_OFFSET);
static_assert(offsetof(struct ff_effect, trigger.button) == FF_EFFECT_TRIGGER_BUTTON_OFFSET);
static_assert(offsetof(struct ff_effect, trigger.interval) == FF_EFFECT_TRIGGER_INTERVAL_OFFSET);
static_assert(offsetof(struct ff_effect, replay.length) == FF_EFFECT_REPLAY_LENGTH_OFFSET);
static_assert(offsetof(struct ff_effect, replay.delay) == FF_EFFECT_REPLAY_DELAY_OFFSET);
static_assert(offsetof(struct ff_effect, u) == FF_EFFECT_UNION_OFFSET);
static_assert(offsetof(struct ff_effect, u.constant.level) == FF_CONSTANT_LEVEL_OFFSET);
static_assert(offsetof(struct ff_effect, u.constant.envelope) == FF_CONSTANT_ENVELOPE_OFFSET);
static_assert(offsetof(struct ff_effect, u.rumble.strong_magnitude) == FF_RUMBLE_STRONG_OFFSET);
static_assert(offsetof(struct ff_effect, u.rumble.weak_magnitude) == FF_RUMBLE_WEAK_OFFSET);
static_assert(offsetof(struct ff_effect, u.periodic.waveform) == FF_PERIODIC_WAVEFORM_OFFSET);
static_assert(offsetof(struct ff_effect, u.periodic.period) == FF_PERIODIC_PERIOD_OFFSET);
static_assert(offsetof(struct ff_effect, u.periodic.magnitude) == FF_PERIODIC_MAGNITUDE_OFFSET);

static_assert(sizeof(struct input_event) == INPUT_EVENT_SIZE, "docs/devices/evdev.md: struct input_event is 24 bytes on x86-64");
static_assert(offsetof(struct input_event, type) == INPUT_EVENT_TYPE_OFFSET);
static_assert(offsetof(struct input_event, code) == INPUT_EVENT_CODE_OFFSET);
static_assert(offsetof(struct input_event, value) == INPUT_EVENT_VALUE_OFFSET);
static_assert(sizeof(struct input_absinfo) == INPUT_ABSINFO_SIZE);
static_assert(offsetof(struct input_absinfo, flat) == 16);
static_assert(sizeof(struct input_id) == INPUT_ID_SIZE);

static_assert(EVDEV_EVIOCSFF == EVIOCSFF);
static_assert(EVDEV_EVIOCRMFF == EVIOCRMFF);
static_assert(EVDEV_EVIOCGEFFECTS == EVIOCGEFFECTS);
static_assert(EVDEV_EVIOCGID == EVIOCGID);
static_assert(evdev_eviocgname(128) == EVIOCGNAME(128));
static_assert(evdev_eviocgkey(EVDEV_KEY_BITS_BYTES) == EVIOCGKEY(EVDEV_KEY_BITS_BYTES));
static_assert(evdev_eviocgbit(EV_FF, EVDEV_FF_BITS_BYTES) == EVIOCGBIT(EV_FF, EVDEV_FF_BITS_BYTES));
static_assert(evdev_eviocgbit(EV_ABS, EVDEV_ABS_BITS_BYTES) == EVIOCGBIT(EV_ABS, EVDEV_ABS_BITS_BYTES));
static_assert(evdev_eviocgabs(ABS_WHEEL) == EVIOCGABS(ABS_WHEEL));

static_assert(EVDEV_EV_SYN == EV_SYN && EVDEV_EV_KEY == EV_KEY && EVDEV_EV_ABS == EV_ABS && EVDEV_EV_FF == EV_FF);
static_assert(EVDEV_EV_MAX == EV_MAX && EVDEV_SYN_REPORT == SYN_REPORT && EVDEV_SYN_DROPPED == SYN_DROPPED);
static_assert(EVDEV_ABS_X == ABS_X && EVDEV_ABS_Y == ABS_Y && EVDEV_ABS_WHEEL == ABS_WHEEL && EVDEV_ABS_MAX == ABS_MAX);
static_assert(EVDEV_BTN_MISC == BTN_MISC && EVDEV_BTN_TRIGGER == BTN_TRIGGER && EVDEV_BTN_THUMB == BTN_THUMB);
static_assert(EVDEV_BTN_SOUTH == BTN_SOUTH && EVDEV_BTN_TRIGGER_HAPPY == BTN_TRIGGER_HAPPY && EVDEV_KEY_MAX == KEY_MAX);
static_assert(EVDEV_FF_RUMBLE == FF_RUMBLE && EVDEV_FF_PERIODIC == FF_PERIODIC && EVDEV_FF_CONSTANT == FF_CONSTANT);
static_assert(EVDEV_FF_RAMP == FF_RAMP && EVDEV_FF_GAIN == FF_GAIN && EVDEV_FF_AUTOCENTER == FF_AUTOCENTER);
static_assert(EVDEV_FF_SQUARE == FF_SQUARE && EVDEV_FF_TRIANGLE == FF_TRIANGLE && EVDEV_FF_SINE == FF_SINE);
static_assert(EVDEV_FF_MAX == FF_MAX);

// Bitmaps: whole longs, as the kernel copies them.
static_assert(EVDEV_EV_BITS_BYTES == (EV_CNT + 63) / 64 * 8);
static_assert(EVDEV_ABS_BITS_BYTES == (ABS_CNT + 63) / 64 * 8);
static_assert(EVDEV_KEY_BITS_BYTES == (KEY_CNT + 63) / 64 * 8);
static_assert(EVDEV_FF_BITS_BYTES == (FF_CNT + 63) / 64 * 8);

void encode_constant_effect_kernel_struct(const FfConstantEffect &p_effect, FfEffectBytes &r_bytes) {
	struct ff_effect effect;
	std::memset(&effect, 0, sizeof(effect)); // Padding too: the bytes are compared whole.
	effect.type = FF_CONSTANT;
	effect.id = p_effect.id;
	effect.direction = p_effect.direction;
	effect.replay.length = p_effect.replay_length_ms;
	effect.replay.delay = p_effect.replay_delay_ms;
	effect.u.constant.level = p_effect.level;
	std::memcpy(r_bytes.data(), &effect, sizeof(effect));
}

} // namespace haptics::evdev
