"""`dynclevr eval-qparser` (the question parser on seen and held-out wordings) and `dynclevr ask` (your question,
answered on a scene of a split, with its program and evidence)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer

REPORT = "qparser_eval.md"


def register(app: typer.Typer) -> None:
    from dynclevr.cli import ConfigOpt, DataOpt, NoPriorOpt, ParticleOpt, SplitOpt

    @app.command("eval-qparser")
    def eval_qparser(split: Optional[str] = SplitOpt, config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt,
                     seed: int = typer.Option(0, "--seed", help="seed of the re-phrasings")):
        """Program exact match and answer accuracy (on the truth) of the question parser for the split's questions
        re-phrased in wordings seen in training and in held-out wordings, its own texts, questions written by hand
        (program exact match), and the share of out-of-scope questions left unparsed. Needs annotate; writes
        <split>/qparser_eval.md and .json."""
        from dynclevr import DynclevrError
        from dynclevr.artifacts import write_json_atomic
        from dynclevr.cli import load_config
        from dynclevr.language.evaluate import evaluate, markdown
        from dynclevr.language.parse import QuestionParser
        from dynclevr.pipeline import Runner
        from dynclevr.scene import Scene4D
        from dynclevr.stages.annotate import QUESTIONS_SCHEMA, QUESTIONS_VERSION
        from dynclevr.artifacts import read_parquet

        cfg = load_config(config)
        r = Runner(cfg, cfg.split(split), data_dir, echo=typer.echo)
        path = r.store.split_file("questions.parquet")
        if not path.exists():
            raise DynclevrError(f"{path} is missing: run `dynclevr annotate --split {r.split.name}"
                                f"{_opts(data_dir)}` first")
        questions = read_parquet(path, QUESTIONS_SCHEMA, QUESTIONS_VERSION).to_pylist()
        truth = {s: Scene4D.read(r.store.path("simulate", s, ".mcap")) for s in sorted({q["scene"] for q in questions})}
        result = evaluate(QuestionParser.load(), questions, truth, cfg["labels"], seed)
        table = markdown(result)
        out = r.store.split_file(REPORT)
        out.write_text(f"# Question parser on split {r.split.name}\n\n`dynclevr eval-qparser --split {r.split.name}`"
                       f"\n\n{table}")
        write_json_atomic(out.with_suffix(".json"), result)
        typer.echo(table)
        typer.echo(f"written to {out}")

    @app.command("ask")
    def ask(question: Optional[str] = typer.Argument(None, help="the question, in your own words"),
            split: Optional[str] = SplitOpt,
            scene: Optional[int] = typer.Option(None, "--scene", help="scene index in the split"),
            on: str = typer.Option("estimate", "--on", help="estimate (the model's parse of the video) or truth"),
            file: Optional[Path] = typer.Option(None, "--file", help="JSON lines with 'scene' and 'text'; "
                                                                     "prints them with program, answer, status"),
            config: Optional[Path] = ConfigOpt, data_dir: Path = DataOpt,
            no_physics_prior: bool = NoPriorOpt, particle_filter: bool = ParticleOpt):
        """Answer a question about one scene: its program, the answer and the evidence (the objects its references
        matched, the frames it looked at). `--on truth` answers on the simulated truth (for dataset users)."""
        from dynclevr import DynclevrError
        from dynclevr.cli import load_config
        from dynclevr.language.parse import QuestionParser
        from dynclevr.pipeline import Runner, model_variant

        if on not in ("estimate", "truth"):
            raise DynclevrError(f"--on must be 'estimate' or 'truth', not {on!r}")
        cfg = load_config(config, no_physics_prior, particle_filter)
        runner = Runner(cfg, cfg.split(split), data_dir, echo=typer.echo)
        names = runner.split.scene_names()
        opts = _opts(data_dir, " --no-physics-prior" * no_physics_prior + " --particle-filter" * particle_filter)
        parser = QuestionParser.load()
        scenes: dict[str, object] = {}

        def world(index) -> object:
            if isinstance(index, bool) or not isinstance(index, int) or not 0 <= index < len(names):
                raise DynclevrError(f"scene {index!r} is not in split {runner.split.name} (scenes 0-{len(names) - 1})")
            if index not in scenes:
                scenes[index] = _scene(runner, cfg, names[index], index, on, model_variant(cfg), opts)
            return scenes[index]

        if file is not None:
            if question is not None:
                raise DynclevrError("give a question or --file, not both")
            _ask_file(file, parser, world, cfg["labels"])
            return
        if question is None or not question.strip():
            raise DynclevrError(f"the question is empty: dynclevr ask --split {runner.split.name} --scene N "
                                "\"Did the red sedan hit the blue bus?\"")
        if scene is None:
            raise DynclevrError(f"which scene? add --scene N (0-{len(names) - 1})")
        result = _answer(parser, question, world(scene), cfg["labels"])
        if result["status"] == "unparsed":
            typer.echo(f"unparsed: {result['reason']}", err=True)
            raise typer.Exit(1)
        typer.echo(f"program:  {result['program']}")
        typer.echo(f"answer:   {result['answer']}   (on the {on} of scene {names[scene]}, split {runner.split.name})")
        for line in result["evidence"]:
            typer.echo(f"evidence: {line}")
        if result["status"] != "ok":
            typer.echo(f"{result['status']}: {result['reason']}", err=True)
            raise typer.Exit(1)


def _opts(data_dir: Path, extra: str = "") -> str:
    """The options a printed command must repeat to act on the same data."""
    from dynclevr.artifacts import command_options

    return command_options(data_dir) + extra


def _scene(runner, cfg, name: str, index: int, on: str, variant: str, opts: str):
    from dynclevr import DynclevrError
    from dynclevr.artifacts import Store
    from dynclevr.scene import Scene4D
    from dynclevr.stages.simulate_future import attach

    split = runner.split.name
    if on == "truth":
        path = runner.store.path("simulate", name, ".mcap")
        if not path.exists():
            raise DynclevrError(f"scene {name} of split {split} is not simulated yet: run "
                                f"`dynclevr simulate --split {split} --scenes {index}{opts}`")
        return Scene4D.read(path)
    store = Store(runner.store.data_dir, split, variant)
    parsed, future = store.path("parse-scene", name, ".mcap"), store.path("simulate-future", name, ".parquet")
    if not parsed.exists() or not future.exists():
        raise DynclevrError(f"scene {name} of split {split} has no estimate yet: run `dynclevr run --split {split} "
                            f"--scenes {index}{opts}` (or ask with --on truth)")
    return attach(Scene4D.read(parsed), future)


def _answer(parser, text: str, scene, labels_cfg: dict) -> dict:
    from dynclevr import DynclevrError
    from dynclevr.questions.programs import Executor

    p = parser.analyse_batch([text])[0]
    read = [f"read '{w}' as '{k}'" for w, k in p.read_as]
    if p.reordered:
        read.append(f"read with its clause of time last: '{p.reordered}'")
    if p.program is None:
        return {"program": "", "answer": "", "status": "unparsed", "reason": p.reason, "evidence": read}
    trace: list = []
    try:
        answer = Executor(scene, labels_cfg).run(p.program, trace)
    except DynclevrError as e:
        return {"program": " ".join(p.program), "answer": "", "status": "failed", "reason": str(e),
                "evidence": read + _evidence(trace, scene)}
    evidence = read + _evidence(trace, scene)
    unresolved = [line for line in evidence if "no object matches" in line]
    return {"program": " ".join(p.program), "answer": answer, "status": "no-match" if unresolved else "ok",
            "reason": "; ".join(unresolved), "evidence": evidence}


def _evidence(trace: list, scene) -> list[str]:
    """Readable lines for the steps a person checks: which object each reference picked, which frame, which event."""
    from dynclevr.questions.programs import CollisionEventSet, FrameID, Object, ObjectSet
    from dynclevr.scene import Collision

    objs = {o.id: o for o in scene.objects}

    def name(oid) -> str:
        o = objs[int(oid)]
        return f"object {o.id} ({o.color} {o.shape.replace('_', ' ')})"

    lines, words = [], []
    for token, inputs, output in trace:
        if token.startswith("filter_attributes["):
            words.append(token[len("filter_attributes["):-1].replace("_", " "))
        if token == "unique" and type(output) is Object:
            described = " ".join(words) or "the object"
            exact = isinstance(inputs[0], ObjectSet) and len(inputs[0]) == 1
            if exact:
                lines.append(f"'{described}' -> {name(output)}")
            elif words:
                lines.append(f"'{described}': no object matches exactly ({len(inputs[0])} do); "
                             f"closest: {name(output)}")
            else:
                lines.append(f"the one object that fits -> {name(output)}" if exact else
                             f"no single object fits ({len(inputs[0])} do); closest: {name(output)}")
            words = []
        elif token == "unique" and isinstance(output, Collision):
            lines.append(f"collision of {name(output.a)} and {name(output.b)} at frame {output.frame}")
        elif type(output) is FrameID:
            lines.append(f"{token} -> frame {int(output)}")
        elif token in ("exist",) and isinstance(inputs[0], CollisionEventSet):
            events = ", ".join(f"{e.a}-{e.b} at frame {e.frame}" for e in inputs[0]) or "none"
            lines.append(f"collisions considered: {events}")
    return list(dict.fromkeys(lines))   # a reference used twice ('when X hits Y, is X ...') is said once


def _ask_file(file: Path, parser, world, labels_cfg: dict) -> None:
    from dynclevr import DynclevrError

    try:
        lines = file.read_text().splitlines()
    except OSError as e:
        raise DynclevrError(f"cannot read {file}: {e.strerror}") from None
    for k, line in enumerate(lines, 1):
        if not line.strip():
            continue
        try:
            item = json.loads(line)
            index, text = item["scene"], item["text"]
        except (ValueError, KeyError, TypeError):
            raise DynclevrError(f"{file}:{k} is not a JSON object with 'scene' and 'text'") from None
        result = _answer(parser, text, world(index), labels_cfg)
        typer.echo(json.dumps({**item, **{k2: result[k2] for k2 in ("program", "answer", "status", "reason")}}))
