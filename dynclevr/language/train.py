"""`dynclevr train qparser`: the question parser (and the blind baseline) from a split's questions.parquet.

Questions of a deterministic 10% of the scenes are held out; training (teacher forcing, Adam) stops early on their
program exact match, measured with the same `QuestionParser` the answer stage uses. Outputs, in `out_dir`:
model.pt (state dict), question_vocab.json, program_vocab.json, parser.json (dims, params, program shapes),
blind.json (the blind baseline) and manifest.json (data, digest, validation exact match, training time).
"""

from __future__ import annotations

import copy
import time
from collections import Counter, defaultdict
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import torch
from torch import nn

from dynclevr import DynclevrError
from dynclevr.artifacts import Store, file_digest, read_parquet, write_json_atomic
from dynclevr.config import Config, Split
from dynclevr.language.params import QParserParams, qparser_params
from dynclevr.language.parse import QuestionParser, program_shape
from dynclevr.language.seq2seq import Dims, Seq2Seq, one_thread, pad_batch
from dynclevr.language.tokenize import tokenize
from dynclevr.language.vocab import EOS_ID, PAD_ID, SOS_ID, UNK_ID, Vocab
from dynclevr.questions.tables import QUESTIONS_SCHEMA, QUESTIONS_VERSION
from dynclevr.stages.annotate import QUESTIONS_FILE

BLIND = "blind.json"
MANIFEST = "manifest.json"


@dataclass
class Fit:
    parser: QuestionParser
    val_scenes: list[str]
    train_questions: int
    val_questions: int
    val_exact_match: float
    epochs: int
    seconds: float


def split_scenes(scenes: list[str], fraction: float, seed: int) -> set[str]:
    """The held-out scenes: a seeded draw of round(fraction x scenes), at least one, never all."""
    names = sorted(set(scenes))
    if len(names) < 2:
        raise DynclevrError(f"the question parser needs questions from at least 2 scenes (got {len(names)}): "
                            "annotate a larger split")
    n = min(len(names) - 1, max(1, round(fraction * len(names))))
    pick = np.random.default_rng(seed).permutation(len(names))[:n]
    return {names[i] for i in pick}


def exact_match(parser: QuestionParser, texts: list[str], programs: list[list[str]]) -> float:
    got = parser.parse_batch(texts)
    return sum(g == p for g, p in zip(got, programs)) / max(1, len(texts))


@torch.no_grad()
def token_accuracy(model: Seq2Seq, src: list[list[int]], tgt: list[list[int]], batch: int = 256) -> float:
    """Teacher-forced share of program tokens (and <eos>) predicted right."""
    right = total = 0
    for k in range(0, len(src), batch):
        x, x_len = pad_batch(src[k:k + batch])
        y, _ = pad_batch([[SOS_ID] + t + [EOS_ID] for t in tgt[k:k + batch]])
        gold = y[:, 1:]
        pred = model(x, x_len, y[:, :-1]).argmax(-1)
        mask = gold != PAD_ID
        right += int(((pred == gold) & mask).sum())
        total += int(mask.sum())
    return right / max(1, total)


def fit(texts: list[str], programs: list[list[str]], scenes: list[str], params: QParserParams,
        echo=print) -> Fit:
    """Train on the questions of the scenes not held out; keep the weights of the best validation exact match."""
    start = time.perf_counter()
    held = split_scenes(scenes, params.val_fraction, params.seed)
    tr = [i for i, s in enumerate(scenes) if s not in held]
    va = [i for i, s in enumerate(scenes) if s in held]
    words = Vocab.build(tokenize(texts[i]) for i in tr)
    prog_vocab = Vocab.build(programs[i] for i in tr)
    shapes = {program_shape(programs[i]) for i in tr}
    src = [words.encode(tokenize(texts[i])) for i in tr]
    tgt = [prog_vocab.encode(programs[i]) for i in tr]
    if any(not s for s in src) or any(not t for t in tgt):
        raise DynclevrError("a training question or program is empty: check questions.parquet")

    with one_thread():
        torch.manual_seed(params.seed)
        gen = torch.Generator().manual_seed(params.seed)
        model = Seq2Seq(Dims(len(words), len(prog_vocab), params.embedding, params.hidden, params.layers,
                             params.dropout))
        parser = QuestionParser(model, words, prog_vocab, params, shapes)
        opt = torch.optim.Adam(model.parameters(), lr=params.lr)
        loss_fn = nn.CrossEntropyLoss(ignore_index=PAD_ID)
        best, best_state, stale, epoch = (-1.0, -1.0), None, 0, 0
        val_texts, val_programs = [texts[i] for i in va], [programs[i] for i in va]
        val_src = [words.encode(tokenize(t)) or [UNK_ID] for t in val_texts]
        val_tgt = [prog_vocab.encode(p) for p in val_programs]
        for epoch in range(1, params.epochs_max + 1):
            model.train()
            total, count = 0.0, 0
            for b in torch.randperm(len(src), generator=gen).split(params.batch_size):
                x, x_len = pad_batch([src[i] for i in b.tolist()])
                drop = (torch.rand(x.shape, generator=gen) < params.word_dropout) & (x != PAD_ID)
                x = x.masked_fill(drop, UNK_ID)
                y, _ = pad_batch([[SOS_ID] + tgt[i] + [EOS_ID] for i in b.tolist()])
                logits = model(x, x_len, y[:, :-1])
                loss = loss_fn(logits.reshape(-1, logits.shape[-1]), y[:, 1:].reshape(-1))
                opt.zero_grad()
                loss.backward()
                nn.utils.clip_grad_norm_(model.parameters(), 5.0)
                opt.step()
                total, count = total + loss.item() * len(b), count + len(b)
            model.eval()
            em = exact_match(parser, val_texts, val_programs)
            acc = token_accuracy(model, val_src, val_tgt)
            echo(f"qparser epoch {epoch}: loss {total / count:.4f}, validation exact match {em:.4f}, "
                 f"token accuracy {acc:.4f}")
            # Exact match decides; teacher-forced token accuracy breaks its ties, so that early epochs, where no
            # program is right yet, still count as progress. A tie keeps the later, longer-trained weights but is
            # no progress: training stops `patience` epochs after a perfect score, not at its first, narrowest fit.
            if (em, acc) >= best:
                best_state = copy.deepcopy(model.state_dict())
            stale = 0 if (em, acc) > best else stale + 1
            best = max(best, (em, acc))
            if stale >= params.patience:
                break
        model.load_state_dict(best_state)
        model.eval()
    return Fit(parser, sorted(held), len(tr), len(va), best[0], epoch, time.perf_counter() - start)


def blind_baseline(families: list[str], answers: list[str]) -> dict:
    """The blind baseline (REFERENCE.md table 1, "blind"): `majority` maps each question family to its most common
    answer (ties: the alphabetically first), `overall` is the most common answer of all."""
    by = defaultdict(Counter)
    for f, a in zip(families, answers):
        by[f][a] += 1

    def majority(c: Counter) -> str:
        return min(c.items(), key=lambda kv: (-kv[1], kv[0]))[0]

    return {"majority": {f: majority(c) for f, c in sorted(by.items())}, "overall": majority(Counter(answers))}


def load_questions(store: Store) -> tuple[Path, dict[str, list]]:
    """The split's questions.parquet (annotate's output) as columns."""
    path = store.split_file(QUESTIONS_FILE)
    table = read_parquet(path, QUESTIONS_SCHEMA, QUESTIONS_VERSION,
                         columns=["scene", "family", "text", "program", "answer"]).to_pydict()
    if not table["text"]:
        raise DynclevrError(f"{path} holds no questions: annotate a larger split")
    return path, table


def train_qparser(cfg: Config, data_dir: Path, split: Split, out_dir: Path, echo=print) -> dict:
    params = qparser_params(cfg)
    path, q = load_questions(Store(Path(data_dir), split.name))
    programs = [p.split() for p in q["program"]]
    echo(f"qparser: {len(q['text'])} questions of split '{split.name}' from {path}")
    result = fit(q["text"], programs, q["scene"], params, echo)
    out_dir = Path(out_dir)
    result.parser.save(out_dir)
    write_json_atomic(out_dir / BLIND, {"split": split.name, "questions": len(q["answer"]),
                                        **blind_baseline(q["family"], q["answer"])})
    manifest = {"split": split.name, "questions": len(q["text"]), "questions_digest": file_digest(path),
                "params": params.to_dict(), "model": result.parser.model.dims.to_dict(),
                "train_questions": result.train_questions, "val_questions": result.val_questions,
                "val_scenes": result.val_scenes, "val_exact_match": result.val_exact_match,
                "epochs": result.epochs, "train_seconds": round(result.seconds, 1), "torch": torch.__version__}
    write_json_atomic(out_dir / MANIFEST, manifest)
    echo(f"qparser: validation exact match {result.val_exact_match:.4f} on {result.val_questions} questions of "
         f"{len(result.val_scenes)} held-out scenes, {result.epochs} epochs, {result.seconds:.0f} s; wrote {out_dir}")
    return manifest
