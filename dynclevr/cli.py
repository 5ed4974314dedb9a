"""`dynclevr <stage> --split NAME [--scenes 0-9] [--force] [--config FILE] [--workers N]`, plus run, status and the
commands each part of the system registers from dynclevr/commands/. Errors are one line, never a traceback."""

from __future__ import annotations

import importlib
import pkgutil
import sys
from pathlib import Path
from typing import Optional

import typer

from dynclevr import DynclevrError, __version__
from dynclevr.config import Config
from dynclevr.pipeline import BASELINES, ORDER, Runner, model_configs, parse_scenes

# Shell completion: `dynclevr --install-completion` (bash, zsh, fish), or `--show-completion` to see the script.
app = typer.Typer(add_completion=True, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="DynSuperCLEVR data generation and the NS-4DPhysics model, as a staged, cached pipeline.")


def _print_version(value: bool) -> None:
    if value:
        typer.echo(f"dynclevr {__version__}")
        raise typer.Exit()


@app.callback()
def _options(version: bool = typer.Option(False, "--version", callback=_print_version, is_eager=True,
                                          help="Print the version and exit.")) -> None:
    pass


def _split_names(incomplete: str) -> list[str]:
    """--split completes to the splits of pipeline.toml."""
    try:
        return [s for s in Config.load().data.get("splits", {}) if s.startswith(incomplete)]
    except DynclevrError:
        return []


SplitOpt = typer.Option(None, "--split", help="split name from pipeline.toml (default: its default_split)",
                        autocompletion=_split_names)
ScenesOpt = typer.Option(None, "--scenes", help="subset of scene indices, e.g. 3-5 or 0,2,7-9")
ForceOpt = typer.Option(False, "--force", help="rerun even where the cache is fresh")
ConfigOpt = typer.Option(None, "--config", help="a TOML file merged over pipeline.toml")
WorkersOpt = typer.Option(1, "--workers", min=1, help="scenes run in parallel processes")
ExecutorOpt = typer.Option("local", "--executor",
                           help="where per-scene tasks run: local (this machine's process pool) or ray (a Ray "
                                "cluster; `make ray` installs it); same cache, manifests and bytes")
RayAddressOpt = typer.Option(None, "--ray-address",
                             help="with --executor ray: the cluster to join (auto: the one `ray start` began on this "
                                  "node); default: a local Ray with --workers CPUs")
DataOpt = typer.Option(Path("data"), "--data-dir", help="artifact root: <data-dir>/<split>/<stage>/")
NoPriorOpt = typer.Option(False, "--no-physics-prior",
                          help="the paper's ablation: the scene parser without the physics prior; model outputs "
                               "go to parsed-noprior/, future-noprior/, answers-noprior/")
ParticleOpt = typer.Option(False, "--particle-filter",
                           help="the scene parser with the particle filter (parser.filter = \"particle\"); model "
                                "outputs go to parsed-particle/, future-particle/, answers-particle/")
PerFrameOpt = typer.Option(False, "--per-frame",
                           help="the per-frame 3D baseline (PO3D-VQA style, parser.filter = \"none\": no prior, no "
                                "temporal filter, constant-velocity future); outputs go to parsed-perframe/, "
                                "future-perframe/, answers-perframe/")


def load_config(config: Path | None, no_physics_prior: bool = False, particle_filter: bool = False,
                per_frame: bool = False) -> Config:
    cfg = Config.load(config)
    if no_physics_prior:
        cfg.data.setdefault("parser", {})["physics_prior"] = False
    if particle_filter:
        cfg.data.setdefault("parser", {})["filter"] = "particle"
    if per_frame:
        cfg.data.setdefault("parser", {}).update(filter="none", physics_prior=False)
    return cfg


def runner(split: str | None, config: Path | None, data_dir: Path, workers: int = 1,
           no_physics_prior: bool = False, particle_filter: bool = False, per_frame: bool = False,
           executor: str = "local", ray_address: str | None = None) -> Runner:
    cfg = load_config(config, no_physics_prior, particle_filter, per_frame)
    return Runner(cfg, cfg.split(split), data_dir, workers, echo=typer.echo, executor=executor,
                  ray_address=ray_address)


def _stage_command(name: str):
    def command(split: Optional[str] = SplitOpt, scenes: Optional[str] = ScenesOpt, force: bool = ForceOpt,
                config: Optional[Path] = ConfigOpt, workers: int = WorkersOpt, data_dir: Path = DataOpt,
                no_physics_prior: bool = NoPriorOpt, particle_filter: bool = ParticleOpt,
                per_frame: bool = PerFrameOpt, executor: str = ExecutorOpt,
                ray_address: Optional[str] = RayAddressOpt):
        r = runner(split, config, data_dir, workers, no_physics_prior, particle_filter, per_frame, executor,
                   ray_address)
        r.run(name, parse_scenes(scenes, r.split), force)

    command.__doc__ = f"Run the {name} stage over a split (cached per scene)."
    return command


for _name in ORDER + BASELINES:
    app.command(_name)(_stage_command(_name))


@app.command()
def run(split: Optional[str] = SplitOpt, scenes: Optional[str] = ScenesOpt, force: bool = ForceOpt,
        config: Optional[Path] = ConfigOpt, workers: int = WorkersOpt, data_dir: Path = DataOpt,
        ablation: bool = typer.Option(True, "--ablation/--no-ablation",
                                      help="also the report's other rows: the model without the physics prior and "
                                           "with the particle filter, the per-frame 3D and the CNN+LSTM baselines"),
        executor: str = ExecutorOpt, ray_address: Optional[str] = RayAddressOpt):
    """Run every stage in order: simulate, render, annotate, parse-scene, simulate-future, answer; then the same
    model stages for the report's other rows, and the CNN+LSTM baseline (answer-cnnlstm)."""
    main = runner(split, config, data_dir, workers, executor=executor, ray_address=ray_address)
    indices = parse_scenes(scenes, main.split)
    for name in ORDER:
        main.run(name, indices, force)
    if ablation:
        for row, cfg in model_configs(main.cfg)[1:]:
            typer.echo(f"{row}:")
            r = Runner(cfg, cfg.split(split), data_dir, workers, echo=typer.echo, executor=executor,
                       ray_address=ray_address)
            for name in ORDER[3:]:
                r.run(name, indices, force)
        typer.echo("CNN+LSTM:")
        for name in BASELINES:
            main.run(name, indices, force)


@app.command()
def status(split: Optional[str] = SplitOpt, config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt,
           no_physics_prior: bool = NoPriorOpt, particle_filter: bool = ParticleOpt, per_frame: bool = PerFrameOpt):
    """Per stage: how many scenes are done (fresh), stale (inputs or params changed) or missing."""
    r = runner(split, config, data_dir, no_physics_prior=no_physics_prior, particle_filter=particle_filter,
               per_frame=per_frame)
    typer.echo(f"split {r.split.name}: {r.split.scenes} scenes under {r.store.root}")
    for name in ORDER + BASELINES:
        try:
            st = r.status(name)
        except DynclevrError as e:
            typer.echo(f"  {name:16s} {e}")
            continue
        line = "  ".join(f"{k} {len(v)}" for k, v in st.items())
        hint = f"  (stale: {', '.join(st['stale'][:5])}{'...' if len(st['stale']) > 5 else ''})" if st["stale"] else ""
        typer.echo(f"  {name:16s} {line}{hint}")


def _register_commands() -> None:
    import dynclevr.commands as commands

    for info in pkgutil.iter_modules(commands.__path__):
        importlib.import_module(f"dynclevr.commands.{info.name}").register(app)


def _remember_config(argv: list[str]) -> None:
    """Error hints print commands; they must carry the user's --config (artifacts.HINT_OPTIONS)."""
    from dynclevr.artifacts import HINT_OPTIONS

    for k, arg in enumerate(argv):
        if arg == "--config" and k + 1 < len(argv):
            HINT_OPTIONS["config"] = Path(argv[k + 1])
        elif arg.startswith("--config="):
            HINT_OPTIONS["config"] = Path(arg.split("=", 1)[1])


def main() -> None:
    _register_commands()
    _remember_config(sys.argv[1:])
    from dynclevr.pipeline import Interrupted

    try:
        app(prog_name="dynclevr")  # standalone: typer reports usage errors itself and exits
    except (Interrupted, KeyboardInterrupt) as e:
        typer.secho(f"interrupted: {e}" if str(e) else "interrupted", err=True, fg="yellow")
        sys.exit(130)
    except DynclevrError as e:
        typer.secho(f"error: {e}", err=True, fg="red")
        sys.exit(2)
    except OSError as e:   # the file system, not the pipeline: a full disk, a file without read permission
        what = f"{e.strerror}: {e.filename}" if e.strerror and e.filename else str(e)
        typer.secho(f"error: {what} (check the path, its permissions and free space)", err=True, fg="red")
        sys.exit(2)


if __name__ == "__main__":
    main()
