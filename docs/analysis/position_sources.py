"""Where the parser's position error comes from: each matched object's end-to-end error (the parse against the
truth, eval-parser's frames) beside the error of the head's own detection of it in the same frame, placed at its
true sub-type (`place.place`), by kind of body (ground or aeroplane) and by what the frame had: a detection within
8 px of the object's true projected centre, none (the track coasts on its prediction), or a wrong sub-type for the
track. The raw detections' error along the camera ray is then split into a bias per object (the median over its
detected frames) and the frame-to-frame jitter (robust sd of consecutive frames' difference / sqrt 2): the filter
and the fits average jitter away, never a bias.

    .venv/bin/python docs/analysis/position_sources.py --split full-test --data-dir D

D holds a finished `dynclevr run` whose detections are cached (`D/.cache/<split>/detections/`). An analysis: it
reads the truth to score and is not part of the model.
"""

from multiprocessing import Pool
from pathlib import Path

import numpy as np

from dynclevr.perception.detections import load
from dynclevr.perception.evaluate import match
from dynclevr.perception.place import place
from dynclevr.scene import Scene4D

from split_args import split_args

NEAR_PX, MIN_SCORE = 8.0, 0.3

ap = split_args(parse=True)
args = ap.parse_args()
root = Path(args.data_dir) / args.split
cache = Path(args.data_dir) / ".cache" / args.split / "detections"


def nearest(dets, uv):
    best = None
    for d in dets:
        gap = np.hypot(d.u - uv[0], d.v - uv[1])
        if d.score >= MIN_SCORE and gap < NEAR_PX and (best is None or gap < best[0]):
            best = (gap, d)
    return None if best is None else best[1]


def scene_rows(path: Path) -> list[tuple]:
    """(plane, end-to-end error, raw error or NaN, raw along-ray error or NaN, right sub-type, frame, track key)."""
    truth, est = Scene4D.read(path), Scene4D.read(root / args.parse / path.name)
    npz = cache / (path.stem + ".npz")
    if not npz.is_file():
        raise SystemExit(f"{npz}: no cached detections (run `dynclevr run --split {args.split}` on {args.data_dir})")
    dets = load(npz, str(np.load(npz, allow_pickle=True)["key"]))
    cam = truth.camera
    rows = []
    for i, j in match(truth, est):
        o = truth.objects[i]
        for f in np.nonzero(truth.visible[:, i] & est.visible[:, j])[0]:
            p = truth.position[f, i]
            d = nearest(dets[f], np.asarray(cam.project(p[None])[0]).reshape(-1)) if f < len(dets) else None
            raw = along = np.nan
            if d is not None:
                m = place(cam, d, shape=o.shape)
                raw, along = float(np.linalg.norm(m.position - p)), float((m.position - p) @ m.ray)
            rows.append((o.category == "aeroplane", float(np.linalg.norm(est.position[f, j] - p)), raw, along,
                         o.shape == est.objects[j].shape, int(f), f"{path.stem}/{i}"))
    return rows


with Pool(2) as pool:
    rows = [r for rs in pool.map(scene_rows, sorted((root / "sim").glob("*.mcap"))) for r in rs]
plane = np.array([r[0] for r in rows])
err, raw, along = (np.array([r[k] for r in rows], float) for k in (1, 2, 3))
right = np.array([r[4] for r in rows])
frame, key = np.array([r[5] for r in rows]), np.array([r[6] for r in rows])
seen = np.isfinite(raw)


def mad(x):
    return 1.4826 * float(np.median(np.abs(x - np.median(x)))) if len(x) else float("nan")


def fig(x):
    return f"{np.median(x):.3f} / {np.percentile(x, 90):.3f}" if len(x) else "-"


def decomposition(sel):
    """Spread of the per-object along-ray bias, and the frame-to-frame jitter, of the raw detections in sel."""
    biases, steps = [], []
    for k in np.unique(key[sel]):
        s = sel & (key == k)
        if s.sum() >= 10:
            biases.append(np.median(along[s]))
            consecutive = np.diff(frame[s]) == 1
            steps.append(np.diff(along[s])[consecutive])
    return mad(np.array(biases)), mad(np.concatenate(steps)) / np.sqrt(2) if steps else float("nan")


print(f"split {args.split}: {len(rows)} frames of matched objects; position error median / 90th percentile (m)\n")
print("| frames | n | end to end | the raw detection, true sub-type | along the ray: bias per object (sd), jitter (sd) |")
print("|---|---|---|---|---|")
print(f"| all | {len(rows)} | {fig(err)} | | |")
for name, kind in (("ground", ~plane), ("aeroplane", plane)):
    bias_sd, jitter_sd = decomposition(kind & seen & right)
    print(f"| {name}, all | {kind.sum()} | {fig(err[kind])} | | |")
    s = kind & seen & right
    print(f"| {name}, detected, sub-type right | {s.sum()} | {fig(err[s])} | {fig(raw[s])} | {bias_sd:.3f}, {jitter_sd:.3f} |")
    s = kind & seen & ~right
    print(f"| {name}, detected, sub-type wrong | {s.sum()} | {fig(err[s])} | {fig(raw[s])} | |")
    s = kind & ~seen
    print(f"| {name}, no detection (the track coasts, or its centre is off the object) | {s.sum()} | {fig(err[s])} | | |")
print(f"\naeroplanes are {plane.mean():.1%} of the frames and {np.mean(plane[err > np.percentile(err, 90)]):.1%} of "
      "the frames over the 90th percentile")
