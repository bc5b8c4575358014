#include "dev_tools/uhid/uhid_device.h"

#include "dev_tools/kernel_device_io.h"

#include <fcntl.h>
#include <linux/uhid.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace haptics::uhid {

namespace {

constexpr const char *UHID_PATH = "/dev/uhid";

void copy_text(char *r_to, size_t p_capacity, const std::string &p_text) {
	const size_t n = std::min(p_text.size(), p_capacity - 1);
	std::memcpy(r_to, p_text.data(), n);
	r_to[n] = '\0';
}

} // namespace

UhidDevice::UhidDevice(UhidHandler &p_handler) :
		handler_(p_handler) {}

UhidDevice::~UhidDevice() {
	destroy();
}

Status UhidDevice::create(const UhidIdentity &p_identity, std::span<const uint8_t> p_descriptor) {
	if (fd_ >= 0) {
		return Status::error(StatusCode::INVALID_STATE, "uhid device already created");
	}
	if (p_descriptor.empty() || p_descriptor.size() > HID_MAX_DESCRIPTOR_SIZE) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "report descriptor of %zu bytes (1 to %d)",
				p_descriptor.size(), HID_MAX_DESCRIPTOR_SIZE);
	}
	const int fd = ::open(UHID_PATH, O_RDWR | O_CLOEXEC);
	if (fd < 0) {
		return errno_status("open /dev/uhid");
	}
	if (::pipe2(wake_, O_CLOEXEC) != 0) {
		const Status status = errno_status("pipe");
		::close(fd);
		return status;
	}
	fd_ = fd;
	uhid_event event{};
	event.type = UHID_CREATE2;
	copy_text(reinterpret_cast<char *>(event.u.create2.name), sizeof(event.u.create2.name), p_identity.name);
	copy_text(reinterpret_cast<char *>(event.u.create2.phys), sizeof(event.u.create2.phys), p_identity.phys);
	copy_text(reinterpret_cast<char *>(event.u.create2.uniq), sizeof(event.u.create2.uniq), p_identity.uniq);
	event.u.create2.rd_size = static_cast<uint16_t>(p_descriptor.size());
	event.u.create2.bus = p_identity.bus;
	event.u.create2.vendor = p_identity.vendor;
	event.u.create2.product = p_identity.product;
	event.u.create2.version = p_identity.version;
	std::memcpy(event.u.create2.rd_data, p_descriptor.data(), p_descriptor.size());
	const Status created = write_event(&event, sizeof(event));
	if (!created) {
		destroy();
		return created;
	}
	thread_ = std::thread(&UhidDevice::run, this);
	return Status::success();
}

void UhidDevice::destroy() {
	if (fd_ < 0) {
		return;
	}
	const char wake = 1;
	[[maybe_unused]] const ssize_t woke = ::write(wake_[1], &wake, 1);
	if (thread_.joinable()) {
		thread_.join();
	}
	uhid_event event{};
	event.type = UHID_DESTROY;
	(void)write_event(&event, sizeof(event));
	::close(fd_); // Closing the node destroys the device too.
	::close(wake_[0]);
	::close(wake_[1]);
	fd_ = -1;
	wake_[0] = wake_[1] = -1;
	started_ = false;
	opened_ = false;
}

Status UhidDevice::send_input(std::span<const uint8_t> p_report) {
	if (fd_ < 0) {
		return Status::error(StatusCode::INVALID_STATE, "uhid device not created");
	}
	if (p_report.size() > UHID_DATA_MAX) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "input report of %zu bytes (at most %d)",
				p_report.size(), UHID_DATA_MAX);
	}
	uhid_event event{};
	event.type = UHID_INPUT2;
	event.u.input2.size = static_cast<uint16_t>(p_report.size());
	std::memcpy(event.u.input2.data, p_report.data(), p_report.size());
	++inputs_;
	return write_event(&event, sizeof(event));
}

UhidCounts UhidDevice::counts() const {
	UhidCounts counts;
	counts.outputs = outputs_;
	counts.get_reports = get_reports_;
	counts.set_reports = set_reports_;
	counts.inputs = inputs_;
	counts.started = started_;
	counts.opened = opened_;
	return counts;
}

void UhidDevice::run() {
	uhid_event event{};
	while (true) {
		const KernelDeviceWait waited = wait_kernel_device(fd_, wake_[0]);
		if (waited == KernelDeviceWait::STOP) {
			return;
		}
		if (waited == KernelDeviceWait::IDLE) {
			continue;
		}
		const ssize_t got = ::read(fd_, &event, sizeof(event));
		if (got <= 0) {
			continue;
		}
		switch (event.type) {
			case UHID_START:
				started_ = true;
				break;
			case UHID_STOP:
				started_ = false;
				break;
			case UHID_OPEN:
				opened_ = true;
				break;
			case UHID_CLOSE:
				opened_ = false;
				break;
			case UHID_OUTPUT: {
				++outputs_;
				const size_t size = std::min<size_t>(event.u.output.size, UHID_DATA_MAX);
				handler_.on_output(std::span<const uint8_t>(event.u.output.data, size));
			} break;
			case UHID_GET_REPORT:
				++get_reports_;
				answer_get_report(event.u.get_report.id, event.u.get_report.rnum,
						event.u.get_report.rtype == UHID_FEATURE_REPORT);
				break;
			case UHID_SET_REPORT: {
				++set_reports_;
				const size_t size = std::min<size_t>(event.u.set_report.size, UHID_DATA_MAX);
				answer_set_report(event.u.set_report.id, std::span<const uint8_t>(event.u.set_report.data, size),
						event.u.set_report.rtype == UHID_FEATURE_REPORT);
			} break;
			default:
				break;
		}
	}
}

void UhidDevice::answer_get_report(uint32_t p_id, uint8_t p_report, bool p_feature) {
	std::vector<uint8_t> reply;
	const bool ok = handler_.on_get_report(p_report, p_feature, reply) && reply.size() <= UHID_DATA_MAX;
	uhid_event event{};
	event.type = UHID_GET_REPORT_REPLY;
	event.u.get_report_reply.id = p_id;
	event.u.get_report_reply.err = ok ? 0 : EIO;
	event.u.get_report_reply.size = ok ? static_cast<uint16_t>(reply.size()) : 0;
	if (ok) {
		std::memcpy(event.u.get_report_reply.data, reply.data(), reply.size());
	}
	(void)write_event(&event, sizeof(event));
}

void UhidDevice::answer_set_report(uint32_t p_id, std::span<const uint8_t> p_report, bool p_feature) {
	const bool ok = handler_.on_set_report(p_report, p_feature);
	uhid_event event{};
	event.type = UHID_SET_REPORT_REPLY;
	event.u.set_report_reply.id = p_id;
	event.u.set_report_reply.err = ok ? 0 : EIO;
	(void)write_event(&event, sizeof(event));
}

Status UhidDevice::write_event(const void *p_event, size_t p_size) {
	const ssize_t written = ::write(fd_, p_event, p_size);
	if (written != static_cast<ssize_t>(p_size)) {
		return errno_status("write /dev/uhid");
	}
	return Status::success();
}

} // namespace haptics::uhid
