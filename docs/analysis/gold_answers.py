"""What the attribution analyses share: a question type's gold programs run on variants of each scene's parse, and
the table of their accuracies over a split."""

import collections
from multiprocessing import Pool
from pathlib import Path
from typing import Callable

import numpy as np
import pyarrow.parquet as pq

from dynclevr import DynclevrError
from dynclevr.questions.programs import Executor


def right(variants: dict, questions: list[dict], labels_cfg: dict) -> dict[str, list[bool]]:
    """{label: per question, whether its gold program on that variant of the scene gives the true answer}."""
    out = {}
    for label, s in variants.items():
        ex = Executor(s, labels_cfg)
        answers = []
        for q in questions:
            try:
                answers.append(ex.run(q["program"]) == q["answer"])
            except DynclevrError:
                answers.append(False)
        out[label] = answers
    return out


def table(root: Path, split: str, kind: str, scene: Callable[[tuple], dict]) -> None:
    """Print the accuracy of every variant over the split's `kind` questions; `scene((name, questions))` gives
    `right`'s dict for one scene (run in 2 processes)."""
    by_scene = collections.defaultdict(list)
    for q in pq.read_table(root / "questions.parquet").to_pylist():
        if q["type"] == kind:
            by_scene[q["scene"]].append(q)
    with Pool(2) as pool:
        results = pool.map(scene, sorted(by_scene.items()))
    total = collections.defaultdict(list)
    for r in results:
        for label, answers in r.items():
            total[label] += answers
    print(f"| {split}: {kind} questions ({len(total['the parse'])}), gold programs | accuracy % |")
    print("|---|---|")
    for label, answers in total.items():
        print(f"| {label} | {100 * np.mean(answers):.2f} |")
