"""parse-scene: seconds per 120-frame video (2 threads, the 2 cores) and peak memory, with the shipped weights."""

from __future__ import annotations

from pathlib import Path

from benchmarks.common import measure

SPLIT = "tiny"


def parse(video_path: str, threads: int, filter_kind: str = "single", detections: str | None = None) -> int:
    """`detections`: a detection cache file (perception/detections.py) to read the head's peaks from, as the model
    rows after the first do."""
    import torch

    from dynclevr.config import Config
    from dynclevr.perception import detections as cache
    from dynclevr.perception.collisions import CollisionModel
    from dynclevr.perception.detector_train import load_detector
    from dynclevr.perception.model import ParserModel
    from dynclevr.perception.tracker import parse_video
    from dynclevr.video import Video

    torch.set_num_threads(threads)
    video = Video.read(Path(video_path))
    cfg = Config.load()
    cfg.data["parser"]["filter"] = filter_kind
    frames, head = video.frames(), load_detector()
    dets = None if detections is None else cache.cached(Path(detections), "bench",
                                                        lambda: cache.detect(head, frames, cfg["parser"]))
    scene = parse_video(frames, video.camera, ParserModel.load(), head, cfg, "bench", CollisionModel.load(), dets)
    return len(scene.objects)


def bench(workdir: Path) -> list[dict]:
    from dynclevr.config import Config
    from dynclevr.pipeline import Runner

    cfg = Config.load()
    r = Runner(cfg, cfg.split(SPLIT), workdir, echo=lambda *a: None)
    r.run("simulate", [0])
    r.run("render", [0])
    video = r.store.path("render", r.split.scene_names()[0], ".mcap")
    seconds, peak, _ = measure("benchmarks.bench_parse.parse", str(video), 2)
    particle, particle_peak, _ = measure("benchmarks.bench_parse.parse", str(video), 2, "particle")
    stored = workdir / "bench-detections.npz"
    measure("benchmarks.bench_parse.parse", str(video), 2, "single", str(stored))    # fills the cache
    cached, _, _ = measure("benchmarks.bench_parse.parse", str(video), 2, "single", str(stored))
    frames = cfg["video"]["frames"]
    return [{"stage": "parse-scene", "metric": f"seconds per {frames}-frame video (2 threads)",
             "value": seconds * 120 / frames, "unit": "s", "target": "<= 15"},
            {"stage": "parse-scene", "metric": "peak memory", "value": peak / 1024, "unit": "GiB", "target": "<= 4"},
            {"stage": "parse-scene, particle filter", "metric": f"seconds per {frames}-frame video (2 threads)",
             "value": particle * 120 / frames, "unit": "s", "target": "<= 15"},
            {"stage": "parse-scene, particle filter", "metric": "peak memory", "value": particle_peak / 1024,
             "unit": "GiB", "target": "<= 4"},
            {"stage": "parse-scene, the head's detections cached (the ablation's rows)",
             "metric": f"seconds per {frames}-frame video (2 threads)", "value": cached * 120 / frames, "unit": "s",
             "target": ""}]
