"""How far the detection head's centres are from the true projected centres, and how those errors behave over time.

    .venv/bin/python docs/analysis/detector_pixel_error.py --split full-val --videos 30
    .venv/bin/python docs/analysis/detector_pixel_error.py --split full-val --videos 40 --view-bins 8 12 24

For each true object in view in the observed frames (0-29) of the split's first videos, the nearest detection within
12 px: its error in pixels per category, split into a per-track bias (the mean over the track's frames) and the
frame-to-frame rest, and the rest's lag-1 autocorrelation. `--view-bins`: whether the error is a bias of the view,
which a table could take off: the mean error per estimated sub-type and bin of the head's relative yaw, fitted on
the even videos' detections, subtracted from the odd videos'. An analysis (it reads the truth), not part of the model.
"""

import collections
from pathlib import Path

import numpy as np

from dynclevr.perception.detector import decode, run
from dynclevr.perception.detector_train import load_detector
from dynclevr.scene import Scene4D
from dynclevr.video import Video

from split_args import split_args

ap = split_args()
ap.add_argument("--videos", type=int, default=30)
ap.add_argument("--view-bins", type=int, nargs="*", default=[])
args = ap.parse_args()
root = Path(args.data_dir) / args.split

net = load_detector()
errors, tracks, views = collections.defaultdict(list), [], []
for k in range(args.videos):
    name = f"{k:06d}"
    truth = Scene4D.read(root / "sim" / f"{name}.mcap")
    dets = [decode(m, 0.3, 20) for m in run(net, Video.read(root / "video" / f"{name}.mcap").frames(slice(0, 30)))]
    for i, o in enumerate(truth.objects):
        series = []
        for f in range(30):
            (u, v), _ = truth.camera.project(truth.position[f, i])
            best = min(dets[f], key=lambda d: (d.u - u) ** 2 + (d.v - v) ** 2, default=None)
            if not truth.visible[f, i] or best is None or np.hypot(best.u - u, best.v - v) > 12:
                series.append((np.nan, np.nan))
                continue
            series.append((best.u - u, best.v - v))
            errors[o.category].append(series[-1])
            views.append((k % 2, int(np.argmax(best.subtype_logp)), best.alpha % (2 * np.pi), *series[-1]))
        tracks.append(np.array(series))

for c, e in sorted(errors.items()):
    e = np.array(e)
    print(f"{c:10s} {len(e):5d} detections: |du| median {np.median(abs(e[:, 0])):.2f} px, |dv| median "
          f"{np.median(abs(e[:, 1])):.2f} px; sd du {e[:, 0].std():.2f}, dv {e[:, 1].std():.2f}")
long = [x for x in tracks if np.isfinite(x[:, 0]).sum() >= 15]
bias = np.array([np.nanmean(x, 0) for x in long])
rest = np.concatenate([x[np.isfinite(x[:, 0])] - np.nanmean(x, 0) for x in long])
print(f"{len(long)} tracks seen in 15+ frames: per-track bias sd du {bias[:, 0].std():.2f} dv {bias[:, 1].std():.2f} "
      f"px; frame-to-frame sd du {rest[:, 0].std():.2f} dv {rest[:, 1].std():.2f} px")
ac = []
for x in long:
    d = x[:, 1] - np.nanmean(x[:, 1])
    ok = np.isfinite(d[:-1]) & np.isfinite(d[1:])
    if ok.sum() > 10:
        ac.append(np.corrcoef(d[:-1][ok], d[1:][ok])[0, 1])
print(f"lag-1 autocorrelation of the frame-to-frame dv: median {np.nanmedian(ac):.2f} over {len(ac)} tracks")

for bins in args.view_bins:
    def key(r):
        return r[1], int(r[2] / (2 * np.pi) * bins) % bins
    cells = collections.defaultdict(list)
    for r in views:
        if r[0] == 0:
            cells[key(r)].append(r[3:])
    mean = {k: np.mean(v, 0) for k, v in cells.items() if len(v) >= 5}
    before = np.array([r[3:] for r in views if r[0] == 1])
    after = np.array([np.subtract(r[3:], mean.get(key(r), 0.0)) for r in views if r[0] == 1])
    print(f"{bins} view bins: the odd videos' sd du {before[:, 0].std():.2f} -> {after[:, 0].std():.2f}, "
          f"dv {before[:, 1].std():.2f} -> {after[:, 1].std():.2f} px")
