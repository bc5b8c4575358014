"""What a path does to each datagram: delay (and with it reordering), loss, bursts, duplicates.

Decisions only, no sockets: udp_relay.py keeps one Lane per direction of each client's path,
asks it the fate of every datagram it receives and tells it when one leaves. Each lane draws
from its own seeded generator, in a fixed order per datagram, so a datagram's fate depends
only on its place in its lane and the seed. A draw is taken only for the features that are
on: a relay run with yesterday's options draws what it drew then, and a seed still gives the
same drops and delays.
"""

from __future__ import annotations

import heapq
import random
from dataclasses import dataclass, fields

# An in-order lane releases each datagram at least this much after the one before it: two
# timers due at the same instant may fire in either order.
IN_ORDER_STEP_S = 1e-6


@dataclass(frozen=True)
class BurstLoss:
    """Gilbert-Elliott loss in Gilbert's form: a two-state Markov chain stepped once per
    datagram; the good state loses nothing, the bad state everything (the relay's independent
    --loss on top plays the good state's loss of Elliott's form). A burst is one stay in the
    bad state, so its length is geometric: a chain can match a mean burst, not a range."""

    enter_bad: float  # P(good -> bad) at each datagram
    leave_bad: float  # P(bad -> good) at each datagram

    @classmethod
    def from_mean(cls, p_average_loss: float, p_mean_burst: float) -> "BurstLoss":
        """The chain that loses [p_average_loss] of the datagrams in bursts of [p_mean_burst]
        datagrams on average. ValueError when no chain does."""
        if not 0.0 < p_average_loss < 1.0:
            raise ValueError(f"burst loss must be in (0, 1), got {p_average_loss}")
        if not p_mean_burst >= 1.0:
            raise ValueError(f"mean burst length must be at least 1 datagram, got {p_mean_burst}")
        leave_bad = 1.0 / p_mean_burst
        # Stationary share of the bad state: enter / (enter + leave) = average loss.
        enter_bad = p_average_loss * leave_bad / (1.0 - p_average_loss)
        if enter_bad > 1.0:
            most = p_mean_burst / (1.0 + p_mean_burst)
            raise ValueError(
                f"bursts of {p_mean_burst:g} on average lose at most {most:.3f} of the datagrams "
                f"(the chain would have to go bad more than always), got {p_average_loss}"
            )
        return cls(enter_bad, leave_bad)

    @property
    def average_loss(self) -> float:
        return self.enter_bad / (self.enter_bad + self.leave_bad)

    @property
    def mean_burst(self) -> float:
        return 1.0 / self.leave_bad

    def starts_bad(self, p_rng: random.Random) -> bool:
        """A first state drawn from the stationary distribution: the loss rate holds from the
        first datagram on, not only once the chain has settled."""
        return p_rng.random() < self.average_loss

    def step(self, p_bad: bool, p_rng: random.Random) -> bool:
        """The state for the next datagram."""
        if p_bad:
            return p_rng.random() >= self.leave_bad
        return p_rng.random() < self.enter_bad


@dataclass(frozen=True)
class PathModel:
    """A path's behaviour, the same each way (each direction draws its own fates)."""

    delay_s: float = 0.0
    jitter_s: float = 0.0
    # Jitter drawn in delay +- jitter instead of delay + 0..jitter.
    centred: bool = False
    # Each datagram leaves at its own drawn time, so later ones may overtake (False: each
    # waits for the one before it, jitter without reordering, like a single queue).
    reorder: bool = True
    loss: float = 0.0
    bursts: BurstLoss | None = None
    duplicate: float = 0.0

    def __post_init__(self) -> None:
        if self.delay_s < 0.0 or self.jitter_s < 0.0:
            raise ValueError("delay and jitter cannot be negative")
        if self.centred and self.jitter_s > self.delay_s:
            raise ValueError(
                f"centred jitter of {self.jitter_s * 1000:g} ms needs a delay at least as long, "
                f"got {self.delay_s * 1000:g} ms"
            )
        for name in ("loss", "duplicate"):
            if not 0.0 <= getattr(self, name) < 1.0:
                raise ValueError(f"{name} must be a probability in [0, 1)")

    def draw_delay(self, p_rng: random.Random) -> float:
        if self.centred:
            return self.delay_s + p_rng.uniform(-self.jitter_s, self.jitter_s)
        return self.delay_s + p_rng.uniform(0.0, self.jitter_s)


@dataclass
class DirectionStats:
    """What happened to the datagrams travelling one way. Every datagram that reaches the
    relay, and every copy it makes, ends in exactly one of dropped, blackholed, delivered or
    undelivered."""

    received: int = 0
    # Lost to the loss models (independent and bursts).
    dropped: int = 0
    # Runs of consecutive datagrams lost to them.
    loss_runs: int = 0
    # Dropped because the path was cut, on arrival or while on its way.
    blackholed: int = 0
    # Extra copies made.
    duplicated: int = 0
    delivered: int = 0
    # Delivered after a datagram that reached the relay later: what a receiver that keeps
    # only the newest (ENet's unreliable ordered channels) throws away.
    reordered: int = 0
    # Delivered before a datagram that reached the relay earlier and was still on its way.
    overtaking: int = 0
    # Still on its way when the relay stopped, or its socket was gone.
    undelivered: int = 0
    bytes_delivered: int = 0

    def add(self, p_other: "DirectionStats") -> None:
        for item in fields(self):
            setattr(self, item.name, getattr(self, item.name) + getattr(p_other, item.name))


class Lane:
    """One direction of one client's path: decides each datagram's fate and counts it."""

    def __init__(self, p_model: PathModel, p_rng: random.Random) -> None:
        self.model = p_model
        self.rng = p_rng
        self.stats = DirectionStats()
        # Dropping everything, arrivals and datagrams on their way (a dead path).
        self.cut = False
        self._arrived = 0
        self._newest_delivered = -1
        self._last_release_s = float("-inf")
        self._bad: bool | None = None  # the burst chain's state; None until the first draw
        self._last_lost = False
        # Sequences on their way (a copy appears twice), as a heap with counts for removal.
        self._on_way: list[int] = []
        self._on_way_count: dict[int, int] = {}

    def admit(self, p_now_s: float) -> list[tuple[int, float]]:
        """(sequence, release time) for each copy of the datagram that arrived at [p_now_s]
        to send on; empty when it is lost or the path is cut."""
        self.stats.received += 1
        sequence = self._arrived
        self._arrived += 1
        if self.cut:
            self.stats.blackholed += 1
            return []
        if self._lost():
            self.stats.dropped += 1
            if not self._last_lost:
                self.stats.loss_runs += 1
            self._last_lost = True
            return []
        self._last_lost = False
        copies = [self._release_s(p_now_s)]
        if self.model.duplicate > 0.0 and self.rng.random() < self.model.duplicate:
            self.stats.duplicated += 1
            copies.append(self._release_s(p_now_s))
        for _ in copies:
            heapq.heappush(self._on_way, sequence)
            self._on_way_count[sequence] = self._on_way_count.get(sequence, 0) + 1
        return [(sequence, release) for release in copies]

    def release(self, p_sequence: int, p_size: int) -> bool:
        """A copy of [p_sequence] is due: whether to send it (not when the path is cut)."""
        self._leave(p_sequence)
        if self.cut:
            self.stats.blackholed += 1
            return False
        self.stats.delivered += 1
        self.stats.bytes_delivered += p_size
        if p_sequence < self._newest_delivered:
            self.stats.reordered += 1
        if self._on_way and self._on_way[0] < p_sequence:
            self.stats.overtaking += 1
        self._newest_delivered = max(self._newest_delivered, p_sequence)
        return True

    def lost_on_way(self, p_sequence: int) -> None:
        """A copy of [p_sequence] could not be sent (its socket is gone)."""
        self._leave(p_sequence)
        self.stats.undelivered += 1

    def abandon(self) -> None:
        """The relay stops: what is still on its way is never delivered."""
        self.stats.undelivered += sum(self._on_way_count.values())
        self._on_way.clear()
        self._on_way_count.clear()

    def _lost(self) -> bool:
        lost = False
        bursts = self.model.bursts
        if bursts is not None:
            self._bad = bursts.starts_bad(self.rng) if self._bad is None else (
                bursts.step(self._bad, self.rng))
            lost = self._bad
        # Drawn even in a burst: the independent loss keeps its own sequence of draws.
        return (self.rng.random() < self.model.loss) or lost

    def _release_s(self, p_now_s: float) -> float:
        release = p_now_s + self.model.draw_delay(self.rng)
        if not self.model.reorder:
            release = max(release, self._last_release_s + IN_ORDER_STEP_S)
        self._last_release_s = max(self._last_release_s, release)
        return release

    def _leave(self, p_sequence: int) -> None:
        left = self._on_way_count.get(p_sequence, 0) - 1
        if left > 0:
            self._on_way_count[p_sequence] = left
        else:
            self._on_way_count.pop(p_sequence, None)
        while self._on_way and self._on_way[0] not in self._on_way_count:
            heapq.heappop(self._on_way)
