"""Where the cut state's speed errors sit: the horizontal velocity at the last observed frame (the state the
predictive questions start from) of every matched object that the observed frames show, grouped by category
(ground or aeroplane) and by what the truth did before the cut: parked or moving with no impact yet, or struck,
by how many frames before the cut its last impact was. Per group: the median error, and the gross errors (over
evaluate.CUT_GROSS, 1.5 m/s) with their share of all gross errors. For moving planes not yet struck, a gross error
is also split into a wrong speed and a wrong direction (the speed within 0.5 m/s of the truth's, the direction
off by more than 45 degrees: a plane flying nearly along the camera ray whose heading axis is read mirrored).

    .venv/bin/python docs/analysis/cut_speed_groups.py --split full-test

An analysis (it reads the truth), not part of the model; it reads `dynclevr run`'s parsed/ and sim/.
"""

import collections
from pathlib import Path

import numpy as np

from dynclevr.perception.evaluate import CUT_GROSS, match
from dynclevr.scene import Scene4D

from split_args import split_args

BINS = ((0, 3), (4, 7), (8, 12), (13, 10 ** 6))

ap = split_args(parse=True)
args = ap.parse_args()
root = Path(args.data_dir) / args.split

errors = collections.defaultdict(list)
plane_gross = collections.Counter()
for path in sorted((root / "sim").glob("*.mcap")):
    truth, est = Scene4D.read(path), Scene4D.read(root / args.parse / path.name)
    cut = est.observed_frames - 1
    ct, ce = truth.state_at(cut), est.state_at(cut)
    last = {}
    for c in truth.collisions:
        if c.frame <= cut:
            for x in (c.a, c.b):
                last[x] = max(last.get(x, -1), c.frame)
    for i, j in match(truth, est):
        if not est.visible[:cut + 1, j].any():
            continue
        o = truth.objects[i]
        vt, ve = ct["velocity"][i, :2], ce["velocity"][j, :2]
        err = float(np.linalg.norm(ve - vt))
        kind = "aeroplane" if o.category == "aeroplane" else "ground"
        if o.id in last:
            lo, hi = next(b for b in BINS if b[0] <= cut - last[o.id] <= b[1])
            group = f"struck {lo}-{hi} frames before" if hi < 10 ** 6 else f"struck {lo}+ frames before"
        elif np.linalg.norm(vt) < 0.5:
            group = "parked, not struck"
        else:
            group = "moving, not struck"
            if kind == "aeroplane" and err > CUT_GROSS:
                speed_ok = abs(np.linalg.norm(ve) - np.linalg.norm(vt)) <= 0.5
                cos = float(ve @ vt) / max(float(np.linalg.norm(ve) * np.linalg.norm(vt)), 1e-9)
                plane_gross["direction (speed right)" if speed_ok and cos < np.cos(np.pi / 4) else
                            "speed right, direction within 45 deg" if speed_ok else "speed wrong"] += 1
        errors[(kind, group)].append(err)

total_gross = sum(int((np.array(v) > CUT_GROSS).sum()) for v in errors.values())
n = sum(len(v) for v in errors.values())
print(f"split {args.split}, {n} matched objects in view by the cut, {total_gross} cut speeds over {CUT_GROSS} m/s "
      "off\n")
print("| objects | n | median error (m/s) | over 1.5 m/s | share of those |")
print("|---|---|---|---|---|")


def order(key: tuple[str, str]) -> tuple:
    """Category, then parked and moving bodies before the struck ones, these by how recently."""
    kind, group = key
    struck = group.startswith("struck ")
    return kind, struck, int(group.split()[1].split("-")[0].rstrip("+")) if struck else 0, group


for key in sorted(errors, key=order):
    v = np.array(errors[key])
    g = int((v > CUT_GROSS).sum())
    print(f"| {key[0]}, {key[1]} | {len(v)} | {np.median(v):.2f} | {g} ({g / len(v):.0%}) | "
          f"{g / max(total_gross, 1):.0%} |")
if plane_gross:
    print("\nmoving planes not yet struck, gross errors: " + ", ".join(f"{k} {v}" for k, v in plane_gross.items()))
