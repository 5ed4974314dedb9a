"""Measure a piece of work in a fresh process: wall seconds and peak resident memory, nothing else running."""

from __future__ import annotations

import importlib
import resource
import time
from queue import Empty
from multiprocessing import get_context


def _child(target: str, args: tuple, queue) -> None:
    module, _, func = target.rpartition(".")
    start = time.perf_counter()
    result = getattr(importlib.import_module(module), func)(*args)
    seconds = time.perf_counter() - start
    queue.put((seconds, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, result))


def measure(target: str, *args) -> tuple[float, float, object]:
    """Run `module.func(*args)` in a spawned process; return (seconds, peak RSS in MiB, its return value).

    The seconds exclude interpreter start-up and imports of the benchmark module, not the work's own imports."""
    ctx = get_context("spawn")
    queue = ctx.Queue()
    proc = ctx.Process(target=_child, args=(target, args, queue))
    proc.start()
    while True:
        try:
            out = queue.get(timeout=1)
            break
        except Empty:
            if not proc.is_alive() and queue.empty():
                raise RuntimeError(f"benchmark {target} died (exit code {proc.exitcode})") from None
    proc.join()
    return out
