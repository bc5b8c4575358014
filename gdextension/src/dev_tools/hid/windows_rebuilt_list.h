#pragma once

// Internal to the Windows descriptor rebuild: hidapi's list of main items (collections, caps,
// padding) in the order they are written, built by windows_rebuilt_descriptor.cpp and written
// as items by windows_rebuilt_items.cpp.

#include "dev_tools/hid/windows_rebuilt_descriptor.h"

#include <cstdint>
#include <vector>

namespace haptics::hid::windows_rebuild {

enum : uint8_t {
	NODE_INPUT = 0, // = the report type of caps and padding.
	NODE_OUTPUT = 1,
	NODE_FEATURE = 2,
	NODE_COLLECTION = 3,
	NODE_END_COLLECTION = 4,
};

enum class NodeKind : uint8_t {
	CAP,
	PADDING,
	COLLECTION,
};

struct Node {
	int32_t first_bit = 0; // From the first bit after the report-ID byte.
	int32_t last_bit = 0;
	NodeKind kind = NodeKind::COLLECTION;
	uint8_t main = NODE_COLLECTION;
	uint8_t report_id = 0;
	int32_t cap = -1; // Into WindowsParsedData::caps[main] for a CAP.
	uint16_t collection = 0;
	int32_t next = -1;
};

// A singly linked list in a vector: hidapi inserts after nodes it finds by walking the list.
struct MainItemList {
	std::vector<Node> nodes;
	int32_t head = -1;
	int32_t tail = -1;

	int32_t append(const Node &p_node) { return tail < 0 ? link_first(p_node) : insert_after(tail, p_node); }
	int32_t insert_after(int32_t p_at, const Node &p_node) {
		Node node = p_node;
		node.next = nodes[static_cast<size_t>(p_at)].next;
		nodes.push_back(node);
		const int32_t index = static_cast<int32_t>(nodes.size() - 1);
		nodes[static_cast<size_t>(p_at)].next = index;
		tail = p_at == tail ? index : tail;
		return index;
	}
	const Node &at(int32_t p_index) const { return nodes[static_cast<size_t>(p_index)]; }

private:
	int32_t link_first(const Node &p_node) {
		nodes.push_back(p_node);
		head = tail = static_cast<int32_t>(nodes.size() - 1);
		return head;
	}
};

// Writes p_list as descriptor items, as hidapi's encoder does.
std::vector<uint8_t> encode_main_items(const WindowsParsedData &p_data, const MainItemList &p_list,
		const WindowsRebuildOptions &p_options);

} // namespace haptics::hid::windows_rebuild
