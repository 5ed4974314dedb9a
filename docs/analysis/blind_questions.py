"""Score a set of questions written by hand against the question parser, before any rule is made for it.

A set is a file in handwritten.txt's format ('family | X | Y | slots | text', '#' comments), optionally with a file
of questions of no family (one a line, like out_of_scope.txt). Prints right / wrong / unparsed (program exact match)
and refused, then every miss with the program read and the program meant. Brief given to the writers:
docs/analysis/blind_questions_brief.md.

    .venv/bin/python docs/analysis/blind_questions.py SET.txt [--oos OOS.txt]
"""
import argparse
from pathlib import Path

from dynclevr import DynclevrError
from dynclevr.language import evaluate
from dynclevr.language.parse import QuestionParser


def score(path: Path, oos: Path | None) -> None:
    for p in filter(None, (path, oos)):
        if not p.is_file():
            raise SystemExit(f"blind_questions: {p} is no file: give a set in handwritten.txt's format (and --oos)")
    evaluate.HANDWRITTEN_FILE = path
    keyed = evaluate.handwritten()
    parser = QuestionParser.load()
    reads = parser.parse_batch([text for text, _ in keyed])
    right = sum(read is not None and " ".join(read) == key for (_, key), read in zip(keyed, reads))
    unparsed = sum(read is None for read in reads)
    print(f"{path}: {right} right, {len(keyed) - right - unparsed} wrong, {unparsed} unparsed of {len(keyed)}")
    if oos:
        texts = [line for line in oos.read_text().splitlines() if line.strip() and not line.startswith("#")]
        oos_reads = parser.parse_batch(texts)
        print(f"{oos}: {sum(read is None for read in oos_reads)} of {len(texts)} refused")
        for text, read in zip(texts, oos_reads):
            if read is not None:
                print(f"  READ   {text}\n         {' '.join(read)}")
    for (text, key), read in zip(keyed, reads):
        if read is None:
            print(f"  UNREAD {text}")
        elif " ".join(read) != key:
            print(f"  WRONG  {text}\n         read {' '.join(read)}\n         meant {key}")


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("set", type=Path)
    ap.add_argument("--oos", type=Path)
    args = ap.parse_args()
    try:
        score(args.set, args.oos)
    except (DynclevrError, OSError) as e:   # a malformed line or a missing file: one line, not a traceback
        raise SystemExit(f"blind_questions: {e}") from None
