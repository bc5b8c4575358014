#include "dev_tools/hid/windows_rebuilt_descriptor.h"

#include "dev_tools/hid/windows_rebuilt_list.h"

#include <algorithm>

namespace haptics::hid {

namespace {

using namespace windows_rebuild;

struct BitRange {
	int32_t first = -1;
	int32_t last = -1;
};
using ReportRanges = std::array<std::array<BitRange, WINDOWS_REPORT_TYPES>, 256>; // [report ID][type]

struct Tree {
	std::vector<ReportRanges> ranges; // Per collection.
	std::vector<std::vector<uint16_t>> children; // Per collection, in writing order.
	std::vector<int32_t> begin, end; // Per collection: its Collection and End Collection nodes.
};

const WindowsLinkCollection &node_of(const WindowsParsedData &p_data, uint16_t p_index) {
	return p_data.collections[p_index];
}

void collect_own_ranges(const WindowsParsedData &p_data, Tree &r_tree) {
	r_tree.ranges.assign(p_data.collections.size(), ReportRanges{});
	for (uint32_t type = 0; type < WINDOWS_REPORT_TYPES; ++type) {
		for (const WindowsCap &cap : p_data.caps[type]) {
			BitRange &range = r_tree.ranges[cap.link_collection][cap.report_id][type];
			if (range.first == -1 || range.first > cap.first_bit) {
				range.first = cap.first_bit;
			}
			range.last = std::max(range.last, cap.last_bit());
		}
	}
}

// hidapi merges each level into its parent, deepest first; the child index follows the sibling
// chain at every (report ID, type) step, so once the chain ends it merges node 0's spans, and
// a parent whose first bit is unset (-1) never takes a child's. Kept: it decides the order.
void merge_into_parents(const WindowsParsedData &p_data, Tree &r_tree) {
	const size_t count = p_data.collections.size();
	std::vector<int32_t> levels(count, 0);
	int32_t deepest = 0;
	for (size_t i = 1; i < count; ++i) {
		levels[i] = levels[node_of(p_data, static_cast<uint16_t>(i)).parent] + 1;
		deepest = std::max(deepest, levels[i]);
	}
	for (int32_t level = deepest - 1; level >= 0; --level) {
		for (size_t parent = 0; parent < count; ++parent) {
			if (levels[parent] != level) {
				continue;
			}
			uint16_t child = node_of(p_data, static_cast<uint16_t>(parent)).first_child;
			while (child != 0) {
				for (size_t id = 0; id < 256; ++id) {
					for (uint32_t type = 0; type < WINDOWS_REPORT_TYPES; ++type) {
						BitRange &into = r_tree.ranges[parent][id][type];
						const BitRange from = r_tree.ranges[child][id][type];
						if (from.first != -1 && into.first > from.first) {
							into.first = from.first;
						}
						into.last = std::max(into.last, from.last);
						child = node_of(p_data, child).next_sibling;
					}
				}
			}
		}
	}
}

// Declaration order (Windows links children newest first), then hidapi's one swap pass per
// (type, report ID) over neighbours whose first bits are both known.
void order_children(const WindowsParsedData &p_data, Tree &r_tree) {
	r_tree.children.assign(p_data.collections.size(), {});
	for (size_t parent = 0; parent < p_data.collections.size(); ++parent) {
		std::vector<uint16_t> &order = r_tree.children[parent];
		for (uint16_t child = node_of(p_data, static_cast<uint16_t>(parent)).first_child; child != 0;
				child = node_of(p_data, child).next_sibling) {
			order.insert(order.begin(), child);
		}
		for (uint32_t type = 0; type < WINDOWS_REPORT_TYPES; ++type) {
			for (size_t id = 0; id < 256; ++id) {
				for (size_t i = 1; i < order.size(); ++i) {
					const BitRange &before = r_tree.ranges[order[i - 1]][id][type];
					const BitRange &after = r_tree.ranges[order[i]][id][type];
					if (before.first != -1 && after.first != -1 && before.first > after.first) {
						std::swap(order[i - 1], order[i]);
					}
				}
			}
		}
	}
}

void list_collections(const WindowsParsedData &p_data, Tree &r_tree, MainItemList &r_list) {
	const size_t count = p_data.collections.size();
	r_tree.begin.assign(count, -1);
	r_tree.end.assign(count, -1);
	std::vector<size_t> written(count, 0); // Children already listed.
	Node collection;
	r_tree.begin[0] = r_list.append(collection);
	uint16_t at = 0;
	int32_t level = 0;
	while (level >= 0) {
		std::vector<uint16_t> &children = r_tree.children[at];
		if (written[at] < children.size()) {
			const uint16_t child = children[written[at]++];
			collection.collection = child;
			r_tree.begin[child] = r_list.append(collection);
			at = child;
			++level;
			continue;
		}
		Node end;
		end.main = NODE_END_COLLECTION;
		end.collection = at;
		r_tree.end[at] = r_list.append(end);
		--level;
		at = node_of(p_data, at).parent;
	}
}

// The node to insert after: walks from p_from while the next node is not a collection boundary
// nor an item of the same report ending at or after p_bit.
int32_t find_position(const MainItemList &p_list, int32_t p_from, int32_t p_bit, uint8_t p_main, uint8_t p_report_id) {
	int32_t at = p_from;
	while (p_list.at(at).next >= 0) {
		const Node &next = p_list.at(p_list.at(at).next);
		if (next.main == NODE_COLLECTION || next.main == NODE_END_COLLECTION ||
				(next.last_bit >= p_bit && next.report_id == p_report_id && next.main == p_main)) {
			break;
		}
		at = p_list.at(at).next;
	}
	return at;
}

void place_caps(const WindowsParsedData &p_data, const Tree &p_tree, MainItemList &r_list) {
	for (uint8_t type = 0; type < WINDOWS_REPORT_TYPES; ++type) {
		for (size_t i = 0; i < p_data.caps[type].size(); ++i) {
			const WindowsCap &cap = p_data.caps[type][i];
			int32_t at = p_tree.begin[cap.link_collection];
			for (const uint16_t child : p_tree.children[cap.link_collection]) {
				if (cap.first_bit < p_tree.ranges[child][cap.report_id][type].first) {
					break;
				}
				at = p_tree.end[child];
			}
			Node node;
			node.first_bit = cap.first_bit;
			node.last_bit = cap.last_bit();
			node.kind = NodeKind::CAP;
			node.main = type;
			node.report_id = cap.report_id;
			node.cap = static_cast<int32_t>(i);
			node.collection = cap.link_collection;
			r_list.insert_after(find_position(r_list, at, cap.first_bit, type, cap.report_id), node);
		}
	}
}

Node padding(int32_t p_first, int32_t p_last, uint8_t p_main, uint8_t p_report_id) {
	Node node;
	node.first_bit = p_first;
	node.last_bit = p_last;
	node.kind = NodeKind::PADDING;
	node.main = p_main;
	node.report_id = p_report_id;
	return node;
}

// Windows keeps no padding: hidapi fills every gap between items of a report, pads each report
// to a whole byte and, without report IDs, each type to its report length.
void add_padding(const WindowsParsedData &p_data, MainItemList &r_list) {
	std::array<std::array<int32_t, 256>, WINDOWS_REPORT_TYPES> last_bit, last_item;
	for (uint32_t type = 0; type < WINDOWS_REPORT_TYPES; ++type) {
		last_bit[type].fill(-1);
		last_item[type].fill(-1);
	}
	bool report_ids = false;
	int32_t before_top_end = -1; // The node before the last End Collection: the top level's.
	for (int32_t at = r_list.head; r_list.at(at).next >= 0; at = r_list.at(at).next) {
		const Node node = r_list.at(at);
		if (node.main <= NODE_FEATURE) {
			int32_t &last = last_bit[node.main][node.report_id];
			int32_t &item = last_item[node.main][node.report_id];
			if (last + 1 != node.first_bit && item >= 0 && r_list.at(item).first_bit != node.first_bit) {
				const int32_t after = find_position(r_list, item, last, node.main, node.report_id);
				r_list.insert_after(after, padding(last + 1, node.first_bit - 1, node.main, node.report_id));
			}
			report_ids = report_ids || node.report_id != 0;
			last = node.last_bit;
			item = at;
		}
		if (r_list.at(r_list.at(at).next).main == NODE_END_COLLECTION) {
			before_top_end = at;
		}
	}
	for (uint8_t type = 0; type < WINDOWS_REPORT_TYPES; ++type) {
		for (size_t id = 0; id < 256; ++id) {
			int32_t &last = last_bit[type][id];
			const int32_t fill = 8 - (last + 1) % 8;
			if (last == -1 || fill >= 8) {
				continue;
			}
			const int32_t added = r_list.insert_after(last_item[type][id], padding(last + 1, last + fill, type, static_cast<uint8_t>(id)));
			before_top_end = last_item[type][id] == before_top_end ? added : before_top_end;
			last += fill;
		}
	}
	for (uint8_t type = 0; type < WINDOWS_REPORT_TYPES && !report_ids && before_top_end >= 0; ++type) {
		if (p_data.counted_caps[type] == 0 || p_data.report_byte_length[type] == 0) {
			continue;
		}
		const int32_t fill = (p_data.report_byte_length[type] - 1) * 8 - (last_bit[type][0] + 1);
		if (fill > 0) {
			r_list.insert_after(before_top_end, padding(last_bit[type][0] + 1, last_bit[type][0] + fill, type, 0));
		}
	}
}

} // namespace

std::vector<uint8_t> rebuild_windows_descriptor(const WindowsParsedData &p_data, const WindowsRebuildOptions &p_options) {
	if (p_data.collections.empty()) {
		return {};
	}
	Tree tree;
	collect_own_ranges(p_data, tree);
	merge_into_parents(p_data, tree);
	order_children(p_data, tree);
	MainItemList list;
	list_collections(p_data, tree, list);
	place_caps(p_data, tree, list);
	add_padding(p_data, list);
	return encode_main_items(p_data, list, p_options);
}

Status windows_rebuilt_descriptor(std::span<const uint8_t> p_descriptor, uint32_t p_top_level,
		const WindowsRebuildOptions &p_options, std::vector<uint8_t> &r_bytes) {
	WindowsParsedData data;
	HAPTICS_RETURN_IF_ERROR(parse_windows_caps(p_descriptor, p_top_level, data));
	r_bytes = rebuild_windows_descriptor(data, p_options);
	return Status::success();
}

} // namespace haptics::hid
