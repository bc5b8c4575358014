#include "core/base/realtime.h"

namespace haptics {

const char *scheduler_kind_name(SchedulerKind p_kind) {
	switch (p_kind) {
		case SchedulerKind::MANUAL:
			return "manual";
		case SchedulerKind::NORMAL:
			return "SCHED_OTHER";
		case SchedulerKind::REALTIME_FIFO:
			return "SCHED_FIFO";
		case SchedulerKind::REALTIME_RR:
			return "SCHED_RR";
		case SchedulerKind::MMCSS_PRO_AUDIO:
			return "MMCSS Pro Audio";
		case SchedulerKind::MMCSS_GAMES:
			return "MMCSS Games";
	}
	return "unknown";
}

const char *rtkit_outcome_name(RtkitOutcome p_outcome) {
	switch (p_outcome) {
		case RtkitOutcome::NOT_ASKED:
			return "not asked";
		case RtkitOutcome::REALTIME:
			return "realtime";
		case RtkitOutcome::HIGH_PRIORITY:
			return "high priority";
		case RtkitOutcome::REFUSED:
			return "refused";
		case RtkitOutcome::UNAVAILABLE:
			return "unavailable";
	}
	return "unknown";
}

bool is_realtime_kind(SchedulerKind p_kind) {
	return p_kind == SchedulerKind::REALTIME_FIFO || p_kind == SchedulerKind::REALTIME_RR ||
			p_kind == SchedulerKind::MMCSS_PRO_AUDIO || p_kind == SchedulerKind::MMCSS_GAMES;
}

} // namespace haptics
