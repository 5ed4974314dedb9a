"""The whole pipeline on a two-video split, end to end through the CLI, as a user runs it."""

import subprocess
import sys

import pytest

from dynclevr.artifacts import Store, read_parquet, write_parquet
from dynclevr.config import Config
from dynclevr.pipeline import SceneJob
from dynclevr.stages import answer
from dynclevr.stages.annotate import QUESTIONS_SCHEMA, QUESTIONS_VERSION

SCENES = ("000000", "000001")
CI_SPLIT = "[splits.ci]\nseed = 7\nscenes = 2\n[video]\nframes = 60\n"   # half the paper's 2 s: every stage, half the time


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    root = tmp_path_factory.mktemp("pipeline")
    config = root / "ci.toml"
    config.write_text(CI_SPLIT)

    def cli(*args):
        out = subprocess.run([sys.executable, "-m", "dynclevr.cli", *args, "--split", "ci", "--config", str(config),
                              "--data-dir", str(root / "data")], capture_output=True, text=True)
        assert out.returncode == 0, out.stderr[-3000:]
        return out.stdout

    cli("run", "--workers", "2")
    return root / "data", config, cli


def test_report_has_every_row_and_the_oracle_is_exact(run):
    data, _, cli = run
    text = cli("report")
    rows = {line.split("|")[1].strip(): line for line in text.splitlines() if line.startswith("| ")}
    for name in ("NS-4DPhysics (ours)", "ours without physics prior", "ours with the particle filter",
                 "per-frame 3D, PO3D-VQA style", "CNN+LSTM", "paper, not reproduced: PLLaVA",
                 "oracle (truth scene, gold programs)",
                 "blind (train-split majority per family)", "paper: NS-4DPhysics"):
        assert name in rows, text
    oracle = [c.strip() for c in rows["oracle (truth scene, gold programs)"].split("|")[2:-1]]
    assert "100.00" in oracle and all(c in ("100.00", "–") for c in oracle), oracle
    assert (data / "ci" / "report.md").exists() and (data / "ci" / "report.png").stat().st_size > 10_000
    assert "95% intervals: the 2 videos resampled" in text and "| the physics prior's gain" in text, text
    # by family: every question in one family row, each measured row's accuracy beside it
    table = text.split("Accuracy by question family")[1]
    family_rows = [line.split("|") for line in table.splitlines() if line.startswith("| ") and "---" not in line][1:]
    total = int(rows["questions"].split("|")[2])
    assert sum(int(r[3]) for r in family_rows) == total and all(len(r) == len(family_rows[0]) for r in family_rows)


def test_answers_read_only_the_question_text(run, tmp_path):
    """With questions.parquet stripped to id, scene, type and text, every prediction stays the same."""
    data, config, _ = run
    cfg, store = Config.load(config), Store(data, "ci")
    full = read_parquet(store.split_file("questions.parquet"), QUESTIONS_SCHEMA, QUESTIONS_VERSION)
    write_parquet(full.select(answer.MODEL_COLUMNS), store.split_file("questions.parquet"), QUESTIONS_SCHEMA,
                  QUESTIONS_VERSION)
    try:
        for i, scene in enumerate(SCENES):
            out = tmp_path / f"{scene}.parquet"
            answer.run_scene(SceneJob("ci", scene, i, 0, cfg.data, data,
                                      {"parse-scene": [store.path("parse-scene", scene, ".mcap")],
                                       "simulate-future": [store.path("simulate-future", scene, ".parquet")]},
                                      [out]))
            stored = store.path("answer", scene, ".parquet")
            read = lambda p: read_parquet(p, answer.PREDICTIONS_SCHEMA, answer.PREDICTIONS_VERSION).to_pylist()
            assert read(out) == read(stored) and read(out)
    finally:
        write_parquet(full, store.split_file("questions.parquet"), QUESTIONS_SCHEMA, QUESTIONS_VERSION)


def test_rerun_is_all_cached_and_status_is_done(run):
    _, _, cli = run
    out = cli("run")
    counts = [line for line in out.splitlines() if "to run" in line]
    assert counts and all(": 0 to run" in line for line in counts), out
    status = cli("status")
    assert all("stale 0" in line and "missing 0" in line for line in status.splitlines()[1:]), status


def test_workers_are_replaced_in_rounds_and_the_bytes_do_not_change(tmp_path, monkeypatch):
    """A pool is replaced every WORKER_TASKS scenes per worker (native memory of pybullet is returned): with one
    scene per worker per pool, three scenes take two pools, finish, and equal an in-process run byte for byte."""
    from dynclevr import pipeline

    cfg = Config.load()
    split = cfg.split("tiny")
    monkeypatch.setattr(pipeline, "WORKER_TASKS", 1)
    pooled = pipeline.Runner(cfg, split, tmp_path / "pooled", workers=2, echo=lambda *a: None)
    assert pooled.run("simulate", [0, 1, 2])["ran"] == 3
    alone = pipeline.Runner(cfg, split, tmp_path / "alone", echo=lambda *a: None)
    alone.run("simulate", [0, 1, 2])
    for scene in ("000000", "000001", "000002"):
        assert (pooled.store.path("simulate", scene, ".mcap").read_bytes()
                == alone.store.path("simulate", scene, ".mcap").read_bytes())


def test_report_refuses_stale_or_missing_answers(run, tmp_path):
    """Issue 14: after the questions change (annotate rerun with another config) the report must not show the old
    answers beside the new questions, and a missing answers table must not silently drop our row."""
    import shutil

    data, _, _ = run
    shutil.copytree(data, tmp_path / "data")
    config = tmp_path / "fewer.toml"
    config.write_text(CI_SPLIT + "[annotate]\nmax_per_family = 1\n")

    def cli(*args):
        return subprocess.run([sys.executable, "-m", "dynclevr.cli", *args, "--split", "ci", "--config", str(config),
                               "--data-dir", str(tmp_path / "data")], capture_output=True, text=True)

    assert cli("annotate").returncode == 0
    out = cli("report")
    fix = f"run `dynclevr run --split ci --data-dir {tmp_path / 'data'} --config {config}`"
    assert out.returncode == 2 and out.stderr.strip().splitlines() == [
        f"error: the row 'NS-4DPhysics (ours)' would show stale numbers (answer is stale for 2 and has not run for 0 "
        f"of 2 scenes): {fix}"]
    assert cli("run").returncode == 0 and cli("report").returncode == 0
    (tmp_path / "data" / "ci" / "answers.parquet").unlink()
    out = cli("report")
    assert out.returncode == 2 and out.stderr.strip() == f"error: no answers of split ci yet: {fix}"


TABLE_FOLDERS = {"labels/frames", "labels/events", "labels/candidates", "labels/dropped", "future", "future-noprior",
                 "future-particle", "answers", "answers-noprior", "answers-particle"}   # at least these


def test_every_table_folder_opens_as_one_dataset(run):
    """Issue 14: each folder of Parquet files is one table, nothing else (the manifests live in manifests/), with a
    scene column, so that duckdb, polars and pyarrow (pandas.read_parquet's engine) read a whole folder in one call;
    a value that does not apply is null, never -1, "" or NaN."""
    import duckdb
    import polars as pl
    import pyarrow.parquet as pq

    data, _, _ = run
    root = data / "ci"
    folders = {p.parent for p in root.rglob("*.parquet")} - {root}
    assert {str(f.relative_to(root)) for f in folders} >= TABLE_FOLDERS
    stage_dirs = [d.name for d in root.iterdir() if d.is_dir() and d.name != "manifests"]
    assert sorted(p.name for p in (root / "manifests").iterdir()) == sorted(f"{d}.json" for d in stage_dirs)
    for folder in folders:
        files = sorted(folder.iterdir())
        assert [p.name for p in files] == [f"{s}.parquet" for s in SCENES], folder
        assert len({pq.read_schema(p).remove_metadata() for p in files}) == 1, folder
        rows = duckdb.sql(f"SELECT scene, count(*) FROM '{folder}/*.parquet' GROUP BY scene ORDER BY scene").fetchall()
        per_file = [(p.stem, pq.read_metadata(p).num_rows) for p in files]
        assert rows == [r for r in per_file if r[1]], folder          # every file's rows, named by their scene
        assert pl.read_parquet(folder).height == pq.read_table(folder).num_rows == sum(n for _, n in per_file)
    one = lambda sql: duckdb.sql(sql).fetchall()[0][0]
    future = f"'{root}/future/*.parquet'"
    assert one(f"SELECT count(*) FROM {future} WHERE run = 'future'") > 0
    assert one(f"SELECT count(*) FROM {future} WHERE run = 'future' AND (object IS NOT NULL OR intervention IS NOT NULL)"
               ) == 0
    assert one(f"SELECT count(*) FROM {future} WHERE run = 'counterfactual' AND (object IS NULL OR intervention IS NULL)"
               ) == 0
    assert one(f"SELECT count(*) FROM {future} WHERE frame < 0 OR a < 0 OR b < 0 OR intervention = ''") == 0
    events = f"'{root}/labels/events/*.parquet'"
    assert one(f"SELECT count(*) FROM {events} WHERE kind = 'observed' AND gap_m IS NOT NULL") > 0
    assert one(f"SELECT count(*) FROM {events} WHERE (kind <> 'counterfactual') <> (target IS NULL)") == 0
    assert one(f"SELECT count(*) FROM {events} WHERE (kind <> 'observed') <> (gap_m IS NULL) OR isnan(gap_m)") == 0
    questions = f"'{root}/questions.parquet'"
    assert one(f"SELECT count(*) FROM {questions} WHERE (type <> 'counterfactual') <> (factual IS NULL)") == 0
    assert one(f"SELECT count(*) FROM '{root}/labels/candidates/*.parquet' WHERE id IS NOT NULL") == 0
    # the split-level tables of the model rows: one schema, side by side with questions.parquet
    rows = len(list(root.glob("answers*.parquet")))
    assert rows >= 3 and one(f"SELECT count(*) FROM '{root}/answers*.parquet'") == rows * one(
        f"SELECT count(*) FROM {questions}")


def _as_older_dynclevr_left_it(root):
    """Lay a split out as dynclevr before issue 14 did: a manifest.json in every stage folder, labels/ with four
    tables side by side, answers.parquet and metrics.parquet in answers/, and the older stage and schema versions."""
    import json

    from dynclevr.stages import annotate, simulate_future

    old_versions = {"labels": annotate.VERSION - 1, "future": simulate_future.STAGE.version - 1,
                    "answers": answer.STAGE.version - 1}
    for m in (root / "manifests").iterdir():
        entries = json.loads(m.read_text())["entries"]
        for name, e in entries.items():
            if m.stem in old_versions:   # an older version: another cache key
                e["key"], e["stage_version"] = "older", old_versions[m.stem]
        (root / m.stem / "manifest.json").write_text(json.dumps({"entries": entries}))
        m.unlink()
    (root / "manifests").rmdir()
    for table, suffix in (("frames", ".parquet"), ("events", ".events.parquet"), ("candidates", ".questions.parquet"),
                          ("dropped", ".dropped.parquet")):
        for p in (root / "labels" / table).iterdir():
            p.rename(root / "labels" / f"{p.stem}{suffix}")
        (root / "labels" / table).rmdir()
    for name in ("answers.parquet", "metrics.parquet"):
        (root / name).rename(root / "answers" / name)
    q = root / "questions.parquet"
    write_parquet(read_parquet(q, QUESTIONS_SCHEMA, QUESTIONS_VERSION), q, QUESTIONS_SCHEMA, 2)


def test_a_data_dir_of_the_older_layout_says_what_to_rerun_then_upgrades(run, tmp_path):
    """Issue 14: reading a data dir that an older dynclevr wrote is one error line naming the stage to rerun, and
    nothing is changed; `run` then rewrites it in today's layout, the same bytes as a fresh run, and keeps the cache
    of the stages whose outputs did not change."""
    import hashlib
    import shutil

    from dynclevr.stages.simulate_future import STAGE as FUTURE

    data, _, _ = run
    old = tmp_path / "data"
    # the main model only: its tables, their manifests (a variant's names have a "-": answers-noprior/, ...)
    shutil.copytree(data, old, ignore=lambda d, names: [n for n in names if "-" in n or n.startswith("report.")
                                                        or n == ".lock"])
    _as_older_dynclevr_left_it(old / "ci")
    config = tmp_path / "ci.toml"
    config.write_text(CI_SPLIT)
    opts = f"--data-dir {old} --config {config}"

    def cli(*args):
        return subprocess.run([sys.executable, "-m", "dynclevr.cli", *args, "--split", "ci", *opts.split()],
                              capture_output=True, text=True)

    def files():
        return {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in old.rglob("*") if p.is_file()
                and p.name != ".lock"}

    before = files()
    for args, line in [
        (["report"], f"error: {old}/ci/questions.parquet has schema dynclevr.questions v2, expected dynclevr.questions "
                     f"v{QUESTIONS_VERSION}: rerun `dynclevr annotate --split ci {opts}`"),
        (["answer"], f"error: future/000000 was made by an older simulate-future (v{FUTURE.version - 1}; this "
                     f"dynclevr has v{FUTURE.version}) for answer: run `dynclevr simulate-future --split ci {opts}` "
                     "first")]:
        out = cli(*args)
        assert out.returncode == 2 and out.stderr.strip().splitlines() == [line], out.stderr
    assert files() == before
    out = cli("run", "--no-ablation")
    assert out.returncode == 0, out.stderr
    said = out.stdout
    assert "simulate: 0 to run, 2 cached" in said and "parse-scene: 0 to run, 2 cached" in said, said
    assert "annotate: removed 8 files of an older dynclevr's layout" in said, said
    assert not list(old.rglob("manifest.json")) and not list((old / "ci" / "labels").glob("*.parquet"))
    for p in sorted((data / "ci").rglob("*.parquet")):
        rel = p.relative_to(data)
        if "-" not in str(rel):
            assert (old / rel).read_bytes() == p.read_bytes(), rel


def test_a_change_to_the_question_parsers_rules_reruns_the_answers(tmp_path, monkeypatch):
    """The answer stage's cache key holds the parser's rules and lexicons and the executor (`answer.READING`), so a
    rule changed without a stage version bump cannot leave a split's answers stale; its evaluation corpora are not
    in it."""
    from dynclevr.stages import answer

    names = {p.name for p in answer.READING}
    assert {"parse.py", "references.py", "synonyms.txt", "wordnet.txt", "programs.py"} <= names
    assert not {"handwritten.txt", "out_of_scope.txt"} & names
    rule = tmp_path / "parse.py"
    rule.write_text("RULE = 1\n")
    monkeypatch.setattr(answer, "READING", [rule])
    before = answer.reading_digest()
    rule.write_text("RULE = 2\n")
    assert answer.reading_digest() != before
