"""The paper's Table 1 measured on our data: NS-4DPhysics, its ablation without the physics prior, the particle
filter, the per-frame 3D baseline (PO3D-VQA style) and the CNN+LSTM baseline, the oracle (truth scene + gold
programs), the blind baseline; below them the paper's reported rows for reference. PLLaVA and GPT-4o are the
paper's figures only ("paper, not reproduced"): their weights are not here and this machine has no network. Under the
table, each measured row's 95% interval and those of the differences the ablation is about (dynclevr/uncertainty.py:
a bootstrap over the split's videos, paired between rows), then every measured row's accuracy by question family."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import Store, read_parquet
from dynclevr.config import Config
from dynclevr.pipeline import model_configs, model_variant
from dynclevr.questions.programs import Executor
from dynclevr.scene import Scene4D
from dynclevr.stages.annotate import QUESTIONS_SCHEMA, QUESTIONS_VERSION
from dynclevr.stages.answer import ANSWERS_FILE, ANSWERS_SCHEMA, ANSWERS_VERSION, table1
from dynclevr.uncertainty import bootstrap, interval

COLUMNS = ("Average", "Factual All", "Vel", "Acc", "Col", "Predictive", "Counterfactual")
NOT_REPRODUCED = "paper, not reproduced: "
PAPER = {  # REFERENCE.md section 3 (paper, Table 1, its test split)
    "paper: NS-4DPhysics": (82.64, 87.70, 88.66, 83.73, 88.46, 85.71, 74.51),
    "paper: NS-4DPhysics w/o physics prior": (75.97, 79.68, 81.40, 81.30, 74.88, 78.83, 69.39),
    "paper: PO3D-VQA": (62.93, 61.22, 62.21, 73.17, 51.20, 65.33, 62.24),
    NOT_REPRODUCED + "PLLaVA": (59.24, 54.61, 55.00, 63.80, 46.63, 67.52, 73.47),
    NOT_REPRODUCED + "GPT-4o + reasoning": (56.06, 55.50, 58.81, 57.67, 47.12, 56.93, 58.16),
    "paper: CNN+LSTM": (48.03, 40.63, 41.71, 56.79, 25.37, 56.04, 47.42),
}
CNNLSTM_ROW = "CNN+LSTM"
# A measured row -> the paper's row of the same model (the chart sets them side by side).
PAPER_OF = {"NS-4DPhysics (ours)": "paper: NS-4DPhysics", "ours without physics prior":
            "paper: NS-4DPhysics w/o physics prior", "per-frame 3D, PO3D-VQA style": "paper: PO3D-VQA",
            CNNLSTM_ROW: "paper: CNN+LSTM"}
OURS = "NS-4DPhysics (ours)"
# build()'s extra entries that markdown() lays out itself; the rest are notes, one line each
LAID_OUT = ("counts", "questions", "videos", "intervals", "differences", "resamples", "families")
# The differences the ablation is about: (label, row, row it is compared with), where both rows ran.
DIFFERENCES = (("the physics prior's gain: ours minus ours without the prior", OURS, "ours without physics prior"),
               ("the particle filter minus the single-particle prior (ours)", "ours with the particle filter", OURS),
               ("ours minus the per-frame 3D baseline", OURS, "per-frame 3D, PO3D-VQA style"))


def _answers(store: Store, variant: str) -> list[dict] | None:
    path = Store(store.data_dir, store.split, variant).model_file(ANSWERS_FILE)
    return read_parquet(path, ANSWERS_SCHEMA, ANSWERS_VERSION).to_pylist() if path.exists() else None


def stale_answers(cfg: Config, store: Store, answers: list[dict], questions: list[dict],
                  stage: str = "answer") -> str | None:
    """Why a model row's answers are not those of the current questions and parses (None: they are). The answer
    stage's cache keys know: a scene is stale when its questions, its parse or its future changed since it ran."""
    from dynclevr.pipeline import Runner

    status = Runner(cfg, cfg.split(store.split), store.data_dir, echo=lambda *a: None).status(stage)
    if status["stale"] or status["missing"]:
        return (f"{stage} is stale for {len(status['stale'])} and has not run for {len(status['missing'])} of "
                f"{len(cfg.split(store.split).scene_names())} scenes")
    if {a["id"] for a in answers} != {q["id"] for q in questions}:
        return "answers.parquet does not cover the current questions.parquet"
    return None


def oracle_rows(store: Store, cfg: Config, questions: list[dict]) -> list[dict]:
    """Gold programs on the truth scenes: checks the executor and the generator agree (must be 100%)."""
    executors: dict[str, Executor] = {}
    rows = []
    for q in questions:
        if q["scene"] not in executors:
            truth = Scene4D.read(store.path("simulate", q["scene"], ".mcap"))
            executors[q["scene"]] = Executor(truth, cfg["labels"])
        try:
            ok = executors[q["scene"]].run(q["program"]) == q["answer"]
        except DynclevrError:
            ok = False
        rows.append({**q, "correct": ok})
    return rows


def blind_rows(questions: list[dict]) -> list[dict] | None:
    path = WEIGHTS_DIR / "qparser" / "blind.json"
    if not path.exists():
        return None
    majority = json.loads(path.read_text())["majority"]
    return [{**q, "correct": majority.get(q["family"]) == q["answer"]} for q in questions]


def build(store: Store, cfg: Config, rerun: str = "") -> tuple[dict[str, tuple], dict]:
    """The table's rows and notes. A model row is computed only from answers of the current questions and parses:
    otherwise one error naming what is stale and `rerun`, the command that fixes it. A model variant never run
    (`run --no-ablation`) is left out with a note; the main model must have run."""
    questions = read_parquet(store.split_file("questions.parquet"), QUESTIONS_SCHEMA, QUESTIONS_VERSION).to_pylist()
    rows: dict[str, tuple] = {}
    measured: dict[str, list[dict]] = {}   # each measured row's answers, for the intervals
    extra = {"questions": len(questions), "videos": len({q["scene"] for q in questions})}
    for k, (name, model_cfg) in enumerate(model_configs(cfg)):
        answers = _answers(store, model_variant(model_cfg))
        if answers is None and k == 0:
            raise DynclevrError(f"no answers of split {store.split} yet: run `{rerun}`")
        if answers is None:
            extra[f"{name}"] = "not run"
            continue
        why = stale_answers(model_cfg, store, answers, questions)
        if why:
            raise DynclevrError(f"the row '{name}' would show stale numbers ({why}): run `{rerun}`")
        rows[name] = tuple(table1(answers)[c][0] for c in COLUMNS)
        measured[name] = answers
        extra[f"{name}: program exact match"] = 100.0 * sum(a["program_match"] for a in answers) / max(len(answers), 1)
        extra[f"{name}: unparsed"] = sum(a["status"] == "unparsed" for a in answers)
        extra[f"{name}: failed programs"] = sum(a["status"] == "failed" for a in answers)
    answers = _answers(store, "cnnlstm")   # answers-cnnlstm.parquet (stage answer-cnnlstm)
    if answers is None:
        extra[CNNLSTM_ROW] = "not run"
    else:
        why = stale_answers(cfg, store, answers, questions, stage="answer-cnnlstm")
        if why:
            raise DynclevrError(f"the row '{CNNLSTM_ROW}' would show stale numbers ({why}): run `{rerun}`")
        rows[CNNLSTM_ROW] = tuple(table1(answers)[c][0] for c in COLUMNS)
        measured[CNNLSTM_ROW] = answers
    rows["oracle (truth scene, gold programs)"] = tuple(
        table1(oracle_rows(store, cfg, questions))[c][0] for c in COLUMNS)
    blind = blind_rows(questions)
    if blind is not None:
        rows["blind (train-split majority per family)"] = tuple(table1(blind)[c][0] for c in COLUMNS)
        measured["blind (train-split majority per family)"] = blind
    counts = table1([{**q, "correct": True} for q in questions])
    extra["counts"] = {c: counts[c][1] for c in COLUMNS}
    resamples = cfg["report"]["bootstrap_resamples"]
    if resamples:
        samples = bootstrap(measured, resamples, cfg["report"]["bootstrap_seed"])
        extra["intervals"] = {name: interval(x) for name, x in samples.items()}
        extra["differences"] = {label: (np.subtract(rows[a], rows[b]), *interval(samples[a] - samples[b]))
                                for label, a, b in DIFFERENCES if a in samples and b in samples}
        extra["resamples"] = resamples
    extra["families"] = list(measured), families(questions, measured)
    return {**rows, **PAPER}, extra


def families(questions: list[dict], measured: dict[str, list[dict]]) -> list[tuple[str, str, int, list[float]]]:
    """(family, type, questions, each measured row's accuracy in %) per question family, by type then family: where
    a row's average comes from (Table 1's columns pool families of very different difficulty)."""
    asked: dict[tuple[str, str], int] = {}
    for q in questions:
        asked[(q["type"], q["family"])] = asked.get((q["type"], q["family"]), 0) + 1
    right = {name: {} for name in measured}
    for name, answers in measured.items():
        for a in answers:
            key = (a["type"], a["family"])
            right[name][key] = right[name].get(key, 0) + bool(a["correct"])
    order = {"factual": 0, "predictive": 1, "counterfactual": 2}
    return [(family, kind, n, [100.0 * right[name].get((kind, family), 0) / n for name in measured])
            for (kind, family), n in sorted(asked.items(), key=lambda kv: (order.get(kv[0][0], 3), kv[0][1]))]


def markdown(split: str, rows: dict[str, tuple], extra: dict) -> str:
    fmt = lambda v: "–" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.2f}"
    lines = [f"# Accuracy on split `{split}` ({extra['videos']} videos, {extra['questions']} questions)", "",
             "| model | " + " | ".join(COLUMNS) + " |", "|---" * (len(COLUMNS) + 1) + "|",
             "| questions | " + " | ".join(str(extra["counts"][c]) for c in COLUMNS) + " |"]
    lines += [f"| {name} | " + " | ".join(fmt(v) for v in vals) + " |" for name, vals in rows.items()]
    lines.append("")
    lines += [f"- {k}: {fmt(v) if isinstance(v, float) else v}" for k, v in extra.items()
              if k not in LAID_OUT]
    if "intervals" in extra:
        lines += ["", f"95% intervals: the {extra['videos']} videos resampled with replacement {extra['resamples']} "
                  "times, every row over the same resamples (`dynclevr/uncertainty.py`; `report.bootstrap_resamples`)",
                  "", "| model | " + " | ".join(COLUMNS) + " |", "|---" * (len(COLUMNS) + 1) + "|"]
        span = lambda lo, hi, sign="": "–" if math.isnan(lo) else f"{lo:{sign}.1f} to {hi:{sign}.1f}"
        lines += [f"| {name} | " + " | ".join(span(lo[c], hi[c]) for c in range(len(COLUMNS))) + " |"
                  for name, (lo, hi) in extra["intervals"].items()]
        if extra["differences"]:
            lines += ["", "| difference (paired: the same resampled videos) | " + " | ".join(COLUMNS) + " |",
                      "|---" * (len(COLUMNS) + 1) + "|"]
            lines += [f"| {label} | " + " | ".join(
                "–" if math.isnan(d[c]) else f"{d[c]:+.2f} ({span(lo[c], hi[c], '+')})" for c in range(len(COLUMNS)))
                + " |" for label, (d, lo, hi) in extra["differences"].items()]
    if extra.get("families"):
        names, table = extra["families"]
        lines += ["", "Accuracy by question family (%; each family's questions counted once)", "",
                  "| family | type | questions | " + " | ".join(names) + " |", "|---" * (len(names) + 3) + "|"]
        lines += [f"| {family} | {kind} | {n} | " + " | ".join(f"{v:.1f}" for v in accs) + " |"
                  for family, kind, n, accs in table]
    return "\n".join(lines) + "\n"


def bar_chart(path: Path, split: str, rows: dict[str, tuple]) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # Each measured row, then (hatched, in its colour) the paper's row of the same model; the paper's rows of models
    # not reproduced here last, in grey.
    measured = [n for n in rows if n not in PAPER]
    bars, colours = [], plt.get_cmap("tab10").colors
    for k, n in enumerate(measured):
        bars.append((n, colours[k % 10], None))
        if PAPER_OF.get(n) in rows:
            bars.append((PAPER_OF[n], colours[k % 10], "//"))
    rest = [n for n in rows if n in PAPER and n not in {b[0] for b in bars}]
    bars += [(n, str(0.65 - 0.3 * k / max(len(rest) - 1, 1)), ("//", "\\\\", "xx")[k % 3]) for k, n in enumerate(rest)]
    x = np.arange(len(COLUMNS))
    w = 0.86 / len(bars)
    fig, ax = plt.subplots(figsize=(14, 6))
    for k, (n, colour, hatch) in enumerate(bars):
        ax.bar(x + k * w - 0.43 + w / 2, [0 if v is None or math.isnan(v) else v for v in rows[n]], w, label=n,
               color="white" if hatch else colour, edgecolor=colour if hatch else "none", hatch=hatch, linewidth=0.6)
    ax.set_xticks(x, COLUMNS)
    ax.set_ylabel("accuracy (%)")
    ax.set_ylim(0, 105)
    ax.set_title(f"DynSuperCLEVR question answering, split '{split}' (hatched: the paper's figures, its test split)")
    ax.legend(fontsize=8, ncol=4, loc="upper center", bbox_to_anchor=(0.5, -0.08), frameon=False)
    fig.tight_layout()
    fig.savefig(path, dpi=110, format="png")
    plt.close(fig)
