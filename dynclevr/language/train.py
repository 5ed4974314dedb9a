"""`dynclevr train qparser`: the question parser from the phrasing grammar, and the blind baseline from a split.

The parser is an ensemble of `members` sequence models, each trained from its own seed on questions drawn afresh
every epoch from the grammar's *seen* and *taught* phrasings (pool 'train', questions/phrasing.py) with random
objects (language/corpus.py; teacher forcing, Adam, word dropout); each stops early on the program exact match of
more such questions drawn apart. Held-out phrasings never reach training or the choice of weights: their exact
match is measured once, at the end, for the manifest (and by `dynclevr eval-qparser` on a split's truth). The
members share the first one's vocabularies.
The blind baseline (the majority answer per family) comes from the split's questions.parquet.
Outputs, in `out_dir`: model.pt (the ensemble's state dict), question_vocab.json, program_vocab.json, parser.json
(dims, ensemble size, params, program shapes), blind.json and manifest.json (data, per member its curve and
scores, the ensemble's exact match seen and held out, training time).
"""

from __future__ import annotations

import copy
import time
from collections import Counter, defaultdict
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from multiprocessing import get_context
from pathlib import Path
from typing import Callable

import torch
from torch import nn

from dynclevr import DynclevrError
from dynclevr.artifacts import Store, file_digest, read_parquet, write_json_atomic
from dynclevr.config import Config, Split
from dynclevr.language.corpus import synthesize
from dynclevr.language.params import QParserParams, qparser_params
from dynclevr.language.parse import QuestionParser, program_shape
from dynclevr.language.seq2seq import Dims, Ensemble, Seq2Seq, one_thread, pad_batch
from dynclevr.language.references import abstract_program, delexicalise
from dynclevr.language.tokenize import tokenize
from dynclevr.language.vocab import EOS_ID, PAD_ID, SOS_ID, UNK_ID, Vocab
from dynclevr.questions.generate import TEMPLATES_PATH
from dynclevr.questions.phrasing import TAUGHT_PATH
from dynclevr.questions.tables import QUESTIONS_SCHEMA, QUESTIONS_VERSION
from dynclevr.stages.annotate import QUESTIONS_FILE

BLIND = "blind.json"
MANIFEST = "manifest.json"
Pairs = list[tuple[str, list[str]]]


@dataclass
class Fit:
    parser: QuestionParser
    val_exact_match: float
    epochs: int
    seconds: float
    curve: list[dict] = field(default_factory=list)


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


def vocabularies(first: list[tuple[list[str], list[str]]]) -> tuple[Vocab, Vocab, set]:
    """Encoded questions -> (word vocabulary, program vocabulary, program shapes)."""
    if not first or any(not w or not p for w, p in first):
        raise DynclevrError("a training question or program is empty: check templates.json and taught.json")
    return Vocab.build(w for w, _ in first), Vocab.build(p for _, p in first), {program_shape(p) for _, p in first}


def fit(sample: Callable[[int], Pairs], val: Pairs, params: QParserParams, echo=print, seed: int | None = None,
        vocab: tuple[Vocab, Vocab, set] | None = None) -> Fit:
    """Train one sequence model on `sample(k)` in epoch k + 1 from torch seed `seed` (default: params.seed); keep the
    weights of the best exact match on `val`. The vocabularies and program shapes are `vocab` (the ensemble's), else
    epoch 1's questions'."""
    start = time.perf_counter()
    seed = params.seed if seed is None else seed
    first = [encoded(t, p) for t, p in sample(0)]
    words, prog_vocab, shapes = vocab or vocabularies(first)

    with one_thread():
        torch.manual_seed(seed)
        gen = torch.Generator().manual_seed(seed)
        model = Seq2Seq(Dims(len(words), len(prog_vocab), params.embedding, params.hidden, params.layers,
                             params.dropout))
        parser = QuestionParser(Ensemble([model]), words, prog_vocab, params, shapes)
        # The grammar's questions draw their objects at random, not from a scene: 'the biplane ... the aeroplane' may
        # be two objects there, so they are scored with every description its own object.
        parser.corefer = False
        opt = torch.optim.Adam(model.parameters(), lr=params.lr)
        loss_fn = nn.CrossEntropyLoss(ignore_index=PAD_ID)
        best, best_state, stale, epoch, curve = (-1.0, -1.0), None, 0, 0, []
        val_texts, val_programs = [t for t, _ in val], [p for _, p in val]
        val_enc = [encoded(t, p) for t, p in val]
        val_src = [words.encode(w) or [UNK_ID] for w, _ in val_enc]
        val_tgt = [prog_vocab.encode(p) for _, p in val_enc]
        for epoch in range(1, params.epochs_max + 1):
            data = first if epoch == 1 else [encoded(t, p) for t, p in sample(epoch - 1)]
            src = [words.encode(w) for w, _ in data]
            tgt = [prog_vocab.encode(p) for _, p in data]
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
            curve.append({"epoch": epoch, "loss": round(total / count, 5), "val_exact_match": round(em, 5),
                          "val_token_accuracy": round(acc, 5)})
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
        # Rounded to half precision, as `QuestionParser.save` stores it (eight members in 7.5 MB): the weights
        # scored here and in the manifest are the ones shipped.
        model.half().float().eval()
        em = exact_match(parser, val_texts, val_programs)
    return Fit(parser, em, epoch, time.perf_counter() - start, curve)


def encoded(text: str, program: list[str]) -> tuple[list[str], list[str]]:
    """A question and its program as the sequence model sees them: object words as placeholders (references.py)."""
    words, refs = delexicalise(tokenize(text))
    try:
        return words, abstract_program(program, refs)
    except ValueError:
        raise DynclevrError(f"the program of {text!r} names an object the text does not: check templates.json") from None


def grammar_pairs(n: int, seed: int, pool: str, augmented: bool = False) -> Pairs:
    return [(e.text, e.program.split()) for e in synthesize(n, seed, pool, augmented)]


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


def _member(job: tuple[QParserParams, int, Callable]) -> Fit:
    """Member k of the ensemble (see train_qparser)."""
    params, k, echo = job
    n, base = params.examples_per_epoch, 1000 * params.seed
    data = 1000 * (params.seed + k)
    vocab = vocabularies([encoded(t, p) for t, p in grammar_pairs(n, base, "train", augmented=True)])
    echo(f"qparser: member {k + 1} of {params.members}")
    return fit(lambda e: grammar_pairs(n, data + e, "train", augmented=True),
               grammar_pairs(params.val_examples, base + 999, "train"), params, echo, seed=params.seed + k,
               vocab=vocab)


def train_qparser(cfg: Config, data_dir: Path, split: Split, out_dir: Path, echo=print, workers: int = 1) -> dict:
    params = qparser_params(cfg)
    path, q = load_questions(Store(Path(data_dir), split.name))
    n = params.examples_per_epoch
    echo(f"qparser: {n} fresh questions per epoch from the phrasing grammar's seen and taught phrasings; blind "
         f"baseline from {len(q['text'])} questions of split '{split.name}' ({path})")
    # Member k of the ensemble: torch seed s + k, epoch e's questions from seed 1000 (s + k) + e; validation (seed
    # 1000 s + 999) and the held-out phrasings (1000 s + 998) are the same for all, and so are the vocabularies
    # (member 0's first epoch's). Members are independent, so `workers` processes train them alike.
    base = 1000 * params.seed
    if workers > 1:
        echo(f"qparser: {params.members} members on {workers} processes")
        with ProcessPoolExecutor(min(workers, params.members), mp_context=get_context("spawn")) as pool:
            fits = list(pool.map(_member, [(params, k, print) for k in range(params.members)]))
    else:
        fits = [_member((params, k, echo)) for k in range(params.members)]
    first = fits[0].parser
    parser = QuestionParser(Ensemble([f.parser.model.members[0] for f in fits]), first.words, first.programs,
                            params, first.shapes)
    parser.corefer = False   # as in fit: the grammar's random objects
    val = grammar_pairs(params.val_examples, base + 999, "train")
    val_em = exact_match(parser, [t for t, _ in val], [p for _, p in val])
    heldout = grammar_pairs(params.val_examples, base + 998, "heldout")
    heldout_em = exact_match(parser, [t for t, _ in heldout], [p for _, p in heldout])
    known = [(t, p) for t, p in heldout if all(w in parser.known for w in tokenize(t))]
    known_em = exact_match(parser, [t for t, _ in known], [p for _, p in known])
    parser.corefer = True
    out_dir = Path(out_dir)
    parser.save(out_dir)
    write_json_atomic(out_dir / BLIND, {"split": split.name, "questions": len(q["answer"]),
                                        **blind_baseline(q["family"], q["answer"])})
    manifest = {"command": "dynclevr train qparser", "training_data": "phrasing grammar, seen and taught phrasings",
                "templates_digest": file_digest(TEMPLATES_PATH), "taught_digest": file_digest(TAUGHT_PATH),
                "examples_per_epoch": n,
                "blind_split": split.name, "blind_questions": len(q["text"]), "questions_digest": file_digest(path),
                "params": params.to_dict(), "model": parser.model.dims.to_dict(),
                "val_exact_match": val_em, "heldout_phrasings_exact_match": heldout_em,
                "heldout_known_words_exact_match": known_em, "heldout_known_words_share": len(known) / len(heldout),
                "members": [{"seed": params.seed + k, "val_exact_match": f.val_exact_match,
                             "heldout_phrasings_exact_match": exact_match(f.parser, [t for t, _ in heldout],
                                                                          [p for _, p in heldout]),
                             "epochs": f.epochs, "curve": f.curve, "train_seconds": round(f.seconds, 1)}
                            for k, f in enumerate(fits)],
                "train_seconds": round(sum(f.seconds for f in fits), 1), "torch": torch.__version__}
    write_json_atomic(out_dir / MANIFEST, manifest)
    echo(f"qparser: exact match {val_em:.4f} on seen and taught phrasings, {heldout_em:.4f} on held-out phrasings "
         f"({params.val_examples} questions each; {known_em:.4f} on the {len(known)} of them whose words all occur "
         f"in training), {params.members} members, {manifest['train_seconds']:.0f} s; wrote {out_dir}")
    return manifest
