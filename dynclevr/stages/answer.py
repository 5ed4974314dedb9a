"""answer: parse each question into a program and execute it on the estimated 4D scene (REFERENCE section 2, 6).

The model side reads only the question's id, scene, type and text; the stored program and answer are read after
all predictions are written, by `finalize`, to score them.

Writes `answers/<scene>.parquet` (the predictions) and, split level beside questions.parquet, `answers.parquet`
(every prediction scored) and `metrics.parquet` (the Table 1 columns); a model variant's are answers-noprior/,
answers-noprior.parquet, ... Split-level tables stay out of answers/, so that the folder is one table.
"""

from __future__ import annotations

import hashlib
import math
from functools import lru_cache
from pathlib import Path

import pyarrow as pa

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import file_digest, read_parquet, write_parquet
from dynclevr.pipeline import SceneJob, Stage
from dynclevr.questions.programs import Executor
from dynclevr.scene import Scene4D
from dynclevr.stages.annotate import QUESTIONS_SCHEMA, QUESTIONS_VERSION
from dynclevr.stages.simulate_future import attach

PREDICTIONS_SCHEMA, PREDICTIONS_VERSION = "dynclevr.predictions", 1   # answers/<scene>.parquet
PREDICTION_FIELDS = [
    ("scene", pa.string()), ("id", pa.string()),
    ("predicted_program", pa.string()),   # null: unparsed
    ("predicted_answer", pa.string()),    # null: unparsed, or the program failed
    ("status", pa.string()),              # ok / unparsed / failed
]
PREDICTIONS = pa.schema(PREDICTION_FIELDS)
# answers.parquet: the predictions scored. 2: split level (it was answers/answers.parquet, where v1 per-scene files
# of another schema shared its name)
ANSWERS_SCHEMA, ANSWERS_VERSION = "dynclevr.answers", 2
ANSWERS = pa.schema(PREDICTION_FIELDS + [
    ("type", pa.string()), ("subtype", pa.string()), ("family", pa.string()), ("answer", pa.string()),
    ("correct", pa.bool_()), ("program_match", pa.bool_())])
METRICS_SCHEMA, METRICS_VERSION = "dynclevr.metrics", 2   # 2: split level; null accuracy where no question
METRICS = pa.schema([("column", pa.string()), ("accuracy", pa.float64()), ("questions", pa.int64())])
ANSWERS_FILE, METRICS_FILE = "answers.parquet", "metrics.parquet"   # Store.model_file: answers-noprior.parquet, ...
MODEL_COLUMNS = ["id", "scene", "type", "text"]   # all the model may read of a question
UNPARSED, FAILED = "unparsed", "failed"   # counted wrong


@lru_cache(maxsize=1)
def question_parser():
    from dynclevr.language.parse import QuestionParser

    return QuestionParser.load(WEIGHTS_DIR / "qparser")


def predict(questions: list[dict], scene: Scene4D, labels_cfg: dict) -> list[dict]:
    programs = question_parser().parse_batch([q["text"] for q in questions])
    executor = Executor(scene, labels_cfg)
    out = []
    for q, program in zip(questions, programs):
        if program is None:
            out.append({"scene": q["scene"], "id": q["id"], "predicted_program": None, "predicted_answer": None,
                        "status": UNPARSED})
            continue
        try:
            answer, status = executor.run(program), "ok"
        except DynclevrError:  # no unique object, wrong types, an ambiguous label: the question counts as wrong
            answer, status = None, FAILED
        out.append({"scene": q["scene"], "id": q["id"], "predicted_program": " ".join(program),
                    "predicted_answer": answer, "status": status})
    return out


def run_scene(job: SceneJob) -> None:
    table = read_parquet(job.store.split_file("questions.parquet"), QUESTIONS_SCHEMA, QUESTIONS_VERSION,
                         columns=MODEL_COLUMNS)
    questions = [q for q in table.to_pylist() if q["scene"] == job.scene]
    scene = attach(Scene4D.read(job.inputs["parse-scene"][0]), job.inputs["simulate-future"][0])
    rows = predict(questions, scene, job.cfg["labels"])
    write_parquet(pa.Table.from_pylist(rows, schema=PREDICTIONS), job.outputs[0], PREDICTIONS_SCHEMA,
                  PREDICTIONS_VERSION)


def _scores(store, scenes: list[str]) -> list[dict]:
    truth = {q["id"]: q for q in read_parquet(store.split_file("questions.parquet"), QUESTIONS_SCHEMA,
                                              QUESTIONS_VERSION).to_pylist()}
    rows = []
    for scene in scenes:
        for p in read_parquet(store.path("answer", scene, ".parquet"), PREDICTIONS_SCHEMA,
                              PREDICTIONS_VERSION).to_pylist():
            q = truth[p["id"]]
            rows.append({**p, "type": q["type"], "subtype": q["subtype"], "family": q["family"],
                         "answer": q["answer"], "correct": p["predicted_answer"] == q["answer"],
                         "program_match": p["predicted_program"] == q["program"]})
    return rows


def table1(rows: list[dict], correct=lambda r: r["correct"]) -> dict[str, tuple[float, int]]:
    """The paper's Table 1 columns: accuracy in % and question count. Average = mean of the three types."""
    def acc(sel):
        sel = list(sel)
        return (100.0 * sum(map(correct, sel)) / len(sel) if sel else float("nan"), len(sel))

    fact = [r for r in rows if r["type"] == "factual"]
    cols = {"Factual All": acc(fact)}
    for sub, name in [("velocity", "Vel"), ("acceleration", "Acc"), ("collision", "Col")]:
        cols[name] = acc(r for r in fact if r["subtype"] == sub)
    cols["Predictive"] = acc(r for r in rows if r["type"] == "predictive")
    cols["Counterfactual"] = acc(r for r in rows if r["type"] == "counterfactual")
    three = [cols[k][0] for k in ("Factual All", "Predictive", "Counterfactual")]
    return {"Average": (sum(three) / 3, len(rows)), **cols}


def finalize(store, cfg, scenes: list[str]) -> list[Path]:
    rows = _scores(store, scenes)
    answers = store.model_file(ANSWERS_FILE)
    write_parquet(pa.Table.from_pylist(rows, schema=ANSWERS), answers, ANSWERS_SCHEMA, ANSWERS_VERSION)
    metrics = [{"column": k, "accuracy": a, "questions": n} for k, (a, n) in table1(rows).items()]
    matched = sum(r["program_match"] for r in rows)
    metrics.append({"column": "Program exact match", "accuracy": 100.0 * matched / max(len(rows), 1),
                    "questions": len(rows)})
    metrics.append({"column": "Unparsed", "accuracy": 100.0 * sum(r["status"] == UNPARSED for r in rows)
                    / max(len(rows), 1), "questions": len(rows)})
    for m in metrics:   # a column without questions has no accuracy
        m["accuracy"] = None if math.isnan(m["accuracy"]) else m["accuracy"]
    path = store.model_file(METRICS_FILE)
    write_parquet(pa.Table.from_pylist(metrics, schema=METRICS), path, METRICS_SCHEMA, METRICS_VERSION)
    return [answers, path]


# What reads a question and runs its program: the question parser's rules and lexicons (not the corpora it is only
# evaluated on) and the executor. A change to either reruns the answers; before, a stage version bumped by hand was
# the only guard, and a parser rule could leave a split's answers stale.
READING = sorted([*(p for p in (Path(__file__).parents[1] / "language").glob("*") if p.suffix in (".py", ".txt")
                    and p.name not in ("handwritten.txt", "out_of_scope.txt")),
                  Path(__file__).parents[1] / "questions" / "programs.py"])


def reading_digest() -> str:
    h = hashlib.sha256()
    for p in READING:
        h.update(p.name.encode() + b"\0" + file_digest(p).encode())
    return h.hexdigest()


def _extra(store, cfg) -> dict[str, str]:
    # The parser's weights themselves, not their manifest nor the blind baseline beside them (the report's): a
    # retrain that gives the same bytes reruns nothing.
    q = store.split_file("questions.parquet")
    weights = sorted(p for p in (WEIGHTS_DIR / "qparser").glob("*") if p.name not in ("manifest.json", "blind.json"))
    return {"questions": file_digest(q) if q.exists() else "missing",
            **{f"qparser/{p.name}": file_digest(p) for p in weights}, "reading": reading_digest()}


# 5: the question parser reads a word after a whole object description as the sentence's (language/parse.py);
# 6: a shorter second mention of an object is its first mention's (language/references.py), and of several collision
# partners `unique` takes the first one (questions/programs.py, get_all_col_partners)
STAGE = Stage("answer", 6, inputs=("parse-scene", "simulate-future"), params=lambda cfg: cfg.digest("labels"),
              outputs=(".parquet",), run_scene=run_scene, finalize=finalize, extra_inputs=_extra,
              # Before version 4 the split-level tables lay in answers/ beside the per-scene ones.
              retired=(ANSWERS_FILE, METRICS_FILE))
