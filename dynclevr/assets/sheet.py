"""A contact sheet of every vehicle sub-type, drawn by a small z-buffered numpy rasteriser (no GL), so that a person
can check the catalogue by eye; plus the binary silhouettes the tests compare sub-types with."""

from __future__ import annotations

from pathlib import Path

import cv2
import numpy as np
import trimesh

from dynclevr.artifacts import atomic_path
from dynclevr.assets.catalogue import CATEGORIES, SUBTYPES, get_asset

# BGR; the body is a neutral grey so the parts read clearly
PART_BGR = {"body": (190, 182, 172), "wheels": (28, 28, 28), "windows": (80, 62, 50), "lights": (40, 40, 215)}
LIGHT = np.array([0.35, -0.45, 0.82])
SUPERSAMPLE = 2


def view_axes(azimuth_deg: float, elevation_deg: float) -> np.ndarray:
    """Rows: screen right, screen up, towards the viewer, for an orthographic camera at that azimuth (from +x, counter-
    clockwise seen from above) and elevation, looking at the origin."""
    a, e = np.radians(azimuth_deg), np.radians(elevation_deg)
    toward = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    right = np.cross(-toward, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    return np.stack([right, np.cross(right, -toward), toward])


def _rasterise(px: np.ndarray, depth: np.ndarray, colour: np.ndarray, img: np.ndarray,
               chunk: int = 1_500_000) -> None:
    """Z-buffered fill of screen triangles px [T, 3, 2] (pixels) with per-vertex depth [T, 3] (larger is nearer), all
    triangles at once: every pixel of each triangle's bounding box is a candidate, tested by edge functions."""
    Sh, Sw = img.shape[:2]
    zbuf = np.full(Sh * Sw, -np.inf)
    flat = img.reshape(-1, 3)
    lim = np.array([Sw - 1, Sh - 1])
    lo = np.clip(np.floor(px.min(1)), 0, lim).astype(np.int64)
    hi = np.clip(np.ceil(px.max(1)), 0, lim).astype(np.int64)
    a, b, c = px[:, 0], px[:, 1], px[:, 2]
    area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    keep = np.abs(area) > 1e-9
    w, h = hi[:, 0] - lo[:, 0] + 1, hi[:, 1] - lo[:, 1] + 1
    counts = np.where(keep, w * h, 0)
    ends = np.cumsum(counts)
    start = 0
    while start < len(counts):
        stop = max(int(np.searchsorted(ends, (ends[start - 1] if start else 0) + chunk)), start + 1)
        idx = np.arange(start, min(stop, len(counts)))
        n = counts[idx]
        t = np.repeat(idx, n)
        local = np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)
        x = lo[t, 0] + local % w[t]
        y = lo[t, 1] + local // w[t]
        qx, qy = x + 0.5, y + 0.5
        w0 = ((b[t, 0] - qx) * (c[t, 1] - qy) - (b[t, 1] - qy) * (c[t, 0] - qx)) / area[t]
        w1 = ((c[t, 0] - qx) * (a[t, 1] - qy) - (c[t, 1] - qy) * (a[t, 0] - qx)) / area[t]
        w2 = 1 - w0 - w1
        inside = (w0 >= 0) & (w1 >= 0) & (w2 >= 0)
        t, pid = t[inside], (y * Sw + x)[inside]
        z = w0[inside] * depth[t, 0] + w1[inside] * depth[t, 1] + w2[inside] * depth[t, 2]
        order = np.lexsort((-z, pid))                            # per pixel, nearest first
        pid, z, t = pid[order], z[order], t[order]
        first = np.r_[True, pid[1:] != pid[:-1]]
        pid, z, t = pid[first], z[first], t[first]
        nearer = z > zbuf[pid]
        zbuf[pid[nearer]] = z[nearer]
        flat[pid[nearer]] = colour[t[nearer]]
        start = stop


def fit_scale(parts: dict[str, trimesh.Trimesh], axes: np.ndarray, size_px: int | tuple[int, int]) -> float:
    """Pixels per metre that fit the parts, seen along `axes`, into a size_px square or (width, height)."""
    w, h = (size_px, size_px) if np.isscalar(size_px) else size_px
    cam = np.vstack([m.vertices for m in parts.values()]) @ axes[:2].T
    ext = cam.max(0) - cam.min(0)
    return 0.92 * min(w / ext[0], h / ext[1])


def render(parts: dict[str, trimesh.Trimesh], axes: np.ndarray, size_px: int | tuple[int, int], colours=PART_BGR,
           background=(255, 255, 255), px_per_m: float | None = None) -> np.ndarray:
    """Lambert-shaded orthographic view of the parts in a size_px square or (width, height) image (BGR uint8),
    centred, at px_per_m pixels per metre (default: fitted)."""
    tris, cols = [], []
    for name, mesh in parts.items():
        t = np.asarray(mesh.vertices)[np.asarray(mesh.faces)]
        tris.append(t)
        cols.append(np.broadcast_to(np.asarray(colours[name], float), (len(t), 3)))
    world = np.concatenate(tris)
    col = np.concatenate(cols)
    n = np.cross(world[:, 1] - world[:, 0], world[:, 2] - world[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-12)
    n *= np.where(n @ axes[2] < 0, -1.0, 1.0)[:, None]          # two-sided: face the viewer
    light = LIGHT / np.linalg.norm(LIGHT)
    shade = 0.42 + 0.58 * np.clip(n @ light, 0, 1)
    cam = world @ axes.T                                         # (screen x, screen y, depth towards viewer)
    w, h = (size_px, size_px) if np.isscalar(size_px) else size_px
    Sw, Sh = w * SUPERSAMPLE, h * SUPERSAMPLE
    lo, hi = cam[..., :2].reshape(-1, 2).min(0), cam[..., :2].reshape(-1, 2).max(0)
    scale = SUPERSAMPLE * (px_per_m or fit_scale(parts, axes, (w, h)))
    centre = (lo + hi) / 2
    px = np.empty(cam.shape[:2] + (2,))
    px[..., 0] = (cam[..., 0] - centre[0]) * scale + Sw / 2
    px[..., 1] = Sh / 2 - (cam[..., 1] - centre[1]) * scale
    img = np.full((Sh, Sw, 3), background, np.uint8)
    _rasterise(px, cam[..., 2], np.clip(col * shade[:, None], 0, 255).astype(np.uint8), img)
    return cv2.resize(img, (w, h), interpolation=cv2.INTER_AREA)


def silhouette(mesh: trimesh.Trimesh, view: str = "side", res: int = 96, extent: float = 4.8) -> np.ndarray:
    """Binary silhouette (res x res) of a mesh centred at the origin, seen from the side (x right, z up), the top (x
    right, y up) or the front (y right, z up), over an extent x extent metre window: shape and size both count, as
    they do for the scene parser."""
    u, v = {"side": (0, 2), "top": (0, 1), "front": (1, 2)}[view]
    P = (np.asarray(mesh.vertices)[:, [u, v]] / extent + 0.5) * res
    P[:, 1] = res - P[:, 1]
    pts = np.round(P * 16).astype(np.int32)[np.asarray(mesh.faces)]
    img = np.zeros((res, res), np.uint8)
    for tri in pts:
        cv2.fillConvexPoly(img, tri, 1, cv2.LINE_8, 4)
    return img.astype(bool)


def draw_sheet(path: Path, size_px: int = 256) -> None:
    """One PNG: a row per category; per sub-type a labelled 3/4 front view above a side view, drawn at one scale per
    category so that sizes compare within a row."""
    rows = [[n for n, (c, _) in SUBTYPES.items() if c == cat] for cat in CATEGORIES]
    ncol = max(len(r) for r in rows)
    font = size_px / 560
    line = int(34 * font) + 6
    label_h, main_h, side_h = 2 * line + 4, int(size_px * 0.8), int(size_px * 0.32)
    cell_h = label_h + main_h + side_h
    sheet = np.full((len(rows) * cell_h, ncol * size_px, 3), 255, np.uint8)
    three_quarter, side = view_axes(-55, 22), view_axes(-90, 0)
    for r, names in enumerate(rows):
        scales = [min(fit_scale(get_asset(n).parts, axes, dims) for n in names)
                  for axes, dims in ((three_quarter, (size_px, main_h)), (side, (size_px, side_h)))]
        for c, name in enumerate(names):
            asset = get_asset(name)
            y0, x0 = r * cell_h, c * size_px
            sheet[y0 + label_h:y0 + label_h + main_h, x0:x0 + size_px] = render(
                asset.parts, three_quarter, (size_px, main_h), px_per_m=scales[0])
            sheet[y0 + label_h + main_h:y0 + cell_h, x0:x0 + size_px] = render(
                asset.parts, side, (size_px, side_h), px_per_m=scales[1])
            L, W, H = asset.size
            for k, (text, scale, thick) in enumerate(((name, font * 1.25, 2),
                                                      (f"{asset.category}  {L:g} x {W:g} x {H:g} m", font, 1))):
                cv2.putText(sheet, text, (x0 + 6, y0 + (k + 1) * line), cv2.FONT_HERSHEY_SIMPLEX, scale,
                            (0, 0, 0), thick, cv2.LINE_AA)
            cv2.rectangle(sheet, (x0, y0), (x0 + size_px - 1, y0 + cell_h - 1), (205, 205, 205), 1)
    ok, buf = cv2.imencode(".png", sheet)
    assert ok
    with atomic_path(Path(path)) as tmp:
        tmp.write_bytes(buf.tobytes())
