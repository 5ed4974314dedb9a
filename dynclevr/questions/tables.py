"""The Arrow schemas of the annotate stage's tables, with their names and versions (the one place they are defined).

One folder per table, so that each folder opens as one dataset (duckdb 'labels/events/*.parquet', polars, pandas);
every per-scene table has a `scene` column, and a value that does not apply is null:
- labels/frames/<scene>.parquet      dynclevr.labels: one row per (frame, object); "ambiguous" where no question is asked
- labels/events/<scene>.parquet      dynclevr.events: merged collision events: observed, future, counterfactual
- labels/candidates/<scene>.parquet  dynclevr.questions: every candidate question of the scene (before balancing)
- labels/dropped/<scene>.parquet     dynclevr.dropped: candidate questions not asked, per family and reason
- questions.parquet (split level)    dynclevr.questions: the balanced questions, with ids "<scene>-<k>"
"""

from __future__ import annotations

from pathlib import Path

import pyarrow as pa

from dynclevr.artifacts import read_parquet, write_parquet

# Output suffixes of the annotate stage (artifacts.Store.path): one folder per table.
FRAMES_OUT, EVENTS_OUT, CANDIDATES_OUT, DROPPED_OUT = ("frames/.parquet", "events/.parquet", "candidates/.parquet",
                                                       "dropped/.parquet")

LABELS_SCHEMA, LABELS_VERSION = "dynclevr.labels", 3   # 3: own folder, scene column
LABELS = pa.schema([
    ("scene", pa.string()), ("frame", pa.int32()), ("object", pa.int32()), ("speed", pa.float32()),
    ("velocity", pa.string()),        # static / slow / fast / ambiguous
    ("direction", pa.string()),       # front / back / left / right / up / down / ambiguous
    ("accel", pa.float32()),          # d|horizontal velocity|/dt, m/s^2
    ("accelerating", pa.string()),    # true / false / ambiguous
    ("floating", pa.string()),        # true / false / ambiguous
    ("pixels", pa.int32()),           # the object's pixels in the rendered frame (visible: labels.min_visible_pixels)
])

EVENTS_SCHEMA, EVENTS_VERSION = "dynclevr.events", 3   # 3: own folder, scene column, nulls
EVENTS = pa.schema([
    ("scene", pa.string()),
    ("kind", pa.string()),            # observed / future / counterfactual / graze (a touch too gentle to collide)
    ("target", pa.int32()),           # counterfactual: the changed object; else null
    ("intervention", pa.string()),    # counterfactual: static / slow / fast / accelerating / floating; else null
    ("frame", pa.int32()), ("a", pa.int32()), ("b", pa.int32()),
    ("gap_m", pa.float32()),          # observed: metres between the two visual meshes at the frame; else null
    ("gap_px", pa.float32()),         # observed: pixels between the two masks (0: touching; inf: one out of frame);
                                      # else null
])

DROPPED_SCHEMA, DROPPED_VERSION = "dynclevr.dropped", 2   # 2: own folder, scene column
DROPPED = pa.schema([("scene", pa.string()), ("family", pa.string()), ("reason", pa.string()), ("count", pa.int32())])

QUESTIONS_SCHEMA, QUESTIONS_VERSION = "dynclevr.questions", 3   # 3: nulls for id (candidates) and factual
QUESTION_FIELDS = [
    ("id", pa.string()),              # "<scene>-<k>"; null in the per-scene candidates
    ("scene", pa.string()),
    ("type", pa.string()),            # factual / predictive / counterfactual
    ("subtype", pa.string()),         # velocity / acceleration / collision
    ("family", pa.string()),          # a family name of templates.json
    ("text", pa.string()),
    ("program", pa.string()),         # postfix tokens, space-separated (dynclevr/questions/programs.py)
    ("answer", pa.string()),
    ("factual", pa.string()),         # counterfactual: the answer of copying the video's own outcome; else null
]
QUESTIONS = pa.schema(QUESTION_FIELDS)


def write_questions(rows: list[dict], path: Path) -> None:
    table = pa.Table.from_pylist([{k: r.get(k) for k, _ in QUESTION_FIELDS} for r in rows], schema=QUESTIONS)
    write_parquet(table, path, QUESTIONS_SCHEMA, QUESTIONS_VERSION)


def read_questions(path: Path) -> list[dict]:
    """questions.parquet (or a scene's candidates) as rows; a stale version fails naming the stage to rerun."""
    return read_parquet(path, QUESTIONS_SCHEMA, QUESTIONS_VERSION).to_pylist()
