"""Why the parser misses the vehicles it misses (issue 10's recall): every true object that no estimate matches
(evaluate.match), sorted by what the head's cached detections show near its projected centre in the frames where a
viewer can see it (labels.min_visible_pixels or more of it in the rendering):

- barely visible: fewer than evaluate.MIN_VISIBLE such frames (the issue's one excuse);
- no peak: a detection within NEAR_PX in under a third of them (the head does not see it);
- peaks under the start bar: detections there, none as confident as parser.new_track_score (no track starts);
- peaks, no object: confident detections (a track should start), yet no estimate stays within the match radius
  (placed too far along the ray, taken over by another vehicle's track, or joined to one);

and, for the last kind, the estimate that stays nearest on average, with its sub-type, so a wrong sub-type's resting
height (a double-decker placed as an articulated bus lies 0.3 m lower, metres further along a flat ray) shows.

    .venv/bin/python docs/analysis/missed_objects.py --split full-val

An analysis (it reads the truth), not part of the model; it reads `dynclevr run`'s parsed/, sim/ and render/, and
the detection cache (`<data>/.cache/<split>/detections/`, filled by parse-scene).
"""

import collections
from pathlib import Path

import numpy as np

from dynclevr.artifacts import Store
from dynclevr.config import Config
from dynclevr.perception.detections import cache_path
from dynclevr.perception.evaluate import MIN_VISIBLE, match
from dynclevr.questions.evidence import pixel_counts
from dynclevr.scene import Scene4D
from dynclevr.video import Video

from split_args import split_args

NEAR_PX = 12   # pixels: a detection this close to the projected centre is on the object

ap = split_args(parse=True)
args = ap.parse_args()
cfg = Config.load()
store = Store(Path(args.data_dir), args.split)
root = Path(args.data_dir) / args.split
start_bar, min_pixels = cfg["parser"]["new_track_score"], cfg["labels"]["min_visible_pixels"]

kinds = collections.Counter()
rows = []
n_true = 0
for path in sorted((root / "sim").glob("*.mcap")):
    truth, est = Scene4D.read(path), Scene4D.read(root / args.parse / path.name)
    n_true += len(truth.objects)
    matched = {i for i, _ in match(truth, est)}
    missed = [i for i in range(len(truth.objects)) if i not in matched]
    if not missed:
        continue
    scene = path.stem
    video = Video.read(store.path("render", scene, ".mcap"))
    pixels = pixel_counts(video.masks(), [o.id for o in truth.objects])
    with np.load(cache_path(store, scene)) as z:
        frame, u, v, score = z["frame"], z["u"], z["v"], z["score"]
    for i in missed:
        o = truth.objects[i]
        seen = np.nonzero(pixels[:, i] >= min_pixels)[0]
        if len(seen) < MIN_VISIBLE:
            kinds[(o.category, "barely visible")] += 1
            continue
        uv, _ = video.camera.project(truth.position[:, i])
        best = np.zeros(len(seen))
        for n, t in enumerate(seen):
            near = (frame == t) & (np.hypot(u - uv[t, 0], v - uv[t, 1]) < NEAR_PX)
            best[n] = score[near].max() if near.any() else 0.0
        if (best > 0).mean() < 1 / 3:
            kind = "no peak"
        elif best.max() < start_bar:
            kind = "peaks under the start bar"
        else:
            kind = "peaks, no object"
        kinds[(o.category, kind)] += 1
        nearest = ""
        if kind == "peaks, no object":
            d = [(np.linalg.norm(truth.position[both, i] - est.position[both, j], axis=1).mean(), j)
                 for j in range(len(est.objects)) for both in [truth.visible[:, i] & est.visible[:, j]] if both.any()]
            if d:
                dist, j = min(d)
                nearest = f"{est.objects[j].color} {est.objects[j].shape}, {dist:.2f} m"
        rows.append((scene, f"{o.color} {o.shape}", len(seen), int(np.median(pixels[seen, i])),
                     float((best > 0).mean()), float(best.max()), kind, nearest))

print(f"split {args.split}: {n_true} true objects, {sum(kinds.values())} unmatched\n")
print("| category | " + " | ".join(k for k in ("barely visible", "no peak", "peaks under the start bar",
                                                  "peaks, no object")) + " |")
print("|---|---|---|---|---|")
for cat in sorted({c for c, _ in kinds}):
    print(f"| {cat} | " + " | ".join(str(kinds[(cat, k)]) for k in ("barely visible", "no peak",
                                                                   "peaks under the start bar",
                                                                   "peaks, no object")) + " |")
print("\n| scene | object | frames in sight | median pixels | frames with a detection | best score | why | "
      "nearest estimate, mean distance |")
print("|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]:.2f} | {r[5]:.2f} | {r[6]} | {r[7]} |")
