#include "system/haptics_system.h"

#include "core/wire/codec.h"
#include "system/settings_validation.h"

#include <cstring>
#include <utility>

namespace haptics {

namespace {

constexpr char UNPLUGGED_MESSAGE[] = "device '%s' disconnected%s%s%s: rendering stopped (zero force); reopen it to resume";
constexpr char FAILED_MESSAGE[] = "device '%s' I/O failed%s%s%s: rendering stopped; reopen it to resume";

Status device_io_status(DeviceIo p_io, const char *p_name, const DeviceStatus &p_device) {
	const char *reason = p_device.reason[0] != '\0' ? p_device.reason : "";
	const char *separator = reason[0] != '\0' ? " (" : "";
	const char *close = reason[0] != '\0' ? ")" : "";
	switch (p_io) {
		case DeviceIo::OK:
			return Status::success();
		case DeviceIo::DISCONNECTED:
			return Status::error(StatusCode::DEVICE_DISCONNECTED, UNPLUGGED_MESSAGE, p_name, separator, reason, close);
		case DeviceIo::FAILED:
			break;
	}
	return Status::error(StatusCode::DEVICE_ERROR, FAILED_MESSAGE, p_name, separator, reason, close);
}

} // namespace

struct HapticsSystem::Impl {
	// Declaration order is destruction order reversed: the loop (and its thread) goes
	// first, before the pipeline, channels and device it uses.
	ServoChannels channels;
	RendererSet renderers;
	ServoPipeline pipeline{ channels, renderers.all };
	std::unique_ptr<HapticDevice> device;
	ServoLoop loop{ pipeline, channels };

	RenderConfig config;
	bool manual_session = false;
	DeviceIo manual_fault = DeviceIo::OK;
	uint64_t frames_rejected = 0;

	void end_session() {
		loop.stop();
		if (manual_session && device) {
			device->write_zero();
		}
		manual_session = false;
		// Stale impacts must not fire in a burst when rendering resumes.
		channels.impacts.clear();
		collect();
	}

	// Frees what the servo has finished with in every renderer's channels.
	void collect() {
		for (RendererChannels *renderer : renderers.all_channels) {
			renderer->collect();
		}
	}

	void publish_config() {
		renderers.publish_settings(config);
		// Last, and always: the servo looks at the renderers' settings when this changes, and
		// one that sees the new mode also sees its renderer's new settings.
		channels.config.store(config.servo);
	}
};

HapticsSystem::HapticsSystem() :
		impl_(std::make_unique<Impl>()) {
	impl_->publish_config();
}

HapticsSystem::~HapticsSystem() {
	close_device();
}

Status HapticsSystem::open_device(std::unique_ptr<HapticDevice> p_device) {
	if (!p_device) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "device: null");
	}
	// The new device is opened before the current one is touched, so a failure changes
	// nothing; only then does the servo stop (zero force, join) and the old device close.
	const Status opened = p_device->open();
	if (!opened) {
		return opened;
	}
	const DeviceLimits limits = p_device->limits();
	if (!(limits.max_force_n > 0.0) || !(limits.workspace_radius_m > 0.0)) {
		p_device->close();
		return Status::error(StatusCode::DEVICE_ERROR, "device '%s' reports invalid limits (max force %g N, radius %g m)",
				p_device->name(), limits.max_force_n, limits.workspace_radius_m);
	}
	p_device->write_zero();
	impl_->end_session();
	impl_->loop.clear_fault();
	if (impl_->device) {
		impl_->device->close();
	}
	impl_->device = std::move(p_device);
	impl_->manual_fault = DeviceIo::OK;
	return Status::success();
}

Status HapticsSystem::open_simulated_device(const SimulatedDeviceConfig &p_config) {
	const Status valid = validate_simulated_device_config(p_config);
	if (!valid) {
		return valid;
	}
	return open_device(std::make_unique<SimulatedDevice>(p_config));
}

void HapticsSystem::close_device() {
	impl_->end_session();
	if (impl_->device) {
		impl_->device->close();
		impl_->device.reset();
	}
}

bool HapticsSystem::has_device() const {
	return impl_->device != nullptr;
}

const char *HapticsSystem::device_name() const {
	return impl_->device ? impl_->device->name() : "";
}

DeviceLimits HapticsSystem::device_limits() const {
	return impl_->device ? impl_->device->limits() : DeviceLimits{};
}

HapticDevice *HapticsSystem::current_device() {
	return impl_->device.get();
}

Status HapticsSystem::calibrate() {
	if (!impl_->device) {
		return Status::error(StatusCode::NO_DEVICE, "calibrate: no device open");
	}
	if (is_running()) {
		return Status::error(StatusCode::INVALID_STATE, "calibrate: stop rendering first");
	}
	return impl_->device->calibrate();
}

Status HapticsSystem::start(double p_rate_hz) {
	ServoOptions options;
	options.rate_hz = p_rate_hz;
	return start(options);
}

Status HapticsSystem::start(const ServoOptions &p_options) {
	const Status rate = validate_rate(p_options.rate_hz);
	if (!rate) {
		return rate;
	}
	if (!impl_->device) {
		return Status::error(StatusCode::NO_DEVICE, "start: no device open");
	}
	if (is_running()) {
		return Status::error(StatusCode::INVALID_STATE, "start: already running at %g Hz; stop first",
				impl_->loop.options().rate_hz);
	}
	impl_->end_session();
	impl_->manual_fault = DeviceIo::OK;
	return impl_->loop.start(impl_->device.get(), p_options);
}

void HapticsSystem::stop() {
	impl_->end_session();
}

bool HapticsSystem::is_running() const {
	return impl_->loop.state() == ServoState::RUNNING;
}

Status HapticsSystem::step(double p_dt_s) {
	const Status dt = validate_step_dt(p_dt_s);
	if (!dt) {
		return dt;
	}
	if (!impl_->device) {
		return Status::error(StatusCode::NO_DEVICE, "step: no device open");
	}
	if (is_running()) {
		return Status::error(StatusCode::INVALID_STATE, "step: the servo thread is running; stop it first");
	}
	if (!impl_->manual_session) {
		impl_->loop.clear_fault(); // Joins a thread that ended on a fault.
		impl_->pipeline.begin_session(impl_->device.get(), p_dt_s);
		impl_->channels.stats.reset(1.0 / p_dt_s);
		impl_->manual_session = true;
		impl_->manual_fault = DeviceIo::OK;
	}
	const int64_t begin_ns = monotonic_now_ns();
	const DeviceIo io = impl_->pipeline.tick(p_dt_s);
	const int64_t end_ns = monotonic_now_ns();
	impl_->channels.stats.record_tick(impl_->pipeline.time_s(), impl_->pipeline.ticks() > 1 ? p_dt_s : -1.0, 0.0,
			static_cast<double>(end_ns - begin_ns) * 1e-9);
	if (io != DeviceIo::OK) {
		impl_->device->write_zero();
		impl_->manual_session = false;
		impl_->manual_fault = io;
		return device_io_status(io, impl_->device->name(), impl_->device->status());
	}
	impl_->collect(); // This thread is the servo here: free what it retired.
	return Status::success();
}

Status HapticsSystem::servo_status() const {
	const char *name = device_name();
	const DeviceStatus device = device_status();
	if (impl_->loop.state() == ServoState::FAULTED) {
		return device_io_status(impl_->loop.fault(), name, device);
	}
	return device_io_status(impl_->manual_fault, name, device);
}

DeviceStatus HapticsSystem::device_status() const {
	return impl_->device ? impl_->device->status() : DeviceStatus{};
}

DeviceCapabilities HapticsSystem::device_capabilities() const {
	return impl_->device ? impl_->device->capabilities() : DeviceCapabilities{};
}

Status HapticsSystem::submit_frame(const Frame &p_frame, GameSpace p_space) {
	const Status valid = check_fields(p_frame);
	if (!valid) {
		++impl_->frames_rejected;
		return valid;
	}
	impl_->channels.frame.store(GameFrame{ p_frame, p_space });
	// At 50 Hz: frees what the servo has replaced (walls), so the next swap is never held up.
	impl_->collect();
	return Status::success();
}

void HapticsSystem::count_rejected_frame() {
	++impl_->frames_rejected;
}

Status HapticsSystem::push_impact(const ImpactEvent &p_event) {
	const Status valid = check_fields(p_event);
	if (!valid) {
		return valid;
	}
	if (!impl_->channels.impacts.try_push(p_event)) {
		impl_->channels.queue_drops.fetch_add(1, std::memory_order_relaxed);
	}
	return Status::success();
}

Status HapticsSystem::set_hand_target(const Vec3 &p_target_m) {
	if (!impl_->device) {
		return Status::error(StatusCode::NO_DEVICE, "set_hand_target: no device open");
	}
	return impl_->device->set_hand_target(p_target_m);
}

Vec3 HapticsSystem::input_vector() const {
	return impl_->channels.output.load().input;
}

Vec3 HapticsSystem::device_position() const {
	return impl_->channels.output.load().position_m;
}

ForceComponents HapticsSystem::forces() const {
	return impl_->channels.output.load().forces;
}

ServoOutput HapticsSystem::output() const {
	return impl_->channels.output.load();
}

size_t HapticsSystem::latency_bins(uint32_t *r_bins, size_t p_capacity) const {
	return impl_->channels.stats.latency_bins(r_bins, p_capacity);
}

ServoStats HapticsSystem::stats() const {
	ServoStats stats;
	impl_->channels.stats.fill(stats);
	const ServoOutput output = impl_->channels.output.load();
	const RealtimeGrants grants = impl_->loop.grants();
	const bool threaded = impl_->loop.state() != ServoState::STOPPED || !impl_->manual_session;
	stats.running = is_running();
	stats.scheduler = threaded ? grants.kind : SchedulerKind::MANUAL;
	stats.realtime = is_realtime_kind(stats.scheduler);
	stats.realtime_priority = threaded ? grants.priority : 0;
	if (threaded) {
		stats.memory_locked = grants.memory_locked;
		stats.cpu_latency_held = grants.cpu_latency_held;
		stats.pinned_cpu = grants.cpu;
		stats.stack_prefaulted_kb = grants.stack_prefaulted_kb;
		stats.timer_slack_minimised = grants.timer_slack_minimised;
		stats.realtime_kit = grants.realtime_kit;
		stats.spin_s = static_cast<double>(impl_->loop.spin_ns()) * 1e-9;
		stats.spin_learned = impl_->loop.spin_learned();
	}
	stats.frames_received = output.frames_received;
	stats.frames_rejected = impl_->frames_rejected;
	stats.frame_age_s = output.frame_age_s;
	stats.watchdog_tripped = (output.flags & TELEMETRY_FLAG_WATCHDOG) != 0;
	stats.transient_drops = output.bank_drops + impl_->channels.queue_drops.load(std::memory_order_relaxed);
	stats.telemetry_drops = output.telemetry_drops;
	stats.clamped_ticks = output.clamped_ticks;
	stats.non_finite_ticks = output.non_finite_ticks;
	if (impl_->device) {
		const DeviceIoStats io = impl_->device->io_stats();
		stats.device_io_cycles = io.cycles;
		stats.device_command_age_mean_s = io.command_age_mean_s;
		stats.device_command_age_max_s = io.command_age_max_s;
	}
	return stats;
}

size_t HapticsSystem::drain_telemetry(float *r_out, size_t p_max_samples) {
	if (!r_out) {
		return 0;
	}
	size_t count = 0;
	TelemetrySample sample;
	while (count < p_max_samples && impl_->channels.telemetry.try_pop(sample)) {
		std::memcpy(r_out + count * TELEMETRY_STRIDE, sample.values, sizeof(sample.values));
		++count;
	}
	return count;
}

Status HapticsSystem::configure(const RenderConfig &p_config) {
	const Status valid = validate_render_config(p_config);
	if (valid) {
		impl_->config = p_config;
		impl_->publish_config();
	}
	return valid;
}

const RenderConfig &HapticsSystem::config() const {
	return impl_->config;
}

RendererSet &HapticsSystem::renderers() {
	return impl_->renderers;
}

} // namespace haptics
