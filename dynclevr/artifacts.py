"""The artifact store: `<data-dir>/<split>/<stage-dir>/`, manifests, atomic writes, schema-checked reads.

Every artifact carries its schema name and version (MCAP metadata record `dynclevr`, Parquet schema metadata);
every stage directory has a manifest, `<split>/manifests/<stage dir>.json`, with one entry per output: stage version,
the params it used, the digests of its inputs and its own digest. A stage reruns an output only when that cache key
changes (as `dvc repro`).

Tables are laid out to open as datasets: each folder of Parquet files holds one table (one schema, a `scene` column,
nulls where a value does not apply) and nothing else, so that `duckdb 'future/*.parquet'`, `polars.read_parquet(
'future')` and `pandas.read_parquet('future')` read a whole split in one call. Hence the manifests live outside the
folders (polars refuses a folder with any other file in it, whatever its name), and a stage with several per-scene
tables writes one sub-folder per table (`labels/events/<scene>.parquet`).
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq

from dynclevr import DynclevrError

# Stage name -> directory name under <data-dir>/<split>/ (DESIGN.md's artifact table).
STAGE_DIRS = {
    "simulate": "sim",
    "render": "video",
    "annotate": "labels",
    "parse-scene": "parsed",
    "simulate-future": "future",
    "answer": "answers",
    "answer-cnnlstm": "answers-cnnlstm",   # the CNN+LSTM baseline (it reads the video, not a parse)
}
# Which stage makes each artifact kind: named in "rerun ..." hints.
DIR_STAGES = {v: k for k, v in STAGE_DIRS.items()}
# The model's stages; a model variant (the paper's ablation without the physics prior) writes them to
# `<dir>-<variant>/` beside the main model's outputs so both rows of the report come from one data directory.
MODEL_STAGES = ("parse-scene", "simulate-future", "answer")


class ArtifactError(DynclevrError):
    pass


def file_digest(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


@contextlib.contextmanager
def atomic_path(path: Path):
    """Yield a temporary path beside `path`; rename it into place only if the block succeeds."""
    path = Path(path)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        # the writer's pid in the name: a later run under the split's lock removes what a killed writer left
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp", dir=path.parent)
    except OSError as e:   # --data-dir or --out names a file, or a folder without write permission
        raise ArtifactError(f"cannot write {path} ({e.strerror}: {e.filename}): choose a writable folder") from None
    os.close(fd)
    os.chmod(tmp, 0o644)  # mkstemp's 0600 would make artifacts unreadable to the rest of a team
    try:
        try:
            yield Path(tmp)
        except OSError as e:   # a full disk while writing: name the file (the error itself often names none)
            if e.filename:
                raise
            raise ArtifactError(f"cannot write {path} ({e.strerror}): check the free space on its disk") from None
        try:
            os.replace(tmp, path)
        except OSError as e:
            raise ArtifactError(f"cannot write {path} ({e.strerror}): name a file, not a folder") from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def write_json_atomic(path: Path, obj) -> None:
    with atomic_path(path) as tmp:
        tmp.write_text(json.dumps(obj, indent=1, sort_keys=True) + "\n")


@dataclass
class Store:
    """Paths of one split's artifacts."""

    data_dir: Path
    split: str
    variant: str = ""

    @property
    def root(self) -> Path:
        return Path(self.data_dir) / self.split

    def stage_dir(self, stage: str) -> Path:
        suffix = f"-{self.variant}" if self.variant and stage in MODEL_STAGES else ""
        return self.root / (STAGE_DIRS[stage] + suffix)

    def path(self, stage: str, scene: str, suffix: str) -> Path:
        """A per-scene output: `suffix` is ".mcap" (sim/000003.mcap) or "<table>/.parquet", one folder per table
        (labels/events/000003.parquet)."""
        table, _, suffix = suffix.rpartition("/")
        return self.stage_dir(stage) / table / f"{scene}{suffix}"

    def split_file(self, name: str) -> Path:
        """A split-level artifact such as questions.parquet or objects.parquet."""
        return self.root / name

    def model_file(self, name: str) -> Path:
        """A split-level output of a model stage: answers.parquet, or answers-noprior.parquet for a variant."""
        stem, dot, ext = name.partition(".")
        return self.root / (f"{stem}-{self.variant}{dot}{ext}" if self.variant else name)

    def manifest(self, stage: str) -> "Manifest":
        d = self.stage_dir(stage)
        return Manifest(self.root / MANIFEST_DIR / f"{d.name}.json", legacy=d / "manifest.json")


MANIFEST_DIR = "manifests"


class Manifest:
    """One stage directory's lock file: output name -> {key, params, inputs, digest, stage_version}.

    `legacy` is where a data dir of an older layout kept it (`<stage dir>/manifest.json`): read when the new file is
    absent, so that a stage whose outputs did not change keeps its cache, and removed by the first save."""

    def __init__(self, path: Path, legacy: Path | None = None):
        self.path = Path(path)
        self.entries: dict[str, dict] = {}
        self.corrupt = False
        self.legacy = legacy if legacy is not None and not self.path.exists() and legacy.exists() else None
        source = self.legacy or self.path
        if source.exists():
            try:
                entries = json.loads(source.read_text())["entries"]
                if not all(isinstance(e, dict) and isinstance(e.get("key"), str) and isinstance(e.get("digest"), str)
                           for e in entries.values()):
                    raise ValueError
                self.entries = entries
            except (ValueError, KeyError, TypeError, AttributeError):
                # A corrupt lock only costs a rerun; the artifacts themselves are checked on read.
                self.corrupt = True

    def fresh(self, name: str, key: str, outputs: list[Path]) -> bool:
        e = self.entries.get(name)
        if e is None or e["key"] != key or not all(p.exists() for p in outputs):
            return False
        return e["digest"] == digest_outputs(outputs)

    def record(self, name: str, key: str, outputs: list[Path], **info) -> None:
        self.entries[name] = {"key": key, "digest": digest_outputs(outputs), **info}

    def digest(self, name: str) -> str | None:
        e = self.entries.get(name)
        return e["digest"] if e else None

    def save(self) -> None:
        write_json_atomic(self.path, {"entries": dict(sorted(self.entries.items()))})
        if self.legacy is not None:
            self.legacy.unlink(missing_ok=True)
            self.legacy = None


def digest_outputs(outputs: list[Path]) -> str:
    if len(outputs) == 1:
        return file_digest(outputs[0])
    return hashlib.sha256("".join(file_digest(p) for p in outputs).encode()).hexdigest()


# Split-level artifacts -> the stage that writes them (a model variant's: answers-noprior.parquet).
SPLIT_FILES = {"objects.parquet": "simulate", "questions.parquet": "annotate", "answers.parquet": "answer",
               "metrics.parquet": "answer"}


# A baseline with a stage of its own, whose outputs are named like a model variant's: "cnnlstm" -> answer-cnnlstm.
BASELINE_STAGES = {"cnnlstm": "answer-cnnlstm"}
# store variant -> CLI flag
VARIANT_FLAGS = {"noprior": " --no-physics-prior", "particle": " --particle-filter", "perframe": " --per-frame"}

# The user's --config, set by the CLI, so that a printed command acts on the same data and settings as the one that
# failed (the data dir comes from the artifact's own path).
HINT_OPTIONS: dict[str, Path | None] = {"config": None}


def command_options(data_dir: Path) -> str:
    """' --data-dir D --config C' where they differ from the defaults: what a printed command must repeat."""
    opts = "" if Path(data_dir).resolve() == Path("data").resolve() else f" --data-dir {data_dir}"
    return opts + (f" --config {HINT_OPTIONS['config']}" if HINT_OPTIONS["config"] else "")


def rerun_hint(path: Path) -> str:
    """The command that rewrites a missing or damaged artifact: the stage on that scene only (the cache sees the
    damage, so no --force), or the stage for a split-level table."""
    path = Path(path)
    stem, _, variant = path.name.split(".", 1)[0].partition("-")
    base = stem + path.suffix
    if base in SPLIT_FILES:
        stage, split, scenes = SPLIT_FILES[base], path.parent.name, ""
        data_dir = path.parent.parent
    else:   # <data-dir>/<split>/<stage dir>[-<variant>]/[<table>/]<scene><suffix>
        folder = path.parent if path.parent.name.partition("-")[0] in DIR_STAGES else path.parent.parent
        kind, _, variant = folder.name.partition("-")
        stage, split, data_dir = DIR_STAGES.get(kind), folder.parent.name, folder.parent.parent
        scene = path.name.split(".", 1)[0]
        scenes = f" --scenes {int(scene)}" if scene.isdigit() else ""
    if variant in BASELINE_STAGES:   # answers-cnnlstm/, answers-cnnlstm.parquet: a stage of its own
        stage, variant = BASELINE_STAGES[variant], ""
    if not stage:
        return "regenerate it"
    flag = VARIANT_FLAGS.get(variant, "")
    return f"rerun `dynclevr {stage} --split {split}{scenes}{flag}{command_options(data_dir)}`"


# ---- Parquet ---------------------------------------------------------------------------------------------------

def write_parquet(table: pa.Table, path: Path, schema: str, version: int) -> None:
    """Write `table` atomically, stamped with its schema name and version."""
    meta = dict(table.schema.metadata or {})
    meta.update({b"dynclevr.schema": schema.encode(), b"dynclevr.version": str(version).encode()})
    table = table.replace_schema_metadata(meta)
    with atomic_path(path) as tmp:
        pq.write_table(table, tmp, compression="zstd")


def read_parquet(path: Path, schema: str, version: int, columns: list[str] | None = None) -> pa.Table:
    """Read a stamped table; a missing, corrupt or other-version file raises one clear ArtifactError."""
    path = Path(path)
    if not path.exists():
        raise ArtifactError(f"{path} is missing: {rerun_hint(path)}")
    try:
        meta = pq.read_schema(path).metadata or {}
    except (pa.ArrowException, OSError) as e:
        raise ArtifactError(f"{path} is not a readable Parquet file ({e}): {rerun_hint(path)}") from None
    found = (meta.get(b"dynclevr.schema", b"?").decode(), meta.get(b"dynclevr.version", b"?").decode())
    if found != (schema, str(version)):
        raise ArtifactError(f"{path} has schema {found[0]} v{found[1]}, expected {schema} v{version}: "
                            f"{rerun_hint(path)}")
    try:
        return pq.read_table(path, columns=columns)
    except (pa.ArrowException, OSError) as e:
        raise ArtifactError(f"{path} is corrupt ({e}): {rerun_hint(path)}") from None
