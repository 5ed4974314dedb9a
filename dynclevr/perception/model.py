"""The trained scene parser's parts in one file: weights/parser/parser.pt, described by weights/parser/manifest.json.

parser.pt holds the feature CNN, the neural meshes (points, neural textures), the clutter model and the colour
classifier; manifest.json the data it was trained on, its params, its metrics, the training time and parser.pt's
sha256 (the parse-scene stage's cache depends on that manifest).
"""

from __future__ import annotations

import io
import json
from dataclasses import dataclass
from pathlib import Path

import torch

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import atomic_path, file_digest, write_json_atomic
from dynclevr.perception.color import ColorNet
from dynclevr.perception.features import FeatureNet
from dynclevr.perception.neural_mesh import NeuralMeshes

WEIGHTS_FILE = "parser.pt"
MANIFEST = "manifest.json"
DEFAULT_DIR = WEIGHTS_DIR / "parser"


class WeightsError(DynclevrError):
    pass


@dataclass
class ParserModel:
    net: FeatureNet
    meshes: NeuralMeshes
    color: ColorNet
    feature_dim: int
    width: int

    def save(self, out_dir: Path, manifest: dict) -> None:
        buf = io.BytesIO()
        torch.save({"net": self.net.state_dict(), "meshes": self.meshes.state(), "color": self.color.state_dict(),
                    "feature_dim": self.feature_dim, "width": self.width}, buf)
        out = Path(out_dir) / WEIGHTS_FILE
        with atomic_path(out) as tmp:
            tmp.write_bytes(buf.getvalue())
        write_json_atomic(Path(out_dir) / MANIFEST, {**manifest, "weights_sha256": file_digest(out)})

    @classmethod
    def load(cls, weights_dir: Path = DEFAULT_DIR) -> "ParserModel":
        path = Path(weights_dir) / WEIGHTS_FILE
        manifest = Path(weights_dir) / MANIFEST
        if not path.exists() or not manifest.exists():
            raise WeightsError(f"scene-parser weights missing in {weights_dir}: run `dynclevr train parser`")
        if json.loads(manifest.read_text()).get("weights_sha256") != file_digest(path):
            raise WeightsError(f"{path} does not match its manifest: rerun `dynclevr train parser`")
        s = torch.load(path, weights_only=True)
        net = FeatureNet(s["feature_dim"], s["width"])
        net.load_state_dict(s["net"])
        net.eval()
        color = ColorNet()
        color.load_state_dict(s["color"])
        color.eval()
        return cls(net, NeuralMeshes.from_state(s["meshes"]), color, s["feature_dim"], s["width"])


def manifest_digest(weights_dir: Path = DEFAULT_DIR) -> str:
    """What the parse-scene cache depends on: the manifest (which names the weights' sha256)."""
    path = Path(weights_dir) / MANIFEST
    return file_digest(path) if path.exists() else "missing"
