"""One model row run again with a changed config (or another checkout's code) in a copy of a split's folder, then
its answers set against the split's own run of that row: questions right, gained and lost, by type and by family,
and the change in Table 1's columns with its 95% interval (the split's videos resampled, both runs over the same
resamples: dynclevr/uncertainty.py). The journal's "measured and not kept" rows are runs of this kind.

    .venv/bin/python docs/analysis/row_experiment.py --split full-val --data-dir D --config C --out E [--tree T]

D holds a finished `dynclevr run --split S` (every row it compares against). C is a TOML merged over pipeline.toml
(`[parser] filter = "particle"` makes the row the particle filter's). E, made here, shares D's truth, video, labels,
questions and the head's cached detections (links, so nothing of D is written) and gets its own parses, futures and
answers (`dynclevr run --no-ablation`: with the detections cached, 4-8 minutes a 100-video split on 2 cores).
--tree T runs the code and pipeline.toml of another checkout (e.g. a `git worktree`); with --fresh-detections E
computes the head's detections itself instead of linking D's (for a change to the head: a link would let E's new
detections replace D's). An analysis: it reads the truth's answers to score, and is not part of the model.

--better-head S asks what a better head would buy: E's detections are D's cached ones with every detection that
pairs with an object in view (its centre within MATCH_PIXELS of the object's projected centre, one to one) moved
towards the truth, its centre pixel's and distance's errors (and the centre height's) scaled by S (0: exact, 1: as
the head read them); --truth-heading also gives those detections the truth's heading. Sub-types, colours, scores,
missed and false detections stay the head's. This reads the truth to make the detections, so it measures the
model's sensitivity, never the model.
"""

import collections
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
from scipy.optimize import linear_sum_assignment

from dynclevr.config import Config
from dynclevr.perception.detector_data import yaw_of
from dynclevr.report import COLUMNS
from dynclevr.scene import Scene4D
from dynclevr.stages.answer import table1
from dynclevr.uncertainty import bootstrap, interval
from split_args import split_args

SHARED = ("sim", "video", "labels", "objects.parquet", "questions.parquet")

ap = split_args()
ap.add_argument("--config", required=True, help="TOML merged over pipeline.toml: the change under test")
ap.add_argument("--out", required=True, help="a new folder for the copy")
ap.add_argument("--tree", default=str(Path(__file__).resolve().parents[2]), help="the checkout whose code runs")
ap.add_argument("--workers", default="2")
ap.add_argument("--fresh-detections", action="store_true", help="compute the head's detections in E, not D's")
ap.add_argument("--better-head", type=float, help="scale the matched detections' placement errors by this (0: exact)")
ap.add_argument("--truth-heading", action="store_true", help="with --better-head: and their heading the truth's")
args = ap.parse_args()
MATCH_PIXELS = 20.0


def better_detections(cached: Path, truth: Scene4D, scale: float, truth_heading: bool, dest: Path) -> None:
    """A video's cached detections (detections.save's file) with the matched ones' errors scaled (see above)."""
    with np.load(cached) as z:
        cols = {k: z[k].copy() for k in z.files}
    cam, eye = truth.camera, np.asarray(truth.camera.position, float)
    yaw = yaw_of(truth.orientation)
    for t in range(int(cols["frames"])):
        idx = np.nonzero(cols["frame"] == t)[0]
        shown = np.nonzero(truth.visible[t])[0]
        if not len(idx) or not len(shown):
            continue
        uv, _ = cam.project(truth.position[t, shown])
        cost = np.hypot(cols["u"][idx, None] - uv[None, :, 0], cols["v"][idx, None] - uv[None, :, 1])
        for a, b in zip(*linear_sum_assignment(cost)):
            if cost[a, b] > MATCH_PIXELS:
                continue
            n, i, centre = idx[a], shown[b], truth.position[t, shown[b]]
            cols["u"][n] = uv[b, 0] + scale * (cols["u"][n] - uv[b, 0])
            cols["v"][n] = uv[b, 1] + scale * (cols["v"][n] - uv[b, 1])
            dist = float(np.linalg.norm(centre - eye))
            cols["dist"][n] = dist + scale * (cols["dist"][n] - dist)
            cols["height"][n] = centre[2] + scale * (cols["height"][n] - centre[2])
            if truth_heading:
                a_ = yaw[t, i] - np.arctan2(centre[1] - eye[1], centre[0] - eye[0])
                cols["alpha"][n] = np.arctan2(np.sin(a_), np.cos(a_))
    with open(dest, "wb") as f:
        np.savez(f, **cols)


src, out = Path(args.data_dir).resolve() / args.split, Path(args.out).resolve()
if not (src / "manifests").is_dir():
    sys.exit(f"{src} holds no finished run: run `dynclevr run --split {args.split} --data-dir {args.data_dir}` first")
if not Path(args.config).is_file():
    sys.exit(f"--config {args.config}: no such file (a TOML merged over pipeline.toml, e.g. [parser] filter = \"particle\")")
if out.exists():
    sys.exit(f"{out} exists: give --out a new folder (nothing is overwritten)")
cache = Path(args.data_dir).resolve() / ".cache" / args.split / "detections"
if args.better_head is not None and args.better_head < 0:
    sys.exit(f"--better-head {args.better_head}: the scale of the head's errors must be >= 0 (0: exact, 1: the head's)")
if args.better_head is not None and args.fresh_detections:
    sys.exit("--better-head rewrites D's cached detections: leave out --fresh-detections")
if args.better_head is not None and not cache.is_dir():
    sys.exit(f"--better-head needs D's cached detections ({cache}): run `dynclevr run --split {args.split} "
             f"--data-dir {args.data_dir}` first")
if args.truth_heading and args.better_head is None:
    sys.exit("--truth-heading goes with --better-head S (S = 1 keeps the head's placements)")
(out / args.split).mkdir(parents=True)
for name in SHARED:
    (out / args.split / name).symlink_to(src / name)
shutil.copytree(src / "manifests", out / args.split / "manifests")
if args.better_head is not None:
    (out / ".cache" / args.split / "detections").mkdir(parents=True)
    for path in sorted(cache.glob("*.npz")):
        better_detections(path, Scene4D.read(src / "sim" / f"{path.stem}.mcap"), args.better_head,
                          args.truth_heading, out / ".cache" / args.split / "detections" / path.name)
elif cache.is_dir() and not args.fresh_detections:
    (out / ".cache" / args.split).mkdir(parents=True)
    (out / ".cache" / args.split / "detections").symlink_to(cache)
tree = Path(args.tree).resolve()
env = dict(os.environ, PYTHONPATH=str(tree))
cmd = [sys.executable, "-c", "from dynclevr.cli import main; main()", "run", "--split", args.split, "--data-dir",
       str(out), "--config", str(Path(args.config).resolve()), "--no-ablation", "--workers", args.workers]
subprocess.run(cmd, cwd=tree, env=env, check=True)


def load(path: Path) -> dict:
    return {(r["scene"], r["id"]): r for r in pq.read_table(path).to_pylist()}


for new_path in sorted((out / args.split).glob("answers*.parquet")):
    old, new = load(src / new_path.name), load(new_path)
    keys = sorted(old.keys() & new.keys())
    print(f"{new_path.name}: {sum(old[k]['correct'] for k in keys)} -> {sum(new[k]['correct'] for k in keys)} "
          f"of {len(keys)} questions right")
    report = Config.load()["report"]
    x = bootstrap({"old": [old[k] for k in keys], "new": [new[k] for k in keys]}, report["bootstrap_resamples"],
                  report["bootstrap_seed"])
    lo, hi = interval(x["new"] - x["old"])
    change = [table1([new[k] for k in keys])[c][0] - table1([old[k] for k in keys])[c][0] for c in COLUMNS]
    print("  change in points, 95% interval (paired): " + ", ".join(
        f"{c} {d:+.2f} ({lo[i]:+.2f} to {hi[i]:+.2f})" for i, (c, d) in enumerate(zip(COLUMNS, change))))
    by = collections.defaultdict(lambda: [0, 0, 0, 0])     # right before, right after, gained, lost
    for k in keys:
        a, b = old[k]["correct"], new[k]["correct"]
        for group in (old[k]["type"], "  " + old[k]["family"]):
            by[group][0] += a
            by[group][1] += b
            by[group][2] += b and not a
            by[group][3] += a and not b
    for group, (a, b, gained, lost) in sorted(by.items(), key=lambda kv: (kv[0].startswith(" "), kv[1][1] - kv[1][0])):
        if gained or lost:
            print(f"  {group:42s} {a:5d} -> {b:5d}   gained {gained}, lost {lost}")
