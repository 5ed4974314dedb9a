"""Issue 16's scaling figures: scenes per minute for simulate + render + annotate of the tiny split from scratch, with
the local process pool and with Ray (1 and 2 workers), and on a simulated two-node Ray cluster on this machine
(`ray.cluster_utils.Cluster`, one CPU per node). Each configuration runs in a fresh process; a Ray configuration's
time includes starting Ray (its start alone is a row of its own). Ray's rows are left out when Ray is not installed
(`make ray`)."""

from __future__ import annotations

import importlib.util
import tempfile
import time
from pathlib import Path

from benchmarks.common import measure

SPLIT = "tiny"
STAGES = ("simulate", "render", "annotate")
CONFIGS = (("local", 1, 1), ("local", 2, 1), ("ray", 1, 1), ("ray", 2, 1), ("ray", 2, 2))   # executor, workers, nodes


def run_config(executor: str, workers: int, nodes: int, workdir: str) -> dict:
    """In a spawned process: the three stages of the split into a fresh data dir; seconds in all and to start Ray."""
    import logging

    from dynclevr.config import Config
    from dynclevr.pipeline import Runner, _ray_connect

    cfg = Config.load()
    split = cfg.split(SPLIT)
    data = Path(tempfile.mkdtemp(dir=workdir)) / "data"
    start = time.perf_counter()
    cluster = None
    if executor == "ray" and nodes > 1:
        import ray
        from ray.cluster_utils import Cluster

        cluster = Cluster(initialize_head=True, head_node_args={"num_cpus": 1, "include_dashboard": False})
        for _ in range(nodes - 1):
            cluster.add_node(num_cpus=1)
        cluster.wait_for_nodes()
        ray.init(address=cluster.address, logging_level=logging.WARNING, log_to_driver=False)
    elif executor == "ray":
        _ray_connect(None, workers)
    started = time.perf_counter() - start
    r = Runner(cfg, split, data, workers=workers, echo=lambda *a: None, executor=executor)
    for name in STAGES:
        r.run(name, list(range(split.scenes)))
    seconds = time.perf_counter() - start
    if executor == "ray":
        import ray

        ray.shutdown()
        if cluster is not None:
            cluster.shutdown()
    return {"seconds": seconds, "start": started, "scenes": split.scenes}


def bench(workdir: Path) -> list[dict]:
    has_ray = importlib.util.find_spec("ray") is not None
    rows = []
    for executor, workers, nodes in CONFIGS:
        if executor == "ray" and not has_ray:
            continue
        _, _, out = measure("benchmarks.bench_scale.run_config", executor, workers, nodes, str(workdir))
        what = f"{executor}, {workers} worker{'s' if workers > 1 else ''}" + (
            f" on a simulated {nodes}-node cluster" if nodes > 1 else "")
        rows.append({"stage": "scale-out", "metric": f"simulate+render+annotate, {SPLIT} split "
                                                     f"({out['scenes']} scenes): {what}",
                     "value": 60 * out["scenes"] / out["seconds"], "unit": "scenes/min"})
        if executor == "ray":
            rows.append({"stage": "scale-out", "metric": f"  of which starting Ray ({what})", "value": out["start"],
                         "unit": "s"})
    return rows
