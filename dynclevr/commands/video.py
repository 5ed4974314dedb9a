"""`dynclevr export-video` (one scene as an H.264 mp4, optionally with masks or boxes drawn over) and
`dynclevr contact-sheet` (one frame of every scene of a split in a grid).

docs/contact_sheet_tiny.png and docs/contact_sheet_mitsuba.png were made with:

    dynclevr simulate --split tiny && dynclevr render --split tiny
    dynclevr contact-sheet --split tiny --out docs/contact_sheet_tiny.png
    printf '[render]\\nbackend = "mitsuba"\\n' > /tmp/realistic.toml     # after `make realistic`
    dynclevr simulate --split tiny --data-dir data/realistic
    dynclevr render --split tiny --data-dir data/realistic --config /tmp/realistic.toml
    dynclevr contact-sheet --split tiny --data-dir data/realistic --out docs/contact_sheet_mitsuba.png
"""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

OVERLAYS = ("none", "masks", "boxes")


def overlay_frame(rgb, mask, mode: str):
    """Draw object masks (tinted, outlined) or their bounding boxes with ids over an RGB frame."""
    import cv2
    import numpy as np

    out = rgb.copy()
    if mode == "none":
        return out
    for oid in np.unique(mask[mask >= 0]):
        colour = tuple(int(c) for c in np.array(_palette(int(oid))))
        sel = (mask == oid).astype(np.uint8)
        if mode == "masks":
            out[sel > 0] = (0.55 * out[sel > 0] + 0.45 * np.array(colour)).astype(np.uint8)
            contours, _ = cv2.findContours(sel, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
            cv2.drawContours(out, contours, -1, colour, 1)
        else:
            x, y, w, h = cv2.boundingRect(sel)
            cv2.rectangle(out, (x, y), (x + w - 1, y + h - 1), colour, 1)
            cv2.putText(out, str(int(oid)), (x + 2, y + 10), cv2.FONT_HERSHEY_SIMPLEX, 0.35, colour, 1, cv2.LINE_AA)
    return out


def _palette(i: int) -> tuple[int, int, int]:
    import colorsys

    r, g, b = colorsys.hsv_to_rgb((i * 0.618034) % 1.0, 0.85, 1.0)
    return int(r * 255), int(g * 255), int(b * 255)


def write_mp4(frames, fps: int, out: Path) -> None:
    """H.264 (x264, yuv420p, faststart) in MP4, which browsers and players open; imageio-ffmpeg's bundled ffmpeg
    carries the encoder (OpenCV's wheels write only MPEG-4 Part 2)."""
    import imageio_ffmpeg
    import numpy as np

    from dynclevr.artifacts import atomic_path

    H, W = frames.shape[1:3]
    with atomic_path(out) as tmp:
        writer = imageio_ffmpeg.write_frames(
            str(tmp), (W, H), fps=fps, codec="libx264", pix_fmt_out="yuv420p", macro_block_size=2,
            output_params=["-crf", "18", "-movflags", "+faststart", "-f", "mp4"], ffmpeg_log_level="error")
        writer.send(None)
        try:
            for f in frames:
                writer.send(np.ascontiguousarray(f))
        finally:
            writer.close()


def contact_sheet(images, labels, columns: int):
    import cv2
    import numpy as np

    H, W = images[0].shape[:2]
    rows = -(-len(images) // columns)
    sheet = np.full((rows * H, columns * W, 3), 24, np.uint8)
    for k, (img, label) in enumerate(zip(images, labels)):
        r, c = divmod(k, columns)
        tile = img.copy()
        tile[:18] = (tile[:18] * 0.45).astype(np.uint8)   # a dark band keeps the label readable on any sky
        cv2.putText(tile, label, (4, 13), cv2.FONT_HERSHEY_SIMPLEX, 0.38, (255, 255, 255), 1, cv2.LINE_AA)
        sheet[r * H:(r + 1) * H, c * W:(c + 1) * W] = tile
    return sheet


def register(app: typer.Typer) -> None:
    from dynclevr.cli import ConfigOpt, DataOpt, SplitOpt

    @app.command("export-video")
    def export_video(split: Optional[str] = SplitOpt, scene: str = typer.Option(..., "--scene", help="e.g. 000003"),
                     out: Path = typer.Option(..., "--out", help="the .mp4 to write (H.264)"),
                     overlay: str = typer.Option("none", "--overlay", help="none, masks or boxes"),
                     config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt):
        """Write one rendered scene as an H.264 mp4, optionally with instance masks or boxes drawn over."""
        import numpy as np

        from dynclevr import DynclevrError
        from dynclevr.artifacts import Store
        from dynclevr.config import Config
        from dynclevr.video import Video

        if overlay not in OVERLAYS:
            raise DynclevrError(f"--overlay {overlay}: use one of {', '.join(OVERLAYS)}")
        if out.suffix.lower() != ".mp4":
            raise DynclevrError(f"--out {out}: export-video writes H.264 in MP4; name the file .mp4")
        chosen = Config.load(config).split(split)
        store = Store(data_dir, chosen.name)
        name = scene.zfill(6) if scene.isdigit() else scene
        if name not in chosen.scene_names():
            raise DynclevrError(f"--scene {scene}: split '{chosen.name}' has scenes 0-{chosen.scenes - 1}")
        video = Video.read(store.path("render", name, ".mcap"))
        frames = video.frames()
        if overlay != "none":
            frames = np.stack([overlay_frame(f, m, overlay) for f, m in zip(frames, video.masks())])
        write_mp4(frames, video.fps, out)
        typer.echo(f"wrote {out} ({video.num_frames} frames, {video.camera.width}x{video.camera.height}, "
                   f"{video.fps} fps)")

    @app.command("contact-sheet")
    def contact_sheet_cmd(split: Optional[str] = SplitOpt, out: Path = typer.Option(..., "--out", help="a .png"),
                          frame: int = typer.Option(0, "--frame", help="which frame of each video"),
                          columns: int = typer.Option(4, "--columns", min=1),
                          limit: int = typer.Option(24, "--limit", min=1, help="at most this many scenes"),
                          config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt):
        """One frame of each rendered scene of a split, in a grid labelled with scene and environment."""
        import cv2

        from dynclevr import DynclevrError
        from dynclevr.artifacts import Store, atomic_path
        from dynclevr.config import Config
        from dynclevr.video import Video

        store = Store(data_dir, Config.load(config).split(split).name)
        paths = sorted(store.stage_dir("render").glob("[0-9]*.mcap"))[:limit]
        if not paths:
            raise DynclevrError(f"no rendered videos under {store.stage_dir('render')}: run `dynclevr render "
                                f"--split {store.split}` first")
        images, labels = [], []
        for path in paths:
            video = Video.read(path)
            if not 0 <= frame < video.num_frames:
                raise DynclevrError(f"--frame {frame}: {path.name} has frames 0-{video.num_frames - 1}")
            images.append(video.frames(slice(frame, frame + 1))[0])
            labels.append(f"{video.scene} {video.meta.get('backend', '')} {video.meta.get('environment', '')}")
        sheet = contact_sheet(images, labels, min(columns, len(images)))
        with atomic_path(out) as tmp:
            ok, buf = cv2.imencode(".png", cv2.cvtColor(sheet, cv2.COLOR_RGB2BGR))
            tmp.write_bytes(buf.tobytes())
        typer.echo(f"wrote {out} ({len(images)} scenes, frame {frame})")
