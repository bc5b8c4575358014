#pragma once

// How fast a force-feedback device behind an event node can take effect updates. EVIOCSFF
// returns as soon as the driver queued the reports; usbhid queues output reports for the
// interrupt OUT endpoint, which carries one per interval, and when its queue is full it
// drops the report with "output queue full" in the kernel log and nothing to the caller.
// hid-pidff then believes the device holds the new force: it does not send an unchanged
// effect again, so a dropped update can leave the device holding a stale force for good
// (seen on Linux 6.1 in the VM tests at our former 500 Hz update rate: docs/linux-kernel.md,
// "Driver facts"). So updates are paced to what the endpoint drains: an update
// that changes the direction costs hid-pidff two reports (Set Effect, Set Constant Force), a
// level alone one, and the next waits that many intervals, with a margin.

#include "devices/evdev/evdev_ff.h"

#include <string>

namespace haptics::evdev {

// When sysfs names no interrupt OUT endpoint (reports go as control transfers, or the device
// is not on USB): one report per USB frame.
inline constexpr double DEFAULT_REPORT_INTERVAL_S = 0.001;
// Room for the reports other requests put in the same queue and for a late frame.
inline constexpr double PACING_MARGIN = 1.5;

// The interval of the interrupt OUT endpoint of the USB interface behind p_event_path
// (/dev/input/eventN), from <root>/class/input/eventN/device and its parents' ep_*/
// (direction "out", type "Interrupt", interval "1ms" or "125us"); DEFAULT_REPORT_INTERVAL_S
// when there is none.
double output_report_interval_s(const std::string &p_event_path, const std::string &p_sysfs_root = "/sys");

// How long after an update from p_from to p_to the next should wait.
double update_hold_s(const FfConstantForce &p_from, const FfConstantForce &p_to, double p_report_interval_s);

} // namespace haptics::evdev
