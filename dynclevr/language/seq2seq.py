"""Bi-LSTM encoder, LSTM decoder with Luong (general) attention; an ensemble of them decoded greedily as one.
Plain torch, small.

The decoder does not feed its attentional state back as input (no input feeding), so that teacher-forced training
runs the decoder LSTM over a whole batch of sequences in one call; programs are short and the questions are
template text, where the attention alone finds the words each program token needs.
"""

from __future__ import annotations

import contextlib
from dataclasses import asdict, dataclass

import torch
from torch import nn
from torch.nn.utils.rnn import pack_padded_sequence, pad_packed_sequence

from dynclevr.language.vocab import EOS_ID, PAD_ID, SOS_ID


@dataclass(frozen=True)
class Dims:
    src_vocab: int
    tgt_vocab: int
    embedding: int
    hidden: int
    layers: int
    dropout: float

    def to_dict(self) -> dict:
        return asdict(self)


class Seq2Seq(nn.Module):
    def __init__(self, dims: Dims):
        super().__init__()
        self.dims = dims
        E, H, L = dims.embedding, dims.hidden, dims.layers
        self.src_embed = nn.Embedding(dims.src_vocab, E, padding_idx=PAD_ID)
        self.encoder = nn.LSTM(E, H, L, batch_first=True, bidirectional=True, dropout=dims.dropout if L > 1 else 0)
        # The two directions' final states, per layer, become the decoder's initial state.
        self.bridge_h = nn.Linear(2 * H, H)
        self.bridge_c = nn.Linear(2 * H, H)
        self.tgt_embed = nn.Embedding(dims.tgt_vocab, E, padding_idx=PAD_ID)
        self.decoder = nn.LSTM(E, H, L, batch_first=True, dropout=dims.dropout if L > 1 else 0)
        self.attn = nn.Linear(2 * H, H, bias=False)
        self.combine = nn.Linear(3 * H, H)
        self.out = nn.Linear(H, dims.tgt_vocab)
        self.drop = nn.Dropout(dims.dropout)

    def encode(self, src: torch.Tensor, src_len: torch.Tensor):
        """src (B, S) ids, src_len (B,) -> memory (B, S, 2H), its keys (B, S, H), mask (B, S), decoder state."""
        emb = self.drop(self.src_embed(src))
        packed = pack_padded_sequence(emb, src_len.cpu(), batch_first=True, enforce_sorted=False)
        out, (h, c) = self.encoder(packed)
        memory, _ = pad_packed_sequence(out, batch_first=True, total_length=src.shape[1])
        B, L, H = src.shape[0], self.dims.layers, self.dims.hidden
        h = h.view(L, 2, B, H).permute(0, 2, 1, 3).reshape(L, B, 2 * H)
        c = c.view(L, 2, B, H).permute(0, 2, 1, 3).reshape(L, B, 2 * H)
        state = (torch.tanh(self.bridge_h(h)).contiguous(), self.bridge_c(c).contiguous())
        return memory, self.attn(memory), src != PAD_ID, state

    def _readout(self, dec: torch.Tensor, memory, keys, mask) -> tuple[torch.Tensor, torch.Tensor]:
        """Decoder outputs (B, T, H) -> token logits (B, T, V) and the attention over the question (B, T, S)."""
        scores = torch.bmm(dec, keys.transpose(1, 2))                     # (B, T, S)
        scores = scores.masked_fill(~mask[:, None, :], float("-inf"))
        weights = torch.softmax(scores, dim=-1)
        context = torch.bmm(weights, memory)                              # (B, T, 2H)
        att = torch.tanh(self.combine(torch.cat([dec, context], dim=-1)))
        return self.out(self.drop(att)), weights

    def forward(self, src: torch.Tensor, src_len: torch.Tensor, tgt_in: torch.Tensor) -> torch.Tensor:
        """Teacher forcing: tgt_in (B, T) starts with <sos>; returns logits (B, T, V) for the next tokens."""
        memory, keys, mask, state = self.encode(src, src_len)
        dec, _ = self.decoder(self.drop(self.tgt_embed(tgt_in)), state)
        return self._readout(dec, memory, keys, mask)[0]


class Ensemble(nn.Module):
    """Sequence models trained alike from different seeds, decoded as one: each step takes the token of highest mean
    probability over the members. One model's errors on a wording it never saw are largely its own draw (another
    seed errs elsewhere); the mean keeps what they agree on."""

    def __init__(self, members: list[Seq2Seq]):
        super().__init__()
        if not members or len({m.dims for m in members}) != 1:
            raise ValueError("an ensemble needs one or more members of the same dims")
        self.members = nn.ModuleList(members)
        self.dims = members[0].dims

    @torch.no_grad()
    def greedy(self, src: torch.Tensor, src_len: torch.Tensor, max_len: int
               ) -> list[tuple[list[int] | None, float, list[float]]]:
        """Greedy decoding; per question (the token ids before <eos>, or None when no <eos> came within max_len;
        the decoding's probability, the product of each chosen token's mean probability; per question word, the
        most mean attention any decoding step paid it)."""
        encoded = [m.encode(src, src_len) for m in self.members]
        states = [e[3] for e in encoded]
        B = src.shape[0]
        tok = torch.full((B, 1), SOS_ID, dtype=torch.long)
        steps = []
        logp = torch.zeros(B)
        attended = torch.zeros(src.shape)
        finished = torch.zeros(B, dtype=torch.bool)
        for _ in range(max_len + 1):   # + 1: room for the <eos> after a program of max_len tokens
            probs, attention = [], []
            for k, (m, (memory, keys, mask, _)) in enumerate(zip(self.members, encoded)):
                dec, states[k] = m.decoder(m.tgt_embed(tok), states[k])
                logits, weights = m._readout(dec, memory, keys, mask)
                probs.append(torch.softmax(logits[:, 0], -1))
                attention.append(weights[:, 0])
            best = torch.stack(probs).mean(0).max(-1)
            attended = torch.where(finished[:, None], attended,
                                   torch.maximum(attended, torch.stack(attention).mean(0)))
            tok = best.indices[:, None]
            logp += torch.where(finished, torch.zeros(B), torch.log(best.values))
            steps.append(tok[:, 0])
            finished |= tok[:, 0] == EOS_ID
            if bool(finished.all()):
                break
        ids = torch.stack(steps, 1).tolist()
        return [(row[:row.index(EOS_ID)] if EOS_ID in row else None, float(torch.exp(lp)), att[:n].tolist())
                for row, lp, att, n in zip(ids, logp, attended, src_len.tolist())]


@contextlib.contextmanager
def one_thread():
    """Run torch on one thread, then restore the caller's setting. This model's matrices are small: extra threads
    only spin on a shared CPU (8x slower decoding on a busy 2-core machine), and one thread gives bit-identical
    training on any machine."""
    before = torch.get_num_threads()
    torch.set_num_threads(1)
    try:
        yield
    finally:
        torch.set_num_threads(before)


def pad_batch(seqs: list[list[int]]) -> tuple[torch.Tensor, torch.Tensor]:
    """Id lists -> (B, max_len) padded tensor and lengths (every sequence must be non-empty)."""
    lens = torch.tensor([len(s) for s in seqs], dtype=torch.long)
    out = torch.full((len(seqs), int(lens.max())), PAD_ID, dtype=torch.long)
    for i, s in enumerate(seqs):
        out[i, :len(s)] = torch.tensor(s, dtype=torch.long)
    return out, lens
