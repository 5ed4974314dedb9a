"""The CNN+LSTM baseline of the paper's Table 1 (its appendix: "aggregates frame-level CNN features and encodes the
question using an LSTM"; section 4: "We extract frame-level features and average them over the time dimension. We
encode questions with the last hidden state from an LSTM and then concatenate the two features to predict
answers"). Plain torch, small enough to train on one CPU core.

- Video: `cnnlstm.frames` frames, evenly spaced over the whole video; for a predictive question over the observed
  frames only (`video.observed_frames`: the model never sees what it is asked to predict). Each frame is shrunk to
  `height` x `width`, a four-layer strided CNN gives a coarse feature grid, a linear layer a frame feature; the video
  feature is the mean over the frames.
- Question: word embeddings (language/tokenize.py's tokens), an LSTM, its last hidden state.
- Answer: an MLP over the two features concatenated, a softmax over the answer vocabulary (every answer of the
  training questions).
What it reads at test time: the video's RGB frames, and of each question its text and type (the type only to choose
the frames: the dataset tells which questions are predictive, and answer.MODEL_COLUMNS allows the same).

Training (`dynclevr train cnnlstm`): the train split's questions and videos (never val or test); its last
`heldout_scenes` scenes are held out for early stopping and the manifest's accuracy. A batch is a few videos with all
their questions, so each video is encoded once per step. Augmentation: a small random shift and brightness (no flips:
left and right are answers; no hue change: colours are). Checkpoints (weights, optimiser, epoch) every
`checkpoint_minutes` to checkpoint.pt; `--resume` goes on from there. The weights of the best held-out epoch are
model.pt; manifest.json logs the curve (loss, train and held-out accuracy per epoch; curve.png) and the training
time.
"""

from __future__ import annotations

import json
import platform
import time
from dataclasses import asdict, dataclass
from pathlib import Path

import cv2
import numpy as np
import torch
from torch import nn
from torch.nn import functional as F
from torch.nn.utils.rnn import pack_padded_sequence

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import atomic_path, file_digest, read_parquet, write_json_atomic
from dynclevr.config import Config, ConfigError, scene_name
from dynclevr.language.tokenize import tokenize
from dynclevr.language.vocab import PAD_ID, UNK_ID, Vocab
from dynclevr.stages.annotate import QUESTIONS_FILE, QUESTIONS_SCHEMA, QUESTIONS_VERSION
from dynclevr.video import Video

DEFAULT_DIR = WEIGHTS_DIR / "cnnlstm"
MODEL, CHECKPOINT, VOCAB, MANIFEST, CURVE = "model.pt", "checkpoint.pt", "vocab.json", "manifest.json", "curve.png"
OBSERVED_TYPES = ("predictive",)   # question types that may see only the observed frames
MEAN, STD = 0.45, 0.25


class CnnLstmWeightsError(DynclevrError):
    pass


@dataclass(frozen=True)
class Dims:
    words: int
    answers: int
    height: int
    width: int
    channels: tuple[int, ...]
    frame_feature: int
    embedding: int
    hidden: int
    dropout: float


def params(cfg: Config) -> dict:
    """cfg["cnnlstm"], checked."""
    p = cfg["cnnlstm"]
    for key in ("frames", "height", "width", "frame_feature", "embedding", "hidden", "heldout_scenes", "epochs",
                "videos_per_batch", "lr", "patience", "checkpoint_minutes", "shift"):
        if p[key] <= 0:
            raise ConfigError(f"'cnnlstm.{key}' = {p[key]!r} must be positive")
    if p["height"] % 16 or p["width"] % 16:
        raise ConfigError("'cnnlstm.height' and 'cnnlstm.width' must be multiples of 16 (four stride-2 layers)")
    if not 0 <= p["dropout"] < 1:
        raise ConfigError(f"'cnnlstm.dropout' = {p['dropout']!r} must lie in [0, 1)")
    return p


def clip_indices(num_frames: int, observed: int, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(frames of the whole video, frames of the observed part): n of each, evenly spaced."""
    whole = np.round(np.linspace(0, num_frames - 1, n)).astype(int)
    seen = np.round(np.linspace(0, min(observed, num_frames) - 1, n)).astype(int)
    return whole, seen


def video_clips(path: Path, p: dict, observed: int) -> np.ndarray:
    """uint8 [2, n, h, w, 3]: the whole video's clip and the observed frames' clip, shrunk. Reads the RGB frames
    only (Video.frames)."""
    video = Video.read(path)
    frames = video.frames()
    whole, seen = clip_indices(len(frames), observed, p["frames"])
    size = (p["width"], p["height"])
    return np.stack([np.stack([cv2.resize(frames[i], size, interpolation=cv2.INTER_AREA) for i in idx])
                     for idx in (whole, seen)])


def _conv(cin: int, cout: int) -> nn.Sequential:
    return nn.Sequential(nn.Conv2d(cin, cout, 3, 2, 1, bias=False), nn.BatchNorm2d(cout), nn.ReLU(inplace=True))


class CnnLstm(nn.Module):
    def __init__(self, d: Dims):
        super().__init__()
        self.dims = d
        ch = (3,) + tuple(d.channels)
        self.cnn = nn.Sequential(*[_conv(a, b) for a, b in zip(ch[:-1], ch[1:])])
        gh, gw = d.height // 2 ** len(d.channels) // 2, d.width // 2 ** len(d.channels) // 2   # pooled grid
        self.grid = (gh, gw)
        self.frame = nn.Sequential(nn.Linear(ch[-1] * gh * gw, d.frame_feature), nn.ReLU(inplace=True))
        self.embed = nn.Embedding(d.words, d.embedding, padding_idx=PAD_ID)
        self.lstm = nn.LSTM(d.embedding, d.hidden, batch_first=True)
        self.head = nn.Sequential(nn.Dropout(d.dropout), nn.Linear(d.frame_feature + d.hidden, 256),
                                  nn.ReLU(inplace=True), nn.Dropout(d.dropout), nn.Linear(256, d.answers))

    def video(self, clips: torch.Tensor) -> torch.Tensor:
        """uint8 [B, n, h, w, 3] -> [B, frame_feature]: frame features averaged over time."""
        B, n = clips.shape[:2]
        x = clips.reshape(B * n, *clips.shape[2:]).permute(0, 3, 1, 2).float().div(255.0)
        x = self.cnn((x - MEAN) / STD)
        x = F.adaptive_avg_pool2d(x, self.grid).flatten(1)
        return self.frame(x).view(B, n, -1).mean(1)

    def question(self, words: torch.Tensor, lengths: torch.Tensor) -> torch.Tensor:
        packed = pack_padded_sequence(self.embed(words), lengths.cpu(), batch_first=True, enforce_sorted=False)
        _, (h, _) = self.lstm(packed)
        return h[-1]

    def forward(self, video_feats: torch.Tensor, words: torch.Tensor, lengths: torch.Tensor) -> torch.Tensor:
        return self.head(torch.cat([video_feats, self.question(words, lengths)], 1))


def encode_questions(texts: list[str], words: Vocab) -> tuple[torch.Tensor, torch.Tensor]:
    ids = [words.encode(tokenize(t)) or [UNK_ID] for t in texts]
    lengths = torch.tensor([len(s) for s in ids])
    out = torch.full((len(ids), int(lengths.max()) if ids else 1), PAD_ID, dtype=torch.long)
    for k, s in enumerate(ids):
        out[k, :len(s)] = torch.tensor(s)
    return out, lengths


class CnnLstmModel:
    """The trained baseline: `answer(clips, questions)`."""

    def __init__(self, net: CnnLstm, words: Vocab, answers: list[str], p: dict):
        self.net, self.words, self.answers, self.p = net, words, answers, p

    @classmethod
    def load(cls, weights_dir: Path = DEFAULT_DIR) -> "CnnLstmModel":
        weights_dir = Path(weights_dir)
        path, manifest = weights_dir / MODEL, weights_dir / MANIFEST
        if not path.exists() or not manifest.exists() or not (weights_dir / VOCAB).exists():
            raise CnnLstmWeightsError(f"CNN+LSTM weights missing in {weights_dir}: run `dynclevr train cnnlstm`")
        m = json.loads(manifest.read_text())
        if m.get("model_sha256") != file_digest(path):
            raise CnnLstmWeightsError(f"{path} does not match its manifest: rerun `dynclevr train cnnlstm --resume`")
        s = torch.load(path, weights_only=True)
        d = s["dims"]
        net = CnnLstm(Dims(**{**d, "channels": tuple(d["channels"])}))
        net.load_state_dict(s["net"])
        net.eval()
        v = json.loads((weights_dir / VOCAB).read_text())
        return cls(net, Vocab(v["words"]), v["answers"], s["params"])

    @torch.no_grad()
    def answer(self, clips: np.ndarray, questions: list[dict]) -> list[str]:
        """clips: video_clips() of the video; questions: dicts with 'text' and 'type'."""
        if not questions:
            return []
        self.net.eval()
        feats = self.net.video(torch.from_numpy(clips))                       # [2, F]
        which = torch.tensor([int(q["type"] in OBSERVED_TYPES) for q in questions])
        words, lengths = encode_questions([q["text"] for q in questions], self.words)
        logits = self.net(feats[which], words, lengths)
        return [self.answers[i] for i in logits.argmax(1).tolist()]


def weights_digest(weights_dir: Path = DEFAULT_DIR) -> str:
    """What the answers depend on: the weights and the vocabularies (not the manifest nor the checkpoint)."""
    weights_dir = Path(weights_dir)
    return "+".join(file_digest(weights_dir / f) if (weights_dir / f).exists() else "missing" for f in (MODEL, VOCAB))


# ---- training ----------------------------------------------------------------------------------------------------

def _augment(clips: np.ndarray, rng: np.random.Generator, shift: int) -> np.ndarray:
    """One shift (rolled round the edges) and brightness per video, its frames alike."""
    out = np.empty_like(clips)
    for b in range(len(clips)):
        dy, dx = rng.integers(-shift, shift + 1, size=2)
        x = np.roll(clips[b], (int(dy), int(dx)), axis=(-3, -2))
        gain = rng.uniform(0.85, 1.15)
        out[b] = np.clip(x.astype(np.float32) * gain, 0, 255).astype(np.uint8)
    return out


def _accuracy(rows: list[tuple[str, bool]]) -> dict:
    """Share right per type and the table's average (the mean of the three types)."""
    out = {"accuracy": round(float(np.mean([ok for _, ok in rows])), 5) if rows else float("nan")}
    for t in ("factual", "predictive", "counterfactual"):
        sel = [ok for typ, ok in rows if typ == t]
        out[t] = round(float(np.mean(sel)), 5) if sel else float("nan")
    out["average"] = round(float(np.nanmean([out[t] for t in ("factual", "predictive", "counterfactual")])), 5)
    return out


@torch.no_grad()
def evaluate(model: CnnLstmModel, clips: dict[str, np.ndarray], by_scene: dict[str, list[dict]]) -> dict:
    rows = []
    for scene, qs in by_scene.items():
        for q, a in zip(qs, model.answer(clips[scene], qs)):
            rows.append((q["type"], a == q["answer"]))
    return _accuracy(rows)


def training_questions(path: Path) -> list[dict]:
    """id, scene, type, text and answer of a split's questions.parquet: of this version, or of an earlier one that
    has these columns (the training data need not be re-annotated when the table gains columns or nulls)."""
    import pyarrow.parquet as pq

    columns = ["id", "scene", "type", "text", "answer"]
    try:
        return read_parquet(path, QUESTIONS_SCHEMA, QUESTIONS_VERSION, columns=columns).to_pylist()
    except DynclevrError:
        if not path.exists():
            raise
        meta = pq.read_schema(path).metadata or {}
        if meta.get(b"dynclevr.schema") != QUESTIONS_SCHEMA.encode() or not set(columns) <= set(pq.read_schema(path).names):
            raise
        return pq.read_table(path, columns=columns).to_pylist()


def plot_curve(manifest: dict, path: Path) -> None:
    """The manifest's curve: training loss, and training and held-out accuracy per epoch (the best epoch marked)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    curve = manifest["curve"]
    if not curve:
        return
    ep = [c["epoch"] for c in curve]
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.6))
    a.plot(ep, [c["loss"] for c in curve])
    a.set_xlabel("epoch")
    a.set_ylabel("training loss")
    b.plot(ep, [c["train_accuracy"] for c in curve], label="train (augmented)")
    b.plot(ep, [c["heldout"]["accuracy"] for c in curve], label="held out: all questions")
    b.plot(ep, [c["heldout"]["average"] for c in curve], label="held out: mean of the three types")
    if manifest.get("best"):
        b.axvline(manifest["best"]["epoch"], color="0.6", linestyle=":", label="kept (best held-out mean)")
    b.set_xlabel("epoch")
    b.set_ylabel("accuracy")
    b.legend(fontsize=7)
    fig.suptitle(f"CNN+LSTM on split {manifest.get('split')}: {manifest.get('train_scenes')} training videos, "
                 f"{len(manifest.get('heldout_scenes', []))} held out", fontsize=9)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=90)
    plt.close(fig)


def _save(path: Path, obj) -> None:
    with atomic_path(path) as tmp:
        torch.save(obj, tmp)


def train_cnnlstm(cfg: Config, data_dir: Path, split_name: str = "train", out_dir: Path = DEFAULT_DIR,
                  resume: bool = False, minutes: float | None = None, epochs: int | None = None, echo=print) -> dict:
    p = params(cfg)
    split = cfg.split(split_name)
    if split_name in ("full-val", "full-test", "small", "tiny"):
        raise DynclevrError(f"the CNN+LSTM trains on a training split, not '{split_name}' (its questions are measured)")
    if p["heldout_scenes"] >= split.scenes:
        raise ConfigError(f"'cnnlstm.heldout_scenes' must be fewer than split {split_name}'s {split.scenes} scenes")
    out_dir = Path(out_dir)
    root = Path(data_dir) / split.name
    questions = training_questions(root / QUESTIONS_FILE)
    names = split.scene_names()
    held = set(names[split.scenes - p["heldout_scenes"]:])
    train_q = [q for q in questions if q["scene"] not in held]
    held_q = [q for q in questions if q["scene"] in held]
    observed = int(cfg["video"]["observed_frames"])
    torch.set_num_threads(1)

    ckpt = out_dir / CHECKPOINT
    state = torch.load(ckpt, weights_only=True) if resume and ckpt.exists() else None
    if resume and state is None:
        raise CnnLstmWeightsError(f"nothing to resume in {out_dir}: run `dynclevr train cnnlstm` without --resume")
    if state is not None:
        words, answers = Vocab(state["words"]), state["answers"]
    else:
        words = Vocab.build(tokenize(q["text"]) for q in train_q)
        answers = sorted({q["answer"] for q in train_q})
    answer_id = {a: i for i, a in enumerate(answers)}
    d = Dims(len(words), len(answers), p["height"], p["width"], tuple(p["channels"]), p["frame_feature"],
             p["embedding"], p["hidden"], p["dropout"])
    torch.manual_seed(p["seed"])
    net = CnnLstm(d)
    opt = torch.optim.AdamW(net.parameters(), lr=p["lr"], weight_decay=p["weight_decay"])
    epoch, manifest = 0, None
    if state is not None:
        net.load_state_dict(state["net"])
        opt.load_state_dict(state["opt"])
        epoch, manifest = state["epoch"], state["manifest"]
        echo(f"train cnnlstm: resuming after epoch {epoch}")

    scenes = sorted({q["scene"] for q in questions})
    echo(f"train cnnlstm: reading {len(scenes)} videos of split {split.name} ...")
    t0 = time.perf_counter()
    clips = {s: video_clips(root / "video" / f"{s}.mcap", p, observed) for s in scenes}
    echo(f"  {len(scenes)} videos read in {time.perf_counter() - t0:.0f} s; {len(train_q)} training questions, "
         f"{len(held_q)} held out ({p['heldout_scenes']} scenes), {len(answers)} answers, {len(words)} words")
    by_scene: dict[str, list[dict]] = {}
    for q in train_q:
        by_scene.setdefault(q["scene"], []).append(q)
    held_by_scene: dict[str, list[dict]] = {}
    for q in held_q:
        held_by_scene.setdefault(q["scene"], []).append(q)
    train_scenes = sorted(by_scene)

    model = CnnLstmModel(net, words, answers, p)
    manifest = manifest or {"curve": [], "training_seconds": 0.0, "best": None, "runs": []}
    manifest.update({
        "split": split.name, "split_seed": split.seed, "questions_sha256": file_digest(root / QUESTIONS_FILE),
        "train_scenes": len(train_scenes), "heldout_scenes": sorted(held), "train_questions": len(train_q),
        "heldout_questions": len(held_q), "answers": len(answers), "words": len(words),
        "dims": {**asdict(d), "channels": list(d.channels)}, "params": dict(p),
        "parameters": sum(x.numel() for x in net.parameters()),
        "machine": f"{platform.machine()}, torch {torch.__version__}, 1 thread",
        "command": "dynclevr train cnnlstm [--resume]"})
    vocab = {"words": words.itos, "answers": answers}
    write_json_atomic(out_dir / VOCAB, vocab)
    total = epochs or p["epochs"]
    start = last_save = time.perf_counter()
    base_seconds, first_epoch = manifest["training_seconds"], epoch
    best = manifest["best"]["heldout"]["average"] if manifest["best"] else -1.0
    stale = epoch - manifest["best"]["epoch"] if manifest["best"] else 0

    def checkpoint(now: float) -> None:
        manifest["training_seconds"] = round(base_seconds + now - start, 1)
        manifest["epochs_done"] = epoch
        _save(ckpt, {"net": net.state_dict(), "opt": opt.state_dict(), "epoch": epoch, "manifest": manifest,
                     "words": words.itos, "answers": answers})

    stopped = "epochs"
    while epoch < total:
        if minutes is not None and time.perf_counter() - start > minutes * 60:
            stopped = "minutes"
            break
        if stale >= p["patience"]:
            stopped = "patience"
            break
        rng = np.random.default_rng([p["seed"], epoch])
        order = rng.permutation(len(train_scenes))
        net.train()
        t_epoch, total_loss, right, count = time.perf_counter(), 0.0, 0, 0
        for k in range(0, len(order), p["videos_per_batch"]):
            batch = [train_scenes[i] for i in order[k:k + p["videos_per_batch"]]]
            x = torch.from_numpy(_augment(np.stack([clips[s] for s in batch]), rng, p["shift"]))  # [B, 2, n, h, w, 3]
            feats = net.video(x.flatten(0, 1)).view(len(batch), 2, -1)
            qs = [(b, q) for b, s in enumerate(batch) for q in by_scene[s]]
            sel = feats[torch.tensor([b for b, _ in qs]), torch.tensor([int(q["type"] in OBSERVED_TYPES) for _, q in qs])]
            w, lengths = encode_questions([q["text"] for _, q in qs], words)
            logits = net(sel, w, lengths)
            target = torch.tensor([answer_id[q["answer"]] for _, q in qs])
            loss = F.cross_entropy(logits, target)
            opt.zero_grad()
            loss.backward()
            nn.utils.clip_grad_norm_(net.parameters(), 5.0)
            opt.step()
            total_loss += loss.item() * len(qs)
            right += int((logits.argmax(1) == target).sum())
            count += len(qs)
        epoch += 1
        held_acc = evaluate(model, clips, held_by_scene)
        row = {"epoch": epoch, "loss": round(total_loss / count, 5), "train_accuracy": round(right / count, 5),
               "heldout": held_acc, "seconds": round(time.perf_counter() - t_epoch, 1)}
        manifest["curve"].append(row)
        echo(f"  epoch {epoch}/{total}: loss {row['loss']:.4f}, train accuracy {row['train_accuracy']:.3f}, held-out "
             + ", ".join(f"{k} {v:.3f}" for k, v in held_acc.items()) + f" ({row['seconds']:.0f} s)")
        if held_acc["average"] > best:
            best, stale = held_acc["average"], 0
            manifest["best"] = {"epoch": epoch, "heldout": held_acc}
            _save(out_dir / MODEL, {"net": net.state_dict(), "dims": {**asdict(d), "channels": list(d.channels)},
                                    "params": dict(p)})
            manifest["model_sha256"] = file_digest(out_dir / MODEL)
            write_json_atomic(out_dir / MANIFEST, manifest)
        else:
            stale += 1
        now = time.perf_counter()
        if now - last_save > p["checkpoint_minutes"] * 60:
            checkpoint(now)
            write_json_atomic(out_dir / MANIFEST, manifest)
            last_save = now
    now = time.perf_counter()
    manifest["runs"].append({"from_epoch": first_epoch, "to_epoch": epoch, "stopped": stopped,
                             "seconds": round(now - start, 1)})
    checkpoint(now)
    write_json_atomic(out_dir / MANIFEST, manifest)
    plot_curve(manifest, out_dir / CURVE)
    echo(f"train cnnlstm: {epoch} epochs ({stopped}), best held-out average {best:.4f} at epoch "
         f"{manifest['best']['epoch'] if manifest['best'] else '-'}; written to {out_dir}")
    return manifest
