"""Bad input, end to end through the CLI: one line `error: ...` naming the problem and the fix, exit code 2, no
traceback, and nothing already written lost or changed."""

import contextlib
import hashlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from dynclevr import DynclevrError
from dynclevr.artifacts import ArtifactError, Manifest, Store, read_parquet, write_parquet
from dynclevr.config import Config, ConfigError
from dynclevr.pipeline import Runner, SceneJob, parse_scenes
from dynclevr.questions.tables import QUESTIONS_SCHEMA, QUESTIONS_VERSION
from dynclevr.stages import answer, simulate
from dynclevr.video import Video

SPLIT = "x"


def cli(data: Path, *args: str, config: Path | None = None):
    config = config or data.parent / "x.toml"
    return subprocess.run([sys.executable, "-m", "dynclevr.cli", *args, "--split", SPLIT, "--config", str(config),
                           "--data-dir", str(data)], capture_output=True, text=True)


def error_line(out) -> str:
    """The one line a failed command prints."""
    assert out.returncode == 2, (out.stdout, out.stderr)
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), out.stderr
    return lines[0]


def checksums(data: Path) -> dict[str, str]:
    """Every data file (not the split's lock file, which names the last process that held it)."""
    return {str(p.relative_to(data)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(data.rglob("*")) if p.is_file() and p.name != ".lock"}


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    """Two simulated, rendered and annotated scenes: a pristine copy each test starts from."""
    root = tmp_path_factory.mktemp("bad_input")
    (root / "x.toml").write_text(f"[splits.{SPLIT}]\nseed = 3\nscenes = 2\n")
    data = root / "data"
    for args in (["simulate"], ["render"], ["annotate"]):
        out = cli(data, *args)
        assert out.returncode == 0 and out.stderr == "", out.stderr   # nothing on stderr, not even pybullet's banner
    return data


@pytest.fixture
def data(built, tmp_path) -> Path:
    (tmp_path / "x.toml").write_text(f"[splits.{SPLIT}]\nseed = 3\nscenes = 2\n")
    shutil.copytree(built, tmp_path / "data")
    return tmp_path / "data"


def test_deleted_input_names_the_stage_to_rerun_and_keeps_the_rest(data):
    store = Store(data, SPLIT)
    store.path("simulate", "000001", ".mcap").unlink()
    before = checksums(data)
    line = error_line(cli(data, "annotate", "--force"))
    # the exact command: that scene only (no --force: the cache sees the damage), on this data dir and config
    assert "sim/000001.mcap is missing" in line and (
        f"`dynclevr simulate --split x --scenes 1 --data-dir {data} --config {data.parent / 'x.toml'}`") in line
    assert checksums(data) == before
    assert cli(data, "simulate").returncode == 0   # the same seed gives the same bytes: annotate stays cached
    out = cli(data, "annotate")
    assert out.returncode == 0 and "annotate: 0 to run, 2 cached" in out.stdout, out.stdout


@pytest.mark.parametrize("damage", ["truncate", "zero bytes"])
def test_damaged_video_is_one_clear_error(data, damage):
    path = Store(data, SPLIT).path("render", "000000", ".mcap")
    raw = bytearray(path.read_bytes())
    if damage == "truncate":
        raw = raw[:len(raw) // 2]
    else:   # inside a JPEG frame: decodes to a plausible image unless the chunk's CRC is checked
        raw[len(raw) // 2:len(raw) // 2 + 200] = bytes(200)
    path.write_bytes(bytes(raw))
    with pytest.raises(ArtifactError, match=r"000000.mcap is (not a readable MCAP file|corrupt).*"
                                            r"rerun `dynclevr render --split x --scenes 0 --data-dir ") as e:
        Video.read(path).frames()
    assert "\n" not in str(e.value)
    line = error_line(cli(data, "export-video", "--scene", "0", "--out", str(data.parent / "x.mp4")))
    assert "video/000000.mcap" in line and not (data.parent / "x.mp4").exists()


def test_garbage_manifest_costs_a_rerun_not_the_data(data):
    Store(data, SPLIT).manifest("simulate").path.write_text("garbage{")
    before = {k: v for k, v in checksums(data).items() if not k.startswith("x/manifests/")}
    line = error_line(cli(data, "annotate"))
    assert (f"manifests/sim.json is corrupt for annotate: run `dynclevr simulate --split x --data-dir {data} "
            f"--config {data.parent / 'x.toml'}` first") in line
    assert cli(data, "simulate").returncode == 0
    assert {k: v for k, v in checksums(data).items() if not k.startswith("x/manifests/")} == before
    out = cli(data, "annotate")
    assert out.returncode == 0 and "annotate: 0 to run, 2 cached" in out.stdout, out.stdout


@pytest.mark.parametrize("text", ['[1, 2]', '{"entries": {"000000": 5}}', '{"entries": {"000000": {"key": "k"}}}',
                                  '{"entries": []}'])
def test_malformed_manifest_reads_as_corrupt(tmp_path, text):
    (tmp_path / "manifest.json").write_text(text)
    m = Manifest(tmp_path / "manifest.json")
    assert m.corrupt and m.entries == {} and m.digest("000000") is None


def test_wrong_version_questions_table(data):
    path = Store(data, SPLIT).split_file("questions.parquet")
    good = path.read_bytes()
    write_parquet(read_parquet(path, QUESTIONS_SCHEMA, QUESTIONS_VERSION), path, QUESTIONS_SCHEMA,
                  QUESTIONS_VERSION + 1)
    line = error_line(cli(data, "report"))
    assert (f"has schema dynclevr.questions v{QUESTIONS_VERSION + 1}, expected dynclevr.questions "
            f"v{QUESTIONS_VERSION}") in line
    assert f"`dynclevr annotate --split x --data-dir {data} --config {data.parent / 'x.toml'}`" in line
    # annotate sees the split-level table changed and writes it again, without --force
    out = cli(data, "annotate")
    assert out.returncode == 0 and "wrote questions.parquet" in out.stdout, out.stdout
    assert path.read_bytes() == good


def test_answer_before_its_inputs(data, tmp_path):
    line = error_line(cli(data, "answer"))
    assert "parsed/000000 is missing for answer: run `dynclevr parse-scene --split x --data-dir" in line
    # questions.parquet is read before anything else of the model's
    job = SceneJob(SPLIT, "000000", 0, 0, Config.load().data, tmp_path / "empty", {}, [tmp_path / "a.parquet"])
    with pytest.raises(ArtifactError, match=r"questions.parquet is missing: rerun `dynclevr annotate --split x --data-dir"):
        answer.run_scene(job)


def test_scene_ranges_and_workers(data):
    split = Config.load(data.parent / "x.toml").split(SPLIT)
    for spec in ("9-12", "1-0", "abc", "-1", "0,,1"):
        with pytest.raises(DynclevrError, match="--scenes"):
            parse_scenes(spec, split)
    assert "split 'x' has scenes 0-1 only" in error_line(cli(data, "render", "--scenes", "9-12"))
    assert "split 'x' has scenes 0-1" in error_line(cli(data, "export-video", "--scene", "9", "--out", "y.mp4"))
    out = cli(data, "render", "--workers", "0")
    assert out.returncode == 2 and "--workers" in out.stderr and "Traceback" not in out.stderr


@pytest.mark.parametrize("text, message", [
    ("[video]\nframes = 100.5\n", "'video.frames' = 100.5 has the wrong type"),
    ("[render]\nwidth = 320.0\n", "'render.width' = 320.0 has the wrong type"),
    ("[physics]\ngravity = 9\n", None),   # an integer where a float is expected is fine
    ("\xff[video]\n", "is not valid TOML"),
])
def test_config_value_types(tmp_path, text, message):
    path = tmp_path / "user.toml"
    path.write_bytes(text.encode("latin-1"))
    if message is None:
        assert Config.load(path)["physics"]["gravity"] == 9.0
    else:
        with pytest.raises(ConfigError, match=message):
            Config.load(path)


def test_bad_scene_values_are_caught_before_any_scene_runs(tmp_path):
    for text, message in [("camera_jitter = -1.0", "'scene.camera_jitter' = -1.0 must not be negative"),
                          ("focal_length_mm = 0.0", "'scene.focal_length_mm' = 0.0 must be positive")]:
        (tmp_path / "user.toml").write_text(f"[scene]\n{text}\n")
        with pytest.raises(ConfigError, match=message):
            simulate.params(Config.load(tmp_path / "user.toml"))


def test_unusable_paths(data):
    assert "not found: pass an existing TOML file" in error_line(cli(data, "status", config=data.parent / "no.toml"))
    assert "cannot be read (Is a directory)" in error_line(cli(data, "status", config=data.parent))
    blocker = data.parent / "a-file"
    blocker.write_text("")
    line = error_line(cli(blocker, "simulate"))
    assert "cannot write" in line and "choose a writable folder" in line
    line = error_line(cli(data, "export-video", "--scene", "0", "--out", str(data.parent)))
    assert "name the file .mp4" in line
    folder = data.parent / "a-folder.mp4"
    folder.mkdir()
    line = error_line(cli(data, "export-video", "--scene", "0", "--out", str(folder)))
    assert "name a file, not a folder" in line


def test_split_table_waits_for_stale_scenes(data, tmp_path):
    """After a params change, running a subset of scenes must not mix old and new scenes into questions.parquet."""
    path = Store(data, SPLIT).split_file("questions.parquet")
    before = path.read_bytes()
    (tmp_path / "user.toml").write_text(f"[splits.{SPLIT}]\nseed = 3\nscenes = 2\n[labels]\ncompare_margin = 2.0\n")
    cfg = Config.load(tmp_path / "user.toml")
    said = []
    runner = Runner(cfg, cfg.split(SPLIT), data, echo=said.append)
    runner.run("annotate", [0])
    assert path.read_bytes() == before and any("wait for 1 scenes" in s for s in said), said
    runner.run("annotate", [1])
    assert "annotate: wrote questions.parquet" in said


def test_hints_are_commands_that_fix_it(data):
    """Issue 14: a printed fix is the exact command (typed as printed, it repairs the damaged scene only)."""
    path = Store(data, SPLIT).path("render", "000001", ".mcap")
    other = Store(data, SPLIT).path("render", "000000", ".mcap").read_bytes()
    path.write_bytes(path.read_bytes()[:1000])
    line = error_line(cli(data, "annotate", "--force"))
    command = line.split("`")[1]
    out = subprocess.run([sys.executable, "-m", "dynclevr.cli", *command.split()[1:]], capture_output=True, text=True)
    assert out.returncode == 0 and "render: 1 to run, 0 cached" in out.stdout, (command, out.stdout, out.stderr)
    assert Store(data, SPLIT).path("render", "000000", ".mcap").read_bytes() == other   # only the damaged scene
    assert cli(data, "annotate", "--force").returncode == 0


def test_reversed_range_and_missing_data_dir_say_so(data, tmp_path):
    assert "the range 5-2 is reversed (did you mean 2-5?)" in error_line(cli(data, "render", "--scenes", "5-2"))
    line = error_line(cli(tmp_path / "nowhere", "stats"))
    assert "no simulated scenes under" in line and f"--data-dir {tmp_path / 'nowhere'}" in line


def test_two_runs_on_one_split_take_turns(data):
    """Issue 14: two stage runs at once on one data dir: the second says what it waits for; both manifest entries
    survive; a killed write's leftover temporary file is removed."""
    import time

    store = Store(data, SPLIT)
    leftover = store.stage_dir("render") / ".000000.mcap.abcd.tmp"
    leftover.write_bytes(b"half a file")
    os.utime(leftover, (time.time() - 3600, time.time() - 3600))
    config = data.parent / "x.toml"
    args = [sys.executable, "-m", "dynclevr.cli", "render", "--force", "--split", SPLIT, "--config", str(config),
            "--data-dir", str(data), "--scenes"]
    first = subprocess.Popen(args + ["0"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        lock = store.root / ".lock"
        deadline = time.time() + 60
        while not (lock.exists() and f"pid {first.pid}" in lock.read_text()) and time.time() < deadline:
            time.sleep(0.05)
        second = subprocess.run(args + ["1"], capture_output=True, text=True, timeout=300)
        assert first.wait(60) == 0 and second.returncode == 0, second.stderr
    finally:
        first.kill()   # a no-op once it has exited; else it would hold the split's lock for the next test
    assert f"held by pid {first.pid} (dynclevr render --force" in second.stdout
    assert set(store.manifest("render").entries) >= {"000000", "000001"}
    assert not leftover.exists()
    status = subprocess.run([sys.executable, "-m", "dynclevr.cli", "status", "--split", SPLIT, "--config",
                             str(config), "--data-dir", str(data)], capture_output=True, text=True)
    render = next(line for line in status.stdout.splitlines() if line.split()[:1] == ["render"])
    assert render.split() == ["render", "done", "2", "stale", "0", "missing", "0"], status.stdout


def _children(pid: int) -> list[int]:
    out = subprocess.run(["pgrep", "-P", str(pid)], capture_output=True, text=True).stdout
    return [int(p) for p in out.split()]


def _descendants(pid: int) -> list[int]:
    """The process's children and theirs: the pool's workers are the fork server's, which is the main process's."""
    return [d for c in _children(pid) for d in (c, *_descendants(c))]


def _workers(pid: int) -> list[int]:
    return [w for c in _children(pid) if "forkserver" in Path(f"/proc/{c}/cmdline").read_text() for w in _children(c)]


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError):
        return False
    return state not in ("Z", "X")   # a zombie has exited: only its parent (init here) has yet to reap it


@contextlib.contextmanager
def _render_with_workers(data):
    """A render of 2 scenes on 2 workers, in a session of its own, once both workers have started: (main, worker
    pids). What the test leaves running of that session (its process group) is killed after it, so that a failed
    check cannot leave the split's lock held for the next test."""
    import signal
    import time

    args = [sys.executable, "-m", "dynclevr.cli", "render", "--force", "--workers", "2", "--scenes", "0-1",
            "--split", SPLIT, "--config", str(data.parent / "x.toml"), "--data-dir", str(data)]
    # As from a terminal: a shell that started the tests in the background (`make test &`) made them ignore SIGINT,
    # and an ignored signal stays ignored in every child.
    main = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.time() + 60
    while len(_workers(main.pid)) < 2 and time.time() < deadline:
        time.sleep(0.1)
    try:
        workers = _descendants(main.pid)
        assert len(_workers(main.pid)) >= 2, "the pool never started"
        yield main, workers
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(main.pid, signal.SIGKILL)
        main.wait(60)


def test_workers_die_with_their_parent(data):
    """Issue 14: kill -9 of the main process leaves no worker running; a rerun gives the same bytes."""
    import signal
    import time

    before = checksums(data)
    with _render_with_workers(data) as (main, workers):
        os.kill(main.pid, signal.SIGKILL)
        main.wait(60)
        time.sleep(5)
        assert not [w for w in workers if _alive(w)]
    assert cli(data, "render").returncode == 0
    assert checksums(data) == before


def test_ctrl_c_stops_cleanly_and_says_how_to_go_on(data):
    import signal
    import time

    with _render_with_workers(data) as (main, workers):
        os.killpg(main.pid, signal.SIGINT)   # what a terminal sends: the whole process group
        _, err = main.communicate(timeout=120)
        assert main.returncode == 130, err
        assert err.strip().splitlines()[-1].startswith("interrupted: render stopped after ") and \
            err.strip().endswith("run the same command again to go on"), err
        time.sleep(5)   # (multiprocessing's resource tracker leaves when it notices its parent is gone)
        assert not [w for w in workers if _alive(w)]
    assert cli(data, "render").returncode == 0


def test_export_video_is_h264_and_refuses_other_extensions(data):
    """Issue 14: browsers play the export (probe the codec); a name it cannot write is refused up front."""
    import imageio_ffmpeg

    out = data.parent / "scene.mp4"
    done = cli(data, "export-video", "--scene", "0", "--out", str(out), "--overlay", "boxes")
    assert done.returncode == 0, done.stderr
    probe = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-i", str(out)], capture_output=True,
                           text=True).stderr
    assert "Video: h264" in probe and "yuv420p" in probe and "320x240" in probe, probe
    line = error_line(cli(data, "export-video", "--scene", "0", "--out", str(data.parent / "scene.avi")))
    assert "writes H.264 in MP4; name the file .mp4" in line and not (data.parent / "scene.avi").exists()


def test_a_killed_writers_temporary_files_go_at_the_next_run_under_the_lock(tmp_path):
    """Issue 14: a write's temporary file names its writer's pid, so the next run under the split's lock removes
    what a killed writer left at once (not only after LEFTOVER_AGE), and never a live writer's."""
    import time

    from dynclevr.artifacts import atomic_path
    from dynclevr.pipeline import split_lock

    with atomic_path(tmp_path / "video" / "000000.mcap") as tmp:
        assert tmp.name.startswith(f".000000.mcap.{os.getpid()}.") and tmp.name.endswith(".tmp")
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    files = {name: tmp_path / "video" / name for name in (
        f".000001.mcap.{dead.pid}.k2x9a0qz.tmp",       # its writer has exited: a leftover, however young
        f".000002.mcap.{os.getppid()}.k2x9a0qz.tmp",   # its writer is alive: kept
        ".000003.mcap.k2x9a0qz.tmp",                   # no pid, young: kept
        ".000004.mcap.k2x9a0qz.tmp")}                  # no pid, an hour old: a leftover
    for path in files.values():
        path.write_bytes(b"half a file")
    old = time.time() - 3600
    os.utime(files[".000004.mcap.k2x9a0qz.tmp"], (old, old))
    with split_lock(tmp_path, echo=lambda *_: None):
        pass
    assert {name for name, path in files.items() if path.exists()} == {
        f".000002.mcap.{os.getppid()}.k2x9a0qz.tmp", ".000003.mcap.k2x9a0qz.tmp"}
