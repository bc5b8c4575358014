"""A SIGTERM to pytest (CI cancelling a job) unwinds like Ctrl-C, so every test's finally
kills its peers and relay by PID and removes its temporary directory."""

import signal
import sys


def _unwind(_signum, _frame):
    raise KeyboardInterrupt


signal.signal(signal.SIGTERM, _unwind)
sys.dont_write_bytecode = True
