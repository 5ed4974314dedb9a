"""`make all` from a fresh clone on 2 cores: wall time of the set-up and of the whole run, and each stage's share.

It clones the committed HEAD (uncommitted changes are not measured) and runs exactly what a newcomer runs."""

from __future__ import annotations

import re
import subprocess
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
STAGE_LINE = re.compile(r"^(?P<stage>[a-z-]+): \d+ done in (?P<seconds>[\d.]+) s( \(.*\))?$")   # (rate, executor)


def bench(workdir: Path) -> list[dict]:
    clone = workdir / "clone"
    subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
    start = time.perf_counter()
    subprocess.run(["make", "setup"], cwd=clone, check=True, capture_output=True)
    setup = time.perf_counter() - start
    out = subprocess.run(["make", "all"], cwd=clone, check=True, capture_output=True, text=True).stdout
    total = time.perf_counter() - start
    stages: dict[str, float] = {}
    ablation = False
    for line in out.splitlines():
        ablation |= line.startswith("ablation")
        m = STAGE_LINE.match(line)
        if m:
            name = m["stage"] + (" (no prior)" if ablation else "")
            stages[name] = stages.get(name, 0.0) + float(m["seconds"])
    rows = [{"stage": "make all", "metric": "wall time from a fresh clone (set-up included)", "value": total,
             "unit": "s", "target": "<= 900"},
            {"stage": "make all", "metric": "share: set-up (.venv, pip)", "value": 100 * setup / total, "unit": "%"}]
    rows += [{"stage": "make all", "metric": f"share: {name}", "value": 100 * s / total, "unit": "%"}
             for name, s in stages.items()]
    return rows
