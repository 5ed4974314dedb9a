"""`make bench`: every benchmarks/bench_*.py module's rows in one table, printed and written to docs/bench.md."""

from __future__ import annotations

import importlib
import pkgutil
import platform
import sys
import tempfile
from pathlib import Path

import benchmarks

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    only = sys.argv[1:]
    rows = []
    for info in sorted(pkgutil.iter_modules(benchmarks.__path__), key=lambda i: i.name):
        if not info.name.startswith("bench_") or (only and info.name[6:] not in only):
            continue
        with tempfile.TemporaryDirectory() as work:
            print(f"running {info.name} ...", flush=True)
            rows += importlib.import_module(f"benchmarks.{info.name}").bench(Path(work))
    head = "| stage | metric | value | unit | target |\n|---|---|---|---|---|\n"
    body = "".join(f"| {r['stage']} | {r['metric']} | {r['value']:.4g} | {r['unit']} | {r.get('target', '')} |\n"
                   for r in rows)
    table = head + body
    print(table)
    if not only:
        out = ROOT / "docs" / "bench.md"
        out.write_text(f"# Benchmarks\n\nMeasured by `make bench` on {platform.machine()}, "
                       f"{platform.python_version()}, 2 cores.\n\n{table}")
        print(f"written to {out.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
