#include "core/base/realtime_kit.h"

#include <dbus/dbus.h>
#include <dlfcn.h>
#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace haptics {

namespace {

constexpr const char *LIBDBUS = "libdbus-1.so.3";
constexpr const char *SERVICE = "org.freedesktop.RealtimeKit1";
constexpr const char *OBJECT = "/org/freedesktop/RealtimeKit1";
// The daemon asks polkit before it answers; a bus that does not answer within this is as
// good as none.
constexpr int CALL_TIMEOUT_MS = 2000;

// The part of libdbus this client uses, resolved at run time.
struct Dbus {
	bool loaded = false;
	dbus_bool_t (*threads_init_default)();
	void (*error_init)(DBusError *);
	void (*error_free)(DBusError *);
	DBusConnection *(*bus_get_private)(DBusBusType, DBusError *);
	void (*set_exit_on_disconnect)(DBusConnection *, dbus_bool_t);
	void (*connection_close)(DBusConnection *);
	void (*connection_unref)(DBusConnection *);
	DBusMessage *(*new_method_call)(const char *, const char *, const char *, const char *);
	dbus_bool_t (*append_args)(DBusMessage *, int, ...);
	DBusMessage *(*send_and_block)(DBusConnection *, DBusMessage *, int, DBusError *);
	void (*message_unref)(DBusMessage *);
	dbus_bool_t (*iter_init)(DBusMessage *, DBusMessageIter *);
	int (*iter_arg_type)(DBusMessageIter *);
	void (*iter_recurse)(DBusMessageIter *, DBusMessageIter *);
	void (*iter_get_basic)(DBusMessageIter *, void *);
};

template <typename Function>
bool resolve(void *p_library, const char *p_name, Function &r_function) {
	r_function = reinterpret_cast<Function>(::dlsym(p_library, p_name));
	return r_function != nullptr;
}

Dbus load_dbus() {
	Dbus dbus{};
	// Never closed: libdbus keeps process-wide state, and the game may use it too.
	void *library = ::dlopen(LIBDBUS, RTLD_NOW | RTLD_LOCAL);
	if (library == nullptr) {
		return dbus;
	}
	dbus.loaded = resolve(library, "dbus_threads_init_default", dbus.threads_init_default) &&
			resolve(library, "dbus_error_init", dbus.error_init) && resolve(library, "dbus_error_free", dbus.error_free) &&
			resolve(library, "dbus_bus_get_private", dbus.bus_get_private) &&
			resolve(library, "dbus_connection_set_exit_on_disconnect", dbus.set_exit_on_disconnect) &&
			resolve(library, "dbus_connection_close", dbus.connection_close) &&
			resolve(library, "dbus_connection_unref", dbus.connection_unref) &&
			resolve(library, "dbus_message_new_method_call", dbus.new_method_call) &&
			resolve(library, "dbus_message_append_args", dbus.append_args) &&
			resolve(library, "dbus_connection_send_with_reply_and_block", dbus.send_and_block) &&
			resolve(library, "dbus_message_unref", dbus.message_unref) &&
			resolve(library, "dbus_message_iter_init", dbus.iter_init) &&
			resolve(library, "dbus_message_iter_get_arg_type", dbus.iter_arg_type) &&
			resolve(library, "dbus_message_iter_recurse", dbus.iter_recurse) &&
			resolve(library, "dbus_message_iter_get_basic", dbus.iter_get_basic);
	if (dbus.loaded) {
		dbus.threads_init_default();
	}
	return dbus;
}

const Dbus &dbus_api() {
	static const Dbus dbus = load_dbus();
	return dbus;
}

void say(RtkitGrant &r_grant, const char *p_format, ...) {
	va_list args;
	va_start(args, p_format);
	std::vsnprintf(r_grant.reason.data, sizeof(r_grant.reason.data), p_format, args);
	va_end(args);
}

// One private connection to the system bus for the requests of one thread.
class RtkitSession {
public:
	explicit RtkitSession(const Dbus &p_dbus) :
			dbus_(p_dbus) {
		dbus_.error_init(&error_);
		connection_ = dbus_.bus_get_private(DBUS_BUS_SYSTEM, &error_);
		if (connection_ != nullptr) {
			// A bus that goes away must not take the game with it.
			dbus_.set_exit_on_disconnect(connection_, FALSE);
		}
	}
	~RtkitSession() {
		if (connection_ != nullptr) {
			dbus_.connection_close(connection_);
			dbus_.connection_unref(connection_);
		}
		dbus_.error_free(&error_);
	}
	RtkitSession(const RtkitSession &) = delete;
	RtkitSession &operator=(const RtkitSession &) = delete;

	bool connected() const { return connection_ != nullptr; }
	// The last error's text ("" when none).
	const char *error() const { return error_.message != nullptr ? error_.message : ""; }
	const char *error_name() const { return error_.name != nullptr ? error_.name : ""; }

	// A property of the daemon's as an integer; false when it cannot be read.
	bool property(const char *p_name, int64_t &r_value) {
		DBusMessage *call = dbus_.new_method_call(SERVICE, OBJECT, "org.freedesktop.DBus.Properties", "Get");
		if (call == nullptr) {
			return false;
		}
		const char *interface = SERVICE;
		dbus_.append_args(call, DBUS_TYPE_STRING, &interface, DBUS_TYPE_STRING, &p_name, DBUS_TYPE_INVALID);
		DBusMessage *reply = send(call);
		if (reply == nullptr) {
			return false;
		}
		DBusMessageIter iter;
		DBusMessageIter variant;
		bool read = false;
		if (dbus_.iter_init(reply, &iter) && dbus_.iter_arg_type(&iter) == DBUS_TYPE_VARIANT) {
			dbus_.iter_recurse(&iter, &variant);
			const int type = dbus_.iter_arg_type(&variant);
			if (type == DBUS_TYPE_INT32) {
				dbus_int32_t value = 0;
				dbus_.iter_get_basic(&variant, &value);
				r_value = value;
				read = true;
			} else if (type == DBUS_TYPE_INT64) {
				dbus_int64_t value = 0;
				dbus_.iter_get_basic(&variant, &value);
				r_value = value;
				read = true;
			}
		}
		dbus_.message_unref(reply);
		return read;
	}

	// MakeThreadRealtime(u64 thread, u32 priority) or MakeThreadHighPriority(u64, i32 nice).
	bool make_realtime(uint64_t p_thread, uint32_t p_priority) {
		return call_thread("MakeThreadRealtime", p_thread, DBUS_TYPE_UINT32, &p_priority);
	}
	bool make_high_priority(uint64_t p_thread, int32_t p_nice) {
		return call_thread("MakeThreadHighPriority", p_thread, DBUS_TYPE_INT32, &p_nice);
	}

private:
	DBusMessage *send(DBusMessage *p_call) {
		dbus_.error_free(&error_);
		dbus_.error_init(&error_);
		DBusMessage *reply = dbus_.send_and_block(connection_, p_call, CALL_TIMEOUT_MS, &error_);
		dbus_.message_unref(p_call);
		return reply;
	}

	bool call_thread(const char *p_method, uint64_t p_thread, int p_type, const void *p_value) {
		DBusMessage *call = dbus_.new_method_call(SERVICE, OBJECT, SERVICE, p_method);
		if (call == nullptr) {
			return false;
		}
		dbus_uint64_t thread = p_thread;
		dbus_.append_args(call, DBUS_TYPE_UINT64, &thread, p_type, p_value, DBUS_TYPE_INVALID);
		DBusMessage *reply = send(call);
		if (reply == nullptr) {
			return false;
		}
		dbus_.message_unref(reply);
		return true;
	}

	const Dbus &dbus_;
	DBusError error_{};
	DBusConnection *connection_ = nullptr;
};

// What RealtimeKit requires before it grants real time: SCHED_RESET_ON_FORK on the thread
// (so a child the game forks does not inherit real time) and a finite RLIMIT_RTTIME no larger
// than its maximum (so a runaway thread gets SIGXCPU, then SIGKILL). The servo sleeps every
// tick, which resets the kernel's count: it never comes near the limit.
bool prepare_for_rtkit(int64_t p_rttime_usec_max, int64_t &r_rttime_usec) {
	sched_param param{};
	if (::sched_setscheduler(0, SCHED_OTHER | SCHED_RESET_ON_FORK, &param) != 0) {
		return false;
	}
	rlimit limit{};
	if (::getrlimit(RLIMIT_RTTIME, &limit) != 0) {
		return false;
	}
	const auto max = static_cast<rlim_t>(std::max<int64_t>(p_rttime_usec_max, 1));
	limit.rlim_max = limit.rlim_max == RLIM_INFINITY ? max : std::min(limit.rlim_max, max);
	limit.rlim_cur = limit.rlim_cur == RLIM_INFINITY ? limit.rlim_max : std::min(limit.rlim_cur, limit.rlim_max);
	if (::setrlimit(RLIMIT_RTTIME, &limit) != 0) {
		return false;
	}
	r_rttime_usec = static_cast<int64_t>(limit.rlim_max);
	return true;
}

} // namespace

RtkitGrant request_realtime_from_rtkit(int32_t p_priority) {
	RtkitGrant grant;
	const Dbus &dbus = dbus_api();
	if (!dbus.loaded) {
		grant.outcome = RtkitOutcome::UNAVAILABLE;
		say(grant, "no %s to reach RealtimeKit with", LIBDBUS);
		return grant;
	}
	RtkitSession session(dbus);
	if (!session.connected()) {
		grant.outcome = RtkitOutcome::UNAVAILABLE;
		say(grant, "no system bus (%s)", session.error());
		return grant;
	}
	int64_t max_priority = 0;
	int64_t min_nice = 0;
	int64_t rttime_max = 0;
	if (!session.property("MaxRealtimePriority", max_priority)) {
		grant.outcome = RtkitOutcome::UNAVAILABLE;
		say(grant, "RealtimeKit is not on the system bus (%s)", session.error_name());
		return grant;
	}
	(void)session.property("MinNiceLevel", min_nice);
	(void)session.property("RTTimeUSecMax", rttime_max);
	grant.max_priority = static_cast<int32_t>(max_priority);
	const auto thread = static_cast<uint64_t>(::gettid());
	const int32_t priority = std::clamp<int32_t>(p_priority, 1, std::max<int32_t>(grant.max_priority, 1));
	if (grant.max_priority > 0 && rttime_max > 0 && prepare_for_rtkit(rttime_max, grant.rttime_usec) &&
			session.make_realtime(thread, static_cast<uint32_t>(priority))) {
		sched_param param{};
		const int policy = ::sched_getscheduler(0) & ~SCHED_RESET_ON_FORK;
		if (policy == SCHED_RR && ::sched_getparam(0, &param) == 0) {
			grant.outcome = RtkitOutcome::REALTIME;
			grant.priority = param.sched_priority;
			say(grant, "SCHED_RR %d from RealtimeKit (it allows up to %d)", grant.priority, grant.max_priority);
			return grant;
		}
	}
	char refused[96];
	std::snprintf(refused, sizeof(refused), "%s", session.error_name());
	if (min_nice < 0 && session.make_high_priority(thread, static_cast<int32_t>(min_nice))) {
		grant.outcome = RtkitOutcome::HIGH_PRIORITY;
		grant.nice = static_cast<int32_t>(min_nice);
		say(grant, "real time refused (%s); nice %d from RealtimeKit", refused, grant.nice);
		return grant;
	}
	grant.outcome = RtkitOutcome::REFUSED;
	say(grant, "RealtimeKit refused real time and a higher priority (%s%s%s)", refused, refused[0] != '\0' ? ", " : "",
			session.error_name());
	return grant;
}

} // namespace haptics
