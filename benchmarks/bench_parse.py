"""parse-scene: seconds per 120-frame video (2 threads, the 2 cores) and peak memory, with the shipped weights."""

from __future__ import annotations

from pathlib import Path

from benchmarks.common import measure

SPLIT = "tiny"


def parse(video_path: str, threads: int, filter_kind: str = "single") -> int:
    import torch

    from dynclevr.config import Config
    from dynclevr.perception.collisions import CollisionModel
    from dynclevr.perception.detector_train import load_detector
    from dynclevr.perception.model import ParserModel
    from dynclevr.perception.tracker import parse_video
    from dynclevr.video import Video

    torch.set_num_threads(threads)
    video = Video.read(Path(video_path))
    cfg = Config.load()
    cfg.data["parser"]["filter"] = filter_kind
    scene = parse_video(video.frames(), video.camera, ParserModel.load(), load_detector(), cfg, "bench",
                        CollisionModel.load())
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
    frames = cfg["video"]["frames"]
    return [{"stage": "parse-scene", "metric": f"seconds per {frames}-frame video (2 threads)",
             "value": seconds * 120 / frames, "unit": "s", "target": "<= 15"},
            {"stage": "parse-scene", "metric": "peak memory", "value": peak / 1024, "unit": "GiB", "target": "<= 4"},
            {"stage": "parse-scene, particle filter", "metric": f"seconds per {frames}-frame video (2 threads)",
             "value": particle * 120 / frames, "unit": "s", "target": "<= 15"},
            {"stage": "parse-scene, particle filter", "metric": "peak memory", "value": particle_peak / 1024,
             "unit": "GiB", "target": "<= 4"}]
