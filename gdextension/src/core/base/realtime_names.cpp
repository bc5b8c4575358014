#include "core/base/realtime.h"

namespace haptics {

const char *scheduler_kind_name(SchedulerKind p_kind) {
	const auto index = static_cast<uint32_t>(p_kind);
	return index < EnumInfo<SchedulerKind>::COUNT ? SCHEDULER_KIND_LABELS[index] : "unknown";
}

const char *rtkit_outcome_name(RtkitOutcome p_outcome) {
	const auto index = static_cast<uint32_t>(p_outcome);
	return index < EnumInfo<RtkitOutcome>::COUNT ? RTKIT_OUTCOME_LABELS[index] : "unknown";
}

bool is_realtime_kind(SchedulerKind p_kind) {
	return p_kind == SchedulerKind::REALTIME_FIFO || p_kind == SchedulerKind::REALTIME_RR ||
			p_kind == SchedulerKind::MMCSS_PRO_AUDIO || p_kind == SchedulerKind::MMCSS_GAMES;
}

} // namespace haptics
