"""Recode detector shards' JPEG frames as WebP (quality 80: a 600-frame path-traced shard 16.7 -> 5.6 MB), so that
six of them travel in one device call beside the repository (docs/gpu_round/README.md). The labels are unchanged;
the training reads either coding (cv2.imdecode).

    python docs/gpu_round/recode.py OUT_DIR SHARD.npz [SHARD.npz ...]
"""

import sys
from pathlib import Path

import cv2
import numpy as np

if __name__ == "__main__":
    out_dir = Path(sys.argv[1])
    out_dir.mkdir(parents=True, exist_ok=True)
    for src in map(Path, sys.argv[2:]):
        z = np.load(src)
        buf, off = z["jpeg"], z["offsets"]
        frames = []
        for k in range(len(off) - 1):
            _, b = cv2.imencode(".webp", cv2.imdecode(buf[off[k]:off[k + 1]], cv2.IMREAD_COLOR),
                                 [cv2.IMWRITE_WEBP_QUALITY, 80])
            frames.append(b.tobytes())
        dst = out_dir / src.name
        np.savez(dst, jpeg=np.frombuffer(b"".join(frames), np.uint8), offsets=np.cumsum([0] + [len(b) for b in frames]),
                 labels=z["labels"])
        print(f"{dst}: {src.stat().st_size / 1e6:.1f} -> {dst.stat().st_size / 1e6:.1f} MB")
