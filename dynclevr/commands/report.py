"""`dynclevr report --split S`: the paper's Table 1 on our data, printed and written as Markdown and a bar chart."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer


def register(app: typer.Typer) -> None:
    from dynclevr.cli import ConfigOpt, DataOpt, SplitOpt

    @app.command()
    def report(split: Optional[str] = SplitOpt, config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt):
        """Accuracy table: ours, ours without the physics prior, oracle, blind, and the paper's rows."""
        from dynclevr.artifacts import Store, atomic_path, command_options
        from dynclevr.config import Config
        from dynclevr.report import bar_chart, build, markdown

        cfg = Config.load(config)
        store = Store(data_dir, cfg.split(split).name)
        rerun = f"dynclevr run --split {store.split}{command_options(data_dir)}"
        rows, extra = build(store, cfg, rerun)
        text = markdown(store.split, rows, extra)
        typer.echo(text)
        with atomic_path(store.root / "report.md") as tmp:
            tmp.write_text(text)
        with atomic_path(store.root / "report.png") as tmp:
            bar_chart(tmp, store.split, rows)
        typer.echo(f"written: {store.root / 'report.md'}, {store.root / 'report.png'}")
