"""Issue 16: the executor seam. The tiny split's data stages on a local Ray (2 CPUs) give the same bytes as the local
process pool, artifacts and manifests alike; a Ray worker killed mid-stage is retried and the bytes stay the same; a
scene that fails for a reason of its own is reported by id while the rest of the split completes; `--executor ray`
without Ray installed is one line telling how to install it."""

import hashlib
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from dynclevr.artifacts import Store
from dynclevr.config import Config
from dynclevr.pipeline import OWN_RAY, RAY_MISSING, Runner, StageFailed

SPLIT = "tiny"
STAGES = ("simulate", "render", "annotate")
KILLED = "000001"   # the scene whose first render attempt kills its own Ray worker


def digests(data: Path, under: str = "") -> dict[str, str]:
    """Every file of the split (not the lock file, which names the last process that held it)."""
    root = data / SPLIT / under
    return {str(p.relative_to(data)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(root.rglob("*")) if p.is_file() and p.name != ".lock"}


def run_stages(data: Path, executor: str, stages=STAGES, **kw) -> Runner:
    cfg = Config.load()
    r = Runner(cfg, cfg.split(SPLIT), data, workers=2, echo=lambda *a: None, executor=executor, **kw)
    for name in stages:
        r.run(name, list(range(r.split.scenes)))
    return r


@pytest.fixture(scope="module")
def local(tmp_path_factory) -> Path:
    """simulate, render and annotate of the tiny split on the local process pool (2 workers): the reference."""
    data = tmp_path_factory.mktemp("local") / "data"
    run_stages(data, "local")
    return data


def copy_stages(src: Path, dst: Path, dirs: tuple[str, ...]) -> None:
    """A data dir holding only `dirs` (stage folders, each with its manifest) of `src`."""
    for d in dirs:
        shutil.copytree(src / SPLIT / d, dst / SPLIT / d)
        (dst / SPLIT / "manifests").mkdir(parents=True, exist_ok=True)
        shutil.copy(src / SPLIT / "manifests" / f"{d}.json", dst / SPLIT / "manifests" / f"{d}.json")


# ---- without Ray ----------------------------------------------------------------------------------------------------

def test_ray_not_installed_is_one_line(tmp_path):
    """The missing import simulated (sys.modules["ray"] = None makes `import ray` raise ImportError)."""
    code = ("import sys; sys.modules['ray'] = None; from dynclevr.cli import main; "
            f"sys.argv = ['dynclevr', 'simulate', '--split', '{SPLIT}', '--executor', 'ray', "
            f"'--data-dir', '{tmp_path / 'data'}']; main()")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 2 and out.stderr.strip().splitlines() == [f"error: {RAY_MISSING}"], out.stderr
    assert "make ray" in RAY_MISSING and "pip install -e '.[ray]'" in RAY_MISSING
    assert not (tmp_path / "data").exists()   # refused before anything is written


def test_a_failing_scene_is_reported_and_the_rest_complete(local, tmp_path):
    """Local pool: a damaged video fails its scene only; the other scenes run and are recorded, the split-level
    table waits, and the command exits non-zero with one line naming the scene and the fix."""
    data = tmp_path / "data"
    copy_stages(local, data, ("sim", "video", "labels"))
    shutil.copy(local / SPLIT / "questions.parquet", data / SPLIT / "questions.parquet")
    store = Store(data, SPLIT)
    damaged = store.path("render", KILLED, ".mcap")
    damaged.write_bytes(damaged.read_bytes()[:1000])
    for scene in ("000000", "000002"):   # gone: only the run of these scenes brings them back
        store.path("annotate", scene, "events/.parquet").unlink()
    out = subprocess.run([sys.executable, "-m", "dynclevr.cli", "annotate", "--force", "--split", SPLIT, "--workers", "2",
                          "--data-dir", str(data)], capture_output=True, text=True)
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr
    assert lines[0].startswith(f"error: annotate failed on 1 of 3 scenes ({KILLED}; the other 2 are done and "
                               f"recorded); {KILLED}: ") and f"video/{KILLED}.mcap" in lines[0], lines[0]
    assert f"`dynclevr render --split {SPLIT} --scenes 1" in lines[0]
    assert digests(data, "labels") == digests(local, "labels")   # the two others rewritten, the same bytes


# ---- on Ray ---------------------------------------------------------------------------------------------------------

def test_cli_starts_a_local_ray(local, tmp_path):
    """`--executor ray` with no address: the command starts a Ray of --workers CPUs itself; same bytes, a quiet
    stderr."""
    pytest.importorskip("ray")
    data = tmp_path / "data"
    out = subprocess.run([sys.executable, "-m", "dynclevr.cli", "simulate", "--split", SPLIT, "--workers", "2",
                          "--executor", "ray", "--data-dir", str(data)], capture_output=True, text=True)
    assert out.returncode == 0 and out.stderr == "", out.stderr
    assert "3 done" in out.stdout and "ray)" in out.stdout, out.stdout
    want = {k: v for k, v in digests(local).items() if k.startswith((f"{SPLIT}/sim/", f"{SPLIT}/objects"))
            or k == f"{SPLIT}/manifests/sim.json"}
    assert digests(data) == want


def test_a_commands_own_ray_runs_its_workers_at_its_own_priority():
    """Ray's default puts workers at nice 15, so that any other work on the cores starves them (the executor tests
    beside two busy processes ran 6 to 17 times slower); the local pool's workers run at the command's priority."""
    pytest.importorskip("ray")
    code = ("import os; from dynclevr.pipeline import _ray_connect; ray = _ray_connect(None, 1); "
            "print(ray.get(ray.remote(lambda: os.nice(0)).remote()), os.nice(0))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    worker, own = out.stdout.split()[-2:]
    assert worker == own, out.stdout + out.stderr


def _kill_first_attempt() -> None:
    """Ray's worker_process_setup_hook (runs in every worker): once the test arms it, the first render of KILLED
    SIGKILLs its own worker process, leaving a marker; the retry renders normally."""
    import dataclasses
    import os
    import signal

    import dynclevr.stages.render as render

    folder = Path(os.environ["DYNCLEVR_TEST_FAULTS"])
    run_scene = render.STAGE.run_scene

    def killing(job):
        marker = folder / f"killed-{job.scene}"
        if (folder / "armed").exists() and job.scene == KILLED and not marker.exists():
            marker.write_text(str(os.getpid()))
            os.kill(os.getpid(), signal.SIGKILL)
        run_scene(job)

    render.STAGE = dataclasses.replace(render.STAGE, run_scene=killing)


@pytest.fixture(scope="module")
def ray_local(tmp_path_factory):
    """A local Ray of 2 CPUs in this process, its workers carrying the fault hook (disarmed)."""
    ray = pytest.importorskip("ray")
    import ray.cloudpickle

    faults = tmp_path_factory.mktemp("faults")
    ray.cloudpickle.register_pickle_by_value(sys.modules[__name__])   # tests/ is not importable in a worker
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False, object_store_memory=100 * 1024 ** 2,
             _system_config=OWN_RAY,
             runtime_env={"worker_process_setup_hook": _kill_first_attempt,
                          "env_vars": {"DYNCLEVR_TEST_FAULTS": str(faults)}})
    yield faults
    ray.shutdown()


def test_ray_gives_the_same_bytes_as_the_local_pool(local, ray_local, tmp_path):
    data = tmp_path / "data"
    r = run_stages(data, "ray")
    assert r.executor == "ray"
    got, want = digests(data), digests(local)
    assert got == want and any(k.startswith(f"{SPLIT}/video/") for k in got) and f"{SPLIT}/questions.parquet" in got


def test_killed_ray_worker_is_retried_and_the_bytes_do_not_change(local, ray_local, tmp_path):
    data = tmp_path / "data"
    copy_stages(local, data, ("sim",))
    (ray_local / "armed").touch()
    try:
        cfg = Config.load()
        r = Runner(cfg, cfg.split(SPLIT), data, workers=2, echo=lambda *a: None, executor="ray")
        assert r.run("render", [0, 1, 2])["ran"] == 3
    finally:
        (ray_local / "armed").unlink()
    assert (ray_local / f"killed-{KILLED}").exists()   # the first attempt did die
    assert digests(data, "video") == digests(local, "video")
    assert (data / SPLIT / "manifests" / "video.json").read_bytes() == (local / SPLIT / "manifests" /
                                                                         "video.json").read_bytes()


def test_a_failing_scene_on_ray_is_reported_by_id(local, ray_local, tmp_path):
    data = tmp_path / "data"
    copy_stages(local, data, ("sim", "video"))
    damaged = Store(data, SPLIT).path("render", KILLED, ".mcap")
    damaged.write_bytes(damaged.read_bytes()[:1000])
    cfg = Config.load()
    r = Runner(cfg, cfg.split(SPLIT), data, workers=2, echo=lambda *a: None, executor="ray")
    with pytest.raises(StageFailed, match=rf"annotate failed on 1 of 3 scenes \({KILLED}; .*video/{KILLED}.mcap") as e:
        r.run("annotate", [0, 1, 2], force=True)
    assert set(e.value.failed) == {KILLED}
    manifest = Store(data, SPLIT).manifest("annotate")
    assert set(manifest.entries) == {"000000", "000002"}   # recorded; no split-level entry while one scene fails
    assert not (data / SPLIT / "questions.parquet").exists()
