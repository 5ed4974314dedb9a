"""simulate-future and answer: seconds per scene and peak memory.

Their inputs are estimated scenes; the truth scenes of a freshly simulated split stand in for them here (the same
object counts and lengths), so the bench needs no parser run. Question parsing uses the shipped weights."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from benchmarks.common import measure

SCENES = 6


def _split(workdir: str):
    from dynclevr.config import Config
    from dynclevr.pipeline import Runner

    Path(workdir).mkdir(parents=True, exist_ok=True)
    path = Path(workdir) / "bench.toml"
    path.write_text(f"[splits.bench]\nseed = 11\nscenes = {SCENES}\n")
    cfg = Config.load(path)
    runner = Runner(cfg, cfg.split("bench"), Path(workdir) / "data", echo=lambda *_: None)
    for stage in ("simulate", "render", "annotate"):   # annotate reads the rendered masks (visibility)
        runner.run(stage, list(range(SCENES)))
    return cfg, runner.store


def future(workdir: str) -> dict:
    from dynclevr.physics import PhysicsParams
    from dynclevr.scene import Scene4D
    from dynclevr.stages.simulate_future import Ensemble, predict

    cfg, store = _split(workdir)
    scenes = [Scene4D.read(store.path("simulate", f"{i:06d}", ".mcap")) for i in range(SCENES)]
    params, ensemble = PhysicsParams.from_config(cfg), Ensemble.from_config(cfg)
    rng = np.random.default_rng(0)
    start = time.perf_counter()
    runs = sum(ensemble.samples + len(predict(s, params, True, ensemble, rng)[1]) for s in scenes)
    return {"per_scene": (time.perf_counter() - start) / SCENES, "runs": runs / SCENES}


def answer(workdir: str) -> dict:
    from dynclevr.artifacts import read_parquet
    from dynclevr.scene import Scene4D
    from dynclevr.stages.annotate import QUESTIONS_SCHEMA, QUESTIONS_VERSION
    from dynclevr.stages.answer import MODEL_COLUMNS, predict, question_parser

    cfg, store = _split(workdir)
    questions = read_parquet(store.split_file("questions.parquet"), QUESTIONS_SCHEMA, QUESTIONS_VERSION,
                             columns=MODEL_COLUMNS).to_pylist()
    scenes = {f"{i:06d}": Scene4D.read(store.path("simulate", f"{i:06d}", ".mcap")) for i in range(SCENES)}
    question_parser()  # loading the weights is once per process
    start = time.perf_counter()
    for name, scene in scenes.items():
        predict([q for q in questions if q["scene"] == name], scene, cfg["labels"])
    return {"per_scene": (time.perf_counter() - start) / SCENES, "questions": len(questions) / SCENES}


def bench(workdir: Path) -> list[dict]:
    _, peak_f, f = measure("benchmarks.bench_model.future", str(workdir / "f"))
    _, peak_a, a = measure("benchmarks.bench_model.answer", str(workdir / "a"))
    return [
        {"stage": "simulate-future",
         "metric": f"seconds per scene ({f['runs']:.1f} runs: the future's ensemble + counterfactuals)",
         "value": f["per_scene"], "unit": "s"},
        {"stage": "simulate-future", "metric": "peak memory", "value": peak_f, "unit": "MiB"},
        {"stage": "answer", "metric": f"seconds per scene ({a['questions']:.1f} questions: parse + execute)",
         "value": a["per_scene"], "unit": "s"},
        {"stage": "answer", "metric": "peak memory", "value": peak_a, "unit": "MiB"},
    ]
