"""What a person sees of the maze study's level on a screenshot, and the way they pick through
it: the walls (the maze's blue-grey fill and light edge), the sub (sub_eyes), the goal flag
(its orange disc), and the way from the sub to the flag that keeps clear of the walls (a
breadth-first search over the free screen, walls widened by the sub's size)."""

from __future__ import annotations

from collections import deque

import numpy as np
from PIL import Image
from scipy import ndimage


# The maze's colours as drawn (game/study/levels/maze_walls.gd, study_goal.gd: a person sees
# them; the test only names them).
WALL_FILL = (51, 115, 140)
WALL_EDGE = (140, 217, 230)
GOAL = (252, 158, 77)
# Screen rows above this are the study's top bar.
TOP_BAR = 110
# A grid cell of the search, screen pixels; and how far from a wall the sub's centre keeps.
CELL = 4
CLEARANCE_PX = 16


def _near(pixels: np.ndarray, colour: tuple[int, int, int], tolerance: int) -> np.ndarray:
    return (np.abs(pixels - np.array(colour)).max(axis=2) <= tolerance)


def pixels_of(shot) -> np.ndarray:
    return np.asarray(Image.open(shot).convert("RGB")).astype(int)


def walls_at(pixels: np.ndarray) -> np.ndarray:
    walls = _near(pixels, WALL_FILL, 18) | _near(pixels, WALL_EDGE, 24)
    walls[:TOP_BAR] = True
    return walls


def goal_at(pixels: np.ndarray) -> tuple[float, float] | None:
    goal = _near(pixels, GOAL, 20)
    goal[:TOP_BAR] = False
    labels, count = ndimage.label(goal)
    if count == 0:
        return None
    sizes = ndimage.sum(goal, labels, range(1, count + 1))
    best = int(np.argmax(sizes)) + 1
    ys, xs = np.nonzero(labels == best)
    return (float(xs.mean()), float(ys.mean()))


class Way:
    """Distances to the goal over the free screen; [next_point] walks them from anywhere."""

    def __init__(self, pixels: np.ndarray, goal: tuple[float, float]) -> None:
        blocked = ndimage.binary_dilation(walls_at(pixels), iterations=CLEARANCE_PX)
        h, w = blocked.shape
        self.cells = blocked[: h - h % CELL, : w - w % CELL].reshape(
            h // CELL, CELL, w // CELL, CELL).any(axis=(1, 3))
        self.distance = np.full(self.cells.shape, -1, dtype=int)
        start = (int(goal[1]) // CELL, int(goal[0]) // CELL)
        self.cells[start] = False
        self.distance[start] = 0
        queue = deque([start])
        while queue:
            y, x = queue.popleft()
            for dy, dx in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                ny, nx = y + dy, x + dx
                if (0 <= ny < self.cells.shape[0] and 0 <= nx < self.cells.shape[1]
                        and not self.cells[ny, nx] and self.distance[ny, nx] < 0):
                    self.distance[ny, nx] = self.distance[y, x] + 1
                    queue.append((ny, nx))

    def _cell_of(self, point: tuple[float, float]) -> tuple[int, int] | None:
        """The reachable cell nearest `point` (the sub's centre may sit in the widened walls)."""
        y, x = int(point[1]) // CELL, int(point[0]) // CELL
        reachable = np.argwhere(self.distance >= 0)
        if len(reachable) == 0:
            return None
        nearest = reachable[np.argmin(np.abs(reachable - (y, x)).sum(axis=1))]
        return (int(nearest[0]), int(nearest[1]))

    def path_from(self, point: tuple[float, float]) -> list[tuple[float, float]]:
        """The screen points from `point` down the distances to the goal, one per cell."""
        cell = self._cell_of(point)
        if cell is None:
            return []
        path = [cell]
        while self.distance[path[-1]] > 0:
            y, x = path[-1]
            options = [(y + dy, x + dx) for dy, dx in ((1, 0), (-1, 0), (0, 1), (0, -1))
                       if 0 <= y + dy < self.distance.shape[0] and 0 <= x + dx < self.distance.shape[1]
                       and self.distance[y + dy, x + dx] == self.distance[y, x] - 1]
            path.append(options[0])
        return [((x + 0.5) * CELL, (y + 0.5) * CELL) for y, x in path]

    def ahead(self, point: tuple[float, float], px: float) -> tuple[float, float] | None:
        """The point `px` along the way from `point` (the goal when it is nearer)."""
        path = self.path_from(point)
        if not path:
            return None
        return path[min(len(path) - 1, int(px / CELL))]
