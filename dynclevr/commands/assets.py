"""`dynclevr assets [--sheet FILE.png]`: the vehicle catalogue as a table, and optionally a contact sheet to check by
eye."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer


def register(app: typer.Typer) -> None:
    @app.command()
    def assets(sheet: Optional[Path] = typer.Option(None, "--sheet", help="write a PNG contact sheet of every sub-type"),
               cell: int = typer.Option(256, "--cell", min=96, help="sheet cell width in pixels")):
        """Sub-type, category, size, faces, volume and mass of every vehicle in the catalogue."""
        from dynclevr import DynclevrError
        from dynclevr.assets.catalogue import DENSITY, SUBTYPES, get_asset

        if sheet is not None and sheet.suffix.lower() != ".png":
            raise DynclevrError(f"--sheet {sheet}: the contact sheet is a PNG, name it *.png")
        typer.echo(f"{'sub-type':16s} {'category':10s} {'size (m)':16s} {'faces':>6s} {'volume m3':>10s} "
                   f"{'mass':>7s}")
        for name in SUBTYPES:
            a = get_asset(name)
            size = "x".join(f"{s:g}" for s in a.size)
            faces = sum(len(m.faces) for m in a.parts.values())
            typer.echo(f"{name:16s} {a.category:10s} {size:16s} {faces:6d} {a.volume:10.3f} {a.mass():7.3f}")
        typer.echo(f"mass = {DENSITY:g} x volume of the convex hull (the collision shape)")
        if sheet is not None:
            from dynclevr.assets.sheet import draw_sheet

            draw_sheet(sheet, cell)
            typer.echo(f"wrote {sheet}")
