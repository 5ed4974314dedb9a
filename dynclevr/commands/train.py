"""`dynclevr train parser | detector | collisions | qparser | cnnlstm`: reproduce the shipped weights from the train split."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from dynclevr import WEIGHTS_DIR


def register(app: typer.Typer) -> None:
    from dynclevr.cli import ConfigOpt, DataOpt, WorkersOpt

    train = typer.Typer(no_args_is_help=True, help="Train the model's parts on a split; writes weights + manifest.")
    app.add_typer(train, name="train")

    @train.command("parser")
    def parser(split: str = typer.Option("train", "--split"), config: Optional[Path] = ConfigOpt,
               data_dir: Path = DataOpt, workers: int = WorkersOpt,
               out: Path = typer.Option(WEIGHTS_DIR / "parser", "--out")):
        """Scene parser: feature CNN, neural mesh models, background model, colour classifier."""
        from dynclevr.config import Config
        from dynclevr.perception.train import train_parser

        cfg = Config.load(config)
        train_parser(cfg, data_dir, cfg.split(split), out, workers, echo=typer.echo)

    @train.command("detector")
    def detector(config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt, workers: int = WorkersOpt,
                 out: Path = typer.Option(WEIGHTS_DIR / "detector", "--out"),
                 resume: bool = typer.Option(False, "--resume", help="continue from the checkpoint in --out"),
                 steps: Optional[int] = typer.Option(None, "--steps", help="total steps (default parser.detector_steps)"),
                 minutes: Optional[float] = typer.Option(None, "--minutes", help="stop (and save) after this long"),
                 grow_from: Optional[Path] = typer.Option(
                     None, "--grow-from", help="start from the trained head in this directory, grown to "
                                               "parser.detector_width, detector_blocks and detector_fine_blocks (it "
                                               "computes the same at first)"),
                 data_only: bool = typer.Option(False, "--data-only", help="make the training shards, then stop"),
                 device: str = typer.Option("cpu", "--device", help="where the head trains: cpu or cuda"),
                 loader_workers: int = typer.Option(0, "--loader-workers",
                                                    help="processes decoding and augmenting the frames (0: this one)")):
        """Detection head: centre heatmap, sub-type, colour, yaw, distance and height per cell (resumable)."""
        from dynclevr.config import Config
        from dynclevr.perception.detector_train import generate, shards, train_detector

        cfg = Config.load(config)
        if data_only:
            generate(cfg, data_dir, workers, shards(cfg), echo=typer.echo)
            return
        train_detector(cfg, data_dir, out, workers, resume, steps, minutes, grow_from, device, loader_workers,
                       echo=typer.echo)

    @train.command("collisions")
    def collisions(split: str = typer.Option("train", "--split"), config: Optional[Path] = ConfigOpt,
                   data_dir: Path = DataOpt, workers: int = WorkersOpt,
                   out: Path = typer.Option(WEIGHTS_DIR / "collision", "--out")):
        """Collision classifier: scene-parser runs on the split's videos against the truth's events."""
        from dynclevr.config import Config
        from dynclevr.perception.collision_train import train_collisions

        cfg = Config.load(config)
        train_collisions(cfg, data_dir, cfg.split(split), out, workers, echo=typer.echo)

    @train.command("qparser")
    def qparser(split: str = typer.Option("train", "--split"), config: Optional[Path] = ConfigOpt,
                data_dir: Path = DataOpt, out: Path = typer.Option(WEIGHTS_DIR / "qparser", "--out"),
                workers: int = typer.Option(1, "--workers", min=1, help="ensemble members trained in parallel "
                                                                         "processes (the same weights)")):
        """Question parser: attention LSTM seq2seq from question text to program; also the blind baseline."""
        from dynclevr.config import Config
        from dynclevr.language.train import train_qparser

        cfg = Config.load(config)
        train_qparser(cfg, data_dir, cfg.split(split), out, echo=typer.echo, workers=workers)

    @train.command("cnnlstm")
    def cnnlstm(split: str = typer.Option("train", "--split"), config: Optional[Path] = ConfigOpt,
                data_dir: Path = DataOpt, out: Path = typer.Option(WEIGHTS_DIR / "cnnlstm", "--out"),
                resume: bool = typer.Option(False, "--resume", help="continue from the checkpoint in --out"),
                epochs: Optional[int] = typer.Option(None, "--epochs", help="total epochs (default cnnlstm.epochs)"),
                minutes: Optional[float] = typer.Option(None, "--minutes", help="stop (and save) after this long")):
        """The CNN+LSTM baseline of Table 1: frame CNN averaged over time, question LSTM, answer classifier
        (resumable; the split's last cnnlstm.heldout_scenes scenes held out)."""
        from dynclevr.baselines.cnnlstm import train_cnnlstm
        from dynclevr.config import Config

        cfg = Config.load(config)
        train_cnnlstm(cfg, data_dir, split, out, resume, minutes, epochs, echo=typer.echo)
