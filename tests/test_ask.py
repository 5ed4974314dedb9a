"""`dynclevr ask`: a question in your own words, answered on a scene's truth or estimate with its program and
evidence; a batch from a JSON-lines file; one clear line for every way it can go wrong."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from dynclevr.artifacts import Store
from dynclevr.language.parse import QuestionParser
from dynclevr.questions.tables import read_questions

SPLIT = "asked"


def cli(data: Path, *args: str):
    return subprocess.run([sys.executable, "-m", "dynclevr.cli", *args, "--split", SPLIT,
                           "--config", str(data.parent / "ask.toml"), "--data-dir", str(data)],
                          capture_output=True, text=True)


@pytest.fixture(scope="module")
def data(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("ask")
    (root / "ask.toml").write_text(f"[splits.{SPLIT}]\nseed = 4242\nscenes = 2\n[video]\nframes = 60\n")   # half the paper's 2 s
    data = root / "data"
    for stage in ("simulate", "render", "annotate"):
        assert cli(data, stage).returncode == 0
    return data


@pytest.fixture(scope="module")
def questions(data) -> list[dict]:
    """The split's questions that the shipped parser reads right (so the test checks `ask`, not the parser)."""
    qs = read_questions(Store(data, SPLIT).split_file("questions.parquet"))
    got = QuestionParser.load().parse_batch([q["text"] for q in qs])
    return [q for q, g in zip(qs, got) if g == q["program"].split()]


def test_ask_on_the_truth_gives_the_stored_answer_with_evidence(data, questions):
    q = next(q for q in questions if q["family"] == "velocity_collision")
    out = cli(data, "ask", q["text"], "--scene", str(int(q["scene"])), "--on", "truth")
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()
    assert lines[0] == f"program:  {q['program']}"
    assert lines[1].split()[1] == q["answer"]
    evidence = [line for line in lines if line.startswith("evidence: ")]
    assert any("-> object" in line for line in evidence) and any("at frame" in line for line in evidence)


def test_ask_a_batch_from_a_file(data, questions, tmp_path):
    batch = questions[:5]
    path = tmp_path / "q.jsonl"
    path.write_text("".join(json.dumps({"scene": int(q["scene"]), "text": q["text"]}) + "\n" for q in batch)
                    + json.dumps({"scene": 0, "text": "florp zzk blarg?"}) + "\n")
    out = cli(data, "ask", "--file", str(path), "--on", "truth")
    assert out.returncode == 0, out.stderr
    rows = [json.loads(line) for line in out.stdout.splitlines()]
    assert [r["answer"] for r in rows[:5]] == [q["answer"] for q in batch]
    assert all(r["status"] == "ok" and r["program"] for r in rows[:5])
    assert rows[5]["status"] == "unparsed" and rows[5]["reason"].startswith("unknown words")


def test_ask_says_which_words_it_read_as_others(data):
    """A word the parser does not know, read through the synonym lexicon or its stem, is shown as evidence."""
    out = cli(data, "ask", "Did the red sedan ram into the blue bus in the footage?", "--scene", "0", "--on", "truth")
    assert out.stdout.startswith("program:  Events "), out.stdout + out.stderr
    evidence = [line for line in out.stdout.splitlines() if line.startswith("evidence: read ")]
    assert evidence == ["evidence: read 'ram' as 'hit'", "evidence: read 'footage' as 'video'"]
    # ... and a question read with its clause of time put last says so
    out = cli(data, "ask", "When it hits the blue bus, how fast is the red sedan going?", "--scene", "0", "--on",
              "truth")
    moved = "'how fast is the red sedan going when it hits the blue bus ?'"
    assert f"evidence: read with its clause of time last: {moved}" in out.stdout.splitlines(), out.stdout + out.stderr


@pytest.mark.parametrize("args,exit_code,says", [
    (["ask", "florp zzk blarg?", "--scene", "0", "--on", "truth"], 1, "unparsed: unknown words"),
    (["ask", "   ", "--scene", "0"], 2, "error: the question is empty"),
    (["ask", "Did the red sedan hit the blue bus?", "--scene", "7", "--on", "truth"], 2,
     "error: scene 7 is not in split asked (scenes 0-1)"),
    (["ask", "Did the red sedan hit the blue bus?", "--scene", "0"], 2,
     "error: scene 000000 of split asked has no estimate yet: run `dynclevr run --split asked --scenes 0 --data-dir"),
])
def test_ask_errors_are_one_line(data, args, exit_code, says):
    out = cli(data, *args)
    assert out.returncode == exit_code
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(says), out.stderr
