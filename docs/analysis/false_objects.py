"""What the parser's false objects are (issue 10's precision, per category): every estimated object that no true
object matches (evaluate.match), by the category it was reported as, sorted by what it stays near over its frames:

- duplicate: on average within evaluate.DUPLICATE_RADIUS of a true object that another estimate matched (eval-parser's
  duplicates: a second track on one vehicle);
- misplaced: nearest, on average, to a true object that no estimate matched, within FAR (the vehicle found, but placed
  beyond the match radius: mostly aeroplanes, whose distance is the head's alone);
- partly on vehicles: within NEAR of some true object in at least a third of its frames (a track that followed one
  vehicle and then another, or a vehicle's second track for part of the video);
- phantom: otherwise (nothing there).

    .venv/bin/python docs/analysis/false_objects.py --split full-test

An analysis (it reads the truth), not part of the model; it reads `dynclevr run`'s parsed/ and sim/.
"""

import collections
from pathlib import Path

import numpy as np

from dynclevr.assets.catalogue import CATEGORIES
from dynclevr.perception.evaluate import DUPLICATE_RADIUS, match
from dynclevr.scene import Scene4D

from split_args import split_args

NEAR, FAR = 0.5, 3.0   # metres

ap = split_args(parse=True)
args = ap.parse_args()
root = Path(args.data_dir) / args.split

reported, kinds, rows = collections.Counter(), collections.Counter(), []
for path in sorted((root / "sim").glob("*.mcap")):
    truth, est = Scene4D.read(path), Scene4D.read(root / args.parse / path.name)
    pairs = match(truth, est)
    matched_true, matched_est = {i for i, _ in pairs}, {j for _, j in pairs}
    for j, o in enumerate(est.objects):
        reported[o.category] += 1
        if j in matched_est:
            continue
        seen = est.visible[:, j]
        near = []   # (mean distance over the frames both are in view, share of them within NEAR, true index)
        for i in range(len(truth.objects)):
            both = seen & truth.visible[:, i]
            if both.any():
                d = np.linalg.norm(truth.position[both, i] - est.position[both, j], axis=1)
                near.append((float(d.mean()), float((d < NEAR).sum()) / max(int(seen.sum()), 1), i))
        mean, _, i = min(near) if near else (np.inf, 0.0, None)
        if i is not None and mean < DUPLICATE_RADIUS and i in matched_true:
            kind = "duplicate"
        elif i is not None and i not in matched_true and mean < FAR:
            kind = "misplaced"
        elif any(share >= 1 / 3 for _, share, _ in near):
            kind = "partly on vehicles"
        else:
            kind = "phantom"
        kinds[(o.category, kind)] += 1
        frames = np.nonzero(seen)[0]
        rows.append((path.stem, o.category, o.shape, o.color, kind,
                     f"frames {frames.min()}-{frames.max()}" if len(frames) else "never in view",
                     f"nearest {truth.objects[i].color} {truth.objects[i].shape} {mean:.2f} m" if i is not None else ""))

for row in rows:
    print(" ".join(row))
print(f"\n| reported as | objects | false | precision | duplicate | misplaced | partly on vehicles | phantom |")
print("|---|---|---|---|---|---|---|---|")
for c in CATEGORIES:
    false = sum(v for (cat, _), v in kinds.items() if cat == c)
    cells = " | ".join(str(kinds[(c, k)]) for k in ("duplicate", "misplaced", "partly on vehicles", "phantom"))
    print(f"| {c} | {reported[c]} | {false} | {1 - false / max(reported[c], 1):.3f} | {cells} |")
