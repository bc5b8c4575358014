#include "dev_tools/uinput/uinput_ff_device.h"

#include "dev_tools/kernel_device_io.h"

#include <fcntl.h>
#include <linux/input.h>
#include <linux/uinput.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace haptics::uinput {

namespace {

constexpr const char *UINPUT_PATH = "/dev/uinput";

// /sys/devices/virtual/input/<p_sysname>/eventN -> /dev/input/eventN (devtmpfs names it so).
std::string event_path_of(const char *p_sysname) {
	std::error_code error;
	const std::filesystem::path dir = std::filesystem::path("/sys/devices/virtual/input") / p_sysname;
	for (const auto &entry : std::filesystem::directory_iterator(dir, error)) {
		const std::string name = entry.path().filename().string();
		if (name.rfind("event", 0) == 0) {
			return "/dev/input/" + name;
		}
	}
	return {};
}

} // namespace

UinputFfDevice::UinputFfDevice(evdev::ScriptedEvdevScript p_script) :
		script_(std::move(p_script)) {}

UinputFfDevice::~UinputFfDevice() {
	destroy();
}

Status UinputFfDevice::setup(const std::string &p_phys) {
	const auto set = [&](unsigned long p_request, int p_value) { return ::ioctl(fd_, p_request, p_value) == 0; };
	bool ok = set(UI_SET_EVBIT, EV_KEY) && set(UI_SET_EVBIT, EV_ABS) && set(UI_SET_EVBIT, EV_FF);
	for (const uint16_t code : script_.key_codes) {
		ok = ok && set(UI_SET_KEYBIT, code);
	}
	for (const evdev::ScriptedAbsAxis &axis : script_.axes) {
		uinput_abs_setup abs{};
		abs.code = axis.code;
		abs.absinfo = { axis.range.value, axis.range.minimum, axis.range.maximum, axis.range.fuzz, axis.range.flat,
			axis.range.resolution };
		ok = ok && set(UI_SET_ABSBIT, axis.code) && ::ioctl(fd_, UI_ABS_SETUP, &abs) == 0;
	}
	for (const uint16_t code : script_.ff_codes) {
		ok = ok && set(UI_SET_FFBIT, code);
	}
	if (!ok || ::ioctl(fd_, UI_SET_PHYS, p_phys.c_str()) != 0) {
		return errno_status("uinput: setting the device's bits");
	}
	uinput_setup setup{};
	setup.id = { script_.bustype, script_.vendor, script_.product, script_.version };
	std::snprintf(setup.name, sizeof(setup.name), "%s", script_.name.c_str());
	setup.ff_effects_max = static_cast<uint32_t>(std::max<int32_t>(script_.max_effects, 1));
	if (::ioctl(fd_, UI_DEV_SETUP, &setup) != 0 || ::ioctl(fd_, UI_DEV_CREATE) != 0) {
		return errno_status("uinput: creating the device");
	}
	char sysname[64] = {};
	if (::ioctl(fd_, UI_GET_SYSNAME(sizeof(sysname) - 1), sysname) < 0) {
		return errno_status("uinput: UI_GET_SYSNAME");
	}
	event_path_ = event_path_of(sysname);
	if (event_path_.empty()) {
		return Status::error(StatusCode::DEVICE_ERROR, "uinput: %s has no event node", sysname);
	}
	return Status::success();
}

Status UinputFfDevice::create(const std::string &p_phys) {
	if (fd_ >= 0) {
		return Status::error(StatusCode::INVALID_STATE, "uinput device already created");
	}
	fd_ = ::open(UINPUT_PATH, O_RDWR | O_NONBLOCK | O_CLOEXEC);
	if (fd_ < 0) {
		return errno_status("open /dev/uinput");
	}
	if (::pipe2(wake_, O_CLOEXEC) != 0) {
		const Status status = errno_status("pipe");
		::close(fd_);
		fd_ = -1;
		return status;
	}
	{
		const std::lock_guard lock(mutex_);
		slots_.assign(static_cast<size_t>(std::max<int32_t>(script_.max_effects, 1)), Slot{});
		gain_ = 0xffff;
	}
	// The thread first: UI_DEV_CREATE may already see a client's upload waiting on us.
	thread_ = std::thread(&UinputFfDevice::run, this);
	const Status made = setup(p_phys);
	if (!made) {
		destroy();
	}
	return made;
}

void UinputFfDevice::destroy() {
	if (fd_ < 0) {
		return;
	}
	// Destroyed while the thread still answers: ff-core erases the open clients' effects
	// through us on the way out.
	(void)::ioctl(fd_, UI_DEV_DESTROY);
	const char wake = 1;
	[[maybe_unused]] const ssize_t woke = ::write(wake_[1], &wake, 1);
	if (thread_.joinable()) {
		thread_.join();
	}
	::close(fd_);
	::close(wake_[0]);
	::close(wake_[1]);
	fd_ = -1;
	wake_[0] = wake_[1] = -1;
	event_path_.clear();
	const std::lock_guard lock(mutex_);
	slots_.clear();
}

Status UinputFfDevice::write_event(uint16_t p_type, uint16_t p_code, int32_t p_value) {
	input_event event{};
	event.type = p_type;
	event.code = p_code;
	event.value = p_value;
	if (::write(fd_, &event, sizeof(event)) != static_cast<ssize_t>(sizeof(event))) {
		return errno_status("write /dev/uinput");
	}
	return Status::success();
}

Status UinputFfDevice::set_stick_axes(double p_x, double p_y) {
	if (fd_ < 0) {
		return Status::error(StatusCode::INVALID_STATE, "uinput device not created");
	}
	for (const evdev::ScriptedAbsAxis &axis : script_.axes) {
		if (axis.code != ABS_X && axis.code != ABS_Y) {
			continue;
		}
		const double centre = 0.5 * (static_cast<double>(axis.range.minimum) + axis.range.maximum);
		const double half = 0.5 * (static_cast<double>(axis.range.maximum) - axis.range.minimum);
		const double fraction = std::clamp(axis.code == ABS_X ? p_x : p_y, -1.0, 1.0);
		const Status written = write_event(EV_ABS, axis.code, static_cast<int32_t>(std::lround(centre + fraction * half)));
		if (!written) {
			return written;
		}
	}
	return write_event(EV_SYN, SYN_REPORT, 0);
}

void UinputFfDevice::run() {
	input_event events[16];
	while (true) {
		const KernelDeviceWait waited = wait_kernel_device(fd_, wake_[0]);
		if (waited == KernelDeviceWait::STOP) {
			return;
		}
		if (waited == KernelDeviceWait::IDLE) {
			continue;
		}
		const ssize_t got = ::read(fd_, events, sizeof(events));
		for (ssize_t i = 0; got > 0 && i < got / static_cast<ssize_t>(sizeof(input_event)); ++i) {
			const input_event &event = events[i];
			if (event.type == EV_UINPUT && event.code == UI_FF_UPLOAD) {
				answer_upload(event.value);
			} else if (event.type == EV_UINPUT && event.code == UI_FF_ERASE) {
				answer_erase(event.value);
			} else if (event.type == EV_FF) {
				take_event(event.code, event.value);
			}
		}
	}
}

void UinputFfDevice::answer_upload(int32_t p_request) {
	uinput_ff_upload upload{};
	upload.request_id = static_cast<uint32_t>(p_request);
	if (::ioctl(fd_, UI_BEGIN_FF_UPLOAD, &upload) != 0) {
		return;
	}
	UinputRecord entry;
	entry.kind = UinputRecord::Kind::UPLOAD;
	static_assert(sizeof(upload.effect) == evdev::FF_EFFECT_SIZE);
	std::memcpy(entry.bytes.data(), &upload.effect, sizeof(upload.effect));
	entry.effect = evdev::decode_ff_effect(entry.bytes);
	entry.id = entry.effect.id;
	entry.replaced = upload.old.type != 0; // uinput zeroes `old` for a new effect.
	upload.retval = 0;
	{
		const std::lock_guard lock(mutex_);
		if (entry.id >= 0 && static_cast<size_t>(entry.id) < slots_.size()) {
			Slot &slot = slots_[static_cast<size_t>(entry.id)];
			slot.in_use = true;
			slot.effect = entry.effect;
		} else {
			upload.retval = -EINVAL;
		}
	}
	uploads_.fetch_add(1, std::memory_order_relaxed);
	record(entry);
	(void)::ioctl(fd_, UI_END_FF_UPLOAD, &upload);
}

void UinputFfDevice::answer_erase(int32_t p_request) {
	uinput_ff_erase erase{};
	erase.request_id = static_cast<uint32_t>(p_request);
	if (::ioctl(fd_, UI_BEGIN_FF_ERASE, &erase) != 0) {
		return;
	}
	UinputRecord entry;
	entry.kind = UinputRecord::Kind::ERASE;
	entry.id = static_cast<int16_t>(erase.effect_id);
	erase.retval = 0;
	{
		const std::lock_guard lock(mutex_);
		if (erase.effect_id < slots_.size()) {
			slots_[erase.effect_id] = Slot{};
		}
	}
	record(entry);
	(void)::ioctl(fd_, UI_END_FF_ERASE, &erase);
}

void UinputFfDevice::take_event(uint16_t p_code, int32_t p_value) {
	UinputRecord entry;
	entry.value = p_value;
	const std::lock_guard lock(mutex_);
	if (p_code == FF_GAIN) {
		entry.kind = UinputRecord::Kind::GAIN;
		gain_ = static_cast<uint16_t>(std::clamp(p_value, 0, 0xffff));
	} else if (p_code == FF_AUTOCENTER) {
		entry.kind = UinputRecord::Kind::AUTOCENTER;
	} else {
		entry.kind = UinputRecord::Kind::PLAY;
		entry.id = static_cast<int16_t>(p_code);
		if (p_code < slots_.size() && slots_[p_code].in_use) {
			slots_[p_code].playing = p_value > 0;
		}
	}
	records_.push_back(entry);
}

void UinputFfDevice::record(UinputRecord p_record) {
	const std::lock_guard lock(mutex_);
	records_.push_back(std::move(p_record));
}

std::vector<UinputRecord> UinputFfDevice::records() const {
	const std::lock_guard lock(mutex_);
	return records_;
}

void UinputFfDevice::clear_records() {
	const std::lock_guard lock(mutex_);
	records_.clear();
}

bool UinputFfDevice::last_upload(uint16_t p_type, UinputRecord &r_record) const {
	const std::lock_guard lock(mutex_);
	for (auto it = records_.rbegin(); it != records_.rend(); ++it) {
		if (it->kind == UinputRecord::Kind::UPLOAD && it->effect.type == p_type) {
			r_record = *it;
			return true;
		}
	}
	return false;
}

evdev::ScriptedRenderedForce UinputFfDevice::rendered() const {
	const std::lock_guard lock(mutex_);
	std::vector<evdev::FfEffectFields> playing;
	for (const Slot &slot : slots_) {
		if (slot.in_use && slot.playing) {
			playing.push_back(slot.effect);
		}
	}
	return evdev::render_playing_effects(playing, gain_);
}

int32_t UinputFfDevice::effects_in_use() const {
	const std::lock_guard lock(mutex_);
	return static_cast<int32_t>(std::count_if(slots_.begin(), slots_.end(), [](const Slot &p_slot) { return p_slot.in_use; }));
}

} // namespace haptics::uinput
