"""A split's own questions, a few of each family, as lines of handwritten.txt ('family | X | Y | slots | text'), for
writers to reword: each line keeps its key and its template text, which the writer replaces with a paraphrase. Then
`blind_questions.py` scores the paraphrases against the programs the split's questions have (the template texts
themselves score all right, which checks the keys).

    .venv/bin/python docs/analysis/split_questions.py --split full-test --data-dir D --seed 1 --per-family 3 > SET.txt
"""
import re
import sys

import numpy as np

from dynclevr import DynclevrError
from dynclevr.artifacts import read_parquet
from dynclevr.language.evaluate import _pattern
from dynclevr.questions.generate import templates
from dynclevr.stages.annotate import QUESTIONS_SCHEMA, QUESTIONS_VERSION
from split_args import split_args


def keyed(question: dict, fam: dict) -> str:
    """The question as a line of handwritten.txt: its objects' attribute values and its slots' keys from its program."""
    m = _pattern(fam).fullmatch(question["program"])
    if m is None:
        raise DynclevrError(f"question {question['id']}: its program is not one of family {fam['name']}'s: annotate "
                            "the split again (`dynclevr annotate --split S --force`)")
    objects = [" ".join(re.findall(r"filter_attributes\[([a-z_]+)\]", m.group(n))) if n in fam["objects"] else ""
               for n in ("X", "Y")]
    slots = ",".join(f"{n}={k}" for n in fam.get("slots", []) for k, v in templates()["slots"][n].items()
                     if v["program"] == m.group(n))
    return f"{fam['name']} | {objects[0]} | {objects[1]} | {slots} | {question['text']}"


def main() -> None:
    ap = split_args()
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--per-family", type=int, default=3)
    args = ap.parse_args()
    questions = read_parquet(f"{args.data_dir}/{args.split}/questions.parquet", QUESTIONS_SCHEMA,
                             QUESTIONS_VERSION).to_pylist()
    rng = np.random.default_rng(args.seed)
    lines = []
    for fam in templates()["families"]:
        of = [q for q in questions if q["family"] == fam["name"]]
        lines += [keyed(of[i], fam) for i in rng.choice(len(of), size=min(args.per_family, len(of)), replace=False)]
    sys.stdout.write("".join(lines[i] + "\n" for i in rng.permutation(len(lines))))


if __name__ == "__main__":
    try:
        main()
    except (DynclevrError, OSError) as e:   # a missing split or a stale annotation: one line, not a traceback
        raise SystemExit(f"split_questions: {e}") from None
