"""A sustained flood of crafted ENet CONNECTs, as an attacker sends it: RATE datagrams a second,
each from a fresh UDP socket (so a new source port, and a new client to ENet), none ever
answered. It runs as a process of its own (the guard test starts it inside its network
namespace, tests/net/test_net_guard.py) until SIGTERM or SECONDS, whichever comes first, and
then prints one JSON line: what it sent and the rate it kept.

    python3 connect_flood.py --port P [--rate 200] [--seconds 45] [--source 127.0.0.2]
"""

from __future__ import annotations

import argparse
import json
import random
import signal
import socket
import sys
import time

from guard_harness import connect_datagram

# A stalled process catches up at most this much of a second's datagrams at once.
CATCH_UP_S = 0.25


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--port", type=int, required=True)
    parser.add_argument("--target", default="127.0.0.1")
    parser.add_argument("--source", default="127.0.0.1")
    parser.add_argument("--rate", type=float, default=200.0)
    parser.add_argument("--seconds", type=float, default=45.0)
    parser.add_argument("--seed", type=int, default=3)
    args = parser.parse_args()
    stopping = []
    signal.signal(signal.SIGTERM, lambda *_: stopping.append(True))
    rng = random.Random(args.seed)
    ports: set[int] = set()
    sent = 0
    sent_bytes = 0
    start = time.monotonic()
    end = start + args.seconds
    print(json.dumps({"started": time.time()}), flush=True)
    while not stopping and time.monotonic() < end:
        due = int(args.rate * (time.monotonic() - start)) + 1 - sent
        for _ in range(min(due, int(args.rate * CATCH_UP_S) + 1)):
            with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
                sock.bind((args.source, 0))
                ports.add(sock.getsockname()[1])
                datagram = connect_datagram(rng.getrandbits(32), rng.randint(2, 2**31 - 1))
                sent_bytes += sock.sendto(datagram, (args.target, args.port))
            sent += 1
        next_at = start + (sent + 1) / args.rate
        time.sleep(max(0.0, min(next_at - time.monotonic(), 0.05)))
    elapsed = time.monotonic() - start
    print(json.dumps({"sent": sent, "bytes": sent_bytes, "seconds": round(elapsed, 3),
                      "rate": round(sent / elapsed, 1), "source_ports": len(ports)}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
