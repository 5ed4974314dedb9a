"""One round of the detection head on a lent GPU machine, inside its 15 minutes (docs/gpu_round/README.md).

On the device: makes the round's TinyRenderer shards on its cores (from the top shard down, a round of processes at
a time, no round begun that would end past --gen-budget; the first shard rises to what was made), places the
path-traced shards carried from a CPU machine (it has no Mitsuba), scores the start head on the held-out shard(s),
trains it on everything with `train_detector --grow-from` (a fresh optimiser and cosine), and writes the new head
without its optimiser (a call brings back at most 16 MB a file), its manifest, curve and scores to OUT.

    python3 docs/gpu_round/round.py --config C --carry .gpu --data /tmp/det --out $OUT --steps N \
        [--gen-workers 16 --loaders 15 --budget 500 --gen-budget 330]

CARRY holds start/ (the head to grow from: detector.pt and manifest.json) and pt/ (path-traced shards, WebP-recoded
by recode.py). Not part of the package: a driver for a session that draws a device.
"""

import argparse
import json
import os
import shutil
import time
from pathlib import Path

T0 = time.time()


def log(*a):
    print(f"[{time.time() - T0:6.1f}s]", *a, flush=True)


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--config", required=True, type=Path)
    ap.add_argument("--carry", required=True, type=Path)
    ap.add_argument("--data", required=True, type=Path)
    ap.add_argument("--out", required=True, type=Path)
    ap.add_argument("--steps", required=True, type=int, help="training steps past the start head's")
    ap.add_argument("--device", default="cuda")
    ap.add_argument("--gen-workers", type=int, default=16)
    ap.add_argument("--loaders", type=int, default=15)
    ap.add_argument("--budget", type=float, default=500, help="seconds for the whole script")
    ap.add_argument("--gen-budget", type=float, default=330, help="seconds by which shard making ends")
    args = ap.parse_args()

    import torch

    from dynclevr.config import Config
    from dynclevr.perception import detector_train as dt
    from dynclevr.perception.detector import DetectNet
    from dynclevr.perception.detector_data import shard_backend, shard_path

    cfg = Config.load(args.config)
    split = cfg.split(cfg["parser"]["detector_split"])
    for f in sorted((args.carry / "pt").glob("shard_*.npz")):
        dst = shard_path(args.data, split, int(f.stem.split("_")[1]), "mitsuba")
        dst.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(f, dst)
    which = dt.shards(cfg)
    missing = [s for s in which if shard_backend(cfg, s) != "tiny"
               and not shard_path(args.data, split, s, shard_backend(cfg, s)).exists()]
    if missing:
        raise SystemExit(f"path-traced shards {missing} were not carried: make them with Mitsuba and recode.py")
    log(f"torch {torch.__version__}, cuda {torch.cuda.is_available()}, {os.cpu_count()} cpus; "
        f"shards {which[0]}-{which[-1]}")

    tiny = sorted((s for s in which if shard_backend(cfg, s) == "tiny"), reverse=True)
    made, rounds = [], []
    for i in range(0, len(tiny), args.gen_workers):
        if rounds and time.time() - T0 + max(rounds) > args.gen_budget:
            break
        t = time.time()
        dt.generate(cfg, args.data, args.gen_workers, tiny[i:i + args.gen_workers], echo=log)
        rounds.append(time.time() - t)
        made += tiny[i:i + args.gen_workers]
    if len(made) < len(tiny):
        cfg["parser"]["detector_first_shard"] = min(made)
    log(f"shards made: {len(made)} TinyRenderer, rounds {[round(r) for r in rounds]} s; "
        f"training shards from {cfg['parser']['detector_first_shard']}")

    def load(path):
        s = torch.load(path, weights_only=True, map_location="cpu")
        net = DetectNet(s["width"], s.get("blocks", 0), s.get("fine_blocks", 0))
        net.load_state_dict(s["net"])
        return net.eval().to(args.device)

    held = cfg["parser"]["detector_heldout_shards"]
    held_sets = {f"{s} {shard_backend(cfg, s)}": dt.Frames([shard_path(args.data, split, s, shard_backend(cfg, s))])
                 for s in which[-held:]}
    scores = {}

    def score(name, net):
        scores[name] = {k: dt.evaluate(net, fr) for k, fr in held_sets.items()}
        log(name, json.dumps(scores[name]))
        (args.out / "scores.json").write_text(json.dumps(scores, indent=1))

    start = args.carry / "start"
    score("start", load(start / "detector.pt"))
    minutes = max(0.5, (args.budget - (time.time() - T0) - 60) / 60)
    log(f"training: {args.steps} steps, at most {minutes:.1f} min")
    head = Path("/tmp/round-head")
    shutil.rmtree(head, ignore_errors=True)
    head.mkdir(parents=True)
    start_step = torch.load(start / "detector.pt", weights_only=True, map_location="cpu")["step"]
    dt.train_detector(cfg, args.data, head, workers=args.gen_workers, steps=start_step + args.steps, minutes=minutes,
                      grow_from=start, device=args.device, loader_workers=args.loaders, echo=log)
    s = torch.load(head / "detector.pt", weights_only=True, map_location="cpu")
    torch.save({k: s[k] for k in ("net", "step", "width", "blocks", "fine_blocks", "schedule_start")},
               args.out / "new.pt")
    for name in ("manifest.json", "curve.png"):
        shutil.copy(head / name, args.out / name)
    score("new", load(head / "detector.pt"))
    log("done")
