"""A dedicated server waiting for players, a real headless process on 127.0.0.1: it must cost
next to nothing, so it runs no 1 kHz servo thread (a stepped peer runs its servo by hand in a
match). Its CPU share and memory are figures of `make bench-net`, not assertions here."""

from __future__ import annotations

from pathlib import Path

from net_harness import Peer, free_udp_port, workspace

SERVO_THREAD = "haptics-servo"  # SERVO_THREAD_NAME in gdextension/src/core/servo/servo_loop.h


def thread_names(pid: int) -> list[str]:
    return [(task / "comm").read_text().strip() for task in Path(f"/proc/{pid}/task").iterdir()]


def test_a_dedicated_server_waiting_for_players_runs_no_servo_thread() -> None:
    with workspace() as work:
        # The game itself (its main scene), as an operator runs it: no test driver.
        server = Peer("server", ["--server", f"--port={free_udp_port()}"], work, scene="")
        server.start()
        try:
            # The servo is stopped before the server starts hosting.
            assert server.wait_for_log("Hosting on port"), server.log()
            assert server.proc is not None and server.proc.poll() is None, server.log()
            names = thread_names(server.proc.pid)
            # The engine's own threads are listed: this is the right process.
            assert len(names) > 1, names
            assert SERVO_THREAD not in names, names
        finally:
            server.kill()
