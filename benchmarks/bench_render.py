"""Render speed per backend at the default resolution: seconds per frame and per video, peak memory, one core.

The scene is a real one (simulated from the tiny split's first seed, not timed). Each backend renders it in a fresh
process with one thread; the fast backend renders the whole video, the realistic one the first RENDER_FRAMES_MITSUBA
frames (its s/video is extrapolated, and says so). s/frame is the steady state (the first frame, which for Mitsuba
includes compiling its kernels, counts with the scene setup); wall and CPU seconds are both given because the
machine may be shared: CPU time is what one core spends."""

from __future__ import annotations

import time
from pathlib import Path

from benchmarks.common import measure

TARGETS = {"tiny": 0.035, "mitsuba": 0.4}   # s per 320x240 frame per core (the render issue)
RENDER_FRAMES_MITSUBA = 12


def render_video(sim_path: str, out_path: str, backend: str, frames: int | None) -> dict:
    import os

    import cv2

    cv2.setNumThreads(1)
    os.environ["OMP_NUM_THREADS"] = "1"   # as in a pool worker: Mitsuba then runs one thread too
    from dynclevr.config import Config, scene_seed
    from dynclevr.render import make_renderer
    from dynclevr.render.environments import environment
    from dynclevr.scene import Scene4D
    from dynclevr.stages.render import appearance, check
    from dynclevr.video import VideoWriter

    cfg = Config.load()
    r = {**check(cfg), "backend": backend}
    scene = Scene4D.read(Path(sim_path))
    T = frames or scene.num_frames
    camera = scene.camera.with_resolution(r["width"], r["height"])
    env_index, variants = appearance(scene_seed(cfg.split("tiny").seed, 0), len(scene.objects))
    start, cpu = time.perf_counter(), time.process_time()
    with VideoWriter(Path(out_path), camera, scene.fps, T) as video, \
            make_renderer(backend, scene, camera, environment(env_index), variants, r) as renderer:
        setup = time.perf_counter() - start
        video.add(*renderer.render(0))
        first, first_cpu = time.perf_counter(), time.process_time()
        for t in range(1, T):
            video.add(*renderer.render(t))
        steady, steady_cpu = time.perf_counter() - first, time.process_time() - first_cpu
    return {"frames": T, "setup": setup, "first": first - start - setup, "frame": steady / (T - 1),
            "frame_cpu": steady_cpu / (T - 1), "total": time.perf_counter() - start,
            "total_cpu": time.process_time() - cpu, "size": (r["width"], r["height"])}


def _simulate(workdir: Path) -> Path:
    from dynclevr.config import Config, scene_seed
    from dynclevr.stages.simulate import simulate_scene

    cfg = Config.load()
    path = workdir / "000000.mcap"
    simulate_scene("000000", scene_seed(cfg.split("tiny").seed, 0), cfg).write(path, kind="truth")
    return path


def bench(workdir: Path) -> list[dict]:
    from dynclevr.render.mitsuba import mitsuba_available

    sim = _simulate(workdir)
    rows = []
    for backend in ("tiny", "mitsuba"):
        if backend == "mitsuba" and not mitsuba_available():
            print("bench_render: mitsuba is not installed (`make realistic`); skipping its rows")
            continue
        frames = RENDER_FRAMES_MITSUBA if backend == "mitsuba" else None
        seconds, peak, res = measure("benchmarks.bench_render.render_video", str(sim),
                                     str(workdir / f"{backend}.mcap"), backend, frames)
        w, h = res["size"]
        video = res["total"] if frames is None else res["setup"] + res["first"] + 119 * res["frame"]
        row = {"stage": f"render/{backend}", "unit": "s", "target": ""}
        rows += [
            {**row, "metric": f"s per frame ({w}x{h}, 1 core, wall)", "value": res["frame"],
             "target": f"<= {TARGETS[backend]}"},
            {**row, "metric": "CPU s per frame (what contention cannot inflate)", "value": res["frame_cpu"]},
            {**row, "metric": "scene setup + first frame", "value": res["setup"] + res["first"]},
            {**row, "metric": "s per 120-frame video" + (" (setup + first + 119 x s/frame)" if frames else ""),
             "value": video},
            {**row, "metric": "peak memory", "value": peak, "unit": "MiB"},
        ]
    return rows
