#pragma once

// Wall sets for the proxy tests: random perfect mazes (every cell reachable, one path
// between any two), deterministic for a seed.

#include "renderers/constraint/swept_disc.h"

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace haptics::test {

// A perfect maze of p_cells x p_cells square cells of side p_cell, lower-left corner at the
// origin, walls as unit segments (shared by the two cells they separate) plus the boundary:
// (p_cells + 1)^2 segments, e.g. 9 -> 100, 99 -> 10 000. Randomised depth-first search.
inline std::vector<Segment2> perfect_maze(int p_cells, double p_cell, uint32_t p_seed) {
	const int n = p_cells;
	// east[x + y n]: wall on the east side of cell (x, y); north likewise.
	std::vector<char> east(static_cast<size_t>(n * n), 1);
	std::vector<char> north(static_cast<size_t>(n * n), 1);
	std::vector<char> seen(static_cast<size_t>(n * n), 0);
	std::mt19937 random(p_seed);
	std::vector<std::pair<int, int>> stack{ { 0, 0 } };
	seen[0] = 1;
	while (!stack.empty()) {
		const auto [x, y] = stack.back();
		std::pair<int, int> options[4];
		int count = 0;
		const int dx[4] = { 1, -1, 0, 0 };
		const int dy[4] = { 0, 0, 1, -1 };
		for (int d = 0; d < 4; ++d) {
			const int nx = x + dx[d];
			const int ny = y + dy[d];
			if (nx >= 0 && ny >= 0 && nx < n && ny < n && !seen[static_cast<size_t>(nx + ny * n)]) {
				options[count++] = { nx, ny };
			}
		}
		if (count == 0) {
			stack.pop_back();
			continue;
		}
		const auto [nx, ny] = options[random() % static_cast<uint32_t>(count)];
		if (nx != x) {
			east[static_cast<size_t>(std::min(x, nx) + y * n)] = 0;
		} else {
			north[static_cast<size_t>(x + std::min(y, ny) * n)] = 0;
		}
		seen[static_cast<size_t>(nx + ny * n)] = 1;
		stack.push_back({ nx, ny });
	}
	std::vector<Segment2> walls;
	const double size = n * p_cell;
	for (int i = 0; i < n; ++i) { // Boundary, one segment per cell side.
		const double a = i * p_cell;
		const double b = (i + 1) * p_cell;
		walls.push_back({ { a, 0.0 }, { b, 0.0 } });
		walls.push_back({ { a, size }, { b, size } });
		walls.push_back({ { 0.0, a }, { 0.0, b } });
		walls.push_back({ { size, a }, { size, b } });
	}
	for (int y = 0; y < n; ++y) {
		for (int x = 0; x < n; ++x) {
			const double x0 = x * p_cell;
			const double y0 = y * p_cell;
			if (x + 1 < n && east[static_cast<size_t>(x + y * n)]) {
				walls.push_back({ { x0 + p_cell, y0 }, { x0 + p_cell, y0 + p_cell } });
			}
			if (y + 1 < n && north[static_cast<size_t>(x + y * n)]) {
				walls.push_back({ { x0, y0 + p_cell }, { x0 + p_cell, y0 + p_cell } });
			}
		}
	}
	return walls;
}

} // namespace haptics::test
