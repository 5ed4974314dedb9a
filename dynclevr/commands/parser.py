"""`dynclevr eval-parser --split S`: the scene parser against the truth, with and without the physics prior."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Optional

import typer

REPORT = "parser_eval.md"


def register(app: typer.Typer) -> None:
    from dynclevr.cli import ConfigOpt, DataOpt, ScenesOpt, SplitOpt, WorkersOpt

    @app.command("eval-parser")
    def eval_parser(split: Optional[str] = SplitOpt, scenes: Optional[str] = ScenesOpt,
                    config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt, workers: int = WorkersOpt):
        """Detection, identity, position, dynamics, collision and predicted-future metrics of parsed/ and future/
        (and parsed-noprior/, parsed-particle/, parsed-refine/: the detection head with render-and-compare) against
        sim/; runs simulate, render, parse-scene and simulate-future first where they are not cached. Then, for
        the first model, the predicted future re-simulated with parts of the cut state from the truth (which part
        carries the prediction's error). Writes <split>/parser_eval.md (with the first model's 95% intervals, its videos
        resampled: `report.bootstrap_resamples`) and the sub-type confusion PNG."""
        from dynclevr.artifacts import write_json_atomic
        from dynclevr.cli import load_config
        from dynclevr.perception.evaluate import (attribution_markdown, confusion_png, cut_attribution, intervals,
                                                  markdown, scene_stats, summarise)
        from dynclevr.physics import PhysicsParams
        from dynclevr.questions.evidence import pixel_counts
        from dynclevr.video import Video
        from dynclevr.config import Config
        from dynclevr.pipeline import Runner, model_configs, parse_scenes
        from dynclevr.scene import Scene4D
        from dynclevr.stages.simulate_future import Ensemble, attach

        results, pixels, spans = {}, {}, None
        base = load_config(config)
        variants = model_configs(base)
        if not base["parser"]["refine"]:   # (the default already refines: the first row is this one)
            refine = copy.deepcopy(base.data)
            refine["parser"]["refine"] = True
            variants.append(("with render-and-compare", Config(refine)))
        for name, cfg in variants:
            r = Runner(cfg, cfg.split(split), data_dir, workers, echo=typer.echo)
            indices = parse_scenes(scenes, r.split)
            for stage in ("simulate", "render", "parse-scene", "simulate-future"):
                r.run(stage, indices)
            stats, attribution = [], []
            first = name == variants[0][0]
            for i in indices:
                scene = r.split.scene_names()[i]
                est = attach(Scene4D.read(r.store.path("parse-scene", scene, ".mcap")),
                             r.store.path("simulate-future", scene, ".parquet"))
                truth = Scene4D.read(r.store.path("simulate", scene, ".mcap"))
                if scene not in pixels:
                    masks = Video.read(r.store.path("render", scene, ".mcap")).masks()
                    pixels[scene] = pixel_counts(masks, [o.id for o in truth.objects])
                stats.append(scene_stats(truth, est, cfg["labels"], future=True, pixels=pixels[scene]))
                if first:
                    attribution.append(cut_attribution(truth, est, cfg["labels"], PhysicsParams.from_config(cfg),
                                                       Ensemble.from_config(cfg)))
            results[name] = summarise(stats)
            if first:
                confusion_png(stats, r.store.split_file("parser_confusion.png"))
                where = attribution_markdown(attribution)
                if cfg["report"]["bootstrap_resamples"]:
                    spans = intervals(stats, cfg["report"]["bootstrap_resamples"], cfg["report"]["bootstrap_seed"])
        table = markdown(results, spans)
        out = r.store.split_file(REPORT)
        out.write_text(f"# Scene parser on split {r.split.name} ({len(indices)} scenes)\n\n"
                       f"`dynclevr eval-parser --split {r.split.name}"
                       f"{f' --scenes {scenes}' if scenes else ''}{f' --config {config}' if config else ''}`\n\n{table}\n"
                       f"Where {variants[0][0]}'s predicted future collision pairs go wrong: the future re-simulated "
                       f"with parts of the matched objects' cut state put in from the truth\n\n{where}")
        write_json_atomic(out.with_suffix(".json"), results)
        typer.echo(table)
        typer.echo(where)
        typer.echo(f"written to {out}")
