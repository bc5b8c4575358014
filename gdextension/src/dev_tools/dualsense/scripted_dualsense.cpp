#include "dev_tools/dualsense/scripted_dualsense.h"

#include "devices/dualsense/dualsense_crc.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace haptics::dualsense {

namespace {

// The pad's button bits (PS-K DS_BUTTONS*), written out independently of the decoder's
// table so that the decode tests cross-check two tables rather than one against itself.
struct RawButton {
	Button button;
	uint8_t byte;
	uint8_t mask;
};

constexpr RawButton RAW_BUTTONS[] = {
	{ BUTTON_SQUARE, 0, 0x10 },
	{ BUTTON_CROSS, 0, 0x20 },
	{ BUTTON_CIRCLE, 0, 0x40 },
	{ BUTTON_TRIANGLE, 0, 0x80 },
	{ BUTTON_L1, 1, 0x01 },
	{ BUTTON_R1, 1, 0x02 },
	{ BUTTON_L2, 1, 0x04 },
	{ BUTTON_R2, 1, 0x08 },
	{ BUTTON_CREATE, 1, 0x10 },
	{ BUTTON_OPTIONS, 1, 0x20 },
	{ BUTTON_L3, 1, 0x40 },
	{ BUTTON_R3, 1, 0x80 },
	{ BUTTON_PS, 2, 0x01 },
	{ BUTTON_TOUCHPAD, 2, 0x02 },
	{ BUTTON_MIC_MUTE, 2, 0x04 },
};

// The d-pad bits -> hat value (0 up, clockwise; 8 released).
uint8_t hat_from(uint32_t p_buttons) {
	const bool up = p_buttons & (1u << BUTTON_DPAD_UP);
	const bool right = p_buttons & (1u << BUTTON_DPAD_RIGHT);
	const bool down = p_buttons & (1u << BUTTON_DPAD_DOWN);
	const bool left = p_buttons & (1u << BUTTON_DPAD_LEFT);
	if (up) {
		return right ? 1 : left ? 7
								: 0;
	}
	if (down) {
		return right ? 3 : left ? 5
								: 4;
	}
	return right ? 2 : left ? 6
							: 8;
}

void raw_buttons(uint32_t p_buttons, uint8_t (&r_raw)[4]) {
	std::memset(r_raw, 0, sizeof(r_raw));
	r_raw[0] = hat_from(p_buttons);
	for (const RawButton &raw : RAW_BUTTONS) {
		if (p_buttons & (1u << raw.button)) {
			r_raw[raw.byte] |= raw.mask;
		}
	}
}

uint8_t raw_axis(double p_value) {
	const double clamped = std::clamp(std::isfinite(p_value) ? p_value : 0.0, -1.0, 1.0);
	return static_cast<uint8_t>(std::clamp(std::lround(128.0 + clamped * 127.0), 0L, 255L));
}

// hidapi's texts on hidraw for a vanished device (HAPI-lib linux/hid.c): strerror(ENODEV) for
// writes and ioctls, the poll error for reads.
constexpr const char *WRITE_GONE = "hid_write: No such device";
constexpr const char *READ_GONE = "hid_read: hid_read_timeout: unexpected poll error (device disconnected)";

} // namespace

ScriptedDualSense::ScriptedDualSense(const ScriptedDualSenseOptions &p_options) :
		options_(p_options), history_(std::make_unique<Recorded[]>(HISTORY_CAPACITY)) {
	working_.full_reports = options_.bus != Bus::BLUETOOTH;
	held_.store(working_);
}

void ScriptedDualSense::set_stick(uint8_t p_x, uint8_t p_y) {
	stick_.store(static_cast<uint32_t>(p_x) | static_cast<uint32_t>(p_y) << 8, std::memory_order_relaxed);
}

void ScriptedDualSense::set_stick_deflection(double p_x, double p_y) {
	set_stick(raw_axis(p_x), raw_axis(-p_y)); // The pad's y grows downward.
}

void ScriptedDualSense::set_buttons(uint32_t p_buttons) {
	buttons_.store(p_buttons, std::memory_order_relaxed);
}

void ScriptedDualSense::set_battery(uint8_t p_tenths) {
	battery_.store(std::min<uint32_t>(p_tenths, 10), std::memory_order_relaxed);
}

ScriptedPadCounters ScriptedDualSense::counters() const {
	ScriptedPadCounters counters;
	counters.reports_accepted = reports_accepted_.load(std::memory_order_relaxed);
	counters.bytes_accepted = bytes_accepted_.load(std::memory_order_relaxed);
	counters.reports_rejected = reports_rejected_.load(std::memory_order_relaxed);
	counters.sequence_errors = sequence_errors_.load(std::memory_order_relaxed);
	counters.input_reports = input_reports_.load(std::memory_order_relaxed);
	counters.feature_reads = feature_reads_.load(std::memory_order_relaxed);
	counters.max_motor = max_motor_.load(std::memory_order_relaxed);
	counters.max_trigger_strength = max_trigger_strength_.load(std::memory_order_relaxed);
	return counters;
}

void ScriptedDualSense::begin_session() {
	have_sequence_ = false;
	poll_burst_ = 0;
}

void ScriptedDualSense::inject_input(const uint8_t *p_report, size_t p_size) {
	if (injected_count_ >= std::size(injected_)) {
		return;
	}
	Injected &slot = injected_[(injected_next_ + injected_count_) % std::size(injected_)];
	slot.size = p_report != nullptr ? std::min(p_size, sizeof(slot.bytes)) : 0;
	if (slot.size > 0) {
		std::memcpy(slot.bytes, p_report, slot.size);
	}
	++injected_count_;
}

size_t ScriptedDualSense::history_size() const {
	return std::min(history_count_, HISTORY_CAPACITY);
}

const ScriptedDualSense::Recorded &ScriptedDualSense::history(size_t p_index) const {
	const size_t first = history_count_ > HISTORY_CAPACITY ? history_count_ - HISTORY_CAPACITY : 0;
	return history_[(first + std::min(p_index, history_size() - 1)) % HISTORY_CAPACITY];
}

void ScriptedDualSense::clear_history() {
	history_count_ = 0;
}

void ScriptedDualSense::record(const uint8_t *p_report, size_t p_size, bool p_accepted) {
	Recorded &slot = history_[history_count_ % HISTORY_CAPACITY];
	slot.size = std::min(p_size, sizeof(slot.bytes));
	std::memcpy(slot.bytes, p_report, slot.size);
	slot.accepted = p_accepted;
	++history_count_;
}

bool ScriptedDualSense::accept(const uint8_t *p_report, size_t p_size) {
	if (options_.bus == Bus::USB) {
		return p_report[0] == USB_OUTPUT_REPORT_ID && (p_size == USB_OUTPUT_SIZE || p_size == 1 + COMMON_SIZE);
	}
	return p_report[0] == BT_OUTPUT_REPORT_ID && p_size == BT_OUTPUT_SIZE && p_report[BT_TAG_OFFSET] == BT_OUTPUT_TAG &&
			bt_output_crc_ok(p_report, p_size);
}

void ScriptedDualSense::apply(const uint8_t *p_common, ScriptedPadHeld &r_held) const {
	const uint8_t flag0 = p_common[common::VALID_FLAG0];
	const uint8_t flag1 = p_common[common::VALID_FLAG1];
	const uint8_t flag2 = p_common[common::VALID_FLAG2];
	const bool legacy_rumble = (flag0 & FLAG0_COMPATIBLE_VIBRATION) != 0;
	const bool improved_rumble = (flag2 & FLAG2_COMPATIBLE_VIBRATION2) != 0;
	if (legacy_rumble || improved_rumble) {
		r_held.motor_right = p_common[common::MOTOR_RIGHT];
		r_held.motor_left = p_common[common::MOTOR_LEFT];
		r_held.improved_rumble = improved_rumble;
	}
	if (flag0 & FLAG0_RIGHT_TRIGGER) {
		std::memcpy(r_held.right_trigger.bytes, p_common + common::RIGHT_TRIGGER, TRIGGER_BLOCK_SIZE);
	}
	if (flag0 & FLAG0_LEFT_TRIGGER) {
		std::memcpy(r_held.left_trigger.bytes, p_common + common::LEFT_TRIGGER, TRIGGER_BLOCK_SIZE);
	}
	if (flag1 & FLAG1_LIGHTBAR) {
		r_held.lightbar = Rgb{ p_common[common::LIGHTBAR_RED], p_common[common::LIGHTBAR_GREEN],
			p_common[common::LIGHTBAR_BLUE] };
	}
	if (flag1 & FLAG1_PLAYER_LEDS) {
		r_held.player_leds = p_common[common::PLAYER_LEDS];
	}
	if ((flag2 & FLAG2_LIGHTBAR_SETUP) && p_common[common::LIGHTBAR_SETUP] == LIGHTBAR_SETUP_LIGHT_OUT) {
		r_held.lightbar_taken = true;
	}
}

TransportIo ScriptedDualSense::receive_output(const uint8_t *p_report, size_t p_size, const char *&r_error) {
	if (!plugged()) {
		r_error = WRITE_GONE;
		return TransportIo::DISCONNECTED;
	}
	if (p_report == nullptr || p_size == 0) {
		r_error = "hid_write: empty report";
		return TransportIo::FAILED;
	}
	const bool ok = accept(p_report, p_size);
	record(p_report, p_size, ok);
	if (options_.bus == Bus::BLUETOOTH && p_report[0] == BT_OUTPUT_REPORT_ID) {
		working_.full_reports = true; // SDL: any effects report switches the mode.
	}
	if (!ok) {
		reports_rejected_.fetch_add(1, std::memory_order_relaxed);
		held_.store(working_);
		return TransportIo::OK; // The write succeeds; the pad ignores the report.
	}
	if (options_.bus == Bus::BLUETOOTH) {
		const uint8_t sequence = static_cast<uint8_t>(p_report[BT_SEQUENCE_OFFSET] >> 4);
		if (have_sequence_ && sequence != ((last_sequence_ + 1) & 0x0F)) {
			sequence_errors_.fetch_add(1, std::memory_order_relaxed);
		}
		have_sequence_ = true;
		last_sequence_ = sequence;
	}
	apply(p_report + (options_.bus == Bus::BLUETOOTH ? BT_COMMON_OFFSET : USB_COMMON_OFFSET), working_);
	std::memcpy(working_.last_report, p_report, p_size);
	working_.last_report_size = p_size;
	held_.store(working_);
	// One writer at a time: load + store is enough for the maxima.
	const uint32_t motor = std::max(working_.motor_left, working_.motor_right);
	if (motor > max_motor_.load(std::memory_order_relaxed)) {
		max_motor_.store(motor, std::memory_order_relaxed);
	}
	const uint32_t strength = static_cast<uint32_t>(
			std::max(trigger_feedback_strength(working_.right_trigger), trigger_feedback_strength(working_.left_trigger)));
	if (strength > max_trigger_strength_.load(std::memory_order_relaxed)) {
		max_trigger_strength_.store(strength, std::memory_order_relaxed);
	}
	reports_accepted_.fetch_add(1, std::memory_order_relaxed);
	bytes_accepted_.fetch_add(p_size, std::memory_order_relaxed);
	return TransportIo::OK;
}

size_t ScriptedDualSense::build_input(uint8_t *r_buffer, size_t p_capacity) {
	const uint32_t stick = stick_.load(std::memory_order_relaxed);
	const uint32_t buttons = buttons_.load(std::memory_order_relaxed);
	const uint8_t battery = static_cast<uint8_t>(battery_.load(std::memory_order_relaxed));
	const uint8_t x = static_cast<uint8_t>(stick);
	const uint8_t y = static_cast<uint8_t>(stick >> 8);
	uint8_t raw[4];
	raw_buttons(buttons, raw);
	uint8_t report[MAX_INPUT_SIZE] = {};
	size_t size = 0;
	if (options_.bus == Bus::BLUETOOTH && !working_.full_reports) {
		// The simple report (SDL PS5SimpleStatePacket): sticks, 3 button bytes, triggers.
		const uint8_t simple[] = { BT_SIMPLE_INPUT_REPORT_ID, x, y, STICK_CENTRE, STICK_CENTRE, raw[0], raw[1], raw[2], 0, 0 };
		size = sizeof(simple);
		std::memcpy(report, simple, size);
	} else {
		const bool bt = options_.bus == Bus::BLUETOOTH;
		size = bt ? BT_INPUT_SIZE : USB_INPUT_SIZE;
		report[0] = bt ? BT_INPUT_REPORT_ID : USB_INPUT_REPORT_ID;
		uint8_t *block = report + (bt ? BT_INPUT_OFFSET : USB_INPUT_OFFSET);
		block[input::LEFT_STICK_X] = x;
		block[input::LEFT_STICK_Y] = y;
		block[2] = STICK_CENTRE; // Right stick.
		block[3] = STICK_CENTRE;
		block[input::L2_AXIS] = (buttons & (1u << BUTTON_L2)) ? 0xFF : 0;
		block[input::R2_AXIS] = (buttons & (1u << BUTTON_R2)) ? 0xFF : 0;
		block[input::SEQUENCE] = input_sequence_++;
		std::memcpy(block + input::BUTTONS, raw, sizeof(raw));
		block[input::STATUS] = battery;
		if (bt) {
			write_le32(report + BT_INPUT_SIZE - 4, crc32_seeded(CRC_SEED_INPUT, report, BT_INPUT_SIZE - 4));
		}
	}
	size = std::min(size, p_capacity); // hidapi truncates to the caller's buffer.
	std::memcpy(r_buffer, report, size);
	return size;
}

TransportIo ScriptedDualSense::produce_input(uint8_t *r_buffer, size_t p_capacity, size_t &r_size, const char *&r_error) {
	r_size = 0;
	if (!plugged()) {
		r_error = READ_GONE;
		return TransportIo::DISCONNECTED;
	}
	if (injected_count_ > 0) {
		const Injected &slot = injected_[injected_next_];
		injected_next_ = (injected_next_ + 1) % std::size(injected_);
		--injected_count_;
		r_size = std::min(slot.size, p_capacity);
		if (r_size > 0) {
			std::memcpy(r_buffer, slot.bytes, r_size);
		}
		return r_size > 0 ? TransportIo::OK : TransportIo::NO_DATA;
	}
	if (poll_burst_ >= options_.reports_per_poll) {
		poll_burst_ = 0;
		return TransportIo::NO_DATA;
	}
	++poll_burst_;
	r_size = build_input(r_buffer, p_capacity);
	input_reports_.fetch_add(1, std::memory_order_relaxed);
	return TransportIo::OK;
}

namespace {

class ScriptedTransport final : public DualSenseTransport {
public:
	explicit ScriptedTransport(std::shared_ptr<ScriptedDualSense> p_pad) :
			pad_(std::move(p_pad)) {
		std::snprintf(location_, sizeof(location_), "scripted %s DualSense%s", bus_name(pad_->options().bus),
				pad_->options().edge ? " Edge" : "");
	}

	Status open() override {
		if (!pad_->plugged()) {
			return Status::error(StatusCode::NO_DEVICE, "DualSense: no device at '%s' (No such file or directory)", location_);
		}
		pad_->begin_session();
		open_ = true;
		return Status::success();
	}
	void close() override { open_ = false; }
	bool is_open() const override { return open_; }
	Bus bus() const override { return pad_->options().transport_knows_bus ? pad_->options().bus : Bus::UNKNOWN; }

	TransportIo write_output(const uint8_t *p_report, size_t p_size) override {
		return open_ ? pad_->receive_output(p_report, p_size, error_) : not_open();
	}
	TransportIo read_input(uint8_t *r_buffer, size_t p_capacity, size_t &r_size, int p_timeout_ms) override {
		(void)p_timeout_ms; // The script always has a report ready (or none at all).
		r_size = 0;
		return open_ ? pad_->produce_input(r_buffer, p_capacity, r_size, error_) : not_open();
	}
	TransportIo get_feature(uint8_t p_report_id, uint8_t *r_buffer, size_t p_capacity, size_t &r_size) override {
		r_size = 0;
		return open_ ? pad_->produce_feature(p_report_id, r_buffer, p_capacity, r_size, error_) : not_open();
	}
	const char *error_text() const override { return error_; }
	const char *location() const override { return location_; }

private:
	TransportIo not_open() {
		error_ = "device not open";
		return TransportIo::FAILED;
	}

	std::shared_ptr<ScriptedDualSense> pad_;
	bool open_ = false;
	const char *error_ = "";
	char location_[64] = {};
};

} // namespace

std::unique_ptr<DualSenseTransport> make_scripted_transport(std::shared_ptr<ScriptedDualSense> p_pad) {
	return std::make_unique<ScriptedTransport>(std::move(p_pad));
}

} // namespace haptics::dualsense
