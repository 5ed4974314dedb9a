"""`dynclevr stats --split S`: dataset statistics of the simulated scenes and the generated questions."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer


def register(app: typer.Typer) -> None:
    from dynclevr.cli import ConfigOpt, DataOpt, SplitOpt

    @app.command()
    def stats(split: Optional[str] = SplitOpt, config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt):
        """Objects, velocity classes, collisions and counterfactual effects per split; question counts and balance."""
        from dynclevr.artifacts import Store
        from dynclevr.config import Config
        from dynclevr.stages import annotate, simulate

        cfg = Config.load(config)
        store = Store(data_dir, cfg.split(split).name)
        typer.echo(simulate.stats(store, cfg))
        if store.split_file("questions.parquet").exists():
            typer.echo(annotate.stats(store, cfg))
