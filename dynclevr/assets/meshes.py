"""Procedural meshes of the 21 vehicle sub-types, split into the parts a renderer colours.

Each builder models its vehicle in metres at about its catalogue size (ground at z = 0, facing +x, left +y), from a
few primitives: side profiles extruded across the width (car and bus silhouettes with wheel arches), top-view
outlines extruded through their thickness (wings), lofted ellipse sections (fuselages, tanks), tubes (bicycle frames)
and tori (tyres). `build_parts` then centres the union on its bounding-box centre and scales each axis to the exact
catalogue size (the models are built within a few percent of it, so circles stay round).

Parts: "body" takes the object's colour; "wheels" is black (tyres, wheel wells, landing-gear wheels); "windows" is the
dark trim (glass, headlamp lenses, bus bellows, rub rails, and for two-wheelers saddles, grips and pedals; propellers);
"lights" are the red lamps (tail lights, aeroplane navigation lights, jet nozzles).

Primitives are plain (vertices, faces) arrays with outward-facing triangles; Trimesh objects are made once per part
because creating thousands of small Trimesh objects would dominate the build time.
"""

from __future__ import annotations

import numpy as np
import trimesh

from dynclevr.assets.catalogue import PARTS

Geom = tuple[np.ndarray, np.ndarray]   # (V x 3 float, F x 3 int)


# ---- primitives ------------------------------------------------------------------------------------------------------

def _frame(axis) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit axis d and u, v with u x v = d."""
    d = np.asarray(axis, float)
    d = d / np.linalg.norm(d)
    helper = np.array([0.0, 0.0, 1.0]) if abs(d[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = np.cross(helper, d)
    u /= np.linalg.norm(u)
    return d, u, np.cross(d, u)


def _rot(axis: str, deg: float) -> np.ndarray:
    c, s = np.cos(np.radians(deg)), np.sin(np.radians(deg))
    return {"x": np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
            "y": np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
            "z": np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])}[axis]


def _tf(g: Geom, R=None, t=(0.0, 0.0, 0.0), about=(0.0, 0.0, 0.0)) -> Geom:
    """Rotate by R about the point `about`, then translate by t."""
    v = g[0]
    if R is not None:
        v = (v - about) @ np.asarray(R).T + about
    return v + np.asarray(t, float), g[1]


def _mirror_y(g: Geom) -> Geom:
    return g[0] * np.array([1.0, -1.0, 1.0]), g[1][:, ::-1]


def _both_sides(g: Geom) -> list[Geom]:
    return [g, _mirror_y(g)]


_CUBE_V = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)])
_CUBE_F = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                    [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])


def box(lo, hi) -> Geom:
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    return _CUBE_V * (hi - lo) + (hi + lo) / 2, _CUBE_F.copy()


def cyl(p0, p1, r: float, n: int = 12, r1: float | None = None) -> Geom:
    """Closed tube (or frustum, radius r at p0 and r1 at p1) between two points."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    d, u, v = _frame(p1 - p0)
    th = np.linspace(0, 2 * np.pi, n, endpoint=False)
    ring = np.cos(th)[:, None] * u + np.sin(th)[:, None] * v
    r1 = r if r1 is None else r1
    V = np.vstack([p0 + r * ring, p1 + r1 * ring, p0, p1])
    i = np.arange(n)
    j = (i + 1) % n
    F = np.vstack([np.c_[i, j, n + j], np.c_[i, n + j, n + i],
                   np.c_[np.full(n, 2 * n), j, i], np.c_[np.full(n, 2 * n + 1), n + i, n + j]])
    return V, F


def torus(c, R: float, r: float, axis=(0, 1, 0), n: int = 20, m: int = 8, ra: float | None = None,
          arc: tuple[float, float] | None = None) -> Geom:
    """Torus of major radius R and tube radius r (ra along the axis, for flat tyres); `arc` (degrees, measured from
    u towards v of the axis frame) keeps only part of the ring, open at its ends (fenders)."""
    d, u, v = _frame(axis)
    ra = r if ra is None else ra
    closed = arc is None
    phi = (np.linspace(0, 2 * np.pi, n, endpoint=False) if closed
           else np.radians(np.linspace(arc[0], arc[1], n)))
    psi = np.linspace(0, 2 * np.pi, m, endpoint=False)
    radial = np.cos(phi)[:, None] * u + np.sin(phi)[:, None] * v                     # n x 3
    P = (np.asarray(c, float) + (R + r * np.cos(psi))[None, :, None] * radial[:, None, :]
         + (ra * np.sin(psi))[None, :, None] * d)
    ii, jj = np.meshgrid(np.arange(n if closed else n - 1), np.arange(m), indexing="ij")
    a = ii * m + jj
    b = ((ii + 1) % n) * m + jj
    cc = ((ii + 1) % n) * m + (jj + 1) % m
    dd = ii * m + (jj + 1) % m
    F = np.vstack([np.c_[a.ravel(), b.ravel(), cc.ravel()], np.c_[a.ravel(), cc.ravel(), dd.ravel()]])
    return P.reshape(-1, 3), F


def loft(stations, n: int = 16, y: float = 0.0) -> Geom:
    """Closed body through elliptic sections along x: rows of (x, zc, ry, rz); the section centre is (x, y, zc)."""
    S = np.asarray(sorted(stations), float)
    th = np.linspace(0, 2 * np.pi, n, endpoint=False)
    P = np.stack([np.repeat(S[:, :1], n, 1), y + S[:, 2:3] * np.cos(th), S[:, 1:2] + S[:, 3:4] * np.sin(th)], -1)
    k = len(S)
    ii, jj = np.meshgrid(np.arange(k - 1), np.arange(n), indexing="ij")
    a, b = ii * n + jj, (ii + 1) * n + jj
    c, d = (ii + 1) * n + (jj + 1) % n, ii * n + (jj + 1) % n
    F = [np.c_[a.ravel(), c.ravel(), b.ravel()], np.c_[a.ravel(), d.ravel(), c.ravel()]]
    V = np.vstack([P.reshape(-1, 3), [[S[0, 0], y, S[0, 1]], [S[-1, 0], y, S[-1, 1]]]])
    j = np.arange(n)
    F.append(np.c_[np.full(n, k * n), (j + 1) % n, j])
    F.append(np.c_[np.full(n, k * n + 1), (k - 1) * n + j, (k - 1) * n + (j + 1) % n])
    return V, np.vstack(F)


def ellipsoid(c, radii, n: int = 12, m: int = 7) -> Geom:
    rx, ry, rz = radii
    t = np.linspace(-1, 1, m + 2)[1:-1]
    stations = [(c[0] - rx, c[2], 1e-3, 1e-3)] + [(c[0] + rx * s, c[2], ry * np.sqrt(1 - s * s),
                                                   rz * np.sqrt(1 - s * s)) for s in t] + [(c[0] + rx, c[2], 1e-3, 1e-3)]
    return loft(stations, n, y=c[1])


def _triangulate(poly: np.ndarray) -> np.ndarray:
    """Ear clipping of a simple counter-clockwise polygon (profiles have a few dozen vertices)."""
    idx = list(range(len(poly)))
    tris = []
    while len(idx) > 3:
        pts = poly[idx]
        for k in range(len(idx)):
            a, b, c = pts[k - 1], pts[k], pts[(k + 1) % len(idx)]
            if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 1e-12:
                continue                                  # reflex or degenerate corner
            others = np.delete(pts, [(k - 1) % len(idx), k, (k + 1) % len(idx)], axis=0)
            if len(others):
                e = [(q[0] - p[0]) * (others[:, 1] - p[1]) - (q[1] - p[1]) * (others[:, 0] - p[0])
                     for p, q in ((a, b), (b, c), (c, a))]
                if np.any((e[0] > -1e-12) & (e[1] > -1e-12) & (e[2] > -1e-12)):
                    continue                              # another vertex inside the ear
            tris.append((idx[k - 1], idx[k], idx[(k + 1) % len(idx)]))
            idx.pop(k)
            break
        else:
            raise ValueError("polygon is not simple")
    tris.append(tuple(idx))
    return np.array(tris)


_PLANES = {"xz": (0, 2, 1), "xy": (0, 1, 2), "yz": (1, 2, 0)}    # (u axis, v axis, depth axis)


def extrude(poly, d0: float, d1: float, plane: str = "xz") -> Geom:
    """Prism of a simple polygon given in `plane` coordinates, spanning d0..d1 along the remaining axis."""
    P = np.asarray(poly, float)
    area = np.sum(P[:, 0] * np.roll(P[:, 1], -1) - np.roll(P[:, 0], -1) * P[:, 1])
    if area < 0:
        P = P[::-1]
    n = len(P)
    tri = _triangulate(P)
    iu, iv, idp = _PLANES[plane]
    V = np.zeros((2 * n, 3))
    V[:n, iu], V[:n, iv], V[:n, idp] = P[:, 0], P[:, 1], d0
    V[n:, iu], V[n:, iv], V[n:, idp] = P[:, 0], P[:, 1], d1
    i = np.arange(n)
    j = (i + 1) % n
    F = np.vstack([tri[:, ::-1], tri + n, np.c_[i, j, n + j], np.c_[i, n + j, n + i]])
    E = np.eye(3)
    if np.linalg.det(np.stack([E[iu], E[iv], E[idp]])) < 0:   # the (u, v, depth) frame is left-handed
        F = F[:, ::-1]
    return V, F


def arch_line(x_from: float, x_to: float, zb: float, arches, n: int = 9) -> list[tuple[float, float]]:
    """Underside of a side profile from x_from to x_to (increasing) at height zb, cut up over each wheel arch
    (xc, zc, radius)."""
    pts = [(x_from, zb)]
    for xc, zc, ra in sorted(arches):
        alpha = np.arcsin(np.clip((zb - zc) / ra, -1, 1))
        for t in np.linspace(np.pi - alpha, alpha, n):
            pts.append((xc + ra * np.cos(t), zc + ra * np.sin(t)))
    pts.append((x_to, zb))
    return pts


def wells(p: "_Parts", zb: float, arches, half: float) -> None:
    """Dark wheel wells: the arch openings closed inboard of the tyres (|y| <= half), so the gap around a tyre reads as
    a wheel arch rather than a hole through the vehicle."""
    for xc, zc, ra in arches:
        alpha = np.arcsin(np.clip((zb - zc) / ra, -1, 1))
        seg = [(xc + ra * np.cos(t), zc + ra * np.sin(t)) for t in np.linspace(np.pi - alpha, alpha, 9)]
        p.add("wheels", extrude(seg, -half, half))


# ---- the part accumulator ------------------------------------------------------------------------------------------

class _Parts:
    def __init__(self):
        self.geoms: dict[str, list[Geom]] = {p: [] for p in PARTS}

    def add(self, part: str, *geoms) -> None:
        for g in geoms:
            if isinstance(g, list):
                self.geoms[part].extend(g)
            else:
                self.geoms[part].append(g)

    def finish(self, size) -> dict[str, trimesh.Trimesh]:
        merged = {}
        for part, gs in self.geoms.items():
            if not gs:
                raise ValueError(f"part {part!r} is empty")
            offs = np.cumsum([0] + [len(v) for v, _ in gs[:-1]])
            merged[part] = (np.vstack([v for v, _ in gs]), np.vstack([f + o for (_, f), o in zip(gs, offs)]))
        allv = np.vstack([v for v, _ in merged.values()])
        lo, hi = allv.min(0), allv.max(0)
        scale = np.asarray(size, float) / (hi - lo)
        centre = (lo + hi) / 2
        # Micrometre vertices: numpy's SIMD math can differ in the last bit between CPUs (AVX-512 or not), and the
        # collision shapes are checked against the mesh's bytes; rounding (and + 0.0 for -0.0) makes them agree.
        return {p: trimesh.Trimesh(np.round((v - centre) * scale, 6) + 0.0, f, process=False)
                for p, (v, f) in merged.items()}


# ---- shared vehicle pieces ------------------------------------------------------------------------------------------

def _car_wheel(p: _Parts, x: float, y_out: float, r: float, width: float, n: int = 18) -> None:
    """Tyre and hub on both sides; y_out is the outer face of the tyre."""
    yc = y_out - width / 2
    for s in (1, -1):
        c = (x, s * yc, r)
        p.add("wheels", torus(c, r * 0.7, r * 0.3, (0, 1, 0), n, 8, ra=width / 2))
        p.add("wheels", cyl((x, s * (yc - width * 0.4), r), (x, s * (yc + width * 0.4), r), r * 0.55, 12))


def _bike_wheel(p: _Parts, x: float, R: float, tube: float, spokes: int = 8, knobs: bool = False) -> None:
    p.add("wheels", torus((x, 0, R), R - tube, tube, (0, 1, 0), 28 if knobs else 24, 6))
    p.add("wheels", cyl((x, -0.05, R), (x, 0.05, R), 0.03, 8))
    for k in range(spokes):
        a = 2 * np.pi * k / spokes
        p.add("wheels", cyl((x, 0, R), (x + (R - tube) * np.cos(a), 0, R + (R - tube) * np.sin(a)), 0.004, 3))
    if knobs:
        for k in range(28):
            a = 2 * np.pi * (k + 0.5) / 28
            c = np.array([x + R * np.cos(a), 0, R + R * np.sin(a)])
            p.add("wheels", _tf(box((-0.018, -tube * 1.05, -0.012), (0.018, tube * 1.05, 0.012)),
                                _rot("y", -np.degrees(a) + 90), c))


def _greenhouse(p: _Parts, W: float, glass, roof, pillars, gw: float = 0.84) -> None:
    """Car cabin: dark glass block, body-coloured roof panel and pillars slightly proud of the glass."""
    p.add("windows", extrude(glass, -gw * W / 2, gw * W / 2))
    p.add("body", extrude(roof, -(gw + 0.02) * W / 2, (gw + 0.02) * W / 2))
    for pil in pillars:
        p.add("body", _both_sides(extrude(pil, gw * W / 2 - 0.03, gw * W / 2 + 0.012)))


def _lamps(p: _Parts, part: str, x0: float, x1: float, z0: float, z1: float, y0: float, y1: float) -> None:
    p.add(part, _both_sides(box((x0, y0, z0), (x1, y1, z1))))


# ---- cars ---------------------------------------------------------------------------------------------------------------

def _sedan(L, W, H):
    p, r, xf, xr = _Parts(), 0.23, 0.98, -0.92
    arches = [(xr, r, 0.28), (xf, r, 0.28)]
    wells(p, 0.15, arches, W / 2 - 0.2)
    lower = arch_line(-1.47, 1.46, 0.15, arches) + [
        (1.5, 0.2), (1.51, 0.4), (1.45, 0.53), (1.0, 0.6), (0.6, 0.64),
        (-0.95, 0.66), (-1.4, 0.64), (-1.5, 0.56), (-1.52, 0.35), (-1.5, 0.2)]
    p.add("body", extrude(lower, -W / 2, W / 2))
    _greenhouse(p, W, [(-1.02, 0.6), (0.68, 0.6), (0.08, 0.96), (-0.55, 0.96)],
                [(-0.58, 0.955), (0.11, 0.955), (0.07, 0.99), (-0.55, 0.99)],
                [[(0.68, 0.6), (0.6, 0.6), (0.03, 0.96), (0.09, 0.96)],
                 [(-0.2, 0.6), (-0.13, 0.6), (-0.13, 0.96), (-0.2, 0.96)],
                 [(-1.02, 0.6), (-0.86, 0.6), (-0.45, 0.96), (-0.56, 0.96)]])
    _car_wheel(p, xf, W / 2 - 0.02, r, 0.17)
    _car_wheel(p, xr, W / 2 - 0.02, r, 0.17)
    _lamps(p, "lights", -1.525, -1.49, 0.42, 0.52, 0.36, 0.6)
    _lamps(p, "windows", 1.47, 1.515, 0.38, 0.46, 0.38, 0.58)
    return p


def _wagon(L, W, H):
    p, r, xf, xr = _Parts(), 0.23, 0.98, -0.9
    arches = [(xr, r, 0.28), (xf, r, 0.28)]
    wells(p, 0.15, arches, W / 2 - 0.2)
    lower = arch_line(-1.47, 1.46, 0.15, arches) + [
        (1.5, 0.2), (1.51, 0.4), (1.45, 0.53), (1.0, 0.6), (0.6, 0.64),
        (-1.45, 0.66), (-1.5, 0.56), (-1.52, 0.35), (-1.5, 0.2)]
    p.add("body", extrude(lower, -W / 2, W / 2))
    _greenhouse(p, W, [(-1.46, 0.6), (0.68, 0.6), (0.1, 1.0), (-1.36, 1.0), (-1.47, 0.8)],
                [(-1.39, 0.995), (0.13, 0.995), (0.09, 1.03), (-1.36, 1.03)],
                [[(0.68, 0.6), (0.6, 0.6), (0.05, 1.0), (0.11, 1.0)],
                 [(-0.22, 0.6), (-0.15, 0.6), (-0.15, 1.0), (-0.22, 1.0)],
                 [(-0.86, 0.6), (-0.78, 0.6), (-0.78, 1.0), (-0.86, 1.0)],
                 [(-1.47, 0.6), (-1.36, 0.6), (-1.3, 1.0), (-1.38, 1.0), (-1.47, 0.8)]])
    p.add("body", _both_sides(box((-1.3, 0.3, 1.03), (-0.05, 0.35, 1.08))))      # roof rails
    _car_wheel(p, xf, W / 2 - 0.02, r, 0.17)
    _car_wheel(p, xr, W / 2 - 0.02, r, 0.17)
    _lamps(p, "lights", -1.525, -1.49, 0.42, 0.6, 0.4, 0.6)
    _lamps(p, "windows", 1.47, 1.515, 0.38, 0.46, 0.38, 0.58)
    return p


def _suv(L, W, H):
    p, r, xf, xr = _Parts(), 0.3, 0.9, -0.86
    arches = [(xr, r, 0.36), (xf, r, 0.36)]
    wells(p, 0.3, arches, W / 2 - 0.25)
    lower = arch_line(-1.36, 1.37, 0.3, arches) + [
        (1.41, 0.36), (1.42, 0.78), (1.36, 0.86), (0.6, 0.9),
        (-1.34, 0.9), (-1.38, 0.84), (-1.39, 0.36)]
    p.add("body", extrude(lower, -W / 2, W / 2))
    _greenhouse(p, W, [(-1.36, 0.86), (0.62, 0.86), (0.34, 1.22), (-1.3, 1.22), (-1.37, 1.05)],
                [(-1.33, 1.215), (0.37, 1.215), (0.34, 1.25), (-1.3, 1.25)],
                [[(0.62, 0.86), (0.53, 0.86), (0.28, 1.22), (0.35, 1.22)],
                 [(-0.3, 0.86), (-0.22, 0.86), (-0.22, 1.22), (-0.3, 1.22)],
                 [(-1.37, 0.86), (-1.16, 0.86), (-1.16, 1.22), (-1.28, 1.22), (-1.37, 1.05)]], gw=0.86)
    p.add("body", _both_sides(box((-1.2, 0.38, 1.25), (0.1, 0.43, 1.3))))        # roof rails
    p.add("body", box((1.38, -0.55, 0.32), (1.46, 0.55, 0.42)))                  # bumper
    _car_wheel(p, xf, W / 2 - 0.02, r, 0.22)
    _car_wheel(p, xr, W / 2 - 0.02, r, 0.22)
    # spare wheel on the tailgate
    p.add("wheels", torus((-1.46, 0, 0.66), 0.19, 0.08, (1, 0, 0), 18, 8, ra=0.07))
    p.add("wheels", cyl((-1.5, 0, 0.66), (-1.4, 0, 0.66), 0.12, 12))
    _lamps(p, "lights", -1.41, -1.37, 0.55, 0.8, 0.5, 0.66)
    _lamps(p, "windows", 1.41, 1.44, 0.66, 0.76, 0.38, 0.6)
    p.add("windows", box((1.41, -0.3, 0.5), (1.44, 0.3, 0.76)))                  # grille
    return p


def _minivan(L, W, H):
    p, r, xf, xr = _Parts(), 0.24, 1.0, -0.95
    arches = [(xr, r, 0.29), (xf, r, 0.29)]
    wells(p, 0.16, arches, W / 2 - 0.2)
    lower = arch_line(-1.42, 1.42, 0.16, arches) + [
        (1.46, 0.24), (1.47, 0.48), (1.4, 0.6), (1.02, 0.73),
        (-1.4, 0.74), (-1.45, 0.68), (-1.46, 0.24)]
    p.add("body", extrude(lower, -W / 2, W / 2))
    _greenhouse(p, W, [(-1.44, 0.7), (1.05, 0.7), (0.42, 1.24), (-1.32, 1.24), (-1.44, 1.05)],
                [(-1.35, 1.235), (0.45, 1.235), (0.41, 1.28), (-1.32, 1.28)],
                [[(1.05, 0.7), (0.96, 0.7), (0.36, 1.24), (0.43, 1.24)],
                 [(0.02, 0.7), (0.1, 0.7), (0.1, 1.24), (0.02, 1.24)],
                 [(-0.78, 0.7), (-0.7, 0.7), (-0.7, 1.24), (-0.78, 1.24)],
                 [(-1.44, 0.7), (-1.3, 0.7), (-1.24, 1.24), (-1.32, 1.24), (-1.44, 1.05)]], gw=0.88)
    # sliding door: seam lines and the rail under the rear side window
    w = W / 2 + 0.006
    for x in (0.06, -0.74):
        p.add("windows", _both_sides(box((x - 0.012, W / 2 - 0.01, 0.2), (x + 0.012, w, 0.72))))
    p.add("windows", _both_sides(box((-1.3, W / 2 - 0.01, 0.66), (-0.74, w, 0.685))))
    p.add("windows", _both_sides(box((-0.2, W / 2 - 0.01, 0.5), (-0.08, w, 0.53))))   # door handle
    _car_wheel(p, xf, W / 2 - 0.02, r, 0.17)
    _car_wheel(p, xr, W / 2 - 0.02, r, 0.17)
    _lamps(p, "lights", -1.475, -1.44, 0.45, 0.68, 0.44, 0.62)
    _lamps(p, "windows", 1.43, 1.475, 0.46, 0.54, 0.38, 0.58)
    return p


def _truck(L, W, H):
    p, r, xf, xr = _Parts(), 0.3, 1.05, -1.0
    wells(p, 0.32, [(xf, r, 0.36), (xr, r, 0.36)], W / 2 - 0.25)
    front = arch_line(-0.42, 1.55, 0.32, [(xf, r, 0.36)]) + [
        (1.6, 0.4), (1.6, 0.8), (1.52, 0.88), (0.62, 0.92), (-0.42, 0.92)]
    p.add("body", extrude(front, -W / 2, W / 2))
    _greenhouse(p, W, [(-0.4, 0.88), (0.64, 0.88), (0.22, 1.36), (-0.34, 1.36)],
                [(-0.37, 1.355), (0.25, 1.355), (0.21, 1.39), (-0.34, 1.39)],
                [[(0.64, 0.88), (0.55, 0.88), (0.16, 1.36), (0.23, 1.36)],
                 [(-0.42, 0.88), (-0.3, 0.88), (-0.28, 1.36), (-0.36, 1.36)]], gw=0.86)
    wall = arch_line(-1.6, -0.42, 0.32, [(xr, r, 0.36)]) + [(-0.42, 0.9), (-1.6, 0.9)]
    p.add("body", _both_sides(extrude(wall, W / 2 - 0.06, W / 2)))               # bed sides
    p.add("body", box((-1.58, -W / 2 + 0.06, 0.62), (-0.42, W / 2 - 0.06, 0.68)))  # bed floor
    p.add("body", box((-1.32, -0.35, 0.34), (-0.42, 0.35, 0.62)))               # chassis under the bed
    p.add("body", box((-1.6, -W / 2, 0.4), (-1.55, W / 2, 0.9)))                # tailgate
    p.add("body", box((1.58, -0.62, 0.32), (1.65, 0.62, 0.42)))                 # bumper
    _car_wheel(p, xf, W / 2 - 0.02, r, 0.22)
    _car_wheel(p, xr, W / 2 - 0.02, r, 0.22)
    _lamps(p, "lights", -1.625, -1.59, 0.62, 0.86, 0.56, W / 2)
    _lamps(p, "windows", 1.59, 1.62, 0.66, 0.78, 0.4, 0.62)
    p.add("windows", box((1.59, -0.34, 0.5), (1.62, 0.34, 0.8)))                # grille
    return p


# ---- buses --------------------------------------------------------------------------------------------------------------

def _side_panes(p: _Parts, W: float, x0: float, x1: float, z0: float, z1: float, n: int, gap: float = 0.05,
                sides=(1, -1)) -> None:
    edges = np.linspace(x0, x1, n + 1)
    for s in sides:
        for a, b in zip(edges[:-1], edges[1:]):
            g = box((a + gap / 2, W / 2 - 0.01, z0), (b - gap / 2, W / 2 + 0.012, z1))
            p.add("windows", g if s > 0 else _mirror_y(g))


def _bus_box(x0, x1, zb, top, arches, rf=0.1, rr=0.1):
    """Bus side profile: flat sides with rounded roof corners and wheel arches."""
    return arch_line(x0 + 0.03, x1 - 0.03, zb, arches) + [
        (x1, zb + 0.06), (x1, top - rf), (x1 - rf * 0.3, top - rf * 0.3), (x1 - rf, top),
        (x0 + rr, top), (x0 + rr * 0.3, top - rr * 0.3), (x0, top - rr), (x0, zb + 0.06)]


def _bus_common(p: _Parts, W, x0, x1, axles, r=0.22, door_x=None):
    wells(p, 0.14, [(x, r, 0.27) for x in axles], W / 2 - 0.24)
    for x in axles:
        _car_wheel(p, x, W / 2 - 0.03, r, 0.2)
    _lamps(p, "lights", x0 - 0.015, x0 + 0.01, 0.3, 0.55, W / 2 - 0.16, W / 2 - 0.04)
    _lamps(p, "windows", x1 - 0.01, x1 + 0.015, 0.28, 0.38, W / 2 - 0.2, W / 2 - 0.05)
    for dx in door_x or ():
        p.add("windows", box((dx[0], -W / 2 - 0.012, 0.18), (dx[1], -W / 2 + 0.01, dx[2])))


def _regular_bus(L, W, H):
    p = _Parts()
    axles = (1.2, -1.05)
    p.add("body", extrude(_bus_box(-1.9, 1.9, 0.14, 1.47, [(x, 0.22, 0.27) for x in axles], 0.15), -W / 2, W / 2))
    p.add("body", box((-0.6, -0.42, 1.46), (0.5, 0.42, 1.53)))                  # roof air conditioning
    _side_panes(p, W, -1.75, 1.25, 0.72, 1.3, 6, sides=(-1,))
    _side_panes(p, W, -1.75, 1.75, 0.72, 1.3, 7, sides=(1,))
    p.add("windows", box((1.895, -0.6, 0.6), (1.915, 0.6, 1.38)))               # windscreen
    p.add("windows", box((-1.915, -0.5, 0.9), (-1.895, 0.5, 1.3)))
    _bus_common(p, W, -1.9, 1.9, axles, door_x=[(1.35, 1.75, 1.3), (-0.15, 0.25, 1.3)])
    return p


def _double_bus(L, W, H):
    p = _Parts()
    axles = (1.12, -1.0)
    p.add("body", extrude(_bus_box(-1.8, 1.8, 0.14, 2.08, [(x, 0.22, 0.27) for x in axles], 0.18, 0.18),
                          -W / 2, W / 2))
    _side_panes(p, W, -1.65, 1.25, 0.7, 1.12, 5, sides=(-1,))
    _side_panes(p, W, -1.65, 1.65, 0.7, 1.12, 6, sides=(1,))
    _side_panes(p, W, -1.6, 1.65, 1.4, 1.88, 6)
    p.add("windows", box((1.795, -0.6, 0.55), (1.815, 0.6, 1.15)))              # lower windscreen
    p.add("windows", box((1.795, -0.58, 1.4), (1.815, 0.58, 1.88)))             # upper deck front
    p.add("windows", box((-1.815, -0.5, 1.45), (-1.795, 0.5, 1.85)))
    p.add("body", _both_sides(box((-1.8, W / 2, 1.22), (1.8, W / 2 + 0.01, 1.28))))  # band between the decks
    _bus_common(p, W, -1.8, 1.8, axles, door_x=[(1.35, 1.7, 1.15)])
    return p


def _school_bus(L, W, H):
    p = _Parts()
    xf, xr = 1.5, -0.95
    wells(p, 0.14, [(xr, 0.22, 0.27)], W / 2 - 0.24)
    main = arch_line(-1.87, 1.22, 0.14, [(xr, 0.22, 0.27)]) + [
        (1.25, 0.2), (1.25, 1.45), (1.17, 1.56), (-1.78, 1.56), (-1.88, 1.48), (-1.9, 1.38), (-1.9, 0.2)]
    p.add("body", extrude(main, -W / 2, W / 2))
    bonnet = [(1.2, 0.3), (1.9, 0.3), (1.92, 0.64), (1.86, 0.74), (1.2, 0.82)]
    p.add("body", extrude(bonnet, -0.36 * W, 0.36 * W))
    fender = [(xf + 0.3 * np.cos(t), 0.22 + 0.3 * np.sin(t)) for t in np.linspace(0, np.pi, 9)] + \
             [(xf + 0.27 * np.cos(t), 0.22 + 0.27 * np.sin(t)) for t in np.linspace(np.pi, 0, 9)]
    p.add("body", _both_sides(extrude(fender, 0.3 * W, W / 2 - 0.01)))
    p.add("body", box((1.88, -0.55, 0.22), (1.95, 0.55, 0.32)))                 # bumper
    p.add("windows", box((1.9, -0.25, 0.42), (1.935, 0.25, 0.66)))              # grille
    _side_panes(p, W, -1.75, 1.1, 0.86, 1.27, 9)
    for z in (0.45, 0.65):                                                       # black rub rails
        p.add("windows", _both_sides(box((-1.9, W / 2 - 0.01, z), (1.25, W / 2 + 0.01, z + 0.035))))
    p.add("windows", box((1.245, -0.58, 0.86), (1.265, 0.58, 1.42)))            # windscreen
    p.add("windows", box((-1.915, -0.25, 0.35), (-1.895, 0.25, 1.3)))           # emergency door
    for x in (xf, xr):
        _car_wheel(p, x, W / 2 - 0.03, 0.22, 0.2)
    _lamps(p, "lights", -1.915, -1.89, 1.2, 1.35, W / 2 - 0.2, W / 2 - 0.06)
    _lamps(p, "lights", -1.915, -1.89, 0.35, 0.55, W / 2 - 0.2, W / 2 - 0.06)
    _lamps(p, "windows", 1.88, 1.93, 0.5, 0.62, 0.3, 0.44)
    p.add("windows", box((0.82, -W / 2 - 0.012, 0.18), (1.18, -W / 2 + 0.01, 1.3)))   # door
    return p


def _articulated_bus(L, W, H):
    p = _Parts()
    axles_f, axles_r = (1.75, 0.75), (-1.6,)
    p.add("body", extrude(_bus_box(0.3, 2.3, 0.14, 1.47, [(x, 0.22, 0.27) for x in axles_f], 0.15, 0.02),
                          -W / 2, W / 2))
    p.add("body", extrude(_bus_box(-2.3, -0.1, 0.14, 1.47, [(x, 0.22, 0.27) for x in axles_r], 0.02, 0.15),
                          -W / 2, W / 2))
    # accordion bellows over the joint
    xs = np.linspace(-0.1, 0.3, 9)
    for k, (a, b) in enumerate(zip(xs[:-1], xs[1:])):
        inset = 0.03 if k % 2 else 0.07
        p.add("windows", box((a, -W / 2 + inset, 0.2 + inset), (b, W / 2 - inset, 1.44 - inset)))
    p.add("windows", box((-0.15, -0.2, 0.3), (0.35, 0.2, 0.36)))               # turntable
    _side_panes(p, W, 0.45, 1.85, 0.72, 1.3, 3, sides=(-1,))
    _side_panes(p, W, 0.45, 2.15, 0.72, 1.3, 4, sides=(1,))
    _side_panes(p, W, -2.15, -0.25, 0.72, 1.3, 4, sides=(1,))
    _side_panes(p, W, -2.15, -1.0, 0.72, 1.3, 2, sides=(-1,))
    p.add("windows", box((2.295, -0.6, 0.6), (2.315, 0.6, 1.38)))
    p.add("windows", box((-2.315, -0.5, 0.9), (-2.295, 0.5, 1.3)))
    _bus_common(p, W, -2.3, 2.3, axles_f + axles_r,
                door_x=[(1.9, 2.2, 1.3), (-0.9, -0.5, 1.3)])
    return p


# ---- aeroplanes -------------------------------------------------------------------------------------------------------

def _wing(p: _Parts, outline, z: float, t: float, dihedral: float = 0.0, part: str = "body") -> None:
    """Half-wing from its top-view outline (x, y >= 0), mirrored to the other side."""
    g = _tf(extrude(outline, z - t / 2, z + t / 2, "xy"), _rot("x", dihedral), about=(0, 0, z))
    p.add(part, _both_sides(g))


def _fin(profile, t: float, y: float = 0.0, cant: float = 0.0) -> Geom:
    g = extrude(profile, y - t / 2, y + t / 2)
    if cant:
        z0 = min(q[1] for q in profile)
        g = _tf(g, _rot("x", cant), about=(0, y, z0))
    return g


def _gear(p: _Parts, x: float, y: float, z_top: float, r: float = 0.05) -> None:
    p.add("body", cyl((x, y, r), (x, y, z_top), 0.012, 6))
    p.add("wheels", cyl((x, y - 0.03, r), (x, y + 0.03, r), r, 10))


def _cabin_windows(p: _Parts, xs, z: float, r_body: float, h: float = 0.045, w: float = 0.04) -> None:
    for x in xs:
        p.add("windows", _both_sides(box((x - w / 2, r_body - 0.03, z - h / 2), (x + w / 2, r_body + 0.008, z + h / 2))))


def _airliner(L, W, H):
    p, zc = _Parts(), 0.44
    p.add("body", loft([(2.1, zc - 0.04, 0.02, 0.02), (2.05, zc - 0.03, 0.1, 0.1), (1.95, zc - 0.015, 0.16, 0.16),
                        (1.8, zc, 0.2, 0.21), (1.55, zc, 0.22, 0.23), (-0.9, zc, 0.22, 0.23),
                        (-1.4, zc + 0.05, 0.18, 0.17), (-1.85, zc + 0.12, 0.1, 0.08), (-2.08, zc + 0.16, 0.03, 0.03)],
                       18))
    _wing(p, [(0.55, 0.0), (-0.32, 2.0), (-0.58, 2.0), (-0.45, 0.0)], zc - 0.12, 0.05, 5)
    _wing(p, [(-1.5, 0.0), (-1.9, 0.7), (-2.05, 0.7), (-1.95, 0.0)], zc + 0.13, 0.03, 4)
    p.add("body", _fin([(-1.35, zc + 0.15), (-1.98, zc + 0.15), (-2.1, 1.2), (-1.86, 1.2)], 0.035))
    y = 0.75                                                            # engines under the wings
    nac = loft([(0.62, 0.2, 0.085, 0.085), (0.5, 0.2, 0.1, 0.1), (0.2, 0.2, 0.09, 0.09), (0.08, 0.2, 0.06, 0.06)],
               14, y=y)
    p.add("body", _both_sides(nac))
    p.add("body", _both_sides(box((0.1, y - 0.015, 0.25), (0.4, y + 0.015, 0.34))))
    p.add("windows", _both_sides(cyl((0.6, y, 0.2), (0.625, y, 0.2), 0.07, 12)))       # intake
    _cabin_windows(p, np.arange(1.45, -1.2, -0.125), zc + 0.06, 0.22)
    p.add("windows", box((1.82, -0.13, zc + 0.08), (1.93, 0.13, zc + 0.16)))   # cockpit
    _gear(p, 1.55, 0.0, zc - 0.15)
    for y in (0.35, -0.35):
        _gear(p, -0.2, y, zc - 0.12)
    p.add("lights", _both_sides(ellipsoid((-0.45, 2.0, zc - 0.03), (0.04, 0.03, 0.03), 8, 4)))
    p.add("lights", ellipsoid((-2.09, 0, zc + 0.16), (0.03, 0.03, 0.03), 8, 4))
    return p


def _fighter(L, W, H):
    p, zc = _Parts(), 0.36
    p.add("body", loft([(1.9, zc, 0.01, 0.01), (1.5, zc, 0.09, 0.08), (1.0, zc + 0.01, 0.16, 0.14),
                        (0.5, zc, 0.26, 0.16), (-0.8, zc, 0.3, 0.15), (-1.55, zc, 0.26, 0.13)], 16))
    # delta wing with a leading-edge extension and cropped tips
    _wing(p, [(1.0, 0.12), (0.35, 0.32), (-0.85, 1.3), (-1.15, 1.3), (-1.2, 0.22), (-1.2, 0.0), (1.0, 0.0)],
          zc, 0.04)
    _wing(p, [(-1.3, 0.2), (-1.65, 0.85), (-1.85, 0.85), (-1.8, 0.2)], zc - 0.02, 0.03)
    for y in (0.26, -0.26):
        fin = _fin([(-0.95, zc + 0.1), (-1.65, zc + 0.1), (-1.78, 0.9), (-1.45, 0.9)], 0.03, y,
                   -18 if y > 0 else 18)
        p.add("body", fin)
    p.add("body", _both_sides(box((0.2, 0.2, zc - 0.15), (0.75, 0.34, zc + 0.02))))    # intakes
    p.add("windows", _both_sides(box((0.74, 0.2, zc - 0.14), (0.76, 0.33, zc + 0.01))))
    p.add("windows", ellipsoid((0.9, 0, zc + 0.14), (0.38, 0.1, 0.1), 12, 6))           # canopy
    for y in (0.12, -0.12):
        p.add("body", cyl((-1.55, y, zc), (-1.82, y, zc), 0.1, 12, 0.09))               # nozzles
        p.add("lights", cyl((-1.82, y, zc), (-1.84, y, zc), 0.075, 12))
    _gear(p, 1.0, 0.0, zc - 0.1, 0.04)
    for y in (0.35, -0.35):
        _gear(p, -0.5, y, zc - 0.1, 0.045)
    return p


def _jet(L, W, H):
    p, zc = _Parts(), 0.42
    p.add("body", loft([(1.8, zc - 0.04, 0.02, 0.02), (1.7, zc - 0.03, 0.1, 0.09), (1.45, zc, 0.19, 0.19),
                        (1.1, zc + 0.01, 0.21, 0.22), (-0.6, zc + 0.01, 0.21, 0.22),
                        (-1.25, zc + 0.06, 0.15, 0.15), (-1.6, zc + 0.1, 0.06, 0.06), (-1.75, zc + 0.12, 0.02, 0.02)],
                       16))
    _wing(p, [(0.3, 0.0), (-0.35, 1.5), (-0.55, 1.5), (-0.5, 0.0)], zc - 0.14, 0.04, 4)
    p.add("body", _both_sides(_fin([(-0.33, zc - 0.05), (-0.57, zc - 0.05), (-0.6, zc + 0.16), (-0.48, zc + 0.16)],
                                   0.02, 1.5)))                                            # winglets
    p.add("body", _fin([(-1.1, zc + 0.15), (-1.6, zc + 0.15), (-1.82, 0.98), (-1.62, 0.98)], 0.04))
    _wing(p, [(-1.58, 0.0), (-1.78, 0.65), (-1.9, 0.65), (-1.84, 0.0)], 0.98, 0.03)       # T-tail
    y = 0.36                                                            # engines on the rear fuselage
    nac = loft([(-0.75, zc + 0.12, 0.09, 0.09), (-0.85, zc + 0.12, 0.11, 0.11), (-1.2, zc + 0.12, 0.1, 0.1),
                (-1.35, zc + 0.12, 0.07, 0.07)], 14, y=y)
    p.add("body", _both_sides(nac))
    p.add("body", _both_sides(box((-1.15, 0.1, zc + 0.09), (-0.95, y, zc + 0.14))))         # pylon
    p.add("windows", _both_sides(cyl((-0.76, y, zc + 0.12), (-0.735, y, zc + 0.12), 0.075, 12)))
    _cabin_windows(p, np.arange(0.95, -0.5, -0.24), zc + 0.06, 0.21, 0.07, 0.06)
    p.add("windows", box((1.42, -0.14, zc + 0.07), (1.56, 0.14, zc + 0.15)))
    _gear(p, 1.3, 0.0, zc - 0.15, 0.045)
    for y in (0.3, -0.3):
        _gear(p, -0.35, y, zc - 0.14, 0.05)
    p.add("lights", _both_sides(ellipsoid((-0.45, 1.5, zc - 0.12), (0.04, 0.025, 0.025), 8, 4)))
    return p


def _biplane(L, W, H):
    p, zc = _Parts(), 0.52
    p.add("body", loft([(1.2, zc, 0.2, 0.21), (1.05, zc, 0.23, 0.24), (0.4, zc, 0.22, 0.24),
                        (-0.5, zc + 0.03, 0.15, 0.17), (-1.4, zc + 0.08, 0.05, 0.06), (-1.48, zc + 0.09, 0.02, 0.02)],
                       14))
    upper = [(0.62, 0.0), (0.62, 1.58), (0.55, 1.7), (0.1, 1.7), (0.04, 1.58), (0.04, 0.0)]
    lower = [(0.5, 0.0), (0.5, 1.5), (0.43, 1.6), (0.0, 1.6), (-0.06, 1.5), (-0.06, 0.0)]
    _wing(p, upper, 1.05, 0.05, 2)
    _wing(p, lower, 0.36, 0.05, 2)
    for x in (0.45, 0.12):                                              # interplane struts
        p.add("body", _both_sides(cyl((x, 1.25, 0.38), (x + 0.04, 1.27, 1.05), 0.015, 6)))
    p.add("body", _both_sides(cyl((0.45, 1.25, 0.38), (0.16, 1.27, 1.05), 0.008, 4)))      # bracing wire
    for x in (0.5, 0.12):                                               # cabane struts
        p.add("body", _both_sides(cyl((x, 0.12, zc + 0.18), (x + 0.03, 0.3, 1.04), 0.015, 6)))
    _wing(p, [(-1.05, 0.0), (-1.2, 0.55), (-1.38, 0.55), (-1.42, 0.0)], zc + 0.05, 0.03)
    p.add("body", _fin([(-1.0, zc + 0.12), (-1.5, zc + 0.08), (-1.52, 0.92), (-1.32, 0.95)], 0.03))
    # propeller, spinner and open cockpit
    p.add("windows", box((1.24, -0.04, zc - 0.42), (1.27, 0.04, zc + 0.42)))
    p.add("body", ellipsoid((1.27, 0, zc), (0.08, 0.07, 0.07), 10, 5))
    p.add("windows", box((-0.3, -0.14, zc + 0.18), (0.05, 0.14, zc + 0.25)))
    p.add("windows", box((0.07, -0.13, zc + 0.2), (0.09, 0.13, zc + 0.33)))
    for y in (0.38, -0.38):                                             # fixed main gear
        p.add("body", cyl((0.68, y, 0.15), (0.72, y * 0.3, zc - 0.15), 0.015, 6))
        p.add("body", cyl((0.68, y, 0.15), (0.45, y * 0.3, zc - 0.15), 0.015, 6))
        p.add("wheels", torus((0.68, y, 0.15), 0.1, 0.05, (0, 1, 0), 16, 6, ra=0.04))
    p.add("body", cyl((0.68, -0.38, 0.15), (0.68, 0.38, 0.15), 0.015, 6))
    p.add("body", cyl((-1.3, 0, 0.1), (-1.25, 0, zc), 0.012, 6))            # tail-wheel strut
    p.add("wheels", cyl((-1.3, -0.02, 0.05), (-1.3, 0.02, 0.05), 0.05, 10))
    p.add("lights", _both_sides(ellipsoid((0.33, 1.72, 1.05), (0.04, 0.03, 0.03), 8, 4)))
    return p


# ---- bicycles -----------------------------------------------------------------------------------------------------------

def _tube(p: _Parts, a, b, r: float = 0.018, part: str = "body", n: int = 8) -> None:
    p.add(part, cyl(a, b, r, n))


def _stays(p: _Parts, a, b, r: float = 0.012, dy: float = 0.06) -> None:
    """Two tubes from a (on the centre plane) to the axle b, one each side of the wheel."""
    for s in (1, -1):
        _tube(p, a, (b[0], s * dy, b[2]), r)


def _saddle(p: _Parts, x: float, z: float, w: float = 0.08, length: float = 0.26) -> None:
    sad = [(x + length * 0.55, z), (x + length * 0.5, z + 0.035), (x - length * 0.45, z + 0.05), (x - length * 0.5, z)]
    p.add("windows", extrude(sad, -w, w))


def _crank(p: _Parts, bb, width: float = 0.16) -> None:
    x, z = bb
    p.add("body", cyl((x, 0.02, z), (x, 0.04, z), 0.09, 16))                # chainring
    for s, ang in ((1, 60), (-1, 240)):
        a = np.radians(ang)
        e = (x + 0.17 * np.cos(a), s * width, z + 0.17 * np.sin(a))
        _tube(p, (x, s * 0.05, z), (e[0], s * 0.07, e[2]), 0.012)
        p.add("windows", box((e[0] - 0.05, s * 0.07, e[2] - 0.012), (e[0] + 0.05, s * width, e[2] + 0.012)) if s > 0
              else box((e[0] - 0.05, -width, e[2] - 0.012), (e[0] + 0.05, -0.07, e[2] + 0.012)))


def _flat_bar(p: _Parts, x: float, z: float, half: float, sweep: float = 0.0) -> None:
    _tube(p, (x - sweep, -half + 0.1, z), (x, -0.12, z), 0.012)
    _tube(p, (x, -0.12, z), (x, 0.12, z), 0.014)
    _tube(p, (x, 0.12, z), (x - sweep, half - 0.1, z), 0.012)
    for s in (1, -1):
        p.add("windows", cyl((x - sweep, s * (half - 0.11), z), (x - sweep, s * half, z), 0.018, 8))


def _bike_lights(p: _Parts, rear, front) -> None:
    p.add("lights", box((rear[0] - 0.02, -0.03, rear[1] - 0.025), (rear[0] + 0.01, 0.03, rear[1] + 0.025)))
    p.add("windows", cyl((front[0] - 0.03, 0, front[1]), (front[0] + 0.03, 0, front[1]), 0.03, 10))


def _bicycle(wheelbase: float, R: float, tube: float, bb, seat, head_top, head_bot, knobs: bool = False,
             crank_width: float = 0.16) -> _Parts:
    """Wheels, diamond frame, fork and cranks of a bicycle (x, z points for bottom bracket, seat cluster, head tube)."""
    p = _Parts()
    xr, xf = -wheelbase / 2, wheelbase / 2
    _bike_wheel(p, xr, R, tube, knobs=knobs)
    _bike_wheel(p, xf, R, tube, knobs=knobs)
    B = (bb[0], 0, bb[1])
    S = (seat[0], 0, seat[1])
    HT, HB = (head_top[0], 0, head_top[1]), (head_bot[0], 0, head_bot[1])
    _tube(p, B, S, 0.018)
    _tube(p, S, HT, 0.017)
    _tube(p, B, HB, 0.02)
    _tube(p, HB, HT, 0.024)
    _stays(p, B, (xr, 0, R))
    _stays(p, S, (xr, 0, R), 0.01)
    _stays(p, HB, (xf, 0, R), 0.014, 0.05)
    _crank(p, bb, crank_width)
    return p


def _mountain_bike(L, W, H):
    R = 0.35
    p = _bicycle(1.08, R, 0.04, (-0.04, 0.32), (-0.2, 0.8), (0.39, 0.86), (0.44, 0.7), knobs=True)
    for s in (1, -1):                                                    # suspension fork stanchions
        _tube(p, (0.44, s * 0.05, 0.72), (0.49, s * 0.05, 0.55), 0.022)
    p.add("body", box((0.41, -0.07, 0.7), (0.47, 0.07, 0.75)))             # fork crown
    _tube(p, (-0.2, 0, 0.8), (-0.23, 0, 0.97), 0.014)                     # seat post
    _saddle(p, -0.24, 0.97)
    _tube(p, (0.39, 0, 0.86), (0.37, 0, 1.0), 0.016)                      # stem
    _flat_bar(p, 0.38, 1.0, 0.3)
    _bike_lights(p, (-0.25, 0.86), (0.46, 0.78))
    return p


def _road_bike(L, W, H):
    R = 0.345
    p = _bicycle(1.0, R, 0.016, (-0.03, 0.3), (-0.2, 0.78), (0.38, 0.78), (0.42, 0.62), crank_width=0.25)
    _tube(p, (-0.2, 0, 0.78), (-0.22, 0, 0.92), 0.013)
    _saddle(p, -0.23, 0.92, 0.06, 0.27)
    _tube(p, (0.38, 0, 0.78), (0.46, 0, 0.86), 0.015)                     # long low stem
    x = 0.46
    _tube(p, (x, -0.2, 0.86), (x, 0.2, 0.86), 0.013)
    for s in (1, -1):                                                    # drops
        pts = [(x, s * 0.2, 0.86), (x + 0.08, s * 0.2, 0.85), (x + 0.09, s * 0.2, 0.77), (x + 0.04, s * 0.2, 0.74),
               (x - 0.01, s * 0.2, 0.75)]
        for a, b in zip(pts[:-1], pts[1:]):
            _tube(p, a, b, 0.014, "windows")
    _bike_lights(p, (-0.24, 0.84), (0.44, 0.7))
    return p


def _utility_bike(L, W, H):
    R = 0.34
    p = _Parts()
    xr, xf = -0.54, 0.56
    _bike_wheel(p, xr, R, 0.03)
    _bike_wheel(p, xf, R, 0.03)
    B, S, HT, HB = (-0.05, 0, 0.3), (-0.18, 0, 0.72), (0.37, 0, 0.95), (0.42, 0, 0.74)
    # step-through frame: a low curved down tube and no top tube
    _tube(p, HB, (0.25, 0, 0.42), 0.026)
    _tube(p, (0.25, 0, 0.42), (0.1, 0, 0.3), 0.026)
    _tube(p, (0.1, 0, 0.3), B, 0.026)
    _tube(p, B, S, 0.02)
    _tube(p, HB, HT, 0.025)
    _stays(p, B, (xr, 0, R))
    _stays(p, S, (xr, 0, R), 0.01)
    _stays(p, HB, (xf, 0, R), 0.014, 0.05)
    _crank(p, (-0.05, 0.3))
    _tube(p, S, (-0.21, 0, 0.92), 0.014)
    _saddle(p, -0.22, 0.92, 0.11, 0.26)
    # swept-back city handlebar
    _tube(p, HT, (0.35, 0, 1.06), 0.016)
    _flat_bar(p, 0.35, 1.06, 0.3, sweep=0.16)
    for x, a0, a1 in ((xf, 10, 150), (xr, 30, 170)):                  # mudguards
        p.add("body", torus((x, 0, R), R + 0.01, 0.03, (0, 1, 0), 14, 5, ra=0.045, arc=(a0, a1)))
    # rear rack and front basket
    p.add("body", box((-0.82, -0.1, 0.74), (-0.3, 0.1, 0.76)))
    _tube(p, (-0.8, 0, 0.74), (xr, 0, R), 0.01)
    bx0, bx1, bz0, bz1, bw = 0.46, 0.8, 0.84, 1.12, 0.17
    p.add("body", box((bx0, -bw, bz0), (bx1, bw, bz0 + 0.02)))
    p.add("body", box((bx0, -bw, bz0), (bx0 + 0.015, bw, bz1)), box((bx1 - 0.015, -bw, bz0), (bx1, bw, bz1)))
    p.add("body", _both_sides(box((bx0, bw - 0.015, bz0), (bx1, bw, bz1))))
    _tube(p, (0.42, 0, 0.76), (bx0 + 0.05, 0, bz0), 0.014)                       # basket carrier
    _tube(p, (xf, 0, R), (bx1 - 0.05, 0, bz0), 0.01)
    p.add("body", box((-0.5, 0.05, 0.3), (0.05, 0.07, 0.4)))                    # chain guard
    _bike_lights(p, (-0.83, 0.74), (0.45, 0.68))
    return p


def _tandem_bike(L, W, H):
    R = 0.345
    p = _Parts()
    xr, xf = -0.95, 0.95
    _bike_wheel(p, xr, R, 0.03)
    _bike_wheel(p, xf, R, 0.03)
    B1, S1 = (0.28, 0, 0.31), (0.16, 0, 0.8)        # captain (front rider)
    B2, S2 = (-0.5, 0, 0.31), (-0.6, 0, 0.8)        # stoker (rear rider)
    HT, HB = (0.78, 0, 0.86), (0.83, 0, 0.7)
    for a, b, r in ((B1, S1, 0.019), (B2, S2, 0.019), (S1, HT, 0.017), (S2, S1, 0.017), (B1, HB, 0.02),
                    (B2, B1, 0.02), (S2, B1, 0.017), (HB, HT, 0.024)):
        _tube(p, a, b, r)
    _stays(p, B2, (xr, 0, R))
    _stays(p, S2, (xr, 0, R), 0.01)
    _stays(p, HB, (xf, 0, R), 0.014, 0.05)
    _crank(p, (B1[0], B1[2]))
    _crank(p, (B2[0], B2[2]))
    for S in (S1, S2):
        _tube(p, S, (S[0] - 0.03, 0, 0.97), 0.014)
        _saddle(p, S[0] - 0.04, 0.97)
    _tube(p, HT, (0.76, 0, 1.0), 0.016)
    _flat_bar(p, 0.77, 1.0, 0.3, sweep=0.04)
    # stoker's bar clamped to the captain's seat post
    _tube(p, (0.12, 0, 0.92), (0.02, 0, 0.94), 0.013)
    _tube(p, (0.02, -0.2, 0.94), (0.02, 0.2, 0.94), 0.013)
    for s in (1, -1):
        p.add("windows", cyl((0.02, s * 0.12, 0.94), (0.02, s * 0.2, 0.94), 0.017, 8))
    _bike_lights(p, (-0.66, 0.86), (0.85, 0.78))
    return p


# ---- motorbikes ---------------------------------------------------------------------------------------------------------

def _moto_wheel(p: _Parts, x: float, R: float, tube: float, ra: float | None = None, knobs: bool = False) -> None:
    p.add("wheels", torus((x, 0, R), R - tube, tube, (0, 1, 0), 24, 8, ra=ra))
    # cast wheel: rim, five spokes and hub in the body colour, open between the spokes
    rim = R - tube * 1.15
    p.add("body", torus((x, 0, R), rim, 0.018, (0, 1, 0), 24, 5, ra=(ra or tube) * 0.6))
    for k in range(5):
        a = 2 * np.pi * k / 5 + 0.3
        p.add("body", cyl((x, 0, R), (x + rim * np.cos(a), 0, R + rim * np.sin(a)), 0.014, 5))
    p.add("body", cyl((x, -(ra or tube) * 0.7, R), (x, (ra or tube) * 0.7, R), 0.05, 10))  # hub
    if knobs:
        for k in range(24):
            a = 2 * np.pi * (k + 0.5) / 24
            c = np.array([x + R * np.cos(a), 0, R + R * np.sin(a)])
            p.add("wheels", _tf(box((-0.025, -(ra or tube) * 1.05, -0.016), (0.025, (ra or tube) * 1.05, 0.016)),
                                _rot("y", -np.degrees(a) + 90), c))


def _fork(p: _Parts, top, axle, dy: float = 0.08, r: float = 0.022) -> None:
    for s in (1, -1):
        _tube(p, (top[0], s * dy, top[1]), (axle[0], s * dy, axle[1]), r)
    p.add("body", cyl((axle[0], -dy, axle[1]), (axle[0], dy, axle[1]), 0.015, 6))


def _handlebar(p: _Parts, x: float, z: float, half: float, rise: float = 0.0, back: float = 0.0) -> None:
    """Bar across the bike; `rise` lifts the grips (ape hangers), `back` pulls them towards the rider."""
    for s in (1, -1):
        mid = (x, s * 0.12, z)
        end = (x - back, s * (half - 0.12), z + rise)
        _tube(p, mid, end, 0.015)
        p.add("windows", cyl(end, (x - back, s * half, z + rise), 0.022, 8))
    _tube(p, (x, -0.12, z), (x, 0.12, z), 0.016)


def _chopper(L, W, H):
    p = _Parts()
    xr, Rr, xf, Rf = -0.8, 0.3, 0.8, 0.33
    _moto_wheel(p, xr, Rr, 0.09, 0.1)
    _moto_wheel(p, xf, Rf, 0.04, 0.04)
    neck = (0.22, 0.78)
    _fork(p, neck, (xf, Rf), 0.07, 0.022)                          # long raked fork
    p.add("body", box((0.14, -0.1, 0.74), (0.26, 0.1, 0.8)))
    _tube(p, (0.2, 0, 0.8), (0.24, 0, 0.72), 0.04)                 # steering head
    _tube(p, (0.2, 0, 0.76), (-0.45, 0, 0.52), 0.025)               # backbone
    _tube(p, (0.22, 0, 0.72), (0.0, 0, 0.2), 0.025)                 # down tube
    _tube(p, (0.0, 0, 0.2), (-0.45, 0, 0.2), 0.025)
    _stays(p, (-0.45, 0, 0.2), (xr, 0, Rr), 0.02, 0.14)
    _stays(p, (-0.45, 0, 0.52), (xr, 0, Rr), 0.02, 0.14)
    p.add("body", ellipsoid((0.0, 0, 0.72), (0.22, 0.1, 0.08), 12, 6))             # peanut tank
    for ang in (-25, 25):                                                          # V-twin
        a = np.radians(ang)
        base = np.array([-0.1, 0, 0.3])
        p.add("body", cyl(base, base + 0.28 * np.array([np.sin(a), 0, np.cos(a)]), 0.07, 10))
    p.add("body", box((-0.3, -0.1, 0.18), (0.1, 0.1, 0.34)))                       # crankcase
    for dz in (0.0, 0.07):                                                         # exhaust pipes
        _tube(p, (0.05, -0.14, 0.42 - dz), (-0.2, -0.16, 0.26 - dz), 0.022)
        _tube(p, (-0.2, -0.16, 0.26 - dz), (-1.05, -0.17, 0.3 - dz), 0.022)
    p.add("windows", extrude([(-0.55, 0.5), (-0.2, 0.52), (-0.3, 0.58), (-0.6, 0.62)], -0.12, 0.12))   # low seat
    p.add("body", torus((xr, 0, Rr), Rr + 0.02, 0.04, (0, 1, 0), 12, 5, ra=0.13, arc=(40, 140)))    # rear fender
    for s in (1, -1):                                                              # sissy bar
        _tube(p, (-0.85, s * 0.1, 0.4), (-0.72, s * 0.08, 0.95), 0.012)
    _tube(p, (-0.72, -0.08, 0.95), (-0.72, 0.08, 0.95), 0.012)
    for s in (1, -1):                                                              # ape-hanger risers
        _tube(p, (0.18, s * 0.1, 0.8), (0.12, s * 0.14, 1.0), 0.015)
    _handlebar(p, 0.12, 1.0, 0.35, 0.0, 0.1)
    p.add("windows", cyl((0.3, 0, 0.78), (0.36, 0, 0.78), 0.07, 12))               # headlight
    p.add("lights", box((-1.12, -0.04, 0.45), (-1.08, 0.04, 0.5)))
    return p


def _cruiser(L, W, H):
    p = _Parts()
    xr, xf, R = -0.72, 0.72, 0.32
    _moto_wheel(p, xr, R, 0.07, 0.075)
    _moto_wheel(p, xf, R, 0.06, 0.06)
    neck = (0.42, 0.85)
    _fork(p, neck, (xf, R), 0.09, 0.03)
    p.add("body", torus((xf, 0, R), R + 0.02, 0.04, (0, 1, 0), 12, 5, ra=0.1, arc=(20, 150)))
    p.add("body", torus((xr, 0, R), R + 0.02, 0.04, (0, 1, 0), 12, 5, ra=0.11, arc=(30, 175)))
    p.add("body", ellipsoid((0.15, 0, 0.74), (0.3, 0.16, 0.11), 12, 6))            # big tank
    _tube(p, (0.42, 0, 0.85), (-0.5, 0, 0.55), 0.03)
    _tube(p, (0.4, 0, 0.8), (0.15, 0, 0.2), 0.03)
    _tube(p, (0.15, 0, 0.2), (-0.45, 0, 0.22), 0.03)
    _stays(p, (-0.45, 0, 0.25), (xr, 0, R), 0.025, 0.13)
    for ang in (-28, 28):
        a = np.radians(ang)
        base = np.array([0.0, 0, 0.3])
        p.add("body", cyl(base, base + 0.3 * np.array([np.sin(a), 0, np.cos(a)]), 0.08, 10))
    p.add("body", box((-0.25, -0.11, 0.18), (0.2, 0.11, 0.36)))
    # two-up seat with a backrest, saddlebags, floorboards
    p.add("windows", extrude([(-0.15, 0.62), (-0.1, 0.7), (-0.35, 0.66), (-0.55, 0.72), (-0.72, 0.74),
                              (-0.75, 0.68), (-0.5, 0.62)], -0.17, 0.17))
    p.add("windows", box((-0.8, -0.12, 0.7), (-0.74, 0.12, 0.95)))
    p.add("body", _both_sides(box((-1.02, 0.22, 0.36), (-0.55, 0.4, 0.66))))
    p.add("body", _both_sides(box((0.1, 0.16, 0.22), (0.38, 0.3, 0.25))))
    _handlebar(p, 0.36, 0.96, 0.4, 0.02, 0.12)                                      # wide bars
    _tube(p, (0.42, 0, 0.86), (0.36, 0, 0.96), 0.025)                               # riser
    p.add("windows", extrude([(0.5, 0.9), (0.53, 0.9), (0.45, 1.1), (0.42, 1.1)], -0.22, 0.22))   # windshield
    p.add("windows", cyl((0.48, 0, 0.78), (0.56, 0, 0.78), 0.09, 12))              # headlight
    p.add("lights", box((-1.06, -0.05, 0.58), (-1.02, 0.05, 0.64)))
    p.add("lights", _both_sides(box((-1.05, 0.25, 0.6), (-1.01, 0.3, 0.64))))
    _tube(p, (0.1, -0.16, 0.3), (-1.0, -0.2, 0.3), 0.035)                             # exhaust
    return p


def _dirtbike(L, W, H):
    p = _Parts()
    xr, Rr, xf, Rf = -0.6, 0.34, 0.62, 0.36
    _moto_wheel(p, xr, Rr, 0.065, 0.06, knobs=True)
    _moto_wheel(p, xf, Rf, 0.05, 0.045, knobs=True)
    _fork(p, (0.36, 0.98), (xf, Rf), 0.08, 0.028)                                 # long-travel fork
    p.add("body", box((0.3, -0.11, 0.93), (0.42, 0.11, 0.98)))
    # high front fender mounted under the crown, well clear of the tyre
    p.add("body", extrude([(0.25, 0.86), (0.5, 0.9), (0.85, 0.86), (0.92, 0.8), (0.6, 0.84), (0.3, 0.82)],
                          -0.07, 0.07))
    p.add("body", extrude([(0.3, 0.96), (0.44, 0.98), (0.49, 0.78), (0.34, 0.76)], -0.12, 0.12))   # number plate
    # tank/shrouds, long tall seat and the up-swept tail
    p.add("body", extrude([(0.34, 0.92), (0.05, 0.95), (-0.05, 0.78), (0.15, 0.6), (0.36, 0.72)], -0.15, 0.15))
    p.add("windows", extrude([(0.08, 0.9), (0.1, 0.95), (-0.5, 0.95), (-0.55, 0.9)], -0.1, 0.1))
    p.add("body", extrude([(-0.45, 0.88), (-0.5, 0.95), (-0.95, 1.03), (-0.92, 0.98), (-0.7, 0.86)], -0.09, 0.09))
    _tube(p, (0.3, 0, 0.88), (0.0, 0, 0.3), 0.025)
    _tube(p, (0.0, 0, 0.3), (-0.2, 0, 0.35), 0.025)
    _tube(p, (-0.2, 0, 0.35), (-0.3, 0, 0.88), 0.025)
    _stays(p, (-0.18, 0, 0.4), (xr, 0, Rr), 0.022, 0.09)                          # swing arm
    _tube(p, (-0.3, 0, 0.85), (-0.3, 0, 0.45), 0.035)                             # rear shock
    p.add("body", box((-0.2, -0.09, 0.3), (0.1, 0.09, 0.55)))                      # engine
    p.add("body", cyl((-0.05, 0, 0.5), (0.05, 0, 0.72), 0.06, 10))
    _tube(p, (0.05, -0.1, 0.6), (-0.25, -0.14, 0.8), 0.03)                         # up-swept exhaust
    p.add("body", cyl((-0.25, -0.14, 0.8), (-0.72, -0.14, 0.88), 0.05, 10))
    _handlebar(p, 0.3, 1.08, 0.35, 0.0, 0.02)
    p.add("windows", cyl((0.46, 0, 0.85), (0.5, 0, 0.85), 0.04, 10))
    p.add("lights", box((-0.97, -0.04, 0.95), (-0.93, 0.04, 0.99)))
    return p


def _scooter(L, W, H):
    p = _Parts()
    xr, xf, R = -0.55, 0.55, 0.2
    _moto_wheel(p, xr, R, 0.065, 0.06)
    _moto_wheel(p, xf, R, 0.06, 0.055)
    # front shield (apron) rising from the floor to the headset
    p.add("body", extrude([(0.34, 0.24), (0.5, 0.3), (0.55, 0.55), (0.5, 0.85), (0.38, 0.86), (0.42, 0.55),
                           (0.28, 0.3)], -0.2, 0.2))
    p.add("body", box((-0.2, -0.17, 0.18), (0.36, 0.17, 0.27)))                   # flat step-through floor
    p.add("body", loft([(-0.85, 0.48, 0.05, 0.04), (-0.75, 0.48, 0.15, 0.13), (-0.45, 0.45, 0.2, 0.2),
                        (-0.2, 0.4, 0.18, 0.18), (-0.12, 0.36, 0.15, 0.14)], 14))  # rear body shell
    p.add("body", torus((xf, 0, R), R + 0.02, 0.03, (0, 1, 0), 10, 5, ra=0.08, arc=(25, 150)))   # front mudguard
    _fork(p, (0.45, 0.78), (xf, R), 0.07, 0.025)
    p.add("body", ellipsoid((0.45, 0, 0.92), (0.1, 0.14, 0.07), 10, 5))            # headset cover
    _tube(p, (0.45, 0, 0.8), (0.45, 0, 0.92), 0.03)
    _handlebar(p, 0.42, 0.95, 0.3, 0.0, 0.04)
    p.add("windows", extrude([(-0.15, 0.62), (-0.12, 0.7), (-0.4, 0.7), (-0.72, 0.7), (-0.75, 0.63)], -0.16, 0.16))
    p.add("windows", cyl((0.54, 0, 0.9), (0.56, 0, 0.9), 0.05, 12))                # headlight
    p.add("lights", box((-0.88, -0.06, 0.46), (-0.84, 0.06, 0.52)))
    _stays(p, (-0.3, 0, 0.3), (xr, 0, R), 0.025, 0.08)
    return p


_BUILDERS = {
    "airliner": _airliner, "fighter": _fighter, "jet": _jet, "biplane": _biplane,
    "mountain_bike": _mountain_bike, "tandem_bike": _tandem_bike, "utility_bike": _utility_bike,
    "road_bike": _road_bike,
    "articulated_bus": _articulated_bus, "double_bus": _double_bus, "school_bus": _school_bus,
    "regular_bus": _regular_bus,
    "minivan": _minivan, "sedan": _sedan, "suv": _suv, "truck": _truck, "wagon": _wagon,
    "chopper": _chopper, "cruiser": _cruiser, "dirtbike": _dirtbike, "scooter": _scooter,
}


def build_parts(name: str, size: tuple[float, float, float]) -> dict[str, trimesh.Trimesh]:
    """The parts of sub-type `name`, centred on their joint bounding box whose extents are `size`."""
    if name not in _BUILDERS:
        raise KeyError(f"no mesh builder for sub-type {name!r}")
    return _BUILDERS[name](*size).finish(size)


def model_extents(name: str, size) -> np.ndarray:
    """Extents of the model before it is scaled to `size` (how far the builder is from the catalogue size)."""
    allv = np.vstack([np.vstack([v for v, _ in gs]) for gs in _BUILDERS[name](*size).geoms.values()])
    return allv.max(0) - allv.min(0)
