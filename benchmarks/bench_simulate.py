"""simulate: seconds per scene (sampling, the factual run and every counterfactual run, MCAP writing) on one core,
wall and CPU, seconds of one 120-frame factual run (a fresh World included), and peak memory."""

from __future__ import annotations

import time
from pathlib import Path

from benchmarks.common import measure

SCENES = 10


def work(workdir: str) -> dict:
    """Simulate SCENES scenes of the small split in this process; the asset catalogue is built first (once per
    process in a real run, shared by all its scenes)."""
    import os

    os.environ["OMP_NUM_THREADS"] = "1"
    import numpy as np

    from dynclevr.config import Config, scene_seed
    from dynclevr.physics import PhysicsParams, catalogue_digest, simulate
    from dynclevr.stages.simulate import sample_scene, simulate_scene

    cfg = Config.load()
    catalogue_digest(cfg)   # builds every sub-type's mesh and collision shape
    split = cfg.split("small")
    start, cpu = time.perf_counter(), time.process_time()
    runs = 0
    for i in range(SCENES):
        scene = simulate_scene(f"{i:06d}", scene_seed(split.seed, i), cfg)
        scene.write(Path(workdir) / f"{i:06d}.mcap", kind="truth")
        runs += 1 + len(scene.counterfactuals)
    per_scene = (time.perf_counter() - start) / SCENES
    cpu_per_scene = (time.process_time() - cpu) / SCENES
    params = PhysicsParams.from_config(cfg)
    _, bodies, _ = sample_scene(np.random.default_rng(scene_seed(split.seed, 0)), cfg)
    start = time.perf_counter()
    for _ in range(5):
        simulate(bodies, params, cfg["video"]["frames"])
    return {"per_scene": per_scene, "cpu_per_scene": cpu_per_scene, "factual": (time.perf_counter() - start) / 5,
            "runs": runs / SCENES}


def bench(workdir: Path) -> list[dict]:
    _, peak, r = measure("benchmarks.bench_simulate.work", str(workdir))
    return [
        {"stage": "simulate", "metric": f"seconds per scene ({r['runs']:.1f} runs: factual + counterfactuals)",
         "value": r["per_scene"], "unit": "s", "target": "<= 1"},
        # CPU seconds are what one core spends, whatever else runs on the machine.
        {"stage": "simulate", "metric": "CPU seconds per scene", "value": r["cpu_per_scene"], "unit": "s",
         "target": "<= 1"},
        {"stage": "simulate", "metric": "seconds of one 120-frame factual run", "value": r["factual"], "unit": "s",
         "target": ""},
        {"stage": "simulate", "metric": "peak memory", "value": peak, "unit": "MiB", "target": ""},
    ]
