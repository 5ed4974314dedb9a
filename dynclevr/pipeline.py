"""Stages as DVC-like functions of (scene, params, inputs), and the runner that maps them over a split with a cache.

A stage declares what it reads (upstream stages, plus split-level files or weights through `extra_inputs`), its
params (a config subset) and its version. Its cache key per scene is the digest of all of them; an unchanged key
with an intact output means the scene is skipped. Split-level outputs (objects.parquet, questions.parquet, ...)
are written by `finalize` once every scene of the split is done.
"""

from __future__ import annotations

import contextlib
import copy
import fcntl
import importlib
import os
import sys
import time
import traceback
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field, replace
from multiprocessing import get_context
from pathlib import Path
from typing import Callable

from dynclevr import DynclevrError
from dynclevr.artifacts import MODEL_STAGES, ArtifactError, STAGE_DIRS, VARIANT_FLAGS, Manifest, Store, command_options
from dynclevr.config import Config, Split, scene_name, scene_seed, stable_digest

ORDER = ("simulate", "render", "annotate", "parse-scene", "simulate-future", "answer")
BASELINES = ("answer-cnnlstm",)   # stages beside the model's that read the video themselves (Table 1's baselines)
SPLIT_ENTRY = "_split"
WORKER_TASKS = 25   # scenes a pool worker runs before it is replaced
# Where per-scene tasks run: "local", this machine's process pool; "ray", a Ray cluster (the optional extra
# `pip install -e '.[ray]'`), local or remote. The same task function, cache keys, manifests and bytes either way.
EXECUTORS = ("local", "ray")
RAY_RETRIES = 3     # times Ray reruns a scene whose worker died (killed, out of memory, a lost node)
OWN_RAY = {"worker_niceness": 0}   # Ray's settings for a local Ray that a command starts itself (_ray_connect)


@dataclass(frozen=True)
class SceneJob:
    """Everything one stage needs to make one scene's outputs. Picklable, so a worker process can run it."""

    split: str
    scene: str
    index: int
    seed: int
    config: dict
    data_dir: Path
    inputs: dict[str, list[Path]]   # upstream stage -> its output paths for this scene
    outputs: list[Path]             # where to write (with atomic writers)

    @property
    def cfg(self) -> Config:
        return Config(self.config)

    @property
    def store(self) -> Store:
        return Store(self.data_dir, self.split)


@dataclass(frozen=True)
class Stage:
    name: str
    version: int
    inputs: tuple[str, ...]                          # upstream per-scene stages
    params: Callable[[Config], dict]                 # the config subset the outputs depend on
    outputs: tuple[str, ...]                         # per-scene output suffixes
    run_scene: Callable[[SceneJob], None]
    finalize: Callable[[Store, Config, list[str]], list[Path]] | None = None
    extra_inputs: Callable[[Store, Config], dict[str, str]] = field(default=lambda store, cfg: {})
    # Globs, in the stage's folder, of files an older version wrote that this one does not: removed when it runs,
    # so that a folder keeps one table (a stage version bump already reruns every scene).
    retired: tuple[str, ...] = ()


def model_variant(cfg: Config) -> str:
    """'' for NS-4DPhysics, 'noprior' for the paper's ablation without the physics prior, 'particle' with the
    particle filter, '...refine' with the render-and-compare refinement where it is not the default; 'perframe' for
    the per-frame 3D baseline (parser.filter = "none": no prior, no temporal filter; baselines/perframe.py)."""
    p = cfg.data.get("parser", {})
    if p.get("filter") == "none":
        return "perframe"
    prior = p.get("physics_prior", True)
    parts = (([] if prior else ["noprior"]) + (["particle"] if prior and p.get("filter") == "particle" else [])
             + (["refine"] if p.get("refine", False) else []))
    return "-".join(parts)


# The model's rows in `dynclevr run`, `report` and `eval-parser` (issue 11's ablation): the scene parser as
# configured, without the physics prior (the paper's ablation), with the particle filter (its future work), and its
# per-frame part alone with no dynamics model (the PO3D-VQA row of Table 1, issue 15).
MODEL_ROWS = (("NS-4DPhysics (ours)", {}),
              ("ours without physics prior", {"physics_prior": False}),
              ("ours with the particle filter", {"filter": "particle"}),
              ("per-frame 3D, PO3D-VQA style", {"filter": "none", "physics_prior": False}))


def model_configs(cfg: Config) -> list[tuple[str, Config]]:
    """(row name, config) of each of MODEL_ROWS, once per distinct variant (a config whose default already is
    one of them gives fewer rows)."""
    out, seen = [], set()
    for name, parser in MODEL_ROWS:
        data = copy.deepcopy(cfg.data)
        data.setdefault("parser", {}).update(parser)
        c = Config(data)
        if model_variant(c) not in seen:
            seen.add(model_variant(c))
            out.append((name, c))
    return out


def get_stage(name: str) -> Stage:
    if name not in STAGE_DIRS:
        raise DynclevrError(f"unknown stage '{name}': use one of {', '.join(ORDER + BASELINES)}")
    module = "dynclevr.stages." + name.replace("-", "_")
    try:
        return importlib.import_module(module).STAGE
    except ModuleNotFoundError as e:
        if e.name == module:
            raise DynclevrError(f"stage '{name}' is not built yet ({module} is missing)") from None
        raise


def parse_scenes(spec: str | None, split: Split) -> list[int]:
    """'3-5' or '0,2,7-9' -> indices; None -> the whole split."""
    if not spec:
        return list(range(split.scenes))
    out: list[int] = []
    try:
        for part in spec.split(","):
            lo, _, hi = part.partition("-")
            lo, hi = int(lo), int(hi or lo)
            if hi < lo:
                raise DynclevrError(f"--scenes '{spec}': the range {part} is reversed (did you mean {hi}-{lo}?)")
            out.extend(range(lo, hi + 1))
    except ValueError:
        raise DynclevrError(f"--scenes '{spec}' is not a list of indices or ranges such as 3-5 or 0,2,7-9") from None
    bad = [i for i in out if not 0 <= i < split.scenes]
    if bad:
        raise DynclevrError(f"--scenes {spec}: split '{split.name}' has scenes 0-{split.scenes - 1} only")
    return sorted(set(out))


class Runner:
    def __init__(self, cfg: Config, split: Split, data_dir: Path, workers: int = 1, echo=print,
                 executor: str = "local", ray_address: str | None = None):
        self.cfg, self.split = cfg, split
        self.store = Store(Path(data_dir), split.name, model_variant(cfg))
        self.workers, self.echo = max(1, workers), echo
        if executor not in EXECUTORS:
            raise DynclevrError(f"--executor {executor}: use one of {', '.join(EXECUTORS)}")
        if executor == "ray":
            require_ray()
        self.executor, self.ray_address = executor, ray_address

    # ---- cache keys ----------------------------------------------------------------------------------------------

    def _input_digests(self, stage: Stage, scene: str, manifests: dict[str, Manifest]) -> dict[str, str]:
        digests = {}
        for up in stage.inputs:
            d = manifests[up].digest(scene)
            made_by = manifests[up].entries.get(scene, {}).get("stage_version")
            if made_by is not None and made_by != get_stage(up).version:
                # A data dir of an older dynclevr: its tables have another layout or schema. (An entry that
                # records no version, a hand-built input, is taken as it is.)
                flag = VARIANT_FLAGS.get(self.store.variant, "") if up in MODEL_STAGES else ""
                raise DynclevrError(f"{STAGE_DIRS[up]}/{scene} was made by an older {up} (v{made_by}; this dynclevr "
                                    f"has v{get_stage(up).version}) for {stage.name}: run `dynclevr {up} --split "
                                    f"{self.split.name}{flag}{command_options(self.store.data_dir)}` first")
            if d is None:
                what = (f"{manifests[up].path} is corrupt" if manifests[up].corrupt
                        else f"{STAGE_DIRS[up]}/{scene} is missing")
                flag = VARIANT_FLAGS.get(self.store.variant, "") if up in MODEL_STAGES else ""
                raise DynclevrError(f"{what} for {stage.name}: run `dynclevr {up} --split {self.split.name}{flag}"
                                    f"{command_options(self.store.data_dir)}` first")
            digests[up] = d
        return digests

    def scene_key(self, stage: Stage, scene: str, index: int, manifests, extra: dict) -> str:
        return stable_digest({"stage": stage.name, "version": stage.version, "params": stage.params(self.cfg),
                              "seed": scene_seed(self.split.seed, index),
                              "inputs": self._input_digests(stage, scene, manifests), "extra": extra})

    def _outputs(self, stage: Stage, scene: str) -> list[Path]:
        return [self.store.path(stage.name, scene, s) for s in stage.outputs]

    # ---- running -------------------------------------------------------------------------------------------------

    def run(self, name: str, indices: list[int], force: bool = False) -> dict[str, float]:
        with split_lock(self.store.root, self.echo):
            return self._run(name, indices, force)

    def _run(self, name: str, indices: list[int], force: bool) -> dict[str, float]:
        start = time.perf_counter()
        stage = get_stage(name)
        manifests = {up: self.store.manifest(up) for up in stage.inputs}
        manifest = self.store.manifest(stage.name)
        extra = stage.extra_inputs(self.store, self.cfg)
        todo, cached = [], 0
        for i in indices:
            scene = scene_name(i)
            key = self.scene_key(stage, scene, i, manifests, extra)
            if not force and manifest.fresh(scene, key, self._outputs(stage, scene)):
                cached += 1
                continue
            job = SceneJob(self.split.name, scene, i, scene_seed(self.split.seed, i), self.cfg.data,
                           self.store.data_dir, {up: self._outputs(get_stage(up), scene) for up in stage.inputs},
                           self._outputs(stage, scene))
            todo.append((job, key))
        # Its inputs are there (or the loop above said what to run first): now, and not before, tidy an older
        # dynclevr's layout.
        if manifest.legacy:   # <stage dir>/manifest.json: moved out of the tables' folder
            manifest.save()
        self._remove_retired(stage)
        self.echo(f"{stage.name}: {len(todo)} to run, {cached} cached (unchanged inputs, params and version)")
        done, failed = 0, {}
        try:
            for job, key, error in self._map(stage, todo):
                if error is not None:   # the scene's own failure: the others go on, the stage fails at the end
                    failed[job.scene] = error
                    if not isinstance(error, DynclevrError):   # a bug, not bad input: its traceback helps
                        print(f"{stage.name} {job.scene}: " + "".join(traceback.format_exception(error)).rstrip(),
                              file=sys.stderr)
                    continue
                manifest.record(job.scene, key, job.outputs, stage_version=stage.version,
                                params=stage.params(self.cfg),
                                inputs={**self._input_digests(stage, job.scene, manifests), **extra})
                manifest.save()
                done += 1
        except KeyboardInterrupt:
            raise Interrupted(f"{stage.name} stopped after {done} of {len(todo)} scenes (each one done is recorded): "
                              "run the same command again to go on") from None
        if failed:
            raise StageFailed(stage.name, failed, len(todo))
        if stage.finalize:
            self._finalize(stage, manifest, manifests, extra, force)
        seconds = time.perf_counter() - start
        if todo:
            self.echo(f"{stage.name}: {len(todo)} done in {seconds:.1f} s ({60 * len(todo) / seconds:.1f} scenes/min, "
                      f"{self.executor})")
        return {"ran": len(todo), "cached": cached, "seconds": seconds}

    def _remove_retired(self, stage: Stage) -> None:
        folder = self.store.stage_dir(stage.name)
        old = sorted(p for g in stage.retired for p in folder.glob(g) if p.is_file())
        for p in old:
            p.unlink()
        if old:
            self.echo(f"{stage.name}: removed {len(old)} files of an older dynclevr's layout from {folder} "
                      f"(e.g. {old[0].name}); the stage writes its tables anew")

    def _map(self, stage: Stage, todo):
        """Run each (job, key) of `todo` on the executor; yield (job, key, None) or (job, key, the scene's error) in
        completion order, with one progress bar for the stage (scenes done / total, rate, ETA)."""
        from rich.console import Console
        from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TaskProgressColumn, TextColumn,
                                   TimeElapsedColumn, TimeRemainingColumn)

        if not todo:
            return
        console = Console(stderr=True)
        columns = (TextColumn("[progress.description]{task.description}"), BarColumn(), MofNCompleteColumn(),
                   TextColumn("scenes"), TaskProgressColumn(), _rate_column(), TimeElapsedColumn(), TextColumn("ETA"),
                   TimeRemainingColumn())
        with Progress(*columns, console=console, transient=True, disable=not console.is_terminal) as bar:
            task = bar.add_task(f"{stage.name} ({self.executor})", total=len(todo))
            run = self._map_ray if self.executor == "ray" else self._map_local
            for job, key, error in run(stage, todo):
                bar.advance(task)
                yield job, key, error

    def _map_local(self, stage: Stage, todo):
        # In this process when that is cheap and bounded: no spawn cost. Past WORKER_TASKS scenes, a pool even
        # for one worker, so that native memory is returned (below).
        if len(todo) == 1 or (self.workers == 1 and len(todo) <= WORKER_TASKS):
            for job, key in todo:
                try:
                    stage.run_scene(job)
                except Exception as e:
                    yield job, key, e
                else:
                    yield job, key, None
            return
        # A fresh pool every WORKER_TASKS scenes per worker: pybullet keeps about 1 MB per connection and the
        # TinyRenderer tens of MB per scene after disconnecting, so a long-lived worker of a 1,000-scene split
        # would grow by gigabytes. (Not max_tasks_per_child: with it, Python 3.11's pool can hang once a worker
        # retires.)
        size = WORKER_TASKS * self.workers
        for chunk in (todo[i:i + size] for i in range(0, len(todo), size)):
            with ProcessPoolExecutor(self.workers, mp_context=_pool_context(),
                                     initializer=_worker_init) as pool:
                try:
                    with _ctrl_c_deferred():   # the pool starts its workers on submit
                        futures = {pool.submit(_run_in_worker, stage.name, job): (job, key) for job, key in chunk}
                    # In completion order, so every scene done is recorded even when a later one fails.
                    for fut in as_completed(futures):
                        job, key = futures[fut]
                        try:
                            fut.result()
                        except BrokenProcessPool:   # a worker died: not the scene's fault, and the pool is gone
                            raise
                        except Exception as e:
                            yield job, key, e
                        else:
                            yield job, key, None
                except BaseException:
                    # Leaving the pool waits for its queue: without this an interrupt would surface only after
                    # every other scene of the chunk had run.
                    pool.shutdown(cancel_futures=True)
                    raise

    def _map_ray(self, stage: Stage, todo):
        """Every scene a Ray task (one CPU each), retried by Ray when its worker dies; a worker process is
        replaced after WORKER_TASKS scenes as the local pool's. Paths are absolute: on a cluster the data dir is a
        shared file system mounted at the same path on every node."""
        ray = _ray_connect(self.ray_address, self.workers)
        from ray.exceptions import RayError, RayTaskError

        remote = _ray_task(ray)
        refs = {remote.remote(stage.name, _absolute(job)): (job, key) for job, key in todo}
        pending = list(refs)
        try:
            while pending:
                ready, pending = ray.wait(pending, num_returns=1)
                job, key = refs[ready[0]]
                try:
                    ray.get(ready[0])
                except RayTaskError as e:   # the scene raised: the exception itself, as the local pool gives it
                    cause = getattr(e, "cause", None)
                    yield job, key, cause if isinstance(cause, Exception) else e
                except RayError as e:   # its worker died RAY_RETRIES + 1 times, or the cluster lost it
                    yield job, key, DynclevrError(f"its Ray worker died {RAY_RETRIES + 1} times "
                                                  f"({type(e).__name__}: {str(e).splitlines()[0] if str(e) else ''})")
                else:
                    yield job, key, None
        except BaseException:   # Ctrl-C, or the caller stopped: the cluster drops what was not run
            for ref in pending:
                ray.cancel(ref, force=True)
            raise

    def _current(self, stage: Stage, scene: str, index: int, manifest: Manifest, manifests, extra: dict) -> bool:
        """The scene's recorded output was made with today's params, inputs and version."""
        entry = manifest.entries.get(scene)
        try:
            return entry is not None and entry["key"] == self.scene_key(stage, scene, index, manifests, extra)
        except DynclevrError:   # its inputs are gone
            return False

    def _finalize(self, stage: Stage, manifest: Manifest, manifests, extra: dict, force: bool) -> None:
        scenes = self.split.scene_names()
        # A scene run with other params (a --scenes subset after a change) would mix into the split's table.
        waiting = [s for i, s in enumerate(scenes) if not self._current(stage, s, i, manifest, manifests, extra)]
        if waiting:
            self.echo(f"{stage.name}: split-level outputs wait for {len(waiting)} scenes not yet run or stale")
            return
        key = stable_digest({"version": stage.version, "params": stage.params(self.cfg),
                             "scenes": [manifest.digest(s) for s in scenes], "extra": extra})
        paths = manifest.entries.get(SPLIT_ENTRY, {}).get("paths")
        if not force and isinstance(paths, list) and manifest.fresh(SPLIT_ENTRY, key,
                                                                    [self.store.root / p for p in paths]):
            return
        paths = stage.finalize(self.store, self.cfg, scenes)
        # Relative to the split's folder: a data directory that is moved or copied checks its own files.
        manifest.record(SPLIT_ENTRY, key, paths, paths=[str(p.relative_to(self.store.root)) for p in paths])
        manifest.save()
        self.echo(f"{stage.name}: wrote {', '.join(p.name for p in paths)}")

    # ---- status --------------------------------------------------------------------------------------------------

    def status(self, name: str) -> dict[str, list[str]]:
        stage = get_stage(name)
        manifests = {up: self.store.manifest(up) for up in stage.inputs}
        manifest = self.store.manifest(stage.name)
        extra = stage.extra_inputs(self.store, self.cfg)
        out = {"done": [], "stale": [], "missing": []}
        for i, scene in enumerate(self.split.scene_names()):
            if manifest.digest(scene) is None or not all(p.exists() for p in self._outputs(stage, scene)):
                out["missing"].append(scene)
                continue
            try:
                key = self.scene_key(stage, scene, i, manifests, extra)
            except DynclevrError:
                out["stale"].append(scene)
                continue
            out["done" if manifest.fresh(scene, key, self._outputs(stage, scene)) else "stale"].append(scene)
        return out


class Interrupted(DynclevrError):
    """Ctrl-C during a stage: what is done is recorded, and the same command resumes."""


class StageFailed(DynclevrError):
    """Scenes that failed for a reason of their own, each by id; every other scene of the stage ran and is recorded,
    and the split-level outputs wait. One line: the first failure's own message says what to do."""

    def __init__(self, stage: str, failed: dict[str, BaseException], total: int):
        self.failed = failed
        ids = sorted(failed)
        first = failed[ids[0]]
        what = str(first) if isinstance(first, DynclevrError) else f"{type(first).__name__}: {first}"
        shown = ", ".join(ids[:10]) + (f" and {len(ids) - 10} more" if len(ids) > 10 else "")
        super().__init__(f"{stage} failed on {len(ids)} of {total} scenes ({shown}; the other {total - len(ids)} are "
                         f"done and recorded); {ids[0]}: {' '.join(what.split())}")


def _rate_column():
    """Scenes per minute, a column of the progress bar (rich is imported where the bar is drawn)."""
    from rich.progress import ProgressColumn
    from rich.text import Text

    class Rate(ProgressColumn):
        def render(self, task):
            speed = task.finished_speed or task.speed
            return Text(f"{60 * speed:.1f} scenes/min" if speed else "-- scenes/min", style="progress.data.speed")

    return Rate()


# ---- Ray (the optional extra) ---------------------------------------------------------------------------------------

RAY_MISSING = ("--executor ray needs Ray, which is not installed: run `make ray` (or `pip install -e '.[ray]'`) "
               "in this environment")


def require_ray():
    try:
        import ray
    except ImportError:
        raise DynclevrError(RAY_MISSING) from None
    return ray


def _ray_connect(address: str | None, workers: int):
    """The Ray this process already joined (a caller's ray.init), the cluster at `address` ("auto": the one
    `ray start` began on this node), or a local Ray of `workers` CPUs started now and stopped with the process."""
    import logging

    ray = require_ray()
    if not ray.is_initialized():
        quiet = dict(logging_level=logging.WARNING, log_to_driver=False, include_dashboard=False)
        try:
            if address:
                ray.init(address=address, **quiet)
            else:
                # A Ray of this process's own, on this machine: its notice that token authentication is on (the
                # secure default) is noise on every command. Its workers run at the command's own priority, as the
                # local pool's do: with Ray's default (nice 15), two busy processes on the cores made the
                # executor tests' Ray runs 6 to 17 times slower.
                logging.getLogger("ray._private.authentication.authentication_token_setup").setLevel(logging.ERROR)
                ray.init(num_cpus=workers, object_store_memory=100 * 1024 ** 2, _system_config=OWN_RAY, **quiet)
        except ConnectionError as e:
            raise DynclevrError(f"cannot join the Ray cluster at {address}: {e} (start it with `ray start --head`, "
                                f"or leave out --ray-address for a local Ray)") from None
    return ray


_RAY_TASK = None


def _ray_task(ray):
    global _RAY_TASK
    if _RAY_TASK is None:
        # max_retries: a dead worker's scene runs again (atomic writes: no half-written artifact is ever seen);
        # not retry_exceptions: a scene that raises fails the same way again. max_calls: as WORKER_TASKS.
        _RAY_TASK = ray.remote(num_cpus=1, max_retries=RAY_RETRIES, retry_exceptions=False,
                               max_calls=WORKER_TASKS)(_run_in_ray)
    return _RAY_TASK


def _absolute(job: SceneJob) -> SceneJob:
    return replace(job, data_dir=Path(job.data_dir).absolute(),
                   inputs={k: [Path(p).absolute() for p in v] for k, v in job.inputs.items()},
                   outputs=[Path(p).absolute() for p in job.outputs])


def _run_in_ray(name: str, job: SceneJob) -> None:
    os.environ["OMP_NUM_THREADS"] = "1"   # as _worker_init: one core per task
    _run_in_worker(name, job)


# ---- one writer per split -------------------------------------------------------------------------------------------

_HELD: dict[Path, int] = {}   # lock file -> nesting depth in this process (`run` takes it once per stage)
LEFTOVER_AGE = 60.0            # seconds: a temporary file this old, found under the lock, is a killed write's,
                               # and so is one whose writer (the pid in its name, atomic_path) has exited


def _leftover(tmp: Path, now: float) -> bool:
    parts = tmp.name.split(".")
    pid = parts[-3] if len(parts) > 3 else ""
    if pid.isdigit() and int(pid) != os.getpid():
        try:
            os.kill(int(pid), 0)
        except ProcessLookupError:
            return True
        except OSError:     # alive, another user's
            pass
    return now - tmp.stat().st_mtime > LEFTOVER_AGE


@contextlib.contextmanager
def split_lock(root: Path, echo=print):
    """Hold <data-dir>/<split>/.lock while a stage runs: a second dynclevr process on the split says what it waits
    for and waits, so that two runs never interleave their manifests or both do the same work. Under the lock,
    temporary files that a killed write left behind are removed."""
    path = (Path(root) / ".lock").resolve()
    if path in _HELD:
        _HELD[path] += 1
        try:
            yield
        finally:
            _HELD[path] -= 1
        return
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        f = open(path, "a+")
    except OSError as e:   # --data-dir names a file, or a folder without write permission
        raise ArtifactError(f"cannot write {path} ({e.strerror}): choose a writable folder") from None
    with f:
        try:
            fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            f.seek(0)
            echo(f"waiting for {path}: held by {f.read().strip() or 'another dynclevr process'}")
            fcntl.flock(f, fcntl.LOCK_EX)
        f.seek(0)
        f.truncate()
        f.write(f"pid {os.getpid()} (dynclevr {' '.join(sys.argv[1:])})")
        f.flush()
        now = time.time()
        for tmp in path.parent.rglob(".*.tmp"):
            if _leftover(tmp, now):
                tmp.unlink(missing_ok=True)
        _HELD[path] = 1
        try:
            yield
        finally:
            del _HELD[path]   # closing the file releases the lock


@contextlib.contextmanager
def _ctrl_c_deferred():
    """Start workers with Ctrl-C ignored, so that one still importing when it comes prints no traceback over the
    report: an ignored signal stays ignored across exec, and Python then installs no KeyboardInterrupt handler.
    In this process SIGINT is blocked meanwhile (Linux keeps a blocked signal pending even while it is ignored),
    so a Ctrl-C then arrives when the handler is back, not lost."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    # The resource tracker unblocks SIGINT once it has started: start it first.
    from multiprocessing import resource_tracker

    resource_tracker.ensure_running()
    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


def _pool_context():
    """Workers forked from one fork server that imported every stage once (with one core per worker in its
    environment, read by the numeric libraries as they load): a stage's pool then starts in milliseconds instead of
    the seconds that importing torch, scipy and the stage take in each spawned worker, over and over through a run
    of thirteen stage runs. Like spawn, a worker shares no state with this process. (The server is started again,
    the same way, if it has died.)"""
    from multiprocessing import forkserver, get_all_start_methods

    if "forkserver" not in get_all_start_methods():   # (Windows)
        return get_context("spawn")
    ctx = get_context("forkserver")
    ctx.set_forkserver_preload(["dynclevr.fork_server",
                                *("dynclevr.stages." + name.replace("-", "_") for name in ORDER + BASELINES)])
    before = os.environ.get("OMP_NUM_THREADS")
    os.environ["OMP_NUM_THREADS"] = "1"
    try:
        with _ctrl_c_deferred():   # the server, and so every worker forked from it, ignores Ctrl-C
            forkserver.ensure_running()
    finally:
        if before is None:
            del os.environ["OMP_NUM_THREADS"]
        else:
            os.environ["OMP_NUM_THREADS"] = before
    return ctx


def _worker_init() -> None:
    # One core per worker: the pool is the parallelism.
    os.environ["OMP_NUM_THREADS"] = "1"
    die_with_parent()


def die_with_parent() -> None:
    """After a kill -9 of the main process a worker would otherwise write files that no manifest records, then idle
    at a few hundred MB for ever; a worker dies with the fork server, and the server with the main process
    (dynclevr.fork_server). Linux: prctl PR_SET_PDEATHSIG."""
    if sys.platform.startswith("linux"):
        import ctypes
        import signal

        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)   # 1 = PR_SET_PDEATHSIG
        if os.getppid() == 1:   # the parent died before the line above ran
            os._exit(1)


def _run_in_worker(name: str, job: SceneJob) -> None:
    get_stage(name).run_scene(job)
