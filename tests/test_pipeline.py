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


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    root = tmp_path_factory.mktemp("pipeline")
    config = root / "ci.toml"
    config.write_text("[splits.ci]\nseed = 7\nscenes = 2\n")

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
                 "oracle (truth scene, gold programs)",
                 "blind (train-split majority per family)", "paper: NS-4DPhysics"):
        assert name in rows, text
    oracle = [c.strip() for c in rows["oracle (truth scene, gold programs)"].split("|")[2:-1]]
    assert "100.00" in oracle and all(c in ("100.00", "–") for c in oracle), oracle
    assert (data / "ci" / "report.md").exists() and (data / "ci" / "report.png").stat().st_size > 10_000


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
            read = lambda p: read_parquet(p, answer.ANSWERS_SCHEMA, answer.ANSWERS_VERSION).to_pylist()
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
    config.write_text("[splits.ci]\nseed = 7\nscenes = 2\n[annotate]\nmax_per_family = 1\n")

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
    (tmp_path / "data" / "ci" / "answers" / "answers.parquet").unlink()
    out = cli("report")
    assert out.returncode == 2 and out.stderr.strip() == f"error: no answers of split ci yet: {fix}"
