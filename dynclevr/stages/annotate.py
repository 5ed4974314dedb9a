"""Stage annotate: language labels and questions from the truth (paper sections 3.2 and 3.4; REFERENCE.md section 1).

Reads: `sim/<scene>.mcap` (the truth), pipeline.toml [labels] and [annotate], dynclevr/questions/templates.json.
Writes per scene: `labels/<scene>.parquet` (per object and frame: velocity class, moving direction, accelerating,
floating; "ambiguous" where no question is asked), `labels/<scene>.events.parquet` (merged collision events: observed,
future, counterfactual) and `labels/<scene>.questions.parquet` (every candidate question with its program and the
answer the executor gives on the truth). Split level: `questions.parquet`, answer-balanced per family
(id, scene, type, subtype, family, text, program, answer).
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pyarrow as pa

from dynclevr.artifacts import Store, file_digest, write_parquet
from dynclevr.config import Config
from dynclevr.pipeline import SceneJob, Stage
from dynclevr.questions.generate import TEMPLATES_PATH, family_names, scene_candidates, select
from dynclevr.questions.labels import compute_labels, future_events, merge_events
from dynclevr.questions.tables import (EVENTS, EVENTS_SCHEMA, EVENTS_VERSION, LABELS, LABELS_SCHEMA, LABELS_VERSION,
                                       QUESTIONS_SCHEMA, QUESTIONS_VERSION, read_questions, write_questions)
from dynclevr.scene import Scene4D

VERSION = 1
QUESTIONS_FILE = "questions.parquet"
# questions.parquet's schema, for its readers (answer, report, the question parser's training)
__all__ = ["STAGE", "QUESTIONS_FILE", "QUESTIONS_SCHEMA", "QUESTIONS_VERSION", "stats"]


def _events_table(scene: Scene4D, merge: int) -> pa.Table:
    runs = [("observed", -1, "", merge_events(scene.collisions, merge)),
            ("future", -1, "", future_events(scene, merge))]
    runs += [("counterfactual", oid, iv, merge_events(ev, merge))
             for (oid, iv), ev in sorted(scene.counterfactuals.items())]
    rows = [{"kind": kind, "target": target, "intervention": iv, "frame": e.frame, "a": e.a, "b": e.b}
            for kind, target, iv, events in runs for e in events]
    return pa.Table.from_pylist(rows, schema=EVENTS)


def run_scene(job: SceneJob) -> None:
    cfg = job.cfg
    scene = Scene4D.read(job.inputs["simulate"][0])
    labels_path, events_path, questions_path = job.outputs
    labels = compute_labels(scene, cfg["labels"])
    write_parquet(pa.Table.from_pydict(labels.rows(), schema=LABELS), labels_path, LABELS_SCHEMA, LABELS_VERSION)
    write_parquet(_events_table(scene, cfg["labels"]["collision_merge_frames"]), events_path, EVENTS_SCHEMA,
                  EVENTS_VERSION)
    write_questions(scene_candidates(scene, cfg["labels"], job.seed), questions_path)


def finalize(store: Store, cfg: Config, scenes: list[str]) -> list[Path]:
    candidates = {s: read_questions(store.path("annotate", s, ".questions.parquet")) for s in scenes}
    path = store.split_file(QUESTIONS_FILE)
    write_questions(select(candidates, cfg["annotate"], cfg.split(store.split).seed), path)
    return [path]


STAGE = Stage(
    name="annotate",
    version=VERSION,
    inputs=("simulate",),
    params=lambda cfg: cfg.digest("labels", "annotate"),
    outputs=(".parquet", ".events.parquet", ".questions.parquet"),
    run_scene=run_scene,
    finalize=finalize,
    extra_inputs=lambda store, cfg: {"templates": file_digest(TEMPLATES_PATH)},
)


# ---- dataset statistics -------------------------------------------------------------------------------------------

def _table(header: list[str], rows: list[list]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    return "\n".join(lines + ["| " + " | ".join(str(c) for c in r) + " |" for r in rows])


def stats(store: Store, cfg: Config) -> str:
    """Markdown: counts per type / subtype / family, per-video density, answer distribution and majority rate."""
    qs = read_questions(store.split_file(QUESTIONS_FILE))
    n_scenes = cfg.split(store.split).scenes
    out = [f"## Questions: split {store.split} ({len(qs)} questions, {n_scenes} videos)", ""]
    by_type = Counter(q["type"] for q in qs)
    paper = {"factual": 7850 / 1200, "predictive": 2750 / 1200, "counterfactual": 989 / 1200}
    out += [_table(["type", "questions", "per video", "paper per video"],
                   [[t, by_type[t], f"{by_type[t] / n_scenes:.2f}", f"{paper[t]:.2f}"] for t in paper]), ""]
    by_sub = Counter((q["type"], q["subtype"]) for q in qs)
    out += [_table(["type", "subtype", "questions"], [[t, s, n] for (t, s), n in sorted(by_sub.items())]), ""]
    fams = Counter(q["family"] for q in qs)
    rows = []
    for fam in family_names():
        answers = Counter(q["answer"] for q in qs if q["family"] == fam)
        n = fams[fam]
        kind = next((q["type"] for q in qs if q["family"] == fam), "-")
        dist = ", ".join(f"{a} {c / n:.0%}" for a, c in answers.most_common()) if n else "-"
        majority = f"{answers.most_common(1)[0][1] / n:.0%}" if n else "-"
        rows.append([fam, kind, n, majority, dist])
    out += [_table(["family", "type", "questions", "majority answer", "answers"], rows)]
    return "\n".join(out)
