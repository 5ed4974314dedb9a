"""Stage annotate: language labels and questions from the truth (paper sections 3.2 and 3.4; REFERENCE.md section 1).

Reads: `sim/<scene>.mcap` (the truth), `video/<scene>.mcap` (its instance masks: what a viewer sees), pipeline.toml
[labels] and [annotate], dynclevr/questions/templates.json.
Writes per scene, one folder per table (each opens as one dataset): `labels/frames/<scene>.parquet` (per object
and frame: velocity class, moving direction, accelerating, floating, pixels in view; "ambiguous" where no question is
asked), `labels/events/<scene>.parquet` (merged collision events: observed with the visible gap between the pair,
future, counterfactual, grazes), `labels/candidates/<scene>.parquet` (every candidate question with its program, the
answer the executor gives on the truth, and for counterfactuals the answer of copying the video's outcome) and
`labels/dropped/<scene>.parquet` (candidates not asked, per family and reason). Split level: `questions.parquet`,
answer-balanced per family (id, scene, type, subtype, family, text, program, answer, factual).

Questions are asked only about what the video shows: objects with at least `labels.min_visible_pixels` pixels in the
frames a question is about, collisions both of whose vehicles are seen, no pair that only grazes.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np
import pyarrow as pa

from dynclevr.artifacts import Store, file_digest, read_parquet, write_parquet
from dynclevr.config import Config
from dynclevr.pipeline import SceneJob, Stage
from dynclevr.questions.evidence import mask_gap, mesh_gap, pixel_counts
from dynclevr.questions.generate import TEMPLATES_PATH, check_annotate_cfg, family_names, scene_candidates, select
from dynclevr.questions.labels import compute_labels, future_events, merge_events
from dynclevr.questions.tables import (CANDIDATES_OUT, DROPPED, DROPPED_OUT, DROPPED_SCHEMA, DROPPED_VERSION, EVENTS,
                                       EVENTS_OUT, EVENTS_SCHEMA, EVENTS_VERSION, FRAMES_OUT, LABELS, LABELS_SCHEMA,
                                       LABELS_VERSION, QUESTIONS_SCHEMA, QUESTIONS_VERSION, read_questions,
                                       write_questions)
from dynclevr.scene import Scene4D
from dynclevr.video import Video

VERSION = 4   # 2: visibility from the masks, grazes, the predictive margin, counterfactual balance; 3: the phrasing
#   grammar and the paper's missing families; 4: one folder per table, scene columns, nulls
QUESTIONS_FILE = "questions.parquet"
# questions.parquet's schema, for its readers (answer, report, the question parser's training)
__all__ = ["STAGE", "QUESTIONS_FILE", "QUESTIONS_SCHEMA", "QUESTIONS_VERSION", "stats"]


def _events_table(scene: Scene4D, merge: int, masks: np.ndarray) -> pa.Table:
    runs = [("observed", None, None, merge_events(scene.collisions, merge)),
            ("future", None, None, future_events(scene, merge)),
            ("graze", None, None, merge_events(scene.grazes, merge))]
    runs += [("counterfactual", oid, iv, merge_events(ev, merge))
             for (oid, iv), ev in sorted(scene.counterfactuals.items())]
    rows = []
    for kind, target, iv, events in runs:
        for e in events:
            seen = kind == "observed"
            rows.append({"scene": scene.name, "kind": kind, "target": target, "intervention": iv, "frame": e.frame,
                         "a": e.a, "b": e.b, "gap_m": mesh_gap(scene, e) if seen else None,
                         "gap_px": mask_gap(masks[e.frame], e.a, e.b) if seen else None})
    return pa.Table.from_pylist(rows, schema=EVENTS)


def run_scene(job: SceneJob) -> None:
    cfg = job.cfg
    scene = Scene4D.read(job.inputs["simulate"][0])
    masks = Video.read(job.inputs["render"][0]).masks()
    labels_path, events_path, questions_path, dropped_path = job.outputs
    labels = compute_labels(scene, cfg["labels"])
    pixels = pixel_counts(masks, [o.id for o in scene.objects])
    rows = {**labels.rows(), "pixels": pixels.ravel().tolist()}   # rows are frame-major, like pixels
    rows["scene"] = [job.scene] * len(rows["pixels"])
    write_parquet(pa.Table.from_pydict(rows, schema=LABELS), labels_path, LABELS_SCHEMA, LABELS_VERSION)
    write_parquet(_events_table(scene, cfg["labels"]["collision_merge_frames"], masks), events_path, EVENTS_SCHEMA,
                  EVENTS_VERSION)
    seen = (pixels >= cfg["labels"]["min_visible_pixels"]) & scene.visible
    candidates, dropped = scene_candidates(scene, cfg["labels"], job.seed, seen,
                                           check_annotate_cfg(cfg["annotate"])["phrasings"])
    write_questions(candidates, questions_path)
    write_parquet(pa.Table.from_pylist([{"scene": job.scene, "family": f, "reason": r, "count": n}
                                        for (f, r), n in sorted(dropped.items())], schema=DROPPED),
                  dropped_path, DROPPED_SCHEMA, DROPPED_VERSION)


def finalize(store: Store, cfg: Config, scenes: list[str]) -> list[Path]:
    candidates = {s: read_questions(store.path("annotate", s, CANDIDATES_OUT)) for s in scenes}
    path = store.split_file(QUESTIONS_FILE)
    write_questions(select(candidates, cfg["annotate"], cfg.split(store.split).seed), path)
    return [path]


STAGE = Stage(
    name="annotate",
    version=VERSION,
    inputs=("simulate", "render"),
    params=lambda cfg: cfg.digest("labels", "annotate"),
    outputs=(FRAMES_OUT, EVENTS_OUT, CANDIDATES_OUT, DROPPED_OUT),
    # The layout of versions before 4: four tables side by side in labels/ (a rerun removes them).
    retired=("*.parquet",),
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
    out += [_table(["family", "type", "questions", "majority answer", "answers"], rows), ""]
    scenes = [s for s in cfg.split(store.split).scene_names() if store.path("annotate", s, EVENTS_OUT).exists()]
    return "\n".join(out + _truth_audit(store, cfg, scenes, qs))


def _share(x) -> str:
    return f"{np.mean(x):.0%}" if len(x) else "-"


def _truth_audit(store: Store, cfg: Config, scenes: list[str], qs: list[dict]) -> list[str]:
    """How far the truth agrees with what a viewer sees, and how much reasoning the questions need."""
    events = [read_parquet(store.path("annotate", s, EVENTS_OUT), EVENTS_SCHEMA, EVENTS_VERSION).to_pylist()
              for s in scenes]
    observed = [e for ev in events for e in ev if e["kind"] == "observed"]
    gm = np.array([e["gap_m"] for e in observed], float)
    gp = np.array([e["gap_px"] for e in observed], float)
    gp = gp[np.isfinite(gp)]
    out = ["### Contacts at collision events (visual meshes and rendered masks at the event frame)", ""]
    if len(gm):
        out += [_table(["events", "gap median", "gap p90", "gap > 10 cm", "gap > 25 cm", "both in frame",
                        "mask gap median", "masks > 1 px apart", "masks > 2 px apart"],
                       [[len(gm), f"{np.median(gm):.3f} m", f"{np.quantile(gm, 0.9):.3f} m", _share(gm > 0.1),
                         _share(gm > 0.25), len(gp), f"{np.median(gp):.1f} px" if len(gp) else "-",
                         _share(gp > 1), _share(gp > 2)]]), ""]
    grazes = sum(e["kind"] == "graze" for ev in events for e in ev)
    observed_frames = cfg["video"]["observed_frames"]
    margin = np.array([e["frame"] - observed_frames for ev in events for e in ev if e["kind"] == "future"])
    within = cfg["labels"]["predict_margin"]
    out += [f"Grazes (touches too gentle to be collisions; no collision question about the pair): {grazes}. "
            f"Future collisions: {len(margin)}, frames after the cut median "
            f"{np.median(margin) if len(margin) else '-'}; {int((margin < within).sum())} start within "
            f"`labels.predict_margin` = {within} frames of it and are never asked about.", ""]
    cf = [q for q in qs if q["type"] == "counterfactual"]
    fams = sorted({q["family"] for q in cf})
    cands = [q for s in scenes for q in read_questions(store.path("annotate", s, CANDIDATES_OUT))
             if q["type"] == "counterfactual"]
    rows = [[f, sum(q["family"] == f for q in cf),
             _share([q["factual"] == q["answer"] for q in cf if q["family"] == f]),
             _share([q["factual"] == q["answer"] for q in cands if q["family"] == f])] for f in fams]
    out += ["### Counterfactuals: accuracy of copying the video's own outcome (`annotate.max_copy_share` = "
            f"{cfg['annotate']['max_copy_share']})", "",
            _table(["family", "questions", "copy-factual accuracy", "before balancing (all candidates)"], rows), ""]
    dropped = Counter()
    for s in scenes:
        for r in read_parquet(store.path("annotate", s, DROPPED_OUT), DROPPED_SCHEMA,
                              DROPPED_VERSION).to_pylist():
            dropped[r["reason"]] += r["count"]
    out += ["### Candidate questions dropped, per reason", "",
            _table(["reason", "candidates"], [[r, n] for r, n in dropped.most_common()])]
    return out
