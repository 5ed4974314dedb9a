"""dynclevr: DynSuperCLEVR data generation and the NS-4DPhysics model."""

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCHEMA_DIR = ROOT / "schemas"
WEIGHTS_DIR = ROOT / "weights"


class DynclevrError(Exception):
    """An error the CLI reports as one line: what is wrong and how to fix it."""
