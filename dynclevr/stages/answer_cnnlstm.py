"""answer-cnnlstm: the CNN+LSTM baseline of Table 1 answers each question from the video and the question text
(baselines/cnnlstm.py; weights/cnnlstm/, `dynclevr train cnnlstm`).

Reads: `video/<scene>.mcap` through `Video.frames()` only (RGB frames), and of questions.parquet the columns
answer.MODEL_COLUMNS (id, scene, type, text; the type only to show a predictive question the observed frames alone).
Writes `answers-cnnlstm/<scene>.parquet` (the predictions, in the answer stage's schema, with no program) and, split
level, `answers-cnnlstm.parquet` and `metrics-cnnlstm.parquet`, scored by `finalize` after every prediction is
written, as the answer stage does.
"""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

import pyarrow as pa

from dynclevr.artifacts import Store, file_digest, read_parquet, write_parquet
from dynclevr.baselines import cnnlstm
from dynclevr.pipeline import SceneJob, Stage
from dynclevr.stages import answer
from dynclevr.stages.annotate import QUESTIONS_SCHEMA, QUESTIONS_VERSION

NAME, VARIANT = "answer-cnnlstm", "cnnlstm"   # Store(variant=VARIANT).model_file: answers-cnnlstm.parquet


@lru_cache(maxsize=1)
def _model() -> cnnlstm.CnnLstmModel:
    return cnnlstm.CnnLstmModel.load(cnnlstm.DEFAULT_DIR)


def run_scene(job: SceneJob) -> None:
    import torch

    torch.set_num_threads(1)   # the runner's process pool is the parallelism
    table = read_parquet(job.store.split_file("questions.parquet"), QUESTIONS_SCHEMA, QUESTIONS_VERSION,
                         columns=answer.MODEL_COLUMNS)
    questions = [q for q in table.to_pylist() if q["scene"] == job.scene]
    model = _model()
    clips = cnnlstm.video_clips(job.inputs["render"][0], model.p, int(job.cfg["video"]["observed_frames"]))
    rows = [{"scene": q["scene"], "id": q["id"], "predicted_program": None, "predicted_answer": a, "status": "ok"}
            for q, a in zip(questions, model.answer(clips, questions))]
    write_parquet(pa.Table.from_pylist(rows, schema=answer.PREDICTIONS), job.outputs[0], answer.PREDICTIONS_SCHEMA,
                  answer.PREDICTIONS_VERSION)


def finalize(store: Store, cfg, scenes: list[str]) -> list[Path]:
    truth = {q["id"]: q for q in read_parquet(store.split_file("questions.parquet"), QUESTIONS_SCHEMA,
                                              QUESTIONS_VERSION).to_pylist()}
    rows = []
    for scene in scenes:
        for p in read_parquet(store.path(NAME, scene, ".parquet"), answer.PREDICTIONS_SCHEMA,
                              answer.PREDICTIONS_VERSION).to_pylist():
            q = truth[p["id"]]
            rows.append({**p, "type": q["type"], "subtype": q["subtype"], "family": q["family"], "answer": q["answer"],
                         "correct": p["predicted_answer"] == q["answer"], "program_match": False})
    out = Store(store.data_dir, store.split, VARIANT)
    answers = out.model_file(answer.ANSWERS_FILE)
    write_parquet(pa.Table.from_pylist(rows, schema=answer.ANSWERS), answers, answer.ANSWERS_SCHEMA,
                  answer.ANSWERS_VERSION)
    metrics = [{"column": k, "accuracy": None if math.isnan(a) else a, "questions": n}
               for k, (a, n) in answer.table1(rows).items()]
    path = out.model_file(answer.METRICS_FILE)
    write_parquet(pa.Table.from_pylist(metrics, schema=answer.METRICS), path, answer.METRICS_SCHEMA,
                  answer.METRICS_VERSION)
    return [answers, path]


def _extra(store: Store, cfg) -> dict[str, str]:
    q = store.split_file("questions.parquet")
    return {"questions": file_digest(q) if q.exists() else "missing", "weights": cnnlstm.weights_digest()}


STAGE = Stage(NAME, 1, inputs=("render",), params=lambda cfg: cfg.digest("video"), outputs=(".parquet",),
              run_scene=run_scene, finalize=finalize, extra_inputs=_extra)
