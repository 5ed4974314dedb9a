"""Issue 14: a real install. The wheel is built from the source tree and installed into a fresh virtual environment,
far from any checkout; there `dynclevr --version`, shell completion and `dynclevr run --split tiny` work.

The fresh environment sees the test environment's site-packages through a .pth line (a path line only: the editable
install's finder there is not loaded), so pip resolves every dependency, torch==2.13.0 included, without downloading
anything (--no-index); the wheel itself is the only thing installed. About 70 s: the `install` marker lets a quick
local run leave it out (`pytest -m "not install"`)."""

import os
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

from dynclevr import ROOT

pytestmark = pytest.mark.install
SKIP = shutil.ignore_patterns(".venv", "data", ".git", "build", "dist", "*.egg-info", "__pycache__", ".pytest_cache",
                              ".hypothesis", "bench-out")


def run(*args, **kw) -> subprocess.CompletedProcess:
    # no PYTHONPATH: it would put a checkout before the installed wheel
    kw.setdefault("env", {k: v for k, v in os.environ.items() if k != "PYTHONPATH"})
    out = subprocess.run([str(a) for a in args], capture_output=True, text=True, **kw)
    assert out.returncode == 0, (args, out.stdout[-2000:], out.stderr[-2000:])
    return out


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> Path:
    """The bin/ of a fresh venv with the wheel installed."""
    tmp = tmp_path_factory.mktemp("install")
    shutil.copytree(ROOT, tmp / "src", ignore=SKIP)   # a copy: the build leaves build/ in the tree it builds
    run(sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "--no-build-isolation", "--disable-pip-version-check",
        "-w", tmp / "dist", tmp / "src")
    (wheel,) = (tmp / "dist").glob("dynclevr-*.whl")
    names = set(zipfile.ZipFile(wheel).namelist())
    for name in ("dynclevr/_data/pipeline.toml", "dynclevr/_data/schemas/dynclevr.FrameStates.json",
                 "dynclevr/_data/weights/qparser/model.pt", "dynclevr/_data/weights/detector/detector.pt",
                 "dynclevr/questions/templates.json", "dynclevr/questions/taught.json",
                 "dynclevr/language/out_of_scope.txt",
                 "dynclevr/language/synonyms.txt", "dynclevr/language/wordnet.txt", "dynclevr/language/english.txt",
                 "dynclevr/assets/collision/sedan.obj"):
        assert name in names, name
    assert not any(n.endswith("checkpoint.pt") for n in names)   # resume checkpoints stay in the checkout
    run(sys.executable, "-m", "venv", "--without-pip", tmp / "venv")
    python = tmp / "venv" / "bin" / "python"
    site = Path(run(python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])").stdout.strip())
    (site / "test-deps.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    run(sys.executable, "-m", "pip", "--python", python, "install", "-q", "--no-index", "--disable-pip-version-check",
        wheel)
    return tmp / "venv" / "bin"


def test_the_installed_wheel_runs_the_tiny_split(installed, tmp_path):
    work = tmp_path / "elsewhere"   # no checkout here: everything must come from the wheel
    work.mkdir()
    where = run(installed / "python", "-c", "import dynclevr; print(dynclevr.__file__); print(dynclevr.ROOT)",
                cwd=work).stdout.split()
    assert all(p.startswith(str(installed.parent)) for p in where), where
    assert run(installed / "dynclevr", "--version", cwd=work).stdout.strip() == "dynclevr 0.1.0"
    out = run(installed / "dynclevr", "run", "--split", "tiny", "--no-ablation", "--workers", "2", cwd=work)
    assert "answer: wrote answers.parquet" in out.stdout, out.stdout
    report = run(installed / "dynclevr", "report", "--split", "tiny", cwd=work).stdout
    assert "| NS-4DPhysics (ours) |" in report and "| oracle (truth scene, gold programs) | 100.00 |" in report, report
    assert (work / "data" / "tiny" / "answers.parquet").exists()


def test_shell_completion_completes_commands_and_splits(installed, tmp_path):
    """The script `dynclevr --show-completion` prints, sourced into bash as `--install-completion` would."""
    def complete(*words: str) -> list[str]:
        script = ('eval "$(dynclevr --show-completion)"; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); '
                  '_dynclevr_completion dynclevr; printf "%s\\n" "${COMPREPLY[@]}"')
        env = {"PATH": f"{installed}:/usr/bin:/bin", "HOME": str(tmp_path)}
        return run("bash", "-c", script, "bash", *words, env=env, cwd=tmp_path).stdout.split()

    assert complete("dynclevr", "ren") == ["render"]
    assert complete("dynclevr", "simulate-") == ["simulate-future"]
    assert complete("dynclevr", "run", "--split", "ti") == ["tiny"]
