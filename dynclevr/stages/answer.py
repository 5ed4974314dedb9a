"""answer: parse each question into a program and execute it on the estimated 4D scene (REFERENCE section 2, 6).

The model side reads only the question's id, scene, type and text; the stored program and answer are read after
all predictions are written, by `finalize`, to score them.
"""

from __future__ import annotations

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

ANSWERS_SCHEMA = "dynclevr.answers"
ANSWERS_VERSION = 1
METRICS_SCHEMA = "dynclevr.metrics"
METRICS_VERSION = 1
MODEL_COLUMNS = ["id", "scene", "type", "text"]   # all the model may read of a question
PREDICTION_FIELDS = pa.schema([("id", pa.string()), ("predicted_program", pa.string()),
                               ("predicted_answer", pa.string()), ("status", pa.string())])
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
            out.append({"id": q["id"], "predicted_program": "", "predicted_answer": "", "status": UNPARSED})
            continue
        try:
            answer, status = executor.run(program), "ok"
        except DynclevrError:  # no unique object, wrong types, an ambiguous label: the question counts as wrong
            answer, status = "", FAILED
        out.append({"id": q["id"], "predicted_program": " ".join(program), "predicted_answer": answer,
                    "status": status})
    return out


def run_scene(job: SceneJob) -> None:
    table = read_parquet(job.store.split_file("questions.parquet"), QUESTIONS_SCHEMA, QUESTIONS_VERSION,
                         columns=MODEL_COLUMNS)
    questions = [q for q in table.to_pylist() if q["scene"] == job.scene]
    scene = attach(Scene4D.read(job.inputs["parse-scene"][0]), job.inputs["simulate-future"][0])
    rows = predict(questions, scene, job.cfg["labels"])
    write_parquet(pa.Table.from_pylist(rows, schema=PREDICTION_FIELDS), job.outputs[0], ANSWERS_SCHEMA,
                  ANSWERS_VERSION)


def _scores(store, scenes: list[str]) -> list[dict]:
    truth = {q["id"]: q for q in read_parquet(store.split_file("questions.parquet"), QUESTIONS_SCHEMA,
                                              QUESTIONS_VERSION).to_pylist()}
    rows = []
    for scene in scenes:
        for p in read_parquet(store.path("answer", scene, ".parquet"), ANSWERS_SCHEMA, ANSWERS_VERSION).to_pylist():
            q = truth[p["id"]]
            rows.append({**p, "scene": scene, "type": q["type"], "subtype": q["subtype"], "family": q["family"],
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
    answers = store.stage_dir("answer") / "answers.parquet"
    write_parquet(pa.Table.from_pylist(rows), answers, ANSWERS_SCHEMA, ANSWERS_VERSION)
    metrics = [{"column": k, "accuracy": a, "questions": n} for k, (a, n) in table1(rows).items()]
    matched = sum(r["program_match"] for r in rows)
    metrics.append({"column": "Program exact match", "accuracy": 100.0 * matched / max(len(rows), 1),
                    "questions": len(rows)})
    metrics.append({"column": "Unparsed", "accuracy": 100.0 * sum(r["status"] == UNPARSED for r in rows)
                    / max(len(rows), 1), "questions": len(rows)})
    path = store.stage_dir("answer") / "metrics.parquet"
    write_parquet(pa.Table.from_pylist(metrics), path, METRICS_SCHEMA, METRICS_VERSION)
    return [answers, path]


def _extra(store, cfg) -> dict[str, str]:
    # The parser's weights themselves, not their manifest nor the blind baseline beside them (the report's): a
    # retrain that gives the same bytes reruns nothing.
    q = store.split_file("questions.parquet")
    weights = sorted(p for p in (WEIGHTS_DIR / "qparser").glob("*") if p.name not in ("manifest.json", "blind.json"))
    return {"questions": file_digest(q) if q.exists() else "missing",
            **{f"qparser/{p.name}": file_digest(p) for p in weights}}


STAGE = Stage("answer", 3, inputs=("parse-scene", "simulate-future"), params=lambda cfg: cfg.digest("labels"),
              outputs=(".parquet",), run_scene=run_scene, finalize=finalize, extra_inputs=_extra)
