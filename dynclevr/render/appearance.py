"""Vehicle appearance (paper: 8 colours x 6 texture variants; only the body takes the object's colour).

A variant changes shade, pattern or gloss but never the colour category: the nearest Super-CLEVR colour of a
variant's mean RGB is always its own colour (tests/test_render.py checks all 48). The other parts have fixed
materials: black tyres, dark glass, red lights.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import cv2
import numpy as np

from dynclevr.colors import COLOR_NAMES, COLORS

VARIANTS = ("matte", "glossy", "dark", "light", "striped", "speckled")
TEXTURE_SIZE = 64


@dataclass(frozen=True)
class Material:
    texture: np.ndarray      # uint8 [S, S, 3] sRGB albedo, tileable; mapped at `texture_scale` metres per tile
    roughness: float         # 0 mirror .. 1 chalk (realistic backend; the fast backend maps it to specular)
    metallic: float = 0.0
    texture_scale: float = 1.0

    @property
    def mean_rgb(self) -> np.ndarray:
        return self.texture.reshape(-1, 3).mean(0)

    @property
    def uniform(self) -> bool:
        return bool((self.texture == self.texture[0, 0]).all())


def nearest_color(rgb) -> str:
    rgb = np.asarray(rgb, float)
    return min(COLOR_NAMES, key=lambda c: float(np.sum((rgb - np.array(COLORS[c], float)) ** 2)))


def _texture(rgb) -> np.ndarray:
    """A colour or an [S, S, 3] float image -> an [S, S, 3] uint8 texture."""
    return np.broadcast_to(np.clip(np.round(rgb), 0, 255).astype(np.uint8), (TEXTURE_SIZE, TEXTURE_SIZE, 3)).copy()


@lru_cache(maxsize=None)
def body_material(color: str, variant: int) -> Material:
    """The body material of one of the 8 x 6 colour variants (deterministic: no random draw)."""
    if color not in COLORS:
        raise KeyError(f"unknown colour {color!r}; known: {', '.join(COLOR_NAMES)}")
    base = np.array(COLORS[color], float)
    name = VARIANTS[variant]
    S = TEXTURE_SIZE
    if name == "matte":
        return Material(_texture(base), roughness=0.75)
    if name == "glossy":
        return Material(_texture(base), roughness=0.12)
    if name == "dark":
        return Material(_texture(base * 0.78), roughness=0.4)
    if name == "light":
        return Material(_texture(base * 1.22 + 6), roughness=0.5)
    yy, xx = np.mgrid[0:S, 0:S]
    if name == "striped":
        # Racing stripes: a band of a darker shade of the same colour along the vehicle.
        band = ((yy // 8) % 4 == 0)[..., None]
        tex = np.where(band, base * 0.62, base * 1.04)
        return Material(_texture(tex), roughness=0.35, texture_scale=1.2)
    # Metallic paint: a soft mottle of brightness around the colour (a fixed seed: the texture is the variant).
    noise = np.random.default_rng(COLOR_NAMES.index(color)).normal(0.0, 1.0, (S, S))
    noise = cv2.GaussianBlur(np.pad(noise, 8, mode="wrap"), (0, 0), 2.5)[8:-8, 8:-8]   # tileable
    noise = (noise / noise.std() * 0.08)[..., None]
    tex = base * (1 + noise) + 12 * noise
    return Material(_texture(tex), roughness=0.25, metallic=0.6, texture_scale=1.5)


# Non-body parts (REFERENCE.md section 1: wheels black, windows dark, tail lights red).
PART_MATERIALS: dict[str, Material] = {
    "wheels": Material(_texture((22, 22, 24)), roughness=0.85),
    "windows": Material(_texture((28, 38, 52)), roughness=0.05),
    "lights": Material(_texture((205, 18, 18)), roughness=0.2),
}


def part_material(part: str, color: str, variant: int) -> Material:
    """The material of a vehicle part; unknown parts are body panels and take the object's colour."""
    return PART_MATERIALS.get(part) or body_material(color, variant)


def choose_variants(rng: np.random.Generator, n: int) -> list[int]:
    """One texture variant per object, drawn from the render stage's generator."""
    return [int(v) for v in rng.integers(0, len(VARIANTS), n)]
