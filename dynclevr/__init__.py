"""dynclevr: DynSuperCLEVR data generation and the NS-4DPhysics model."""

from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

_PACKAGE = Path(__file__).resolve().parent
# pipeline.toml, schemas/ and weights/: at the root of a checkout (and of an editable install); an installed wheel
# carries them inside the package as _data/ (setup.py).
ROOT = _PACKAGE / "_data" if (_PACKAGE / "_data").is_dir() else _PACKAGE.parent
SCHEMA_DIR = ROOT / "schemas"
WEIGHTS_DIR = ROOT / "weights"

try:
    __version__ = version("dynclevr")
except PackageNotFoundError:   # a checkout on sys.path without being installed
    __version__ = "0+unknown"


class DynclevrError(Exception):
    """An error the CLI reports as one line: what is wrong and how to fix it."""
