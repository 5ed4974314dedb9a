"""Only the wheel's data: pyproject.toml says everything else.

A checkout keeps pipeline.toml, schemas/ and weights/ at the repository root (the design's layout); a wheel carries
them inside the package as dynclevr/_data/, where dynclevr/__init__.py finds them when no checkout is around.
Resume checkpoints are left out: running needs the weights, not an optimiser's state."""

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

ROOT_DATA = ("pipeline.toml", "schemas", "weights")
LEFT_OUT = ("checkpoint.pt", "*.tmp", ".*")


class BuildPyWithData(build_py):
    def run(self):
        super().run()
        if getattr(self, "editable_mode", False):   # an editable install reads the checkout itself
            return
        out = Path(self.build_lib) / "dynclevr" / "_data"
        shutil.rmtree(out, ignore_errors=True)
        out.mkdir(parents=True)
        for name in ROOT_DATA:
            src = Path(name)
            if src.is_dir():
                shutil.copytree(src, out / name, ignore=shutil.ignore_patterns(*LEFT_OUT))
            else:
                shutil.copy2(src, out / name)


setup(cmdclass={"build_py": BuildPyWithData})
