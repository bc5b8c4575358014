#pragma once

// The control side of the fake OpenHaptics runtime (libfake_hd.so), for tests and the
// bench. The fake exports the HDAPI functions the backend loads (docs/devices/openhaptics.md)
// with their
// exact C signatures, over a scripted device; these extern "C" fake_hd_* functions script it
// and read what it recorded. Tests resolve them with dlsym on the same library the backend
// loads (openhaptics_fake.h), so both talk to one instance.
//
// Behaviour worth knowing when reading a test:
//  - Every exported HD function appends a FakeHdCall (name, parameter, values, whether the
//    calling thread was inside hdBeginFrame/hdEndFrame, whether it was the scheduler thread,
//    which callback was running, the scheduler tick).
//  - hdStartScheduler starts a thread that runs the scheduled callbacks at the rate of
//    hdSetSchedulerRate (default 1000 Hz), highest priority first, until hdStopScheduler
//    (which joins). hdScheduleSynchronous waits until its callback returned DONE on that
//    thread (or runs it on the caller's thread when the scheduler is stopped).
//  - Errors stack like HD's: hdGetError pops the most recent, {HD_SUCCESS, 0, 0} when empty.
//    "Unplugged": hdInitDevice fails and every hdEndFrame pushes HD_COMM_ERROR.
//  - Misuse is counted, with the first one's text: a frame parameter (HD_CURRENT_*,
//    HD_LAST_*, forces) read or written outside a frame, nested or unmatched frames, a frame
//    on a handle that is not current, hdInitDevice while a device is initiated, a second
//    hdStartScheduler, a force that is not finite or above HD_NOMINAL_MAX_FORCE.

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FAKE_HD_CALL_NAME_CAPACITY 32
#define FAKE_HD_CALL_VALUES 16

typedef struct FakeHdCall {
	char name[FAKE_HD_CALL_NAME_CAPACITY]; // "hdGetDoublev"
	unsigned int pname; // Parameter, capability, style, priority or handle, per function.
	int count; // Values recorded.
	double values[FAKE_HD_CALL_VALUES]; // What was read or written, or returned.
	int in_frame; // The calling thread was between hdBeginFrame and hdEndFrame.
	int on_scheduler; // Called from the fake scheduler's thread.
	unsigned long callback; // Handle of the callback running on this thread, 0 when none.
	unsigned long long tick; // Scheduler ticks started so far.
} FakeHdCall;

// Back to the defaults: a plugged-in, calibrated Touch-like device (see fake_hd_state.cpp),
// no errors, empty record, recording on, 1 kHz. The scheduler must be stopped.
void fake_hd_reset(void);

// Scripted answers of hdGetDoublev / hdGetIntegerv / hdGetString for a parameter.
void fake_hd_set_doubles(unsigned int p_pname, const double *p_values, int p_count);
void fake_hd_set_integer(unsigned int p_pname, int p_value);
void fake_hd_set_string(unsigned int p_pname, const char *p_value); // NULL: hdGetString returns NULL.
// What hdCheckCalibration answers. hdUpdateCalibration turns NEEDS_UPDATE into OK.
void fake_hd_set_calibration(unsigned int p_status);
// The next hdInitDevice returns HD_INVALID_HANDLE and pushes {p_code, p_internal}.
void fake_hd_fail_init(unsigned int p_code, int p_internal);
void fake_hd_set_unplugged(int p_unplugged);
// Pushed at the next hdEndFrame (an error of the servo loop).
void fake_hd_inject_error(unsigned int p_code, int p_internal, unsigned int p_hhd);
// Pushed now.
void fake_hd_push_error(unsigned int p_code, int p_internal, unsigned int p_hhd);

// Recording costs a lock and a copy per call; the bench turns it off.
void fake_hd_set_recording(int p_on);
// The scheduler runs ticks back to back instead of at its rate (max callbacks per second).
void fake_hd_set_free_running(int p_on);

size_t fake_hd_call_count(void);
int fake_hd_get_call(size_t p_index, FakeHdCall *r_call); // 0 past the end.
unsigned long long fake_hd_ticks(void);
int fake_hd_scheduler_running(void);
// Waits until p_count more ticks ran; 0 on timeout or when the scheduler is stopped.
int fake_hd_wait_ticks(unsigned long long p_count, int p_timeout_ms);
unsigned long long fake_hd_misuse_count(void);
void fake_hd_misuse_text(char *r_text, size_t p_capacity); // The first misuse.
// Durations of the latest asynchronous callback runs, ns (up to p_max, oldest first).
size_t fake_hd_callback_costs(double *r_ns, size_t p_max);
unsigned long long fake_hd_force_sets(void);
void fake_hd_last_force(double r_force[3]);

#ifdef __cplusplus
}
#endif
