"""Procedural environments: the stand-in for the paper's 509 HDRI domes (REFERENCE.md section 1, Backgrounds).

An environment is a sky (a function of direction: gradient, sun, clouds and a skyline of hills, trees, a city or
mountains on the horizon; `equirect()` bakes it into an environment map), a ground material (asphalt with lane
marks, grass, sand, tiles, concrete, snow, gravel, dirt, cobblestone, brick) as a tileable texture, and the light
they imply (sun direction and colour, sky ambient, haze). 10 ground materials x 6 skies, each with its own palette,
skyline and sun drawn from the environment's index, give NUM_ENVIRONMENTS = 60 distinct places. Everything is a pure
function of the index; a scene picks its index with `choose(rng)`.

Conventions: colours are display RGB in [0, 1]; world z is up. The equirectangular sky has row r at elevation
90 - 180 (r + 0.5) / H degrees and column c at azimuth atan2(y, x) = 360 (c + 0.5) / W - 180 degrees.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import cv2
import numpy as np

GROUNDS = ("asphalt", "grass", "sand", "tiles", "concrete", "snow", "gravel", "dirt", "cobblestone", "brick")
SKIES = ("clear", "partly_cloudy", "hazy", "overcast", "sunset", "morning")
NUM_ENVIRONMENTS = len(GROUNDS) * len(SKIES)
TEX = 512                 # ground texture tile, texels per side


@dataclass(frozen=True)
class SkyStyle:
    zenith: tuple
    horizon: tuple
    sun_elevation: tuple     # degrees, range
    sun: tuple               # sun irradiance colour (display units)
    ambient: tuple           # sky irradiance colour
    clouds: float            # cover, 0..1
    haze_m: float            # distance at which the ground is 63% haze


SKY_STYLES = {
    "clear": SkyStyle((0.22, 0.42, 0.82), (0.70, 0.80, 0.94), (35, 60), (0.78, 0.75, 0.68), (0.40, 0.44, 0.52),
                      0.12, 260.0),
    "partly_cloudy": SkyStyle((0.28, 0.46, 0.80), (0.74, 0.82, 0.92), (30, 55), (0.72, 0.70, 0.64),
                              (0.44, 0.47, 0.53), 0.5, 200.0),
    "hazy": SkyStyle((0.50, 0.60, 0.74), (0.84, 0.85, 0.86), (25, 50), (0.55, 0.53, 0.48), (0.52, 0.53, 0.56),
                     0.2, 80.0),
    "overcast": SkyStyle((0.56, 0.58, 0.62), (0.78, 0.79, 0.80), (40, 60), (0.14, 0.14, 0.14), (0.78, 0.79, 0.82),
                         1.0, 140.0),
    "sunset": SkyStyle((0.20, 0.28, 0.52), (1.00, 0.64, 0.38), (6, 13), (0.85, 0.55, 0.32), (0.40, 0.36, 0.42),
                       0.3, 180.0),
    "morning": SkyStyle((0.32, 0.50, 0.82), (0.95, 0.86, 0.72), (14, 24), (0.80, 0.70, 0.55), (0.42, 0.44, 0.52),
                        0.25, 220.0),
}


@dataclass(frozen=True)
class Environment:
    index: int
    name: str                 # e.g. "asphalt/sunset/city"
    ground: str
    sky_style: str
    skyline: str
    sky: "Sky"                # the sky model: colour per direction
    ground_mips: tuple        # float32 [S, S, 3] albedo tile and its halvings
    ground_tile_m: float      # metres covered by one texture tile
    variation: np.ndarray     # float32 [64, 64]: large-scale brightness variation over 64 m, breaks the tiling
    road_angle: float | None  # asphalt: direction of the lane marks (radians); None: no marks
    sun_dir: np.ndarray       # unit vector towards the sun
    sun: np.ndarray           # rgb
    ambient: np.ndarray       # rgb
    haze: np.ndarray          # rgb: the colour the ground fades into at the horizon
    haze_m: float

    @property
    def ground_mean(self) -> np.ndarray:
        return self.ground_mips[-1].reshape(-1, 3).mean(0)

    def ground_albedo(self, x: np.ndarray, y: np.ndarray, footprint: np.ndarray) -> np.ndarray:
        """Albedo [..., 3] at world points (x, y) on the ground seen through pixels `footprint` metres wide:
        a trilinear mip lookup, so distant ground blurs instead of aliasing."""
        S = self.ground_mips[0].shape[0]
        level = np.log2(np.maximum(footprint * S / self.ground_tile_m, 1.0)).astype(np.float32)
        level = np.minimum(level, len(self.ground_mips) - 1)
        out = np.zeros(x.shape + (3,), np.float32)
        lo = np.floor(level).astype(int)
        frac = (level - lo)[..., None]
        for k in range(int(lo.min()), int(lo.max()) + 1):
            sel = (lo == k)
            if not sel.any():
                continue
            a = _sample_wrap(self.ground_mips[k], x[sel], y[sel], self.ground_tile_m)
            b = _sample_wrap(self.ground_mips[min(k + 1, len(self.ground_mips) - 1)], x[sel], y[sel],
                             self.ground_tile_m)
            out[sel] = a * (1 - frac[sel]) + b * frac[sel]
        out *= (1.0 + _sample_wrap(self.variation[..., None], x, y, 64.0))[..., None]
        if self.road_angle is not None:
            out = _lane_marks(out, x, y, footprint, self.road_angle)
        return np.clip(out, 0, 1)

    def sky_radiance(self, directions: np.ndarray) -> np.ndarray:
        """Sky colour [..., 3] seen along world directions [..., 3] (any length)."""
        return self.sky.radiance(directions)

    def equirect(self, height: int = 512) -> np.ndarray:
        """The sky as an equirectangular image [height, 2 height, 3] (module docstring: row/column angles)."""
        W = 2 * height
        e = np.radians(90 - 180 * (np.arange(height) + 0.5) / height)[:, None]
        a = np.radians(360 * (np.arange(W) + 0.5) / W - 180)[None, :]
        d = np.stack(np.broadcast_arrays(np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)), -1)
        return self.radiance_below_horizon(d, self.sky_radiance(d))

    def radiance_below_horizon(self, d: np.ndarray, sky: np.ndarray) -> np.ndarray:
        """Below the horizon an environment map shows distant hazy ground (past the rendered ground disc)."""
        ground = (self.ground_mean * (self.ambient + self.sun * max(self.sun_dir[2], 0))).astype(np.float32)
        t = np.exp(np.minimum(d[..., 2:3], 0) * 30).astype(np.float32)
        return np.where(d[..., 2:3] < 0, ground * (1 - t) + self.haze * t, sky).astype(np.float32)


def _remap(tex: np.ndarray, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Bilinear, horizontally wrapping lookup of texel coordinates of any shape (cv2 wants 2-D maps < 32k wide)."""
    shape, n = u.shape, u.size
    rows = -(-n // 1024)
    pad = rows * 1024 - n
    uu = np.pad(u.ravel().astype(np.float32), (0, pad)).reshape(rows, 1024)
    vv = np.pad(v.ravel().astype(np.float32), (0, pad)).reshape(rows, 1024)
    out = cv2.remap(tex, uu, vv, cv2.INTER_LINEAR, borderMode=cv2.BORDER_WRAP)
    channels = tex.shape[2] if tex.ndim == 3 and tex.shape[2] > 1 else None
    out = out.reshape(rows * 1024, -1)[:n]
    return out.reshape(shape + ((channels,) if channels else ()))


def _sample_wrap(tex: np.ndarray, x: np.ndarray, y: np.ndarray, tile_m: float) -> np.ndarray:
    """Lookup of a tileable texture at world coordinates (metres); x runs along columns, y along rows."""
    S = tex.shape[0]
    u = np.mod(np.asarray(x, np.float64) / tile_m * S - 0.5, S)
    v = np.mod(np.asarray(y, np.float64) / tile_m * S - 0.5, S)
    return _remap(tex, u, v)


def _lane_marks(albedo, x, y, footprint, angle):
    """A two-lane road through the scene: dashed centre line, solid edge lines (3.5 m lanes, 12 cm paint)."""
    along = x * np.cos(angle) + y * np.sin(angle)
    across = -x * np.sin(angle) + y * np.cos(angle)
    fp = np.maximum(footprint, 1e-3)
    paint = np.zeros_like(across)
    for offset, dashed in ((0.0, True), (-3.6, False), (3.6, False)):
        cover = np.clip((0.06 - np.abs(across - offset)) / fp + 0.5, 0, 1)
        if dashed:
            cover = cover * np.clip((1.5 - np.abs(np.mod(along, 6.0) - 1.5)) / fp, 0, 1)
        paint = np.maximum(paint, cover)
    # Paint this thin averages away with distance instead of flickering.
    paint *= np.clip(0.12 / fp, 0, 1)
    return albedo * (1 - paint[..., None]) + np.array([0.86, 0.86, 0.82], np.float32) * paint[..., None]


# ---- noise -------------------------------------------------------------------------------------------------------

def _noise(rng: np.random.Generator, shape, beta: float, low: float = 1.0) -> np.ndarray:
    """Tileable fractal noise (spectrum ~ f^-beta, nothing below frequency `low`), zero mean, unit std."""
    white = rng.standard_normal(shape)
    fy = np.fft.fftfreq(shape[0]) * shape[0]
    fx = np.fft.rfftfreq(shape[1]) * shape[1]
    f = np.sqrt(fy[:, None] ** 2 + fx[None, :] ** 2)
    spec = np.fft.rfft2(white) * np.where(f >= low, np.maximum(f, 1e-9) ** (-beta / 2), 0)
    n = np.fft.irfft2(spec, s=shape)
    return ((n - n.mean()) / (n.std() + 1e-9)).astype(np.float32)


def _cells(rng: np.random.Generator, S: int, count: int):
    """Tileable Voronoi: (cell index per texel, distance to the nearest border proxy F2 - F1, in texels)."""
    from scipy.spatial import cKDTree

    pts = rng.uniform(0, S, (count, 2))
    yy, xx = np.mgrid[0:S, 0:S]
    q = np.stack([yy.ravel() + 0.5, xx.ravel() + 0.5], 1)
    d, i = cKDTree(pts, boxsize=S).query(q, k=2)
    return i[:, 0].reshape(S, S), (d[:, 1] - d[:, 0]).reshape(S, S)


def _mix(a, b, t):
    t = np.asarray(t, np.float32)[..., None] if np.ndim(t) else np.float32(t)
    a, b = np.asarray(a, np.float32), np.asarray(b, np.float32)
    return a + (b - a) * t


def _jitter(rng, rgb, amount=0.06):
    return np.clip(np.asarray(rgb, float) * (1 + rng.uniform(-amount, amount)) + rng.uniform(-amount, amount, 3)
                   * 0.3, 0, 1)


# ---- ground materials ------------------------------------------------------------------------------------------

def _ground_texture(kind: str, rng: np.random.Generator) -> tuple[np.ndarray, float]:
    """A tileable albedo texture [TEX, TEX, 3] and the metres one tile covers."""
    S = TEX
    fine, mid = _noise(rng, (S, S), 0.6, 8), _noise(rng, (S, S), 2.2, 1)
    if kind == "asphalt":
        base = _jitter(rng, (0.27, 0.27, 0.28), 0.15)
        tex = base * (1 + 0.16 * fine[..., None] + 0.08 * mid[..., None])
        specks = (rng.random((S, S)) < 0.01)[..., None]
        return np.where(specks, base * 1.6, tex), 4.0
    if kind == "grass":
        g1, g2 = _jitter(rng, (0.22, 0.40, 0.12)), _jitter(rng, (0.42, 0.50, 0.20))
        blades = _noise(rng, (S, S), 0.2, 40)
        tex = _mix(g1, g2, np.clip(0.5 + 0.35 * mid, 0, 1)) * (1 + 0.22 * blades[..., None] + 0.1 * fine[..., None])
        return tex, 5.0
    if kind == "sand":
        base = _jitter(rng, (0.78, 0.66, 0.46))
        yy, xx = np.mgrid[0:S, 0:S] / S
        ripples = np.sin(2 * np.pi * (9 * yy + 2 * xx + 0.25 * mid))
        return base * (1 + 0.06 * ripples[..., None] + 0.07 * fine[..., None] + 0.05 * mid[..., None]), 6.0
    if kind == "tiles":
        n = int(rng.choice([4, 6, 8]))
        palettes = [((0.66, 0.40, 0.28), (0.58, 0.33, 0.23)), ((0.70, 0.70, 0.68), (0.55, 0.55, 0.56)),
                    ((0.80, 0.74, 0.62), (0.66, 0.60, 0.50)), ((0.45, 0.47, 0.52), (0.72, 0.72, 0.70))]
        a, b = palettes[int(rng.integers(len(palettes)))]
        yy, xx = np.mgrid[0:S, 0:S]
        cell = (yy * n // S) * n + (xx * n // S)
        checker = ((yy * n // S) + (xx * n // S)) % 2
        tone = rng.uniform(-0.06, 0.06, n * n)[cell]
        tex = _mix(a, b, checker * rng.uniform(0.3, 1.0)) * (1 + tone[..., None] + 0.05 * fine[..., None])
        gy, gx = (yy * n) % S, (xx * n) % S
        grout = (np.minimum(gy, S - gy) < n * 3) | (np.minimum(gx, S - gx) < n * 3)
        return np.where(grout[..., None], np.float32(0.35), tex), n * rng.uniform(0.5, 0.8)
    if kind == "concrete":
        base = _jitter(rng, (0.62, 0.61, 0.58))
        yy, xx = np.mgrid[0:S, 0:S]
        seam = (np.minimum(yy, S - 1 - yy) < 2) | (np.minimum(xx, S - 1 - xx) < 2)
        tex = base * (1 + 0.07 * fine[..., None] + 0.09 * mid[..., None])
        return np.where(seam[..., None], base * 0.55, tex), 3.0
    if kind == "snow":
        base = np.array((0.88, 0.90, 0.95))
        return base * (1 + 0.03 * fine[..., None] + 0.05 * mid[..., None]), 6.0
    if kind in ("gravel", "cobblestone"):
        count = 2600 if kind == "gravel" else 300
        cell, edge = _cells(rng, S, count)
        base = _jitter(rng, (0.52, 0.50, 0.46) if kind == "gravel" else (0.48, 0.47, 0.46))
        tone = rng.uniform(-0.2, 0.2, count)[cell]
        hue = rng.uniform(-0.015, 0.015, (count, 3))[cell]
        gap = np.clip(edge / (2.0 if kind == "gravel" else 3.5), 0, 1)
        tex = (base * (1 + tone[..., None]) + hue) * (0.45 + 0.55 * gap[..., None]) * (1 + 0.05 * fine[..., None])
        return tex, (2.5 if kind == "gravel" else 4.0)
    if kind == "dirt":
        a, b = _jitter(rng, (0.42, 0.31, 0.20)), _jitter(rng, (0.55, 0.44, 0.31))
        tex = _mix(a, b, np.clip(0.5 + 0.4 * mid, 0, 1)) * (1 + 0.12 * fine[..., None])
        pebbles = (rng.random((S, S)) < 0.004)[..., None]
        return np.where(pebbles, np.float32(0.6), tex), 5.0
    if kind == "brick":
        rows, cols = 16, 8
        yy, xx = np.mgrid[0:S, 0:S]
        r = yy * rows // S
        shift = (r % 2) * (S // cols // 2)
        c = ((xx + shift) % S) * cols // S
        tone = rng.uniform(-0.12, 0.12, rows * cols)[r * cols + c]
        base = _jitter(rng, (0.58, 0.28, 0.20))
        gy, gx = (yy * rows) % S, ((xx + shift) * cols) % S
        mortar = (np.minimum(gy, S - gy) < rows * 2) | (np.minimum(gx, S - gx) < cols * 2)
        tex = base * (1 + tone[..., None] + 0.06 * fine[..., None])
        return np.where(mortar[..., None], np.float32(0.62), tex), 3.2
    raise ValueError(kind)


# ---- sky -------------------------------------------------------------------------------------------------------

SKYLINE_SAMPLES = 4096   # skyline heights per full turn of azimuth


def _skyline(rng: np.random.Generator, kind: str) -> list[tuple[np.ndarray, np.ndarray, np.ndarray, float]]:
    """Layers of (height in degrees, brightness per azimuth sample, colour, haze 0..1), far to near."""
    W = SKYLINE_SAMPLES
    az = (np.arange(W) + 0.5) / W
    layers = []

    def bumps(count, width, height, square):
        """Round tree crowns or flat-topped buildings, each with its own brightness."""
        h, tone = np.zeros(W), np.ones(W)
        for c, w, hh, b in zip(rng.uniform(0, 1, count), rng.uniform(*width, count), rng.uniform(*height, count),
                               rng.uniform(0.7, 1.3, count)):
            idx = np.arange(int((c - w) * W), int((c + w) * W) + 1) % W
            d = np.abs(az[idx] - c + np.round(c - az[idx]))
            shape = np.full(len(idx), hh) if square else hh * np.sqrt(np.clip(1 - (d / w) ** 2, 0, 1))
            higher = shape > h[idx]
            h[idx[higher]], tone[idx[higher]] = shape[higher], b
        return h, tone

    flat = np.ones(W)
    if kind == "mountains":
        ridge = 1.0 + 1.6 * np.abs(_noise(rng, (1, W), 2.8, 2)[0]) + 0.15 * _noise(rng, (1, W), 1.6, 40)[0]
        layers.append((ridge, flat, np.array((0.36, 0.42, 0.52)), 0.55))
    if kind in ("hills", "trees"):
        hills = 0.6 + 1.2 * np.clip(_noise(rng, (1, W), 2.4, 1)[0], -0.5, None)
        layers.append((hills, flat, np.array((0.30, 0.40, 0.22)), 0.45))
    if kind == "trees":
        trees, tone = bumps(700, (0.0015, 0.004), (1.2, 3.2), False)
        layers.append((np.maximum(trees, 0.9), tone, np.array((0.10, 0.19, 0.09)), 0.3))
    if kind == "city":
        far, far_tone = bumps(70, (0.002, 0.006), (1.0, 3.5), True)
        near, near_tone = bumps(140, (0.002, 0.008), (0.4, 1.8), True)
        layers.append((far, far_tone, np.array((0.44, 0.46, 0.52)), 0.45))
        layers.append((near, near_tone, np.array((0.32, 0.32, 0.36)), 0.25))
    return [(h.astype(np.float32), t.astype(np.float32), c, haze) for h, t, c, haze in layers]


@dataclass(frozen=True)
class Sky:
    """A sky as a function of direction: horizon-to-zenith gradient, sun glow and disc, a cloud layer (a noise
    texture on a plane above, so clouds crowd towards the horizon) and skyline silhouettes standing on the horizon."""

    style: SkyStyle
    sun_dir: np.ndarray
    clouds: np.ndarray                  # tileable noise [512, 512]
    skyline: list                       # _skyline layers
    shading: np.ndarray                 # tileable noise [64, 1024]: texture of the skyline silhouettes

    def radiance(self, directions: np.ndarray) -> np.ndarray:
        st = self.style
        d = (directions / np.linalg.norm(directions, axis=-1, keepdims=True)).astype(np.float32)
        elev = np.degrees(np.arcsin(np.clip(d[..., 2], -1, 1)))
        zen, hor = np.array(st.zenith, np.float32), np.array(st.horizon, np.float32)
        sky = _mix(hor, zen, 1 - np.exp(-np.clip(elev, 0, None) / 14.0))
        cos_sun = np.clip(d @ self.sun_dir.astype(np.float32), -1, 1)
        angle = np.degrees(np.arccos(cos_sun))
        sun = np.array(st.sun, np.float32) / max(st.sun)
        if st.clouds < 1:
            sky += sun * (0.35 * np.exp(-angle / 12.0) + 0.2 * np.exp(-angle / 40.0))[..., None]
        pz = np.maximum(d[..., 2], 0.02)
        n = _sample_wrap(self.clouds[..., None], d[..., 0] / pz * 60, d[..., 1] / pz * 60, 400.0)
        above = np.clip(elev / 3, 0, 1)
        if st.clouds >= 1:
            sky = _mix(sky, zen * (1 + 0.12 * n[..., None]) + 0.08, above)
        elif st.clouds > 0:
            cover = np.clip((n - (1.2 - 2.4 * st.clouds)) / 0.8, 0, 1) * above
            if st.sun_elevation[1] < 15:   # low sun: clouds glow orange towards it
                cloud = _mix(np.array((0.55, 0.42, 0.48)), np.array((1.0, 0.70, 0.45)), np.clip(cos_sun, 0, 1) ** 3)
            else:
                cloud = np.float32(0.93) * (0.82 + 0.18 * np.clip(cos_sun, 0, 1))[..., None] * np.ones(3, np.float32)
            sky = _mix(sky, cloud, cover)
        if st.clouds < 1:
            sky = np.where((angle < 0.8)[..., None], np.maximum(sky, 1.0), sky)
        azim = np.mod(np.degrees(np.arctan2(d[..., 1], d[..., 0])) + 180, 360) / 360
        col = np.minimum((azim * SKYLINE_SAMPLES).astype(np.int32), SKYLINE_SAMPLES - 1)
        tone = _remap(self.shading[..., None], azim * 1024, np.clip(elev, 0, 20) * 3.2)
        for h, brightness, colour, haze in self.skyline:
            inside = (elev >= 0) & (elev < h[col])
            shade = colour.astype(np.float32) * (brightness[col] + 0.1 * tone)[..., None]
            sky = np.where(inside[..., None], _mix(shade, hor, haze), sky)
        return np.clip(sky, 0, 1.5).astype(np.float32)


# ---- environments ----------------------------------------------------------------------------------------------

def choose(rng: np.random.Generator) -> int:
    """The environment of a scene: one draw from the render stage's generator."""
    return int(rng.integers(NUM_ENVIRONMENTS))


@lru_cache(maxsize=4)
def environment(index: int) -> Environment:
    if not 0 <= index < NUM_ENVIRONMENTS:
        raise ValueError(f"environment index {index} outside 0..{NUM_ENVIRONMENTS - 1}")
    rng = np.random.default_rng([20250, index])
    ground = GROUNDS[index % len(GROUNDS)]
    style_name = SKIES[index // len(GROUNDS)]
    style = SKY_STYLES[style_name]
    skyline = str(rng.choice(["none", "hills", "trees", "city", "mountains"] if ground != "snow"
                             else ["none", "hills", "trees", "mountains"]))
    if ground == "asphalt" or ground == "concrete":
        skyline = "city" if rng.random() < 0.6 else skyline
    elev = np.radians(rng.uniform(*style.sun_elevation))
    azim = rng.uniform(-np.pi, np.pi)
    sun_dir = np.array([np.cos(elev) * np.cos(azim), np.cos(elev) * np.sin(azim), np.sin(elev)])
    tex, tile_m = _ground_texture(ground, rng)
    tex = np.clip(tex, 0, 1).astype(np.float32)
    mips = [tex]
    while mips[-1].shape[0] > 1:
        mips.append(cv2.resize(mips[-1], (mips[-1].shape[0] // 2,) * 2, interpolation=cv2.INTER_AREA))
    variation = (0.10 * _noise(rng, (64, 64), 2.0, 1)).astype(np.float32)
    road = float(rng.uniform(0, np.pi)) if ground == "asphalt" and rng.random() < 0.7 else None
    sky = Sky(style, sun_dir, _noise(rng, (512, 512), 2.6, 2), _skyline(rng, skyline),
              _noise(rng, (64, 1024), 1.0, 2))
    return Environment(
        index=index, name=f"{ground}/{style_name}/{skyline}", ground=ground, sky_style=style_name, skyline=skyline,
        sky=sky, ground_mips=tuple(mips), ground_tile_m=float(tile_m), variation=variation, road_angle=road,
        sun_dir=sun_dir, sun=np.array(style.sun) * rng.uniform(0.92, 1.08), ambient=np.array(style.ambient),
        haze=np.array(style.horizon, np.float32), haze_m=style.haze_m * rng.uniform(0.8, 1.25))
