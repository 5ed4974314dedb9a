"""`QuestionParser`: question text -> program tokens (postfix), or unparsed with a one-line reason, never a crash.

A question is unparsed (counted wrong) rather than given a confident wrong program when
- it asks for a count ('how many': no program counts) or a cause ('why': no program explains);
- it is empty, or has more unknown words than `max_unknown_words` (a word one slip of the fingers from exactly one
  readable word counts as that word, whatever its length: 'slolwy' as 'slowly', 'oclor' as 'color'; a word one
  typo away from exactly one colour or vehicle name counts as that name, so a misspelt colour such as 'gren' reads
  as 'green', and so does a word of TYPO_LETTERS or more one typo away from exactly one known word: 'acelerating'
  as 'accelerating'; a word of the synonym lexicon, SYNONYMS_FILE, counts as the known word it stands for: 'rammed'
  as 'hit', 'footage' as 'video';
  failing that, a word with the stem of a known word or of a lexicon word counts as that word: 'hovered' as
  'hovering'; and last, a word of WordNet's lexicon, WORDNET_FILE, as the known word it shares a main sense with:
  'journeying' as 'travelling');
- a word it does not know carries the question: some step of the decoding attends to it more than
  `max_unknown_attention` ("Is the red sedan *bigger* than the blue bus?" would be read as faster or slower by
  the words around it), while an unknown word the decoding looks past (a filler: "really", "please") is harmless;
- decoding gives no well-formed program: no <eos> within `max_decode_len`, a special token, an operation sequence no
  training program has, or not a valid postfix program of dynclevr/questions/programs.py's operations;
- the decoding's probability is below `min_confidence` (a wording unlike any the parser learnt);
- it names an object the catalogue lacks ('the green *tractor*', 'the *pink* suv': object words next to an unknown
  word, except a word after a whole description, which is the sentence's: 'the red sedan *ends* up hitting'),
  compares objects by what no question asks ('the red sedan *bigger* than'), or runs object words together that
  describe no one object ('red blue green');
- the program asks the opposite of the question: motion asked as rest ('Is the red sedan moving at the start?'
  read as is_static), a negation the grammar never says ('not accelerating', 'never hit'), or a word reversing the
  program's predicate ('miss', 'braking', 'grounded'; 'decelerating' is refused as said, before WordNet reads it
  as 'slow'). No operation negates, so the model reads such a
  wording as its nearest phrase, the unreversed one, and would answer the opposite;
- it asks what no family asks, however near a family's its words are: a direction or a place asked as yes or no
  ('is it moving left?', 'is it behind the bus?'), the video's end or another time than the start ('in the middle',
  'after two seconds': `time_unasked`), how often ('twice'), the time before or after a collision, the second or
  last of its partners, a turn or a spin, a vehicle's pose, a landing; a speed as a number ('20 mph'), a time window
  ('within 2 seconds': `clock_unasked`), a count of vehicles, a height, a direction towards another vehicle, a
  counterfactual that compares a vehicle with itself ('had it been slower': `comparison_imagined`), a partner
  described by its motion ('a stationary vehicle': `motion_unread`), a vehicle ranked among all ('the fastest',
  'the first vehicle to collide': `ranking`), two speeds alike ('as quick as the bus': `speeds_alike`), 'how' with
  a word no family asks ('how hard does it hit'), an amount of acceleration, two kinds of motion or two questions at
  once (`properties_joined`, `questions_joined`), several vehicles' colours or types (`several_asked`), a path's
  shape, a take-off, a near miss, one vehicle chasing or passing another, a size or a material (CLEVR's), what
  ought to happen, a loss of control, a collision at the start (`collision_at_start`); or a yes/no question is read
  as asking which (`form_unmatched`) or how, a reading answers another property than the one asked
  (`property_unread`), or asks floating or rest where the question says neither (`floating_unsaid`, a speed read
  as static in `reversed_reading`), or not whether a vehicle is visible (`visibility_unread`); all or every vehicle
  at once (`quantified`), a premise (`premised`), a vehicle described through another described one (`chained`),
  the order in which vehicles appear; a measure of speed or a comparison's degree (`speed_measure`), a colour
  checked (`checked_attribute`), a collision with scenery ('the wall'), an order of collisions ('what does it hit
  next': `ordered`), a collision said not to happen ('passed without touching': `impact_denied`), a rest no word says
  (`reversed_reading`), 'afterwards' read within the video or a reading after the video no word says
  (`future_unread`), a reading of accelerating no word says (`acceleration_unsaid`), the video's end, a later time or
  a vehicle entering read at the start (`end_unread`), a size (`size_unread`), which event came first, a change
  assumed ('assume the cruiser starts slow; does it ...') read as what happened (`imagining_unread`);
- it names a vehicle the catalogue lacks where a question names one ('does the zamboni hit ...': `_unknown_vehicle`);
- the program leaves out an object the question names (a sentence read as a question about fewer objects), or
  refers to one it does not name. Object words reach the program only through the
  copy path (references.py): the sequence model may generalise a sentence, never invent or change an object.
"""

from __future__ import annotations

import io
import json
import pickle
import re
import unicodedata
from dataclasses import dataclass, replace
from difflib import SequenceMatcher
from pathlib import Path

import snowballstemmer
import torch

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import ArtifactError, atomic_path, write_json_atomic
from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.colors import COLOR_NAMES
from dynclevr.language.code import code_as_said
from dynclevr.language.params import QParserParams
from dynclevr.language.seq2seq import Dims, Ensemble, Seq2Seq, one_thread, pad_batch
from dynclevr.language.references import (CATEGORY_SAID, EVERYDAY_NAMES, OBJECT_WORDS, catalogue_names,
                                          concrete_program, coordinated,
                                          corefer, delexicalise, described_as_named, description_as_said,
                                          generalises, heard_as_said,
                                          is_description, mentions,
                                          phrase_table, phrases_as_said, placeholders)
from dynclevr.language.tokenize import SPELLINGS, tokenize
from dynclevr.language.vocab import SPECIALS, UNK_ID, Vocab, run_together, slipped, slips, stretched
from dynclevr.questions.generate import templates
from dynclevr.questions.programs import OPS, ProgramError
from dynclevr.questions.programs import parse as parse_program

QUESTION_VOCAB = "question_vocab.json"
PROGRAM_VOCAB = "program_vocab.json"
SETTINGS = "parser.json"   # dims, ensemble size, params, the training programs' shapes: what `load` rebuilds from
MODEL = "model.pt"
OBJECT_LEXICON = Vocab(sorted(OBJECT_WORDS))
MAX_WORDS = 200      # far beyond any template question; bounds the cost of a pasted essay
TYPO_LETTERS = 7     # a sentence word this long with one known word one edit away is that word misspelt
BATCH = 256
SYNONYMS_FILE = Path(__file__).with_name("synonyms.txt")
WORDNET_FILE = Path(__file__).with_name("wordnet.txt")   # made by dynclevr/language/wordnet.py


def synonyms(path: Path = SYNONYMS_FILE) -> dict[str, list[str]]:
    """A lexicon 'word = known word(s)' -> {word: [known words]}."""
    try:
        text = path.read_text()
    except (OSError, UnicodeDecodeError) as e:
        raise DynclevrError(f"the question parser's lexicon {path} is unreadable ({e}): restore it "
                            f"(`git checkout -- dynclevr/language/{path.name}`) or reinstall dynclevr") from None
    out = {}
    for n, line in enumerate(text.splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        word, sep, known = (x.strip() for x in line.partition("="))
        if not sep or not word or not known or len(tokenize(word)) != 1:
            raise DynclevrError(f"{path}:{n}: expected 'word = known word(s)', got {line!r}")
        out[tokenize(word)[0]] = tokenize(known)
    return out


def operation(token: str) -> str:
    """'filter_attributes[red]' -> 'filter_attributes': a program token without its argument."""
    return token.split("[", 1)[0]


def program_shape(tokens: list[str]) -> str:
    return " ".join(operation(t) for t in tokens)


@dataclass(frozen=True)
class Parse:
    """A question's program (None: unparsed), why it is unparsed, the decoding's probability, the words it read as
    others (the synonym lexicon's and the stems': ('rammed', 'hit')), and the sentence it read where it moved a
    clause."""
    program: list[str] | None
    reason: str = ""
    confidence: float = 0.0
    read_as: tuple[tuple[str, str], ...] = ()
    reordered: str = ""      # the words as read, where a clause of time was put last (`time_clause_last`)


class QuestionParser:
    def __init__(self, model: Ensemble, words: Vocab, programs: Vocab, params: QParserParams, shapes: set[str]):
        self.model = model.eval()
        self.words, self.programs, self.params = words, programs, params
        # Every word the parser knows: the model's, and the object words that the copy path carries past it.
        self.known = set(words.itos[len(SPECIALS):]) | OBJECT_WORDS
        # The operation sequences of the training programs: a decoded program must have one of them (as well as
        # pass `well_formed`), so a decoding that wanders off every template is unparsed, not executed.
        self.shapes = shapes
        # A shorter mention as its fuller mention's object (references.corefer): true of a scene's questions,
        # where each description picks out one object; training reads its random objects without it.
        self.corefer = True
        # Synonyms stand in only for words the parser does not know, and only by words it knows.
        self.synonyms = {w: known for w, known in synonyms().items()
                         if w not in self.known and all(k in self.known for k in known)}
        self.readable = self.known | set(self.synonyms)
        # ... and so does a word of a known word's stem, or else of a lexicon word's
        self.stems = {**_by_stem(self.synonyms), **_by_stem({w: [w] for w in self.known})}
        # Last, WordNet's: an unknown word that shares a main sense with a known one (wordnet.py), read by its stem
        # too ('hastened' as 'hasten', so 'speed'), and said with the ending it came with where a known form has it.
        # Never for or by an object word, which only the copy path carries.
        object_stems = {STEMMER.stemWord(w) for w in OBJECT_WORDS}
        self.wordnet = _by_stem({w: known for w, known in synonyms(WORDNET_FILE).items()
                                 if w not in self.known and w not in self.synonyms and STEMMER.stemWord(w) not in
                                 object_stems and all(k in self.known and k not in OBJECT_WORDS for k in known)})

    @classmethod
    def load(cls, dir: Path = WEIGHTS_DIR / "qparser") -> "QuestionParser":
        dir = Path(dir)
        hint = f"run `dynclevr train qparser --out {dir}`"
        try:
            settings = json.loads((dir / SETTINGS).read_text())
            params = QParserParams.from_dict(settings["params"])
            words, programs = Vocab.load(dir / QUESTION_VOCAB), Vocab.load(dir / PROGRAM_VOCAB)
            model = Ensemble([Seq2Seq(Dims(**settings["model"])) for _ in range(settings["members"])])
            model.load_state_dict(torch.load(dir / MODEL, map_location="cpu", weights_only=True))
            shapes = set(settings["shapes"])
        except FileNotFoundError as e:
            raise ArtifactError(f"question parser weights incomplete ({e.filename} is missing): {hint}") from None
        except ArtifactError:
            raise
        except (ValueError, KeyError, TypeError, RuntimeError, pickle.UnpicklingError, DynclevrError) as e:
            raise ArtifactError(f"question parser weights in {dir} are unreadable ({e}): {hint}") from None
        return cls(model, words, programs, params, shapes)

    def save(self, dir: Path) -> None:
        dir = Path(dir)
        dir.mkdir(parents=True, exist_ok=True)
        # Through a buffer: torch.save names the archive's root folder after the file, here a random temporary
        # name, which would make the same weights differ byte for byte.
        # In half precision: fit() rounds the weights so, and loading casts them back to float32.
        buf = io.BytesIO()
        torch.save({k: v.half() for k, v in self.model.state_dict().items()}, buf)
        with atomic_path(dir / MODEL) as tmp:
            tmp.write_bytes(buf.getvalue())
        self.words.save(dir / QUESTION_VOCAB)
        self.programs.save(dir / PROGRAM_VOCAB)
        write_json_atomic(dir / SETTINGS, {"model": self.model.dims.to_dict(), "members": len(self.model.members),
                                           "params": self.params.to_dict(), "shapes": sorted(self.shapes)})

    def parse(self, text: str) -> list[str] | None:
        return self.parse_batch([text])[0]

    def parse_batch(self, texts: list[str]) -> list[list[str] | None]:
        return [p.program for p in self.analyse_batch(texts)]

    def analyse_batch(self, texts: list[str]) -> list[Parse]:
        # Each question is read as said and, where it opens with a clause of time, with the clause put last
        # (`time_clause_last`); where the two readings differ and the clause names its time, the reading asking at
        # that time wins (`clause_time`), else the one the decoder is surer of, the question as said on a tie.
        readings: list[list[Parse]] = [[] for _ in texts]
        times: list[str | None] = [None] * len(texts)
        own: list[bool] = [False] * len(texts)
        said_words: list[list[str]] = [[] for _ in texts]
        read_words: list[list[str]] = [[] for _ in texts]
        todo = []
        for i, t in enumerate(texts):
            words, why, read_as, said_words[i] = self._words(t)
            read_words[i] = words
            if why:
                readings[i].append(Parse(None, why, read_as=read_as))
                continue
            if time_clause_last(words):
                times[i] = clause_time(words[:words.index(",")])
                main = words[words.index(",") + 1:]
                own[i] = bool(OBJECT_WORDS.intersection(main)) and not {"it", "its"}.intersection(main)
            for order in filter(None, (words, time_clause_last(words))):
                said, named = delexicalise(order)
                moved = " ".join(order) if order is not words else ""
                order, refs = corefer(said, named) if self.corefer else (said, named)
                seen_as = read_as + _second_mentions(said, named, order, refs)
                why = self._objects(order, refs)
                readings[i].append(Parse(None, why, read_as=seen_as, reordered=moved))
                if not why:
                    todo.append((i, len(readings[i]) - 1, order, refs))
        for start in range(0, len(todo), BATCH):
            chunk = todo[start:start + BATCH]
            src, lens = pad_batch([[self.words.stoi.get(w, UNK_ID) for w in order] for _, _, order, _ in chunk])
            with torch.inference_mode(), one_thread():
                decoded = self.model.greedy(src, lens, self.params.max_decode_len)
            for (i, k, order, refs), (ids, p, attended) in zip(chunk, decoded):
                readings[i][k] = replace(self._check(order, refs, ids, p, attended), read_as=readings[i][k].read_as,
                                         reordered=readings[i][k].reordered)
        chosen = [_chosen(parses, time, o) for parses, time, o in zip(readings, times, own)]
        # checked against the words as said: the lexicon reads some as others ('away' as 'off', 'turn' as 'turned');
        # a collision against the words as read, typos fixed ('colide'), where no word it does not know may be an
        # impact's misspelt (the decoder reads a collision in 'collied' from the rest of the question)
        return [replace(c, program=None, reason=why) if c.program and (
            why := form_unmatched(said, c.program) or direction_unasked(said, c.program)
            or time_unasked(said, c.program) or collision_at_start(said, c.program) or clock_unasked(said, c.program)
            or anything_unasked(said, c.program)
            or (not any(map(impact_like, set(read) - self.known)) and impact_unsaid(read, c.program))
            or form_unasked(said, c.program)
            or what_happens(read, c.program) or attribute_unsaid(said, read, c.program)
            or collision_unread(said, c.program) or uncompared(read, c.program)
            or future_unread(said, c.program) or speed_unsaid(read, c.program) or floating_unsaid(read, c.program)
            or comparison_imagined(read, c.program) or comparison_unsaid(read, c.program)
            or imagining_unread(said, c.program) or floating_unread(said, c.program)
            or condition_unsaid(said + [w for a, _ in c.read_as for w in a.split()], c.program)
            or motion_unread(said, c.program)
            or motion_unfiltered(said, c.program) or still_continuing(read, c.program)
            or property_unread(said, c.program) or visibility_unread(said, c.program)
            or acceleration_unread(said, c.program) or acceleration_unsaid(read, c.program)
            or end_unread(said + read, c.program) or size_unread(said, c.program)) else c
            for c, said, read in zip(chosen, said_words, read_words)]

    def _words(self, text) -> tuple[list[str], str, tuple[tuple[str, str], ...], list[str]]:
        """The question's words, unknown ones read as known ones where it can and typos fixed, or a reason it cannot
        be parsed; the words read as others; and the words as the rules left them, before any was read as another."""
        if not isinstance(text, str) or not text.strip():
            return [], "empty question", (), []
        text, coded = code_as_said(text)
        words = tokenize(text)
        if not words:
            return [], "empty question", (), []
        if len(words) > MAX_WORDS:
            return [], f"too long ({len(words)} words, at most {MAX_WORDS})", (), []
        held = {w: stretched(w, self.readable) for w in words if w not in self.readable}
        held = {w: k for w, k in held.items() if k}   # 'sloooow', 'sooo': chat's held letters
        words = [held.get(w, w) for w in words]
        words, starred = corrections_starred(words, self.readable)
        words, archaic = archaic_as_said(words, self.readable)
        words, relayed = quoted_question(words)
        starred += archaic + relayed
        words, printed = worksheet_as_said(words)
        words, shorthand = shorthand_as_said(words)
        words, heard = heard_as_said(words, self.known)
        words, sounded = homophones_as_said(words)
        shorthand = coded + tuple(held.items()) + starred + printed + shorthand + heard + sounded
        words, named = catalogue_names(words)
        words, looked = described_as_named(words)
        words, clause = colour_clause_as_named(words)
        words, glossed = glosses_read(words)
        named += looked + clause + glossed
        words, corrected = corrections_dropped(words)
        words, setting = settings_as_imagined(words)
        words, scenario = scenario_as_asked(words)
        words, told = told_otherwise_as_imagined(words)
        corrected += setting + scenario + told
        words, examined = examination_as_asked(words)
        words, wagered = wagers_read(words)
        words, requested = requested_as_asked(words)
        words, tested = hypothesis_as_asked(words)
        wagered += requested + tested
        corrected += examined + wagered
        words, hedged = hedges_dropped(words)
        words, dislocated = dislocated_as_asked(words)
        corrected += hedged + dislocated
        words, ticket = ticket_fields_read(words)
        words, prompted = prompt_dropped(words)
        prompted = ticket + prompted
        words, kind = type_of_category_as_vehicle(words)
        words, context = context_as_question(words, self.known)
        context = prompted + kind + context
        words, after = afterthoughts_read(words, self.known)
        words, impact = impact_said_first(words)
        after += impact
        words, owned = owners_dropped(words)
        words, labelled = asides_dropped(words)
        words, inserted = inserted_time_last(words)
        words, opened = interjections_dropped(words)
        words, idioms = idioms_as_said(words)
        words, digressed = digressions_dropped(words)
        idioms += digressed
        words, described = description_as_said(words)
        words, typed = type_as_said(words)
        words, afloat = floating_plane_as_vehicle(words)
        words, end = video_end_as_said(words)
        words, framing = framing_dropped(words)
        words, preamble = preamble_dropped(words)
        framing += preamble
        words, attended = attention_as_subject(words)
        words, request = request_as_imperative(words)
        words, stated = imperative_as_stated(words)
        words, negative = negative_question_as_asked(words)
        words, asked = noun_phrase_as_question(words)
        words, aloft = height_as_aloft(words)
        words, heading = heading_as_direction(words)
        words, subject = speed_as_subject(words)
        words, first = first_frames_as_said(words)
        words, more = comparative_as_said(words)
        words, tail = tail_as_question(words)
        words, choices = attributes_offered_dropped(words)
        words, offered = alternatives_as_asked(words)
        offered = choices + offered
        request = (shorthand + named + corrected + context + after + owned + labelled + inserted + opened + idioms
                   + described + typed + afloat + end + framing + attended + request + stated + negative + asked + aloft
                   + heading + subject + first + more + tail + offered)
        if not words:   # 'y/n' alone: an answer's form, and nothing asked
            return [], "the question asks nothing once its asides are read ('" + text.strip() + "')", request, words
        reverse = reversed_as_said(words)
        if reverse:
            return [], reverse, request, words
        said = words
        stand_ins = {w: self._stand_in(w) for w in words if w not in self.known}
        read_as = request + tuple((w, " ".join(k)) for w, k in stand_ins.items() if k != [w])
        words = [k for w in words for k in stand_ins.get(w, [w])]
        words = [w for j, w in enumerate(words) if not (j and w == words[j - 1] and w in OBJECT_WORDS)]
        # Typos are fixed towards object words, which the copy path must carry exactly, and towards a sentence word
        # only in words of TYPO_LETTERS or more ('acelerating', 'stationery'): a short one has too many neighbours
        # (fixing every word made 'black' 'back' and 'pink' 'pick'; 'sitting' would be 'hitting').
        # A slip of the fingers ('slolwy', 'oclor') is fixed first, in a word of any length, towards a word the
        # parser reads (known, or a synonym's, which then stands in; 'tsruck' is 'struck', not 'truck').
        # Two words run together ('fastmoving', 'speedup') are read apart where they split one way only. A question's
        # first word is no vehicle's ('Track the blue bus' was read about a truck).
        fixed = {w: slipped(w, self.readable, SPELLINGS) or run_together(w, self.readable)
                 or (w != words[0] and OBJECT_LEXICON.closest(w)) or (len(w) >= TYPO_LETTERS and self.words.closest(w))
                 or w
                 for w in words if w not in self.known}
        # a colour only before a vehicle's name ('of what hue was it , pray ?': 'pray' was read as a gray vehicle)
        fixed = {w: k for w, k in fixed.items() if k not in COLOR_NAMES or any(
            a == w and b in NAMING | GENERIC | GENERIC_NOUNS for a, b in zip(words, words[1:]))}
        # before 'than' a slip is of a comparative, where it is of one and of other words ('fater': 'after', 'faster')
        fixed.update({w: hits[0] for w, after in zip(words, words[1:]) if w in fixed and after == "than"
                      and len(hits := [h for h in slips(w, self.readable, SPELLINGS) if h in COMPARISONS]) == 1})
        read_as += tuple((w, k) for w, k in fixed.items() if k != w and k not in OBJECT_WORDS)
        words = [k for w in words for part in fixed.get(w, w).split() for k in (self._stand_in(part) if w in fixed
                                                                               else [part])]
        # No program counts (questions/programs.py has no count operation): 'how many' or 'how much' asks what no
        # question here answers, however the rest reads.
        if any(a == "how" and b in ("many", "much") for a, b in zip(words, words[1:])) or \
                said[:1] == ["count"] or any(said[k:k + 3] == ["the", "number", "of"] for k in range(len(said))):
            return [], "the question asks for a count ('how many'), which no question here answers", read_as, said
        lasting = next((w for w in said if w in DURATIONS), None)
        if lasting:
            return [], f"the question asks how long something lasts ('{lasting}'), which no question here answers", \
                read_as, said
        counted = next((" ".join(said[k:k + n]) for k, a in enumerate(said) for n in (2, 3)
                        if (a.isdigit() or a in NUMBERS) and said[k + n - 1:k + n] and said[k + n - 1] in PLURALS
                        and (n == 2 or said[k + 1] in ("other", "more", "different", "separate"))), None)
        if counted:
            return [], f"the question counts ('{counted}'), which no question here does", read_as, said
        higher = next((a for a in said if a in HEIGHT_COMPARISONS and not MOTION_NOUNS.intersection(words)), None)
        if higher:
            return [], (f"the question compares heights ('{higher}'), which no question here asks: ask which is faster "
                        "or slower"), read_as, said
        toward = next((f"{a} {b}" for k, (a, b) in enumerate(zip(said, said[1:])) if (a in TOWARD and b in DETERMINERS
                       or (a, b) == ("away", "from")) and not _at_viewer(said, k + 1 + (b == "from"))), None)
        if toward:
            return [], (f"the question asks a direction relative to another vehicle ('{toward}'), which no question "
                        "here asks: ask which way it moves (left, right, front, back, up or down)"), read_as, said
        often = next((" ".join(r) for k in range(len(said)) for r in REPEATS if said[k:k + len(r)] == r), None) or \
            next((f"{a} times" for a, b in zip(said, said[1:]) if b == "times" and a in NUMBERS), None)
        if often:
            return [], f"the question asks how often ('{often}'), which no question here answers", read_as, said
        offered = next((f"{a} or {c}" for a, b, c in zip(said, said[1:], said[2:])
                        if b == "or" and {a, c} <= COMPARISONS and SPEED_ORDER[a] != SPEED_ORDER[c]), None)
        if offered:
            return [], (f"the question offers '{offered}' to choose from, which no question here answers: ask "
                        "whether one is faster (or slower) than the other"), read_as, said
        measured = speed_measured(said)
        if measured:
            return [], (f"the question measures a speed in numbers ('{measured}'), which no question here asks: ask "
                        "whether the vehicle is static, slow or fast"), read_as, said
        looks = next((f"{a} {b}" for a, b in zip(said, said[1:]) if a in LOOKS and b in OBJECT_WORDS), None)
        if looks:
            return [], (f"the question describes a vehicle by its size or material ('{looks}'), which no vehicle here "
                        "has: they have a colour and a type"), read_as, said
        if said[:1] and said[0] in NORMATIVE:
            return [], (f"the question asks what '{said[0]}' happen, which no question here asks: ask what does, or "
                        "what would have if ..."), read_as, said
        ranked = ranking(said) or properties_joined(said) or times_joined(said) or possibility_asked(said) or \
            onset_asked(said) or \
            several_asked(said) or questions_joined(said) or quantified(said) or premised(said) or chained(said) or \
            ordered(said) or impact_denied(said) or speed_measure(said) or checked_attribute(said) or \
            imagined_otherwise(said, words) or otherwise_compared(said, words)
        if ranked:
            return [], ranked, read_as, said
        alike = speeds_alike(said)
        if alike:
            return [], (f"the question asks whether two speeds are alike ('{alike}'), which no question here asks: ask "
                        "whether one is faster (or slower) than the other"), read_as, said
        if {"why", "wherefore"} & set(said) or CAUSES.intersection(said) or words[:2] == ["how", "come"] or \
                said[:1] == ["explain"] and said[1:2] not in (["whether"], ["if"]) or \
                any(a == "what" and b in CAUSING for a, b in zip(said, said[1:])):
            return [], "the question asks why, which no question here answers", read_as, said
        first = next((f"{a} {b} first" for a, b, c in zip(said, said[1:], said[2:]) if a in ("which", "what") and
                      b in ("came", "comes", "happened", "happens", "occurred", "occurs") and c == "first"), None)
        if first:
            return [], (f"the question asks which event came first ('{first}'), which no question here asks"), \
                read_as, said
        unasked = unknown_property(words, self.known, said)
        if unasked:
            return [], unasked, read_as, said
        # 'how hard does it hit the bus?' was read as whether it does ('hard' fixed to 'had'); a slip ('how fsat')
        # reads as a speed
        manner = next((b for a, b in zip(said, said[1:]) if a == "how" and b not in HOW_ASKED | AUXILIARIES
                       | SPEED_CLASS_WORDS), None) or next(   # 'how high above the ground is it?': a height
            (b for a, b, c in zip(said, said[1:], said[2:] + [""]) if a == "how" and b in ("high", "low", "tall")
             and c not in SPEED_NOUNS), None)
        if manner and (manner in ("high", "low", "tall") or not any(a == "how" and b in SPEED_CLASS_WORDS
                                                                    for a, b in zip(words, words[1:]))):
            return [], (f"the question asks how '{manner}', which no question here asks (they ask how fast a vehicle "
                        "moves, which way, its colour or type, and about its collisions)"), read_as, said
        # 'does the zamboni hit the bus?': an unknown word that heads a noun phrase names an object no catalogue has
        # (the decoder read the question as the bus's alone)
        headed = next((f"{a} {b}" for k, (a, b) in enumerate(zip(words, words[1:])) if a in ("the", "a", "an")
                       and b not in self.known and _unknown_vehicle(words, k)), None)
        if headed:
            return [], (f"the question names '{headed}', which is no vehicle here (they are cars, buses, motorbikes, "
                        "bicycles and aeroplanes)"), read_as, said
        unknown = [w for w in words if w not in self.known]
        if len(unknown) > self.params.max_unknown_words:
            return [], "unknown words: " + ", ".join(f"'{w}'" for w in dict.fromkeys(unknown)), read_as, said
        return words, "", read_as, said

    def _stand_in(self, word: str) -> list[str]:
        """Known words for an unknown one: its synonym, else the known (or lexicon) word of its stem with the same
        ending ('hovered' -> 'hovering' when no 'hovered' is known, 'zooms' -> 'zooming'), else WordNet's word for
        it, said with its ending ('journeying' -> 'travelling'), else itself."""
        if word in self.synonyms:
            return self.synonyms[word]
        stem = STEMMER.stemWord(word)
        forms = self.stems.get(stem)
        if forms:
            return forms[_same_ending(word, forms)]
        forms = self.wordnet.get(stem)
        if not forms:
            return [word]
        known = forms[_same_ending(word, forms)]
        inflected = self.stems.get(STEMMER.stemWord(known[0]), {}) if len(known) == 1 else {}
        return inflected[_same_ending(word, inflected)] if inflected else known

    def _objects(self, words: list[str], refs: list) -> str:
        """Why the question's object words name no object of the catalogue ('' when they all do)."""
        bad = [r for r in refs if not is_description(r)]
        if bad:
            return f"'{' '.join(bad[0]).replace('_', ' ')}' does not describe one object"
        for k, w in enumerate(words):
            if not w.startswith("<obj"):
                continue
            ref = refs[int(w[4:-1]) - 1]
            named = " ".join(ref).replace("_", " ")
            before, after = words[k - 1] if k else "", words[k + 1] if k + 1 < len(words) else ""
            # 'the green tractor': an object the catalogue lacks, where the unknown word is the object's noun. After
            # a sub-type or category the description is whole, and the word after it is the sentence's ('the red
            # sedan ends up hitting ...'), unless 'than' follows it: 'the red sedan bigger than the blue bus'
            # compares what no question asks.
            if after and after not in self.known:
                if words[k + 2:k + 3] == ["than"]:
                    return f"the question compares the {named} by '{after}', which no question here asks about"
                if all(v in COLOR_NAMES for v in ref):
                    return f"the question names the {named} {after}: no vehicle here is called '{after}'"
            # 'the green articulated omnibus': a sub-type's first word, then a noun the catalogue lacks
            j = k + 1
            while j < len(words) and words[j] in OBJECT_WORDS:
                j += 1
            if j > k + 1 and j < len(words) and words[j] not in self.known and all(v in COLOR_NAMES for v in ref):
                said = " ".join(words[k + 1:j + 1])
                return f"the question names the {named} {said}: no vehicle here is called '{said}'"
            if before and before not in self.known:   # 'the pink suv': a colour the dataset does not use
                return f"the question names the {before} {named}: no object here is '{before}'"
            # ... said further off ('the pink little stand-up motorbike' was read as any motorbike)
            shade = next((v for v in reversed(words[max(k - 5, 0):k]) if v in OTHER_COLOURS), None)
            if shade and not DETERMINERS.intersection(words[words.index(shade, max(k - 5, 0)):k]):
                return f"the question names a {shade} {named}: no object here is '{shade}'"
        return ""

    def _check(self, words: list[str], refs: list, ids: list[int] | None, p: float, attended: list[float]) -> Parse:
        if not ids:
            return Parse(None, "no program came out of the decoder", p)
        hinges = [w for w, a in zip(words, attended) if w not in self.words and a > self.params.max_unknown_attention]
        if hinges:
            return Parse(None, "the question turns on " + ", ".join(f"'{w}'" for w in dict.fromkeys(hinges))
                         + ", a word the parser does not know", p)
        abstract = self.programs.decode(ids)
        tokens = concrete_program(abstract, refs)
        if (any(t in SPECIALS for t in abstract) or program_shape(abstract) not in self.shapes or tokens is None
                or not well_formed(tokens)):
            return Parse(None, "the question matches no known question family", p)
        if p < self.params.min_confidence:
            return Parse(None, f"not a question the parser knows how to read (confidence {p:.2f})", p)
        reverse = reversed_reading(words, abstract) or named_attribute(words, abstract) or \
            compared_unsaid(words, abstract, refs)
        if reverse:
            return Parse(None, reverse, p)
        abstract = condition_subject_first(words, abstract)
        tokens = concrete_program(abstract, refs)
        # 'What type of plane is floating?': only aeroplanes float, so a bare 'plane' there is the object's noun
        # ('vehicle'), not an object the program leaves out
        unused = [" ".join(refs[k - 1]).replace("_", " ") for k in range(1, len(refs) + 1)
                  if k not in placeholders(abstract) and not (refs[k - 1] == ("aeroplane",)
                                                              and "filter_floating" in abstract)]
        if unused:
            return Parse(None, f"the question names the {' and the '.join(unused)}, but no question family here "
                               "reads it that way", p)
        return Parse(tokens, "", p)


# where a noun phrase names a vehicle: the subject of a yes/no question ('does the zamboni hit ...'), and what a
# collision's verb names last ('... made contact with the jumbo?')
SUBJECT_VERBS = {"hit", "hits", "collide", "collides", "crash", "crashes", "bump", "bumps", "move", "moves", "moving",
                 "start", "starts", "go", "goes", "going", "accelerate", "accelerates", "accelerating", "float",
                 "floats", "floating", "fast", "slow", "static", "faster", "slower", "and"}
PARTNER_WORDS = {"with", "into", "hit", "hits", "hitting", "struck", "strike", "strikes"}


def _unknown_vehicle(words: list[str], k: int) -> bool:
    """Whether the unknown word after the determiner at k is where the question names a vehicle."""
    after = words[k + 2:k + 3]
    subject = words[k] == "the" and words[k - 1:k] and words[k - 1] in YES_NO_OPENERS and after and \
        after[0] in SUBJECT_VERBS
    partner = words[k - 1:k] and words[k - 1] in PARTNER_WORDS and after in ([], ["?"], ["."], [","]) and \
        asks_impact(words[:k - 1])   # 'crashes into the zamboni', not 'pops into the shot'
    return bool(subject or partner)


# How often a thing happens ('twice', 'more than once', 'three times'): a count, which no program makes
DURATIONS = {"duration", "durations", "lasts", "lasted", "lasting"}   # 'the duration for which it stays parked'
REPEATS = (["twice"], ["thrice"], ["again"], ["more", "than", "once"], ["repeatedly"], ["multiple", "times"],
           ["several", "times"], ["many", "times"], ["at", "most"], ["only", "once"], ["just", "once"],
           *(["exactly", n] for n in ("once", "one", "two", "2", "1")))
NUMBERS = {"two", "three", "four", "five", "2", "3", "4", "5"}
PLURALS = {"vehicles", "objects", "things", "cars", "buses", "bikes", "bicycles", "motorbikes", "planes", "aeroplanes",
           "airplanes", "collisions", "crashes", "others", "ones"}
# a comparison of height ('is the jet higher than the bus?' was read as faster: the grammar's 'at a higher speed');
# other words of place and size are unknown words, refused as such
HEIGHT_COMPARISONS = {"higher", "lower"}
TOWARD = {"toward", "towards", "approaching", "nearing"}   # 'heading towards the bus': a direction no family asks


# Words a speaker opens with that ask nothing ('So, um, does ...', 'Hmm... is it ...', 'Okay, right, what ...'). The
# decoder looks past one such unknown word, not a run of them with their commas. 'right', 'now' and 'like' only with
# a comma after them: 'Right at the start, is ...' opens with a time.
CHAT = {"ngl", "tbh", "idk", "imo", "imho", "fr", "smh", "omg", "lowkey", "srsly", "tbf"}   # a chat's asides
INTERJECTIONS = {"so", "um", "umm", "uh", "uhm", "er", "erm", "hmm", "hm", "well", "ok", "okay", "alright", "oh", "ah",
                 "hey", "anyway", "anyways", "yo", "hi", "hello", "dear", "greetings", "good", "morning", "afternoon",
                 "evening", "sure", "roger", "copy"} | CHAT
COMMA_INTERJECTIONS = {"right", "now", "like"}
# whom a spoken question is addressed to, after a greeting ('hey assistant, does ...', 'ok google is ...', 'yo chat')
VOCATIVES = {"assistant", "chat", "folks", "guys", "everyone", "everybody", "siri", "alexa", "google", "computer",
             "bot", "buddy", "mate", "dude", "bro", "friend", "friends", "team", "y'all", "all", "support", "there",
             "sir", "madam", "colleagues", "staff", "helpdesk"}   # and a letter's ('Dear support,')
# ... and a child's or to a child, said alone before a comma or between commas ('Mummy, how fast ...', 'Can you tell
# me, sweetie, is ...'): 'daddy' was read as 'pops' (into view)
ADDRESSED = {"mummy", "mommy", "mum", "mom", "mama", "momma", "mamma", "daddy", "dad", "papa", "grandma", "granny",
             "gran", "nana", "grandpa", "grandad", "granddad", "gramps", "sweetie", "sweetheart", "honey", "darling",
             "kiddo", "kids", "children", "class", "teacher", "auntie", "aunty", "uncle", "pal", "guys", "folks",
             "everyone", "chat", "bro", "dude", "mate", "buddy", "sis", "fam"}
# A letter's sign-off after its question ('? Many thanks, Nadia', '? Best regards', '? I would appreciate your
# prediction.'): it asks nothing, and its name is an unknown word
SIGN_OFFS = {"thanks", "thank", "many", "best", "regards", "kind", "kindest", "cheers", "sincerely", "warm", "warmest",
             "yours", "ta", "appreciate", "appreciated", "respectfully", "looking", "hope", "have", "i", "all", "much",
             "greetings", "with"}
THANKING = {"thanks", "thank", "cheers", "ta", "many"}
FILLERS = {"um", "umm", "uh", "uhh", "uhm", "er", "erm", "hmm", "already", "literally", "basically", "seriously",
           "honestly"}
INTERJECTION_ENDS = {",", ".", "-", "!", "?", ":", ";"}
# ... and the chat's words it closes with ('does the bus hit anything lol': the decoder turned on the unknown word)
CLOSING_INTERJECTIONS = {"lol", "lmao", "rofl", "haha", "hahaha", "xd", "pls", "plz", "thx", "ty", "tia", "btw",
                         "thanks", "cheers", "tho",
                         # and the particles regional Englishes close with ('they collide or not, lah?', '..., abi?')
                         "lah", "leh", "lor", "abi", "innit", "eh", "mate", "ken", "yeah",
                         # ... and a radio's ('..., affirmative?'; not 'over', which may end a video)
                         "affirmative", "roger"} | CHAT


def _says_nothing(tail: list[str]) -> bool:
    """Whether words after a question say nothing of a vehicle, a time, a motion or a collision, nor ask anything
    ('? couldn't see', '? Many thanks, Nadia'; not '? Give its colour.')."""
    return not asks_impact(tail) and not set(tail) & (
        OBJECT_WORDS | FILM_WORDS | START_WORDS | HEADING_KEPT | MOTION_WORDS | MOTION_DESCRIPTIONS | QUERY_NOUNS
        | {"?", "which", "what", "how"}) and tail[0] not in ("give", "tell", "name", "state", "say")


# A worksheet's or an exam paper's print around its question ('9. ... ? A) static B) slow C) fast [1 mark]', 'True or
# false: the red sedan is moving fast.', 'Circle one: static / slow / fast', 'it is moving ______ (static/slow/fast).')
MARKS = {"mark", "marks", "pt", "pts", "point", "points"}
BOXES = {"☐", "□", "◯", "○", "[", "]"}
ANSWER_WORDS = {"yes", "no", "true", "false", "none", "of", "these", "the", "above", "static", "slow", "fast", "/", ",",
                "or", "."} | set(COLOR_NAMES) | OBJECT_WORDS | {w for name in EVERYDAY_NAMES for w in name.split()}
INSTRUCTIONS = (("answer", "in", "one", "word"), ("answer", "yes", "or", "no"), ("answer", "yes", "/", "no"),
                ("explain", "nothing", ",", "just", "answer"), ("just", "answer"), ("circle", "one"), ("circle",),
                ("tick", "one"), ("tick", "the", "correct", "box"), ("tick",), ("choose", "one"), ("select", "one"),
                ("yes", "or", "no"), ("yes", "/", "no"), ("true", "/", "false"))


def _numbered(words: list[str]) -> int:
    """How many words a worksheet's number takes before its question ('9 .', 'q4 )', '( c )', 'q25 .'); 0 where none."""
    first = words[0] if words else ""
    if (first.isdigit() or re.fullmatch(r"q\d+", first)) and words[1:2] and words[1] in (".", ")", ":"):
        return 2
    if re.fullmatch(r"q\d+", first):
        return 1
    if first == "(" and words[2:3] == [")"] and re.fullmatch(r"[a-z]|[ivx]+|\d+", words[1]):
        return 3
    return 0


def _options_at(words: list[str], k: int) -> bool:
    """Whether a list of lettered options starts at words[k] ('( a ) static ( b ) ...', 'a ) red b ) gray ...')."""
    return words[k:k + 3] == ["(", "a", ")"] or words[k:k + 2] == ["a", ")"]


def worksheet_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question a worksheet prints, without its number, marks, options and instructions; a statement to judge
    true or false asked whether it is true; a blank to fill from choices asked as the choices. With what was read
    so, or the words as they are and ()."""
    out, read = list(words), []
    n = _numbered(out)
    if n:
        read.append((" ".join(out[:n]), "nothing, a number"))
        out = out[n:]
    # an instruction said first ('Answer yes or no: is the jet ...?', 'Yes or no - does ...')
    lead = next((i for i in INSTRUCTIONS if i[0] in ("answer", "explain", "just", "yes") and tuple(out[:len(i)]) == i
                 and out[len(i):len(i) + 1] in ([":"], [","], ["."], ["-"]) and out[len(i) + 1:]), None)
    if lead:
        read.append((" ".join(out[:len(lead) + 1]), "nothing, an instruction"))
        out = out[len(lead) + 1:]
    while len(out) > 3 and (out[-1] in ("]", ")") and out[-2] in MARKS and out[-3].isdigit() and out[-4] in ("[", "(")):
        read.append((" ".join(out[-4:]), "nothing, the marks"))
        out = out[:-4]
    asked = next((k for k, w in enumerate(out) if w == "?"), None)
    if asked is not None:
        rest = out[asked + 1:]
        options = next((k for k in range(len(rest)) if _options_at(rest, k)), None)
        if options is not None and set(rest[options:]) <= ANSWER_WORDS | {"(", ")", "a", "b", "c", "d", "e"}:
            read.append((" ".join(rest[options:]), "nothing, the options"))
            rest = rest[:options]
        while rest:
            said = next((i for i in INSTRUCTIONS if tuple(rest[:len(i)]) == i), None)
            if said is None:
                break
            end = len(said)
            while end < len(rest) and rest[end] in ANSWER_WORDS | BOXES | {":", "!"}:
                end += 1
            read.append((" ".join(rest[:end]), "nothing, an instruction"))
            rest = rest[end:]
        out = out[:asked + 1] + rest
    # a statement to judge ('true or false : the bus is fast .', 'circle one : ... true / false', '☐ true ☐ false')
    judged = out[:4] == ["true", "or", "false", ":"]
    label = next((i for i in INSTRUCTIONS[5:10] if tuple(out[:len(i)]) == i
                  and out[len(i):len(i) + 1] in ([":"], ["."])), None)
    tail = [w for w in out[-5:] if w not in BOXES]
    if judged or label and tail[-3:] in (["true", "/", "false"], ["true", "false"]) or \
            out[-1:] != ["?"] and [w for w in out if w not in BOXES][-2:] == ["true", "false"]:
        body = out[4:] if judged else out[len(label) + 1:] if label else out
        body = [w for w in body if w not in BOXES]
        while body and body[-1] in ("true", "false", "/", ".", "?"):
            body = body[:-1]
        read.append(("true or false", "is it true that"))
        out = ["is", "it", "true", "that", *body, "?"]
    if out[:4] == ["fill", "in", "the", "blank"]:
        read.append(("fill in the blank", "nothing, an instruction"))
        out = out[4 + (out[4:5] == [":"]):]
    blank = next((k for k in range(len(out) - 1) if out[k] == out[k + 1] == "_"), None)
    if blank is not None:
        end = blank
        while end < len(out) and out[end] == "_":
            end += 1
        close = out.index(")", end) if out[end:end + 1] == ["("] and ")" in out[end:] else None
        choices = [w for w in out[end + 1:close] if w not in ("/", ",", "or")] if close else []
        if len(choices) >= 2:
            said = [w for c in choices[:-1] for w in (c, ",")][:-1] + ["or", choices[-1]]
            read.append((" ".join(out[blank:close + 1]), " ".join(said)))
            out = out[:blank] + said + ["?" if w == "." else w for w in out[close + 1:]]
    return out, tuple(read)


# A speech recogniser's words that sound like the ones said ('is the bus faster then the car', 'sitting their',
# 'weather it hits'), where the words around them say which was said
def homophones_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'faster then the' -> 'faster than the', 'sitting their not' -> 'sitting there not', 'weather the bus' ->
    'whether the bus'; with the words read so."""
    out, read = list(words), []
    for k, w in enumerate(out):
        after = out[k + 1] if k + 1 < len(out) else ""
        said = ("than" if w == "then" and k and out[k - 1] in COMPARISONS | {"more", "less"} else
                "there" if w == "their" and after not in NAMING | GENERIC | QUERY_NOUNS and not after.endswith("s")
                else "whether" if w == "weather" and after in DETERMINERS | {"it", "they"} else None)
        if said:
            read.append((w, said))
            out[k] = said
    return out, tuple(read)


def interjections_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question after the interjections it opens with ('so , um , does ...' -> 'does ...'), where a question
    follows them. With the interjections read as nothing, or the words as they are and ()."""
    addressed = [j for j in range(1, len(words) - 1) if words[j] in ADDRESSED and words[j - 1] == ","
                 and words[j + 1] in (",", "?", "!", ".")]
    addressees = " ".join(words[j] for j in addressed)
    if addressed:   # between commas, or at the end: 'is it fast , honey ?'
        words = [w for j, w in enumerate(words) if j not in addressed and j + 1 not in addressed]
    k = 0
    # 'like' after another interjection needs no comma ('so like does ...'), nor whom the question is addressed to
    while k < len(words) and (words[k] in INTERJECTIONS or words[k] in COMMA_INTERJECTIONS | ADDRESSED
                              and words[k + 1:k + 2] and words[k + 1] in INTERJECTION_ENDS
                              or k and words[k - 1] in INTERJECTIONS | VOCATIVES and words[k] in VOCATIVES | {"like"}):
        k += 1
        while k < len(words) and words[k] in INTERJECTION_ENDS:
            k += 1
    end = len(words)
    while end > k and (words[end - 1] in CLOSING_INTERJECTIONS or words[end - 1] in INTERJECTION_ENDS
                       and end - 1 > k and words[end - 2] in CLOSING_INTERJECTIONS):
        end -= 1
    # ... and a letter's sign-off or a short remark after the question ('? couldn't see'), where it says nothing of
    # a vehicle, a time, a motion or a collision
    asked = max((j for j in range(k, end) if words[j] == "?"), default=None)
    tail = words[asked + 1:end] if asked is not None else []
    if tail and (tail[0] in SIGN_OFFS or len(tail) <= 4 or len(tail) <= 6 and tail[-1] == ".") and _says_nothing(tail):
        end = asked + 1
    # ... or after a request closed by a full stop ('I should like to know whether ... . Thank you kindly.')
    thanked = max((j for j in range(k, end - 1) if words[j] == "." and words[j + 1] in THANKING), default=None)
    if asked is None and thanked is not None and _says_nothing(words[thanked + 1:end]):
        end = thanked + 1
    # without a question mark, a chat's remark after the question ('..., i missed it', '... ngl cant tell')
    remark = next((j for j in range(k + 3, end) if asked is None and (words[j] in CHAT or words[j - 1] == ","
                                                                        and words[j] == "i"
                                                                        or tuple(words[j:j + 4]) in VIEWER_DOUBTS
                                                                        or tuple(words[j:j + 3]) in VIEWER_DOUBTS)
                   and len(words[j:end]) <= 6 and _says_nothing(words[j:end])), None)
    if remark:
        end = remark - (words[remark - 1] == ",")
    closing = ((" ".join(words[end:]), "nothing, an interjection"),) if words[end:] else ()
    # a speaker's fillers within the question ('the um green sedan'), with the commas around them
    within = [j for j in range(k, end) if words[j] in FILLERS]
    if within:
        fillers = set(within) | {j + 1 for j in within if words[j + 1:j + 2] == [","]} | {
            j - 1 for j in within if words[j - 1] == "," and words[j + 1:j + 2] in ([","], ["?"], ["."], [])}
        closing = ((" ".join(words[j] for j in within), "nothing, a filler"), *closing)
        kept = [w for j, w in enumerate(words[:end]) if j not in fillers]
        words, end = kept + words[end:], len(kept)
    closing = ((addressees, "nothing, whom it is asked"),) * bool(addressed) + closing
    if k == 0 or k == len(words) or words[k] not in QUESTION_OPENERS | TIME_OPENERS | CONDITION_WORDS | {"tell"} and \
            not ADDRESSED & set(words[:k]):
        return words[:end], closing
    return words[k:end], ((" ".join(words[:k]), "nothing, an interjection"), *closing)


# A digression between commas, or before the first, that says nothing the question could need ('So, Jen, and this
# is the part I love, was the red sedan ...', 'at what speed, I wonder, was it moving?'): no vehicle, motion,
# collision, time, place, condition, negation or asking in it.
def _says_something(span: list[str]) -> bool:
    return bool(set(span) & SAYING) or asks_impact(span) or any(
        w.startswith(("accelerat", "speed", "float", "hover")) or w.isdigit() for w in span)


def digressions_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'so , jen , and this is the part i love , was the red sedan moving ?' -> 'was the red sedan moving ?'. With
    the digressions read as nothing, or the words as they are and ()."""
    commas = [k for k, w in enumerate(words) if w == ","]
    if not commas:
        return words, ()
    drop, read, start = set(), [], 0
    for c in commas:
        span = words[start:c]
        if span and not _says_something(span):
            drop |= set(range(start, c + 1))
            read.append(" ".join(span))
        start = c + 1
    # ... and after the last comma, before the question mark ('..., my dear fellow?'), where it asks nothing itself
    # (', is it crawlig?' is the question, its slip not yet read)
    end = len(words) - (words[-1:] in (["?"], ["."]))
    if words[start:end] and end - start <= 4 and not _says_something(words[start:end]) and \
            not (YES_NO_OPENERS | QUESTION_OPENERS | {"it", "they"}).intersection(words[start:end]):
        drop |= set(range(start - 1, end))
        read.append(" ".join(words[start:end]))
    rest = [w for k, w in enumerate(words) if k not in drop]
    if not read or not _says_something(rest):
        return words, ()
    return rest, tuple((r, "nothing, a digression") for r in read)


# Context said before the question ('The yellow school bus is near the left edge. I couldn't tell whether it was
# moving. How fast is it going right at the start?'). The question is the last sentence ending in '?'; the sentences
# before it are read for what the question refers back to, and dropped: the vehicles its 'it', 'they', 'the former'
# or shorter names mean, a counterfactual's condition ('Suppose the bus had been parked. ... Would it hit the car?'),
# the moment its 'then' means ('The SUV slams into the jet. How fast was the SUV going then?') and the start it says
# nothing of ('Beginning of the video. Is the first one slower than the second?').
SENTENCE_ENDS = {".", "!", "?"}
CONTEXT_OPENERS = {"so", "ok", "okay", "and", "now", "but", "well", "alright", "right", "also", ",", "-", ":"}
CONDITIONS_SAID = {("what", "if"): ("if",), ("let", "'", "s", "say"): ("suppose",), ("lets", "say"): ("suppose",),
                   ("say",): ("suppose",), ("hypothetically", ":"): ("suppose",), ("hypothetically", ","): ("suppose",),
                   ("hypothetically",): ("suppose",), ("consider",): ("suppose",), ("think",): ("suppose",),
                   **{(w,): (w,) for w in ("suppose", "supposing", "imagine", "assume", "assuming", "pretend", "if",
                                           "picture", "envision", "envisage", "visualise", "visualize")}}
# a sentence of context that imagines something otherwise, but not as a condition read here: the question is left
# whole ('if' only where a clause of it imagines: 'I can't tell if it's moving' asks whether); said alone, it makes
# the next sentence the condition ('ok weird what-if. the biplane is accelerating from the beginning instead.')
IMAGINED_SAID = {"suppose", "supposing", "imagine", "assume", "assuming", "pretend", "hypothetically",
                 "hypothetical", "instead", "otherwise", "wish", "scenario", "counterfactual", "counterfactually",
                 "intervention", "hypothesis", "alternate", "alternative"}
WHETHER = {"tell", "know", "see", "sure", "wonder", "wondering", "check", "ask", "asking", "unsure", "clear", "say"}
# openers that may state a fact as well as imagine one, and the words that say they imagine
STATING = {"assume", "assuming", "consider", "think"}
# a condition given a label ('Counterfactual: the pickup moves slowly from the first frame.', 'Intervention: ...')
CONDITION_LABELS = {"counterfactual", "intervention", "hypothetical", "hypothesis", "scenario", "what-if", "if",
                    "alternative", "alternate", "change", "suppose", "assume", "imagine", "timeline", "universe",
                    "whatif", "twist", "cf", "variable", "treatment", "manipulation", "manipulate"}
IMAGINING_MARKS = {"had", "were", "instead", "would", "hypothetically", "otherwise", "pretend", "version", "where",
                   "scenario", "world", "case"}
CHANGE_ENDS = (("instead", "of"), ("rather", "than"), ("instead",))   # '... instead of on the ground': the change alone
# A state said without its verb after the condition's vehicle ('Picture the airliner up in the air from the start')
STATES_SAID = {"up", "in", "at", "floating", "hovering", "flying", "parked", "static", "stationary", "still", "moving",
               "going", "travelling", "traveling", "driving", "riding", "rolling", "speeding", "accelerating",
               "standing", "sitting", "fast", "slow", "already", "stopped", "motionless", "airborne", "aloft"}
PLURAL_PRONOUNS = (*((w, "two", "of", "them") for w in ("the", "all")), ("both", "of", "them"),
                   ("the", "pair", "of", "them"), *((w, "two", *v) for w in ("the", "these", "those")
                                                   for v in (("vehicles",), ("of", "them"), ())),
                   ("the", "pair"), ("they",), ("both", "vehicles"), ("both",))
# a vehicle of the context by its place in it ('the first one', 'the latter') or as the one not named ('the other');
# 'the first' and 'the second' alone where no noun follows ('the second frame')
PLACES_SAID = {**{("the", w, *n): 0 for w in ("first", "former") for n in (("one",), ("vehicle",), ())},
               **{("the", w, *n): 1 for w in ("second", "latter") for n in (("one",), ("vehicle",), ())},
               **{("the", "other", *n): None for n in (("one",), ("vehicle",), ())}}
AFTER_PLACE = {"?", ",", ".", "at", "when", "in", "during", "as", "and", "or", "than", "once", "while", "right", "just",
               "is", "was", "does", "did", "going", "moving"}
# 'it' that points forward, not back ('is it true that ...', 'is it possible ...')
IT_FORWARD = {"true", "possible", "likely", "the", "that", "so", "right", "correct", "fair", "safe", "clear", "all"}
# A vehicle the context describes without naming ('Something hits the cyan jet. What colour is it?',
# 'The SUV hits a vehicle. What kind of vehicle is that?'): the question is left whole, which reads it so
UNNAMED = {"something", "someone", "somebody"}
GENERIC = {"vehicle", "vehicles", "thing", "things", "object", "objects", "toy", "toys", "one", "other"}
NAMELESS = {"some", "a", "an", "another", "one"}
THEN_SAID = (("at", "that", "moment"), ("at", "that", "point"), ("at", "that", "instant"), ("at", "that", "time"),
             ("in", "that", "moment"), ("at", "that", "stage"), ("right", "then"), ("just", "then"),
             *((p, d, m) for p in ("at", "in", "during") for d in ("this", "that", "the") if (p, d) != ("at", "the")
               for m in ("moment", "instant", "point", "event", "collision", "crash", "impact")),
             *((w, d, h) for w in ("when", "as") for d in ("that", "this", "it") for h in ("happens", "happened")),
             ("then",))
# a collision said without its partner ('At the moment of impact, how fast is the bike?'), the context's
IMPACT_NOUNS = ("impact", "crash", "collision", "contact", "hit", "smash")
IMPACT_MOMENTS = sorted({(p, "the", m, "of", *the, n) for p in ("at", "in") for m in ("moment", "instant", "time")
                         for the in ((), ("the",), ("that",), ("this",)) for n in IMPACT_NOUNS}
                        | {(p, n) for p in ("at", "on", "upon") for n in ("impact", "contact")}
                        | {(p, "the", n) for p in ("at", "during", "in") for n in IMPACT_NOUNS}, key=len, reverse=True)
# a question's own time, besides the start and coming into view
OWN_TIMES = {"after", "end", "ends", "ended", "will", "future"}


def _sentence_spans(words: list[str]) -> list[tuple[int, int]]:
    """(first, past-last) word of each sentence; a run of ends ('?!') closes one; an ellipsis after a statement
    closes it ('the bike seems to dodge everything... does it'), after a word or two ('well... is it') or a word
    that cannot end one ('which...') none; a point
    after a letter ('i.e.') or between digits closes none; a semicolon before a question closes one ('a plane is
    hanging in the air ; which colour is ...'), except after a condition ('suppose it had ... ; would it ...')."""
    spans, start = [], 0
    for k, w in enumerate(words):
        before, after = words[k - 1] if k else "", words[k + 1] if k + 1 < len(words) else ""
        said = [v for v in words[start:k] if v != "."]
        if w == ";" and (after in QUESTION_OPENERS or after in ASKING) and not \
                (IMAGINED_SAID | {"if", "had"}) & set(words[start:k]):   # not a condition's ('suppose ... ; would')
            pass
        elif w not in SENTENCE_ENDS or after in SENTENCE_ENDS or w == "." and (
                before == "." and (len(said) < 3 or said[-1] in STATEMENT_ENDS_NOT)   # 'crash , which... is it'
                or len(before) == 1 and before.isalpha()
                or before.isdigit() and after[:1].isdigit()):
            continue
        spans.append((start, k + 1))
        start = k + 1
    return spans + [(start, len(words))] * (start < len(words))


def _at(words: list[str], phrases) -> tuple[int, tuple] | None:
    return next(((k, p) for k in range(len(words)) for p in phrases if tuple(words[k:k + len(p)]) == p), None)


def _opener_said(sentence: list[str]) -> tuple[int, tuple, tuple] | None:
    """Where a sentence opens on a condition's opener (after a label: 'Game designer: suppose ...', or as a label:
    'Counterfactual: the pickup ...'): its place, its words and the opener it is read as; None where it does not."""
    colon = sentence.index(":") if ":" in sentence else None
    if colon and sentence[colon - 1] in CONDITION_LABELS and (mentions(sentence[colon:]) or "it" in sentence):
        return colon + 1, (), ("suppose",)
    for k in (0, colon + 1 if colon is not None else 0):
        while k < len(sentence) and sentence[k] in CONTEXT_OPENERS:
            k += 1
        said = next(((p, o) for p, o in CONDITIONS_SAID.items() if tuple(sentence[k:k + len(p)]) == p), None)
        if said and (mentions(sentence[k:]) or sentence[k + len(said[0]):k + len(said[0]) + 1] in (["it"], ["they"])
                     or sentence[k + len(said[0]):k + len(said[0]) + 1] in (["instead"], ["that"])):
            return k, *said
    return None


def _stated(sentence: list[str]) -> bool:
    """Whether a sentence opens on an opener that may state a fact as well as imagine ('Assume the sedan makes
    contact with the jet near the middle.'), with nothing that imagines: a sentence of context, not a condition."""
    said = _opener_said(sentence)
    return bool(said) and said[1][:1] and said[1][0] in STATING and not (IMAGINING_MARKS & set(sentence) or any(
        w == "from" and START_WORDS & set(sentence[k + 1:k + 3]) for k, w in enumerate(sentence))
        or said[1][0] in ("assume", "assuming") and START_WORDS & set(sentence) and SPEED_CLASS_WORDS & set(sentence))
    # ('assume the cruiser starts slow')



def _condition_said(sentence: list[str], after_imagining: bool = False) -> list[str] | None:
    """A sentence of context that states a counterfactual's condition (after a label: 'Game designer: suppose ...';
    with its vehicle as 'it'; as a statement after a sentence that imagines), as the clause 'if ...' or 'suppose ...'
    that the parser reads before a question; None for any other sentence."""
    opened = _opener_said(sentence)
    if opened is None or _stated(sentence):
        if not (after_imagining and mentions(sentence)):
            return None
        opened = (0, (), ("suppose",))
    k, said, reading = opened
    rest = sentence[k + len(said):-1]
    while rest[:1] in (["instead"], ["that"], [","]):   # 'Assume instead that the fighter had been ...'
        rest = rest[1:]
    out = [*reading, *rest]
    subject = mentions(out)[0][1] if mentions(out) else out.index("it") + 1 if "it" in out else \
        out.index("they") + 1 if "they" in out else None
    if subject is None:
        return None
    subject += out[subject:subject + 1] == ["one"]   # 'the green one'
    if out[subject:subject + 1] and out[subject] in STATES_SAID:
        out[subject:subject] = ["had", "been"]
    elif out[subject:subject + 1] and (done := PARTICIPLES.get(out[subject])):
        out[subject:subject + 1] = ["had", done]   # 'the tandem starts off slowly': 'had started off slowly'
    elif out[subject:subject + 1] == ["never"] and out[subject + 1:subject + 2] and out[subject + 1] in UNMOVED:
        out[subject:subject + 2] = ["had", "stayed", "still"]   # 'imagine the green one never budges'
    zero = _at(out, (("t", "=", "0"), ("t", "0"), ("time", "zero"), ("t", "=", "zero")))   # 'from t=0'
    if zero:
        out[zero[0]:zero[0] + len(zero[1])] = ["the", "start"]
    change_end = _at(out[subject:], CHANGE_ENDS)
    return out[:subject + change_end[0]] + ["."] if change_end else out + ["."]


# A condition's verb as the grammar says it imagined ('if it had started'); the decoder read 'suppose the bike starts
# slowly' as a question about now
PARTICIPLES = {"is": "been", "was": "been", "goes": "gone", "went": "gone", "comes": "come", "came": "come",
               "begins": "begun", "began": "begun", "keeps": "kept", "kept": "kept", "drives": "driven",
               "drove": "driven", "rides": "ridden", "rode": "ridden", "flies": "flown", "flew": "flown",
               "sits": "sat", "sat": "sat", "stands": "stood", "stood": "stood", "runs": "run", "ran": "run",
               "speeds": "sped", "sped": "sped", "stays": "stayed", "stayed": "stayed"}
UNMOVED = {"budges", "budged", "budge", "moves", "moved", "move"}   # after 'never'
REGULAR_VERBS = ("start", "move", "travel", "float", "hover", "accelerate", "remain", "roll", "cruise", "crawl", "zoom",
                 "race", "idle", "wait", "rest", "drift", "coast")
PARTICIPLES.update({form: v + ("d" if v.endswith("e") else "ed") for v in REGULAR_VERBS
                    for form in (v + "s", v + ("d" if v.endswith("e") else "ed"))})


IMAGINED_BACK = tuple((p, d, n) for p in ("in", "within") for d in ("that", "this", "such", "the") for n in (
    "world", "case", "scenario", "version", "timeline", "universe", "situation", "alternate", "telling", "retelling",
    "tale", "story", "ruling", "reality"))


def _imagining_only(sentence: list[str]) -> bool:
    """Whether a sentence says only that what follows is imagined ('What if?', 'Hypothetically...'): no question of
    its own, however it ends."""
    return set(sentence) - {"?", "!", ".", ",", ":", "-"} <= IMAGINED_SAID | CONDITION_LABELS | {"what", "so", "ok"}


def _unnamed(sentence: list[str]) -> bool:
    """Whether a sentence speaks of a vehicle without naming it ('something', 'a vehicle', 'one of them')."""
    return bool(UNNAMED & set(sentence)) or any(a in NAMELESS and b in GENERIC | {"of"}
                                                for a, b in zip(sentence, sentence[1:]))


# 'the purple dirt bike ... the bike', 'the fighter ... the jet'
SAID_OF = {"bicycle": "motorbike", "jet": "aeroplane"}


def _fits(short, full) -> bool:
    """Whether a shorter mention can be a fuller one's vehicle; a 'bike' may be a motorbike and a 'jet' any
    aeroplane."""
    return generalises(short, full) or generalises(tuple(SAID_OF.get(v, v) for v in short), full)


APPOSED = {",", "-", "a", "an", "(", "i", "think", "like", "probably", "maybe", "or", "rather"}


def _appositions(sentence: list[str]) -> list[tuple[int, int, tuple]]:
    """The sentence's mentions, a vehicle named again in apposition as one ('a gray plane - a jet, I think -', 'this
    purple plane, a fighter jet,'): the colour of the first, the sub-type of either."""
    out = []
    for a, b, ref in mentions(sentence):
        if out and set(sentence[out[-1][1]:a]) <= APPOSED and sentence[out[-1][1]:a] and \
                not any(v in COLOR_NAMES for v in ref) and _compatible(out[-1][2], ref):
            first = out[-1][2]
            kind = [v for v in ref if v in SUBTYPES] or [v for v in first if v not in COLOR_NAMES]
            out[-1] = (out[-1][0], b, tuple([v for v in first if v in COLOR_NAMES] + kind))
        else:
            out.append((a, b, ref))
    return out


def _named(ref, asked: list[tuple]) -> bool:
    return any(_fits(r, ref) or _fits(ref, r) for _, _, r in asked)


def _said(ref) -> list[str]:
    return ["the", *(w for v in ref for w in v.split("_"))]


def _moment(context: list[list[str]], fullest: list, of=None) -> list[str] | None:
    """The moment a question's 'then' means, from the latest sentence of context that names one: two vehicles'
    collision (one of them `of`, where given), or a vehicle coming into view; None where none does."""
    for sentence in reversed(context):
        refs = list(dict.fromkeys(next((f for f in fullest if _fits(r, f)), r) for _, _, r in mentions(sentence)))
        if asks_impact(sentence) and len(refs) >= 2 and (of is None or of in refs[:2]):
            return ["when", *_said(refs[0]), "and", *_said(refs[1]), "collide"]
        if of is None and COMES_IN_WORDS & set(sentence) and refs:
            return ["when", *_said(refs[0]), "comes", "into", "view"]
    return None


# Speech transcribed without stops ('the blue cruiser is still moving at the end will it hit anything after the video
# is over'): the question starts where an auxiliary or a question word that opens one follows a word that may end a
# statement, with a statement before it; said so, the context is read as above.
# ('purple dirtbike fast from start would it collide ...' is a note's condition, not a statement: no 'would')
RUN_ON_ASKS = {**dict.fromkeys(("is", "was", "are", "were", "does", "did", "do", "will", "can", "could", "has",
                                "have"), {"the", "it", "they", "its", "this", "that", "there", "any", "either",
                                          "both", "a", "an", "these", "those", *COLOR_NAMES}),
               **dict.fromkeys(("how", "what", "which"), {"fast", "quickly", "slowly", "direction", "way", "color",
                                                          "colour", "type", "kind", "sort", "speed", "vehicle"}),
               "if": {"the", "it", "they", *COLOR_NAMES},
               "where": {"is", "was", "are", "were", "does", "did", "do", "will"}}
STATEMENT_ENDS_NOT = {"the", "a", "an", "that", "this", "which", "who", "what", "and", "or", "but", "if", "when", "to",
                      "of", "than", "as", "with", "into", "at", "in", "on", "by", "from", "is", "was", "are", "were",
                      "does", "did", "do", "will", "would", "not", ",", "it", "its", "where", "how", "why", "who"}


def _run_on_question(words: list[str]) -> int | None:
    """Where the question of a transcript without stops starts, after a statement of 3 words or more; None where
    none does, or what comes before it is a clause of time or a question ('when the bike enters the frame how
    fast ...' is one question)."""
    if any(not w.isalnum() and w != "'" for w in words[:-1]):   # said with stops or commas: written, not spoken
        return None
    opener = next((w for w in words if w not in INTERJECTIONS | FILLERS | {"like", ","}), "")
    if opener in TIME_OPENERS | CONDITION_OPENERS | set(RUN_ON_ASKS) | {"after", "before", "until", "why", "who"}:
        return None
    return next((k for k in range(3, len(words) - 2) if words[k] in RUN_ON_ASKS and words[k + 1] in RUN_ON_ASKS[
        words[k]] and words[k - 1] not in STATEMENT_ENDS_NOT and (
            words[k] != "if" or {"would", "will"} & set(words[k:]))), None)


def _run_on_clause(words: list[str], k: int) -> int:
    """Where a clause of time said just before a run-on question starts ('... smash into each other near the bottom
    when they collide is the pickup faster'), as its part; k where none is."""
    return next((j for j in range(k - 1, max(k - 9, 2), -1) if words[j] in ("when", "once", "whenever", "while") or
                 words[j:j + 3] in ([at, d, m] for at in ("at", "in") for d in ("the", "that")
                                    for m in ("moment", "instant", "time", "point")) or
                 words[j] == "as" and words[j + 1:j + 2] in (["soon"], ["they"], ["it"], ["the"])), k)


OPENING_SAID = {"there", "theres", "'", "s", "is", "are", "like", "so", "ok", "okay", "um", "uh", "i", "see", "saw",
                "look", "in", "this", "video", "clip", "one", ","}


def _opening(sentence: list[str]) -> list[str]:
    """A sentence from the first words that say something ('theres like a tractor ...' -> 'a tractor ...')."""
    return sentence[next((k for k, w in enumerate(sentence) if w not in OPENING_SAID), len(sentence)):]


AMOUNTS = {"lot", "bit", "couple", "few", "bunch", "little"}


def _thing_first(sentence: list[str], known) -> bool:
    """Whether a sentence opens on a thing the parser does not know ('theres like a tractor near the bus'), where
    what 'it' means is not read."""
    said = _opening(sentence)
    return len(said) > 2 and said[0] in DETERMINERS and said[1].isalpha() and \
        said[1] not in known | AMOUNTS | OBJECT_WORDS | NOUNS_SAID \
        and said[2] != "of"   # 'the top of the frame' is a place


ECHO_CLOSERS = {"tho", "though", "really", "actually", "then", "now", "?", "!"} | CHAT


def _echoed(question: list[str], said: list[str]) -> list[str] | None:
    """A question that only echoes the statement before it, asked of it ('the cyan chopper and the gray wagon crash
    after the clip is over . will they tho ?' -> 'will the cyan chopper and the gray wagon crash after the clip is
    over ?', 'the red car is fast . is it ?'); None where it does not."""
    be, others = COPULAS - {"s", "'"}, {"do", "does", "did", "will", "would", "can", "could"}
    asked = [w for w in question if w not in ECHO_CLOSERS]
    if len(asked) != 2 or asked[0] not in be | others or asked[1] not in ("it", "they", "he", "she"):
        return None
    said = said[said.index(":") + 1:] if ":" in said else said
    said = said[:-1] if said[-1:] and said[-1] in SENTENCE_ENDS else said
    subject = coordinated_subject(said)
    if subject is None or (asked[1] == "they") != (len(subject[1]) == 2) or not said[subject[0]:]:
        return None
    rest = said[subject[0]:]
    if (asked[0] in be) != (rest[0] in be) or rest[0] in others:
        return None
    return [asked[0], *said[:subject[0]], *rest[asked[0] in be:], "?"]


CLAIMING = {"insists", "insisted", "says", "said", "thinks", "thought", "claims", "claimed", "reckons", "swears",
            "bets", "believes", "told", "tells", "argues", "guessed", "guesses"}
JUDGING = {"right", "correct", "true", "wrong"}
WONDERING = {"asked", "asks", "wonders", "wondered", "wondering", "know", "knows", "asking"}
IDEA_ASKS = (["any", "idea"], ["any", "ideas"], ["do", "you", "know"], ["can", "you", "tell"], ["thoughts"],
             ["any", "clue"], ["anyone"], ["help"])


def impact_said_first(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'in the crash , was the brown suv slower than the cyan truck ?' -> 'when the brown suv and the cyan truck
    collide , was ...': a collision said first without its pair, where the question names the two vehicles; with
    the words read so, or the words as they are and ()."""
    said = _at(words[:6], IMPACT_MOMENTS)
    if not said or said[0] != 0:
        return words, ()
    rest = words[len(said[1]):]
    rest = rest[(rest[:1] == [","]):]
    pair = list(dict.fromkeys(r for _, _, r in mentions(rest)))
    if len(pair) != 2 or not rest or rest[0] not in QUESTION_OPENERS:
        return words, ()
    clause = ["when", *_said(pair[0]), "and", *_said(pair[1]), "collide", ","]
    return clause + rest, ((" ".join(said[1]), " ".join(clause[:-1])),)


def _judged(question: list[str], said: list[str]) -> list[str] | None:
    """Someone's claim asked whether it is right ('My granddaughter insists the yellow double-decker is faster ... .
    Is she right?' -> 'is it true that the yellow double bus is faster ... ?'); None where it is not."""
    asked = [w for w in question if w not in ECHO_CLOSERS]
    if not (asked and asked[-1] in JUDGING and len(asked) <= 3):
        return None
    claim = next((k for k, w in enumerate(said) if w in CLAIMING), None)
    if claim is None:
        return None
    clause = said[claim + 1:]
    clause = clause[(clause[:1] == ["me"]):]
    clause = clause[(clause[:1] == ["that"]):]
    clause = clause[:-1] if clause[-1:] and clause[-1] in SENTENCE_ENDS else clause
    return ["is", "it", "true", "that", *clause, "?"] if mentions(clause) else None


def _wondered(question: list[str], said: list[str]) -> list[str] | None:
    """A question someone wondered, then asked of the reader ('My kid asked what color the thing floating ... is. Any
    idea?' -> 'what color the thing floating ... is ?'); None where it is not."""
    asked = [w for w in question if w not in ECHO_CLOSERS]
    if asked not in IDEA_ASKS:
        return None
    wh = next((k + 1 for k, w in enumerate(said[:-1]) if w in WONDERING and said[k + 1] in
               ("what", "which", "how", "whether", "if")), None)
    if wh is None:
        return None
    clause = said[wh:-1] if said[-1] in SENTENCE_ENDS else said[wh:]
    return (["tell", "me"] if clause[0] in ("whether", "if") else []) + clause + ["?"]


def coordinated_subject(said: list[str]) -> tuple[int, list] | None:
    """Where a statement's subject of one vehicle or two joined by 'and' ends, and the vehicles; None where it does
    not open on one."""
    runs = mentions(said)
    if not runs or said[:runs[0][0]] not in ([], ["the"], ["a"], ["an"]):
        return None
    end, named = runs[0][1], [runs[0][2]]
    if len(runs) > 1 and said[end:runs[1][0]] in (["and"], ["and", "the"], ["and", "a"]):
        end, named = runs[1][1], named + [runs[1][2]]
    return end, named


DISLOCATED_ASKS = {"are", "were", "will", "would", "did", "do", "does", "is", "was", "have", "had"}


# A speaker's doubt around the question: said first ('Not sure, but ...', 'I could be off here, but ...', 'Since the
# clip cuts off, I can't be sure: ...'), or after it (', or am I misremembering?', '; is that right?')
# a viewer who cannot make it out ('ngl cant tell, ...', '... cant see it rly')
VIEWER_DOUBTS = tuple((*i, can, "not", see) for i in ((), ("i",)) for can in ("can", "could")
                      for see in ("tell", "see")) + (("hard", "to", "tell"),)
HEDGE_STARTS = (("not", "sure"), ("not", "certain"), ("unless",), ("maybe",), ("correct", "me"), ("no", "idea"),
                ("hard", "to", "say"), *VIEWER_DOUBTS)
HEDGE_ENDS = ((",", "but"), (",", "so"), (":",), (";",), ("-",), (",",))
DOUBTING = {"am", "did", "do", "have", "was", "is", "could"}
# ... and what a doubt said first never says: a question's words, a time, a motion, a vehicle unnamed
ASKED_IN_DOUBT = {"if", "suppose", "had", "when", "?", "which", "what", "how", "where", "who", "whether", "tell",
                  "give", "name", "direction", "speed", "colour", "color", "type", "kind", "hover", "hovers",
                  "hovered", "float", "floats", "floated"}


def hedges_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'not sure , but did the sedan hit the bus ?' and 'sorry if this is a silly question , but does ...' -> 'did the
    sedan hit the bus ?', 'does ...'; 'was it slower , or am i misremembering ?' -> 'was it slower ?'; '...; is that
    right ?' -> '..., is that right ?' (a tag, read as one by `negative_question_as_asked`). A doubt said first names
    no vehicle. With the words read so, or the words as they are and ()."""
    out, read = list(words), []
    ends = [(k, len(e)) for k in range(1, min(len(out), 16)) for e in HEDGE_ENDS if tuple(out[k:k + len(e)]) == e]
    opened = lambda said: said[next((j for j, w in enumerate(said) if w not in INTERJECTIONS | {","}), len(said)):]
    first_person = lambda said: bool({"i", "me", "my"} & set(said)) or any(opened(said)[:len(h)] == list(h)
                                                                          for h in HEDGE_STARTS)
    undoubted = NAMING | ASKED_IN_DOUBT | UNNAMED | START_WORDS | MOTION_WORDS | AFLOAT_SAID | END_WORDS
    # an apology before the question needs no 'I' ('sorry if this is a silly question , but does ...')
    unapologetic = NAMING | GENERIC_NOUNS | START_WORDS | MOTION_WORDS | MOTION_DESCRIPTIONS | FLOATING_WORDS
    apology = lambda k, n: n == 2 and out[k + 1] == "but" and out[k + 2:k + 3] and out[k + 2] in QUESTION_OPENERS
    doubted = lambda said: next((opened(said)[len(v):] for v in VIEWER_DOUBTS if opened(said)[:len(v)] == list(v)),
                                said)
    cut = max((k + n for k, n in ends if (first_person(out[:k]) and not undoubted & set(doubted(out[:k]))
                                          or apology(k, n) and not unapologetic & set(out[:k]))
               and not asks_impact(out[:k]) and out[k + n:]), default=None)
    if cut is not None:
        read.append((" ".join(out[:cut]), "nothing, a doubt"))
        out = out[cut:]
    if out[-1:] == ["?"]:
        doubt = next((k for k in range(1, len(out) - 3) if out[k:k + 2] == [",", "or"] and out[k + 2] in DOUBTING
                      and "i" in out[k + 2:k + 5] and not NAMING & set(out[k:])), None)
        if doubt is not None:
            read.append((" ".join(out[doubt:-1]), "nothing, a doubt"))
            out = out[:doubt] + ["?"]
    tag = next((k for k in range(1, len(out) - 2) if out[k] == ";" and list(out[k + 1:-1]) in AGREEING_TAGS), None)
    if tag is not None and out[-1:] == ["?"]:
        read.append((";", ","))
        out[tag] = ","
    return (out, tuple(read)) if read else (words, ())


# A witness examined ('I put it to you that the bus was parked. Is that correct?', 'You'd concede, wouldn't you,
# that ...', 'Would it be accurate to say that ...'): a statement put to be confirmed, the grammar's 'is it true that'
_AGREE = ("agree", "accept", "concede", "admit", "acknowledge")
_TAGGED = ([], [",", "would", "not", "you", ","], [",", "do", "not", "you", ","], [",", "will", "not", "you", ","])
CONFIRMING = {*((*you, verb, *tag, "that") for you in (["you"], ["you", "would"], ["you", "'", "d"], ["you", "will"])
                for verb in _AGREE for tag in _TAGGED),
              *((*ask, "you", verb, *me, "that") for ask in (["would"], ["do"], ["will"], ["can"], ["could"])
                for verb in _AGREE for me in ([], ["with", "me"])),
              *(("i", "put", "it", *to, "that") for to in ([], ["to", "you"])),
              *(("i", "suggest", *to, "that") for to in ([], ["to", "you"])),
              *((*be, fair, "to", "say", "that") for be in (["would", "it", "be"], ["is", "it"])
                for fair in ("accurate", "fair", "correct", "right", "true")),
              *(("is", "it", "your", view, "that") for view in ("opinion", "view", "evidence", "testimony",
                                                               "position", "understanding", "belief", "assessment",
                                                               "contention", "recollection")),
              *(("is", "it", "not", case, "that") for case in (("true",), ("correct",), ("the", "case"))),
              *(("is", "not", "it", case, "that") for case in (("true",), ("correct",), ("the", "case"))),
              ("is", "it", "the", "case", "that"),
              # a report put to be confirmed ('Sources tell us the bus was parked; can we confirm that?')
              *((*said, *that) for said in (("sources", "tell", "us"), ("sources", "say"), ("we", "are", "told"),
                                            ("we", "'", "re", "told"), ("i", "am", "told"), ("i", "'", "m", "told"),
                                            ("reports", "say"), ("word", "is"), ("rumour", "has", "it"),
                                            ("rumor", "has", "it")) for that in ((), ("that",)))}
# ... closed by a question of its own ('. Is that correct?', '. Do you agree?'): the statement's question mark
CONFIRM_ENDS = [[end, *q, "?"] for end in (".", ";", ",")
                for q in (["is", "that", "correct"], ["is", "that", "right"], ["is", "that", "true"],
                          ["is", "that", "so"], ["is", "that", "not", "so"], ["is", "not", "that", "so"], ["correct"],
                          ["yes"], ["right"], ["do", "you", "agree"], ["would", "you", "agree"], ["agreed"], ["true"],
                          ["can", "we", "confirm", "that"], ["can", "you", "confirm", "that"],
                          ["can", "anyone", "confirm", "that"], ["is", "that", "accurate"], ["can", "we", "confirm"],
                          ["can", "you", "confirm"])]
# asides of an examination, which ask nothing ('in your own words', 'if you know', 'for the sake of argument')
EXAMINATION_ASIDES = sorted({("in", "your", "own", "words"), ("if", "you", "know"), ("if", "you", "can"),
                             ("if", "you", "recall"), ("if", "you", "remember"), ("as", "best", "you", "can"),
                             *(("to", "the", "best", "of", "your", m) for m in ("knowledge", "recollection",
                                                                               "memory", "ability")),
                             ("as", "far", "as", "you", "know"), ("as", "far", "as", "you", "can", "tell"),
                             ("for", "the", "sake", "of", "argument"), ("for", "argument", "'", "s", "sake"),
                             *(("in", "your", *expert, view) for expert in ((), ("expert",), ("professional",),
                                                                           ("honest",), ("considered",))
                               for view in ("opinion", "view", "assessment", "judgement", "judgment",
                                            "estimation")),
                             *(("correct", "me", "if", *i, "wrong", *but) for i in (("i", "'", "m"), ("i", "am"))
                               for but in ((), (",", "but"), ("but",)))}, key=len, reverse=True)
# the court said for 'me' ('Tell the court whether ...', 'Explain to the jury how fast ...', 'Walk us through ...')
AUDIENCE = (["the", "court"], ["the", "jury"], ["the", "panel"], ["the", "tribunal"], ["the", "committee"], ["us"],
            ["me"])
EXAMINATION_ASKS = sorted({*((verb, *a) for verb in ("tell", "show") for a in AUDIENCE if a != ["me"]),
                           *(("explain", "to", *a) for a in AUDIENCE), *(("walk", *a, "through") for a in AUDIENCE),
                           *(("describe", "to", *a) for a in AUDIENCE)}, key=len, reverse=True)
ATTENTION_TO = sorted({(verb, *whose, "attention", "to") for verb in ("directing", "direct", "turning", "turn",
                                                                    "drawing", "draw")
                       for whose in (["your"], ["the", "court", "'", "s"], ["the", "jury", "'", "s"])},
                      key=len, reverse=True)


def examination_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'i put it to you that the bus was parked . is that correct ?' -> 'is it true that the bus was parked ?';
    'explain to the jury how fast ...' -> 'tell me how fast ...'; 'directing your attention to the start , ...' ->
    'at the start , ...'; asides that ask nothing dropped with their commas ('what type of vehicle , if you know ,
    was ...'). With the words read so, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        aside = next((a for a in EXAMINATION_ASIDES if tuple(words[k:k + len(a)]) == a), None)
        if aside:
            end = k + len(aside)
            between = out[-1:] == [","] and words[end:end + 1] == [","]
            read.append((" ".join(words[k - between:end + between]), "nothing, an aside"))
            out = out[:-1] if between else out
            k = end + between + (not out and words[end:end + 1] == [","])
            continue
        confirm = next((c for c in CONFIRMING if tuple(words[k:k + len(c)]) == c), None)
        asks = next((a for a in EXAMINATION_ASKS if tuple(words[k:k + len(a)]) == a), None)
        attention = next((a for a in ATTENTION_TO if tuple(words[k:k + len(a)]) == a), None)
        if confirm or asks:
            said = ["is", "it", "true", "that"] if confirm else ["tell", "me"]
            read.append((" ".join(confirm or asks), " ".join(said)))
            out += said
            k += len(confirm or asks)
        elif attention:
            at = words[k + len(attention) + 1:k + len(attention) + 2]
            said = ["at"] if at and at[0] in START_ADJECTIVES | START_WORDS | TIME_SAID else ["look", "at"]
            read.append((" ".join(attention), " ".join(said)))
            out += said
            k += len(attention)
        else:
            out.append(words[k])
            k += 1
    if read and any(c in ("is it true that", "nothing, an aside") for _, c in read):
        end = next((e for e in CONFIRM_ENDS if out[-len(e):] == e), None)
        if end:
            read.append((" ".join(end), "?"))
            out = out[:-len(end)] + ["?"]
    # an explanation asked of how fast or which way is the grammar's 'tell me' ('explain how fast it was going')
    if out[:2] in (["explain", "how"], ["explain", "what"], ["explain", "which"]):
        read.append(("explain", "tell me"))
        out = ["tell", "me", *out[1:]]
    return (out, tuple(read)) if read else (words, ())


# A request put in a third person's or a report's words ('The authors should clarify how fast ...', 'Reviewer 3 would
# like to know how quickly ...', 'It is not evident from the footage whether ...', 'Action item: confirm how fast
# ...'): a preamble that names no vehicle and sets no condition, ending on a verb of asking or of what is unknown,
# then what is asked. Read as the grammar's 'tell me' (or 'is it true that' before 'that'); a clause said before it
# ('Given that the clip is cut short, ...') stays. A remark after it that says nothing ('; confirmation is
# requested.', 'The submission does not say.', '; could the authors comment?') is dropped.
REQUESTING = {"clarify", "clarified", "state", "stated", "specify", "specified", "report", "reported", "confirm",
              "confirmed", "indicate", "indicated", "explain", "explained", "establish", "established", "determine",
              "determined", "know", "advise", "predict", "enquire", "enquires", "inquire", "inquires", "ask", "asks",
              "seek", "seeks", "request", "requests", "requested", "speculate", "forecast", "evident", "clear",
              "obvious", "unclear", "sure", "certain", "tell", "verify", "verified", "document", "documented",
              # a question relayed ('A coworker asked me how quickly ...', 'Mum wondered which colour ...')
              "asked", "wondered", "wonders", "curious", "pestering"}
_REQUESTED = ("whether", "if", "how", "what", "which", "that", "the")
CONFIRMING_VERBS = {"confirm", "confirmed", "verify", "verified", "establish", "established"}
OBJECT_TAKING = CONFIRMING_VERBS | {"state", "report", "specify", "clarify", "indicate", "determine", "explain",
                                    "predict", "forecast", "document"}
_ASKED_FOR = (["confirmation"], ["clarification"], ["a", "statement", "of"], ["confirmation", "of"])
_ASKED_AS = (["as", "to"], ["on"], ["me", "about"], ["me"], ["about"], ["from", "the", "footage"],
             ["from", "the", "video"], ["from", "the", "clip"], ["in", "the", "footage"], ["in", "the", "video"])
# (nor a question of its own: 'what is the motion state of ...')
_NOT_PREAMBLE = {"if", "had", "suppose", "imagine", "when", "after", "before", "were", "?", ".", "!", ";", "what",
                 "which", "how", "where", "who", "why"}


def _requested_at(words: list[str], k: int) -> int | None:
    """Where what is asked begins after a verb of asking at words[k] ('clarify how', 'seeks confirmation that',
    'not evident from the footage whether'), or None."""
    j = k + 1
    for skip in (_ASKED_FOR, _ASKED_AS):
        j += next((len(s) for s in skip if words[j:j + len(s)] == s), 0)
    # 'report the speed of', never 'ask the authors'; 'not evident whether', never 'dead certain the ...'
    asked = _REQUESTED[:5] + ("that",) * (j > k + 1 or words[k] in CONFIRMING_VERBS) + \
        ("the",) * (words[k] in OBJECT_TAKING)
    return j if words[j:j + 1] and words[j] in asked else None


# A hypothesis put to a test ('H0: the green motorbike is moving fast at the very beginning. Do the data support
# it?', 'Test the hypothesis that the blue SUV is static at the start: accept or reject?'): whether it holds, the
# grammar's 'is it true that'. Asked whether it is rejected, the answer is the other way round, and it stays unread.
HYPOTHESES = (["h0", ":"], ["h1", ":"], ["ha", ":"], ["null", "hypothesis", ":"], ["hypothesis", ":"],
              ["alternative", "hypothesis", ":"], ["test", "the", "hypothesis", "that"], ["our", "null", "says"],
              ["the", "null", "says"], ["hypothesis", "that"])
HOLDING = {"support", "supported", "supports", "true", "accept", "accepted", "retained", "retain", "hold", "holds",
           "confirmed", "correct", "consistent"}


def hypothesis_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'h0 : the bus is parked at the start . do the data support it ?' -> 'is it true that the bus is parked at the
    start ?'. With the words read so, or the words as they are and ()."""
    label = next((h for h in HYPOTHESES if words[:len(h)] == h), None)
    if label is None:
        return words, ()
    end = next((k for k in range(len(label), len(words)) if words[k] in (".", ":", "?", ";")), len(words))
    claim, closing = words[len(label):end], words[end + 1:]
    rejected = "reject" in closing or "rejected" in closing
    either = any(closing[k:k + 3] in (["accept", "or", "reject"], ["reject", "or", "accept"])
                 for k in range(len(closing)))
    if not claim or closing and (not HOLDING & set(closing) or rejected and not either):
        return words, ()
    return ["is", "it", "true", "that", *claim, "?"], ((" ".join(label), "is it true that"),
                                                      *(((" ".join(words[end:]), "?"),) if closing else ()))


def requested_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the authors should clarify how fast the red sedan is ...' -> 'tell me how fast the red sedan is ...';
    'reviewer 4 seeks confirmation that the scooter is ...' -> 'is it true that the scooter is ...'. With the words
    read so, or the words as they are and ()."""
    for k in range(min(len(words), 24)):
        if words[k] not in REQUESTING or not _requested_at(words, k) or \
                k and words[k - 1] in DETERMINERS | {"its", "their", "motion", "kinetic"}:   # 'the motion state of'
            continue
        first = max((j + 1 for j in range(k) if words[j] in (",", "-", ":")), default=0)
        # before it nothing, a label, or a clause that says the video stopped ('given that the clip is cut short ,')
        before = words[:first]
        opening = k > first or words[k] not in ("tell", "state", "know") and words[_requested_at(words, k)] != "the"
        if not NAMING & set(words[:k]) and not _NOT_PREAMBLE & set(words[first:k]) and k - first <= 10 and \
                (not _says_something(before) or FILM_WORDS & set(before)) and opening:
            break
    else:
        return words, ()
    j = _requested_at(words, k)
    # ('establish whether ...', 'confirm the bus was parked' ask whether it holds)
    confirmed = words[j] == "that" or words[j] in ("the", "whether", "if") and words[k] in CONFIRMING_VERBS
    said = ["is", "it", "true", "that"] if confirmed else ["tell", "me"]
    dropped = words[j] in ("that", "whether", "if") and confirmed
    out = words[:first] + said + words[j + dropped:]
    read = [(" ".join(words[first:j + dropped]), " ".join(said))]
    # the remark after it
    cut = max((m for m in range(len(out) - 1) if out[m] in (";", ".", "?", "-") or out[m] == "," and
               out[m + 1:m + 2] == ["and"]), default=None)   # '..., and i said i'd ask you .'
    tail = out[cut + 1:] if cut is not None else []
    if tail and len(tail) <= 10 and _says_nothing([w for w in tail if w not in ("?", ".", "no")]):   # 'no idea'
        read.append((" ".join(out[cut:]), "nothing, a remark"))
        out = out[:cut] + ["."]
    return out, tuple(read)


# A wager around the question. A stake says nothing the question asks ('I've a tenner on yes.', 'Fiver says no.',
# '... and I'll pay out', 'Freeze-frame punt:', ', so it's an in-play bet:') and is dropped; a claim bet on ('I bet
# the sedan hits the bus. Does it?', 'Is it a lock that ...?', 'Fiver says the tandem is faster ..., do I collect?')
# is put to be confirmed, the grammar's 'is it true that'.
WAGER_WORDS = {"bet", "bets", "betting", "wager", "wagers", "wagered", "wagering", "stake", "stakes", "staked",
               "tenner", "fiver", "quid", "bucks", "odds", "punt", "bookie", "bookies", "bookmaker", "favourite",
               "favorite", "money", "pot", "kitty", "sweepstake", "payout", "cert", "collect", "settles",
               "backing", "tipping", "wins", "lock"}
_STAKES = (["a", "fiver"], ["a", "tenner"], ["fiver"], ["tenner"], ["my", "money"], ["money"], ["a", "quid"])
WAGER_CLAIMS = sorted({*((*i, "bet", *you) for i in (["i"], ["i", "'", "d"], ["i", "'", "ll"], ["i", "would"], [])
                         for you in ([], ["you"])),
                       *((*stake, "says") for stake in _STAKES),
                       *(("is", "it", "a", *lock) for lock in (["lock"], ["sure", "thing"], ["dead", "cert"],
                                                              ["safe", "bet"], ["done", "deal"])),
                       ("odds", "-", "on"), ("odds", "on")}, key=len, reverse=True)
BACKING = [[*i, backing] for i in (["i", "'", "m"], ["i", "am"], []) for backing in ("backing", "tipping")]
# a wager's stake said before its claim ('Wagering my lunch money that ...', 'I'm betting a fiver that ...')
WAGERING = {"wagering", "betting", "bet", "wager"}
# ... closed by the claim's own question ('. Does it?', ', do I collect?')
WAGER_ENDS = [[end, *q, "?"] for end in (".", ";", ",", "-")
              for q in (["do", "i", "collect"], ["do", "i", "win"], ["am", "i", "right"], ["yes", "or", "no"],
                        *([aux, it] for aux in ("does", "do", "did", "will", "would", "is", "was", "are", "were")
                          for it in ("it", "they")))]


def _wagered(words: list[str]) -> bool:
    return bool(WAGER_WORDS & set(words)) or any(a == "pay" and b == "out" for a, b in zip(words, words[1:]))


def wagers_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'was it parked ? i have a tenner on yes .' -> 'was it parked ?'; 'i bet the sedan hits the bus . does it ?'
    -> 'is it true that the sedan hits the bus ?'. With the words read so, or the words as they are and ()."""
    if not _wagered(words):
        return words, ()
    out, read = list(words), []
    # the claim bet on, where it opens the question or a sentence of it
    asked = out.index("?") if "?" in out else len(out)
    for k in range(asked):
        if k and out[k - 1] not in SENTENCE_ENDS | {":", ",", ";"}:
            continue
        claim = next((c for c in WAGER_CLAIMS if tuple(out[k:k + len(c)]) == c), None)
        stake = None if claim or out[k:k + 1] == ["what"] else next(
            (j for j in range(k, min(k + 8, len(out))) if out[j] == "that" and WAGERING & set(out[k:j])
             and not NAMING & set(out[k:j])), None)
        backing = next((len(b) for b in BACKING if out[k:k + len(b)] == b), 0)
        to = next((j for j in range(k + backing + 1, min(k + backing + 7, len(out))) if out[j] == "to"
                   and NAMING & set(out[k + backing:j])), None) if backing else None
        if to is not None:   # 'i'm backing the dirt bike to crash into something' -> '... the dirtbike will crash'
            read.append((" ".join(out[k:to + 1]), "is it true that " + " ".join(out[k + backing:to]) + " will"))
            out[k:to + 1] = ["is", "it", "true", "that", *out[k + backing:to], "will"]
            claim = ("is", "it", "true", "that")
        elif claim or stake is not None:
            end = k + len(claim) if claim else stake + 1
            end += out[end:end + 1] == ["that"]
            read.append((" ".join(out[k:end]), "is it true that"))
            out[k:end] = ["is", "it", "true", "that"]
        if claim or stake is not None:
            close = next((e for e in WAGER_ENDS if out[-len(e):] == e), None)
            if close:
                read.append((" ".join(close), "?"))
                out = out[:-len(close)] + ["?"]
            elif out[-1:] in (["."], ["!"]):
                out[-1] = "?"
            break
    # the stakes: a part between commas, or a sentence, that names no vehicle, or any sentence after the question's
    # ('My stake's on a motorbike.': a guess at the answer)
    kept, start = [], 0
    parts = [k + 1 for k, w in enumerate(out) if w in SENTENCE_ENDS | {",", ":", ";"}
             or out[k + 1:k + 3] == ["and", "i"]]   # '... and i'll pay out'
    parts = sorted(set(parts))
    for end in parts + [len(out)] * (not parts or parts[-1] != len(out)):
        part = out[start:end]
        said = [w for w in part if w not in SENTENCE_ENDS | {",", ":", ";", "and", "but", "so"}]
        if _wagered(said) and not (NAMING & set(said) and "?" not in kept) and not {"true", "?"} & set(part):
            read.append((" ".join(part), "nothing, a wager"))
        else:
            kept += part
        start = end
    kept = kept[:-1] + ["?"] if kept[-1:] == [","] else kept
    return (kept, tuple(read)) if read and kept else (words, ())


# A ticket's or a form's fields around the question ('Steps: watch clip; Expected: partner identified; Question:
# ...'). What a ticket expects, its priority or status, and a step that only watches the video say nothing the
# question asks; the other fields' items (a step that sets a condition, a summary that says the clip ends early) are
# context, a sentence each. A field that asks for the answer ('prediction needed -') says nothing either.
TICKET_FIELDS = {"question", "q", "steps", "step", "repro", "summary", "issue", "description", "context", "title",
                 "request", "note", "notes", "ticket", "details", "scenario"}
TICKET_NOISE = {"expected", "actual", "priority", "severity", "status", "component", "assignee", "reporter",
                "environment", "version", "eta", "labels", "tags", "result", "outcome", "deliverable", "format"}
WATCHING = {"watch", "view", "play", "open", "replay", "load", "review", "rewatch"}
ANSWER_NEEDED = [[asked, needed, *end] for asked in ("prediction", "answer", "response", "confirmation", "input",
                                                     "clarification", "verdict", "ruling")
                 for needed in ("needed", "required", "requested", "wanted") for end in ([":"], ["-"], [","], [])]


def ticket_fields_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'steps : watch clip ; expected : partner identified ; question : what type ... ?' -> 'what type ... ?';
    'summary : clip ends early ; prediction needed - do ...' -> 'clip ends early . do ...'. With the fields read so,
    or the words as they are and ()."""
    out, read = list(words), []
    for k in range(len(out)):
        need = next((n for n in ANSWER_NEEDED if out[k:k + len(n)] == n), None)
        if need and (k == 0 or out[k - 1] in {";", ".", ",", ":"}):
            read.append((" ".join(need), "nothing, a ticket's field"))
            out = out[:k] + out[k + len(need):]
            break
    labels = [k for k in range(len(out) - 1) if out[k + 1] == ":" and out[k] in TICKET_FIELDS | TICKET_NOISE
              and (k == 0 or out[k - 1] in {";", ".", ",", "-", "|"})]
    if len(labels) < 2:
        return (out, tuple(read)) if read else (words, ())
    kept = out[:labels[0]]
    for k, end in zip(labels, labels[1:] + [len(out)]):
        field = out[k + 2:end]
        if out[k] in TICKET_NOISE or not field:
            read.append((" ".join(out[k:end]), "nothing, a ticket's field"))
            continue
        items, start = [], 0
        for m in [j + 1 for j, w in enumerate(field) if w in (";", "|")] + [len(field)]:
            item = [w for w in field[start:m] if w not in (";", "|")]
            start = m
            if item and item[0] in WATCHING and not NAMING & set(item):
                read.append((" ".join(item), "nothing, a ticket's step"))
            elif item:
                items.append(item + ["."] * (item[-1] not in SENTENCE_ENDS))
        kept += [w for item in items for w in item]
        read.append((" ".join(out[k:k + 2]), "nothing, a ticket's label"))
    # the question's own field last: its words as they are
    return (kept, tuple(read)) if kept and kept[-1] in SENTENCE_ENDS else (words, ())


def dislocated_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'blue minivan and green chopper , they collide ?' -> 'do blue minivan and green chopper collide ?', and 'the
    sedan , it is fast ?' -> 'is the sedan fast ?': the vehicles said first, then asked about as 'they' or 'it' in
    a statement with a question mark. With the words read so, or the words as they are and ()."""
    subject = coordinated_subject(words) if words[-1:] == ["?"] else None
    if subject is None:
        return words, ()
    end, named = subject
    pronoun = ["they"] if len(named) == 2 else ["it"]
    if words[end:end + 2] != [","] + pronoun or not words[end + 2:end + 3]:
        return words, ()
    verb, rest = words[end + 2], words[end + 3:]
    said = [verb, *words[:end], *rest] if verb in DISLOCATED_ASKS else \
        ["do" if len(named) == 2 else "does", *words[:end], verb, *rest]
    return said, ((" ".join(words[end:end + 3]), " ".join(said[:1])),)


def type_of_category_as_vehicle(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'... . what kind of aircraft is it ?' -> '... . what kind of vehicle is it ?': the category in a question of
    the type of what 'it' is names no other object (it was read as a plane of its own, the context's description of
    'it' lost). With the words read so, or the words as they are and ()."""
    for k in range(len(words) - 4):
        if SENTENCE_ENDS.intersection(words[:k]) and words[k] in ("what", "which") and words[k + 1] in SHAPE_ASKED and \
                words[k + 2] == "of" and words[k + 3] in NOUNS_SAID | PLANE_SAID and \
                words[k + 4:k + 6] in (["is", "it"], ["was", "it"]):
            return words[:k + 3] + ["vehicle"] + words[k + 4:], ((f"of {words[k + 3]}", "of vehicle"),)
    return words, ()


def context_as_question(words: list[str], known=None) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question after its context, what it refers back to read from the context; with the context read as
    what it gave. The words as they are and () where there is no context; where the question needs more than the
    vehicles, a condition, a moment or the start (a vehicle the context describes: 'Something is speeding up. What
    colour is it?'; a vehicle said with a word the parser does not know, of `known`: 'the pink scooter'); or where
    the context asks a question of its own, or imagines otherwise than as a condition."""
    spans = _sentence_spans(words)
    asked_at = max((j for j, (a, b) in enumerate(spans) if words[b - 1] == "?"), default=None)
    if not spans or len(spans) > 1 and not asked_at:
        return words, ()
    if len(spans) == 1:
        k = _run_on_question(words)
        if k is None:
            return words, ()
        j = _run_on_clause(words, k)
        asked = words[j:k] + [","] * (j < k) + words[k:] + ["?"] * (words[-1] != "?")
        out, read = context_as_question(words[:j] + ["."] + asked, known)
        return (out, read) if read else (words, ())
    context = [words[a:b] for a, b in spans[:asked_at]]
    question = words[spans[asked_at][0]:spans[asked_at][1]]
    conditions = [_condition_said(s, bool(j and (IMAGINED_SAID | {"if"}) & set(context[j - 1])
                                          and not mentions(context[j - 1]))) for j, s in enumerate(context)]
    # 'In that world, does it ...?': where no sentence imagines, the sentence before is what is imagined
    back = _at(question[:4], IMAGINED_BACK)
    back = back and back[0] == 0 and not any(conditions) and back[1]
    if back:
        question = question[len(back) + (question[len(back):len(back) + 1] == [","]):]
        conditions[-1] = _condition_said(context[-1], True)
    if any(c is None and not _stated(s) and not _imagining_only(s) and (
            s[-1] == "?" or mentions(s) and (IMAGINED_SAID & set(s)
                                             or "if" in s and s[s.index("if") - 1] not in WHETHER))
           for s, c in zip(context, conditions)) or back and not conditions[-1]:
        return words, ()
    tail = words[spans[asked_at][1]:]
    question = _echoed(question, context[-1]) or _judged(question, context[-1]) or _wondered(question, context[-1]) \
        or question
    condition = next((c for c in reversed(conditions) if c), None)
    own_condition = bool({"if", "suppose", "imagine", "had", "were"} & set(question))
    # a vehicle said 'he' or 'she', as learners and fond speakers do ('Does he crash with any other thing?')
    question = ["it" if w in ("he", "she") else "its" if w == "his" else w for w in question]
    asked = (condition if condition and not own_condition else []) + question
    # a sentence that says the video stopped ('video stops partway through . does the sedan hit ...?'): the question
    # asks after its end
    stopped = next((c for c in context if (e := _video_end(c)) and (e[0] == 0 or c[e[0] - 1] == ":")), None)
    if stopped and asks_impact(question) and not (_video_end(question) or _at_cut(question)):
        asked = ["after", "the", "video", "ends", ",", *asked]
    # the vehicles the context names, fullest mention of each, in the order of the sentences that name them; those
    # said with a word the parser does not know are not read for it
    said = [[(a, b, r) for a, b, r in _appositions(s) if "not" not in s[max(a - 2, 0):a]] for s in context]
    # a sentence that opens on a thing the parser does not know ('theres like a tractor near the bus'): what 'it'
    # means is not read
    strange = known is not None and any(_thing_first(s, known) for s in context)
    every = [r for runs in said for _, _, r in runs]
    fullest = [r for r in dict.fromkeys(every) if not any(o != r and _fits(r, o) for o in every)]
    # the most recent sentence's first, past sentences that go on about it ('A white airliner floats. It drifts toward
    # the bus. Did it ...?': the airliner)
    latest = [r for s, runs in zip(reversed(context), reversed(said)) if _opening(s)[:1] not in (["it"], ["they"])
              for _, _, r in runs if r in fullest] + [r for runs in reversed(said) for _, _, r in runs if r in fullest]
    unread = {next((f for f in fullest if _fits(r, f)), r) for s, runs in zip(context, said) for a, b, r in runs
              if _unknown_beside(s, a, b, r, known)}
    used, read = set(), []
    out = list(asked)
    for start, end, ref in reversed(mentions(asked)):   # a shorter name: the one vehicle of the context it fits
        fits = [r for r in fullest if r != ref and generalises(ref, r)] or \
            [r for r in fullest if r != ref and _fits(ref, r)]
        alike = [r for _, _, r in mentions(asked) if r != ref and generalises(ref, r)]   # the parser's to read
        if len(fits) == 1 and not alike:
            end += out[end:end + 1] == ["one"]
            start -= bool(start) and out[start - 1] in LOOKS   # 'the big bus': the context says which one
            read.append((" ".join(out[start:end]), " ".join(_said(fits[0])[1:])))
            out[start:end] = _said(fits[0])[1:]
            used.add(fits[0])
    for k in reversed(range(len(out))):
        place = next((p for p in PLACES_SAID if tuple(out[k:k + len(p)]) == p and (
            p[-1] in ("one", "vehicle", "former", "latter", "other") or out[k + len(p):k + len(p) + 1] and
            out[k + len(p)] in AFTER_PLACE) and not (out[k + len(p):k + len(p) + 1] and
                                                       out[k + len(p)] in OBJECT_WORDS | GENERIC)), None)
        if place is not None:
            at = PLACES_SAID[place]
            others = [r for r in fullest if not _named(r, mentions(out[:k] + out[k + len(place):]))]
            # 'the first' and 'the second' of two; 'the other' of the one not named ('the second vehicle it hits'
            # after one vehicle is its second partner)
            meant = (fullest[at] if len(fullest) == 2 else None) if at is not None else \
                others[0] if len(others) == 1 else None
            if meant is None:
                return words, ()
            read.append((" ".join(place), " ".join(_said(meant))))
            out[k:k + len(place)] = _said(meant)
            used.add(meant)
    named = mentions(out)
    pronoun = next((k for k, w in enumerate(out) if w in ("it", "its") and out[k + 1:k + 2] and
                    out[k + 1] not in IT_FORWARD), None)
    pronoun = pronoun if pronoun is not None and not any(start < pronoun for start, _, _ in named) else None
    plural = _at(out, PLURAL_PRONOUNS)
    plural = plural if plural and len({r for _, _, r in named}) < 2 else None
    # 'what colour is that?', 'that vehicle', 'is that suspect?'
    pointed = any(a in ("that", "this") and (b in GENERIC | {"?"} or out[k - 1:k] in (["is"], ["was"])
                                            and out[k + 2:k + 3] == ["?"] and b not in OBJECT_WORDS)
                  for k, (a, b) in enumerate(zip(out, out[1:])))
    asked_of = pronoun is not None and out[pronoun + 1] in SENTENCE_ENDS | {","}   # 'what colour is it?'
    if pointed or (asked_of or plural) and any(map(_unnamed, context)) or (pronoun is not None or plural) and strange:
        return words, ()
    if pronoun is not None:
        # said before the question's own mentions, it may be one of them ('Had it been floating ..., would the jet
        # and the bike ...?')
        meant = next((r for r in latest if not _named(r, named)), latest[0] if latest else None)
        if meant is None:
            return words, ()
        read.append((out[pronoun], " ".join(_said(meant)) + "'s" * (out[pronoun] == "its")))
        out[pronoun:pronoun + 1] = _said(meant) + ["'", "s"] * (out[pronoun] == "its")
        used.add(meant)
        named = mentions(out)
    # 'it' hit by the vehicle the question names: the context's other one ('The cyan jet bonks the yellow airliner.
    # Was the jet slow when it collided with it?')
    struck = next((k for k, w in enumerate(out) if w == "it" and k and (out[k - 1] in ("with", "into", "against") or
                                                                         out[k - 1].startswith(IMPACT_STEMS))), None)
    others = [r for r in fullest if not _named(r, named)]
    if struck is not None and len({r for _, _, r in named}) == 1 and len(others) == 1:
        read.append(("it", " ".join(_said(others[0]))))
        out[struck:struck + 1] = _said(others[0])
        used.add(others[0])
        named = mentions(out)
    if plural:
        others = [r for r in latest if not _named(r, named)]
        pair = [r for _, _, r in named][:1] + others[:2 - len(named[:1])]
        if len(pair) < 2 or len(fullest) > 2 and not named:
            return words, ()
        k, p = plural
        read.append((" ".join(p), " ".join(_said(pair[0]) + ["and"] + _said(pair[1]))))
        out[k:k + len(p)] = _said(pair[0]) + ["and"] + _said(pair[1])
        used |= set(pair)
    if used & unread:
        return words, ()
    if not condition and not own_condition:
        timed = START_WORDS | COMES_IN_WORDS | OWN_TIMES
        then = _at(out, THEN_SAID)
        impact = _at(out, IMPACT_MOMENTS)
        own = {next((f for f in fullest if _fits(r, f)), r) for _, _, r in mentions(out)}
        if then and not (timed & set(out) or asks_impact(out[:then[0]] + out[then[0] + len(then[1]):])):
            moment, (k, p) = _moment(context, fullest), then
        elif impact and len(own) == 1:
            moment, (k, p) = _moment(context, fullest, of=next(iter(own))), impact
        else:
            moment, k, p = [], 0, ()
            started = next((s for s in reversed(context) if START_WORDS & set(s)), None)
            if started and not (timed & set(out) or asks_impact(out)):
                out = out[:-1] + ["at", "the", "start", "?"]
                read.append((" ".join(started), "at the start"))
        if moment is None:
            return words, ()
        if moment:   # said first, as a clause of time ('when the bus and the car collide, how fast ...')
            rest = out[:k] + out[k + len(p):]
            rest = [w for j, w in enumerate(rest) if w != "," or j and rest[j + 1:j + 2] not in (["?"], [","])]
            out = [*moment, ",", *rest]
            read.append((" ".join(p), " ".join(moment)))
    dropped = " ".join(w for s, c in zip(context, conditions) if c is not condition or own_condition for w in s)
    return out + tail, (((dropped, "nothing, context the question refers back to"),) * bool(dropped) + tuple(read))

# What is said after the question, where it says which vehicle was meant ('Is it moving fast at the start? The red
# car, I mean.', 'Does the bus hit the car? Sorry, the blue car, not the red one.', '... the bus? The cyan bus, the
# regular one.'), the time ('How fast is the jet going? At the very beginning, I mean.'), which property is asked
# ('What kind of vehicle is moving fast? The type, not the colour.'), or nothing ('Asking for a friend.').
AFTER_OPENERS = {"sorry", "oops", "wait", "no", "actually", "i", "mean", "meant", "correction", "rather", "er", "um",
                 "uh", "oh", "ah", "my", "bad", "that", "is", "s", "'", "like", ",", "-", ":", "and", "so"}
AFTER_CLOSERS = {",", ".", "!", "i", "mean", "meant", "that", "is", "please", "thanks", "thx", "though", "obviously"}
NOT_SAID = (("not",), ("instead", "of"), ("rather", "than"))
SUBTYPE_FIRST = {v.split("_")[0]: tuple(v.split("_")) for v in SUBTYPES if "_" in v}   # 'the regular one'
CATEGORY_OF = {**{v: c for v, (c, *_) in SUBTYPES.items()}, **{c: c for c, *_ in SUBTYPES.values()}}
SHAPE_ASKED = ("type", "kind", "sort", "shape", "model", "category", "class")   # the words that ask a vehicle's type
ASKED_PROPERTY = {**dict.fromkeys(SHAPE_ASKED, "shape"), "colour": "color", "color": "color"}


# colours no catalogue colour is (references.COLOUR_SHADES reads those that are one)
OTHER_COLOURS = {"pink", "orange", "white", "black", "silver", "navy", "teal", "tan", "khaki", "magenta", "beige",
                 "cream", "ivory", "lime", "olive", "peach", "coral", "lavender", "rose", "mauve", "copper", "amber",
                 "lilac", "fuchsia", "rainbow", "striped", "spotted"}


def _unknown_beside(words: list[str], a: int, b: int, ref: tuple, known) -> bool:
    """Whether a mention words[a:b] is said with a word the parser does not know: before it ('the pink scooter'), or
    after its colour alone ('green tractor'); never where `known` is None."""
    def unknown(w: str) -> bool:
        return known is not None and w.isalpha() and w not in known
    return bool(a and unknown(words[a - 1]) and words[a - 1] in OTHER_COLOURS
                or b < len(words) and unknown(words[b]) and set(ref) <= set(COLOR_NAMES))


def _one_vehicle(words: list[str]) -> tuple | None:
    """The values of the one vehicle some words name ('the cyan bus, the regular one' -> ('cyan', 'regular_bus')),
    () where they name none, None where they name more than a colour and a type."""
    values = [v for _, _, r in mentions(words) for v in r]
    colours = list(dict.fromkeys(v for v in values if v in COLOR_NAMES))
    kinds = list(dict.fromkeys(v for v in values if v not in COLOR_NAMES))
    kinds = [k for k in kinds if not any(o != k and CATEGORY_OF[o] == k for o in kinds)]   # the bus, the regular one
    return None if len(colours) > 1 or len(kinds) > 1 else tuple(colours + kinds)


def _meant(ref: tuple, meant: tuple) -> tuple:
    """A mention's values with what the words after the question say of it instead."""
    colour = [v for v in meant if v in COLOR_NAMES] or [v for v in ref if v in COLOR_NAMES]
    kind = [v for v in meant if v not in COLOR_NAMES] or [v for v in ref if v not in COLOR_NAMES]
    return tuple(colour + kind)


def _compatible(ref: tuple, meant: tuple) -> bool:
    """Whether the vehicle a mention names can be the one said after the question (its category, or its colour
    where the mention has none)."""
    kinds = [CATEGORY_OF[v] for v in meant if v not in COLOR_NAMES]
    own = [CATEGORY_OF[v] for v in ref if v not in COLOR_NAMES]
    if kinds:
        return not own or own == kinds
    return not any(v in COLOR_NAMES for v in ref)


def afterthoughts_read(words: list[str], known=None) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question with what is said after it read into it, and what was said after it read as nothing; the words
    as they are and () where nothing is said after it, it asks again, or what it says cannot be read so (a vehicle
    said with a word the parser does not know, of `known`: 'The white sedan, I mean.')."""
    spans = _sentence_spans(words)
    asked_at = max((j for j, (a, b) in enumerate(spans) if words[b - 1] == "?"), default=None)
    if asked_at is None or asked_at == len(spans) - 1:
        return words, ()
    start, end = spans[asked_at]
    out, read = words[:end], []
    for a, b in spans[asked_at + 1:]:
        said = words[a:b]
        if said[-1] == "?":
            return words, ()
        k, e = 0, len(said)
        while k < e and said[k] in AFTER_OPENERS:
            k += 1
        while e > k and said[e - 1] in AFTER_CLOSERS:
            e -= 1
        core = [w for j, w in enumerate(said[k:e]) for w in (
            SUBTYPE_FIRST[w] if w in SUBTYPE_FIRST and said[k:e][j + 1:j + 2] == ["one"] else (w,))]
        cut = _at(core, NOT_SAID)
        meant, other = (core[:cut[0]], core[cut[0] + len(cut[1]):]) if cut else (core, [])
        vehicle, wrong = _one_vehicle(meant), _one_vehicle(other)
        question = out[start:]
        runs = mentions(question)
        if vehicle is None or wrong is None or any(_unknown_beside(core, *run, known) for run in mentions(core)) or \
                {"tell", "give", "name", "state", "say", "list"} & set(core):   # '? Give its colour.' asks
            return words, ()
        if vehicle:
            hits = [r for r in runs if wrong and (_fits(wrong, r[2]) or _fits(r[2], wrong))] or \
                [r for r in runs if _compatible(r[2], vehicle)]
            it = next((j for j, w in enumerate(question) if w == "it"), None)
            if len(hits) == 1:
                first, last, ref = hits[0]
                question[first:last] = _said(_meant(ref, vehicle))[1:]
            elif not runs and it is not None:
                question[it:it + 1] = _said(vehicle)
            else:
                return words, ()
        elif ASKED_PROPERTY.keys() & set(core):
            asked = ASKED_PROPERTY[next(w for w in core if w in ASKED_PROPERTY)]
            if question[:2] in (["which", "vehicle"], ["which", "one"]):   # 'which vehicle is ...? the type'
                question[:2] = ["what", "type", "of", "vehicle"] if asked == "shape" else \
                    ["what", "color", "is", "the", "vehicle", "that"]
        elif START_WORDS & set(core):
            if not (START_WORDS | COMES_IN_WORDS | OWN_TIMES) & set(question) and not asks_impact(question):
                question[-1:] = ["at", "the", "start", "?"]
        elif set(core) & (FILM_WORDS | HEADING_KEPT | MOTION_WORDS | MOTION_DESCRIPTIONS | QUERY_NOUNS):
            return words, ()
        out = out[:start] + question
        read.append((" ".join(said), " ".join(question)))
    return out, tuple(read)

NOUNS_SAID = {w for said in CATEGORY_SAID.values() for w in said}
NAMING = OBJECT_WORDS | NOUNS_SAID   # the words of a vehicle's name

# A speaker correcting a vehicle's name as they say it ('the red no the blue sedan', 'the gray jet no sorry the gray
# biplane', 'the bus I mean the truck'): the words after the correction stand for the ones before it.
CORRECTING = {"no", "wait", "sorry", "mean", "rather", "oops", "correction", "scratch", "actually"}
CORRECTION_WORDS = CORRECTING | {"i", "or", "that", ","} | FILLERS   # 'uh wait no', 'I mean', 'or rather'


def corrections_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'does the red no the blue sedan hit ...' -> 'does the blue sedan hit ...': a vehicle's name said, corrected
    ('no', 'sorry', 'I mean', 'uh', commas around them) and said again from its article. With the correction read
    so, or the words as they are and ()."""
    for k in range(1, len(words)):
        if words[k - 1] not in NAMING:
            continue
        j = k
        while words[j:j + 1] and words[j] in CORRECTION_WORDS:
            j += 1
        marker = [w for w in words[k:j] if w != ","]
        # a word that corrects, or a speaker's filler alone ('the blue uh the purple bus'); 'or' and 'that' only in
        # 'or rather' and 'scratch that' ('the red car or the blue bus' offers two)
        if not marker or not (CORRECTING.intersection(marker) or set(marker) <= FILLERS) or \
                "or" in marker and "rather" not in marker or "that" in marker and "scratch" not in marker:
            continue
        if not (words[j:j + 1] and words[j] in ("the", "a", "an", "that") and words[j + 1:j + 2]
                and words[j + 1] in NAMING):
            continue
        start = k - 1
        while start > 0 and words[start - 1] in NAMING:
            start -= 1
        start -= start > 0 and words[start - 1] in ("the", "a", "an", "that", "this")
        return words[:start] + words[j:], ((" ".join(words[start:j]), "nothing, a correction"),)
    return words, ()


OWNERS = {"my", "our", "your", "yer", "ma", "me"}   # 'yer grey city bike', 'me little bus' as said in Ireland
TOYS = {"toy", "toys", "model", "little", "wee"}


def colour_clause_as_named(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the bicycle , which is brown ,' -> 'the brown bicycle'; 'the biplane that is blue' -> 'the blue biplane': a
    colour said in a clause after its vehicle (the decoder read the vehicle without it). With the words read so,
    or the words as they are and ()."""
    out, read, k = list(words), [], 0
    while k < len(out):
        j = k
        while j < len(out) and out[j] in NAMING and out[j] not in COLOR_NAMES:
            j += 1
        clause = j + (out[j:j + 1] == [","])
        if j > k and (k == 0 or out[k - 1] not in COLOR_NAMES) and out[clause:clause + 1] and \
                out[clause] in ("which", "that", "who") and out[clause + 1:clause + 2] in (["is"], ["was"]) and \
                out[clause + 2:clause + 3] and out[clause + 2] in COLOR_NAMES:
            end = clause + 3 + (out[clause + 3:clause + 4] == [","] and out[j:j + 1] == [","])
            read.append((" ".join(out[k:end]), " ".join([out[clause + 2], *out[k:j]])))
            out[k:end] = [out[clause + 2], *out[k:j]]
            k += j - k + 1
        else:
            k = max(j, k + 1)
    return (out, tuple(read)) if read else (words, ())


GLOSS_OPENERS = (["ie"], ["eg"], ["that", "is"], ["meaning"], ["namely"], ["in", "other", "words"])
CHOICE_LABELS = {"levels", "options", "choices", "classes", "categories", "answers"}
CHOICES_SAID = {"static", "stationary", "parked", "still", "moving", "slow", "slowly", "fast", "quick", "quickly",
                "yes", "no", "or", ",", "/", "left", "right", "front", "back", "up", "down"}
# the words of a speaker's aside in brackets, about how they say it ('I think they call it', 'is that the word?')
SPEAKING = {"i", "we", "they", "say", "call", "called", "word", "think", "believe", "hope", "mean", "gather", "reckon",
            "?"}


def glosses_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A report's brackets: a gloss ('accelerating (i.e. under engine power)') says again what the words before it
    say and is dropped, where it names no vehicle; a vehicle named in brackets after a description of it ('the
    insured vehicle (the red sedan)', 'the third-party vehicle (blue pickup)') is that vehicle, the description
    dropped. With the words read so, or the words as they are and ()."""
    out, read, a = list(words), [], 0
    while "(" in out[a:]:
        a = out.index("(", a)
        b = out.index(")", a) if ")" in out[a:] else None
        if b is None:
            break
        inside = out[a + 1:b]
        name = inside[inside[:1] in (["the"], ["a"], ["an"]):]
        if any(inside[:len(g)] == g for g in GLOSS_OPENERS) and not NAMING.intersection(inside):
            read.append((" ".join(out[a:b + 1]), "nothing, a gloss"))
            out[a:b + 1] = []
            continue
        d = next((d for d in range(a - 1, max(a - 6, -1), -1) if out[d] in DETERMINERS), None)
        described = out[d + 1:a] if d is not None else []
        levels = inside[2:] if inside[1:2] == [":"] and inside[0] in CHOICE_LABELS else None   # '(levels: ...)'
        if ("or" in inside or levels) and set(levels or inside) <= CHOICES_SAID:   # '(static, slow or fast)'
            read.append((" ".join(out[a:b + 1]), "nothing, the choices offered"))
            out[a:b + 1] = []
            continue
        if SPEAKING & set(inside):   # a speaker's aside: '(the motorbike, i should say)', '(is that the word?)'
            said = name[:name.index(",")] if "," in name else name
            named = said and all(w in NAMING for w in said) and any(w in OBJECT_WORDS for w in said) and described
            colours = [w for w in described if w in COLOR_NAMES]
            read.append((" ".join(out[d if named else a:b + 1]), " ".join(["the", *colours, *said]) if named
                         else "nothing, an aside"))
            out[d if named else a:b + 1] = ["the", *colours, *said] if named else []
            continue
        if name and all(w in NAMING for w in name) and any(w in OBJECT_WORDS for w in name) and described and \
                not set(described) & (OBJECT_WORDS | {"grey", "and", "or", ","}):
            read.append((" ".join(out[d:b + 1]), " ".join(["the", *name])))
            out[d:b + 1] = ["the", *name]
            a = d + 1
            continue
        a = b + 1
    return (out, tuple(read)) if read else (words, ())


SET_VERBS = {"set", "sets", "setting", "initialise", "initialised", "initialize", "initialized", "reset", "change",
             "changed", "changing"}
SET_VALUES = {"static": "static", "stationary": "static", "zero": "static", "0": "static", "slow": "slow",
              "low": "slow", "fast": "fast", "high": "fast"}


def settings_as_imagined(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """An intervention said as a setting ('set the gray chopper's initial speed to slow', 'the sedan initialised in
    the fast speed bin') as the grammar's condition: 'the gray chopper had been slow from the start'. With the words
    read so, or the words as they are and ()."""
    for k, w in enumerate(words):
        if w not in SET_VERBS:
            continue
        a = k + 1 + (words[k + 1:k + 2] == ["the"])
        b = a
        while b < len(words) and words[b] in NAMING:
            b += 1
        c = b + 2 * (words[b:b + 2] == ["'", "s"])
        c += words[c:c + 1] and words[c] in ("initial", "starting", "start")
        value = None
        if b > a and words[c:c + 1] and words[c] in SPEED_NOUNS and words[c + 1:c + 2] == ["to"]:
            value, end = words[c + 2:c + 3], c + 3
        elif k and words[k - 1] in NAMING and words[k + 1:k + 2] in (["to"], ["in"], ["into"], ["as"]):
            # 'the brown sedan initialised in the fast speed bin'
            b = k - (words[k - 1:k] == ["was"])
            a = b
            while a and words[a - 1] in NAMING:
                a -= 1
            k = a - (a and words[a - 1] == "the")
            value = words[b + 2 + (words[b + 2:b + 3] == ["the"]):][:1]
            end = b + 3 + (words[b + 2:b + 3] == ["the"])
        elif b > a and c == b and words[b:b + 1] == ["to"]:   # 'set the sedan to slow'
            value, end = words[b + 1:b + 2], b + 2
        if not value or value[0] not in SET_VALUES:
            continue
        while words[end:end + 1] and words[end] in SPEED_NOUNS | {"bin", "bucket", "class", "category", "speeds"}:
            end += 1
        said = ["the", *words[a:b], "had", "been", SET_VALUES[value[0]], "from", "the", "start"]
        end += 3 * (words[end:end + 3] == said[-3:])
        k -= bool(k) and words[k - 1] in ("we", "you", "i", "they")   # 'if we set ...'
        return words[:k] + said + words[end:], ((" ".join(words[k:end]), " ".join(said)),)
    return words, ()


def scenario_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A tester's scenario ('given the clip , when it starts , then how fast is the red sedan ?') as the question it
    asks ('at the start , how fast is the red sedan ?'): the clip given says nothing, 'when it starts' (or ends) is
    the video's time, and 'then' opens the question. With the words read so, or the words as they are and ()."""
    if words[:2] != ["given", "the"] or words[2:3] and words[2] not in FILM_WORDS or words[3:4] != [","]:
        return words, ()
    out, read = words[4:], [(" ".join(words[:4]), "nothing, a scenario")]
    when = next((m for m in (2, 3) if out[:1] == ["when"] and out[m:m + 1] and out[m] in START_WORDS | END_SAID
                 and out[1:m] in (["it"], ["the", words[2]]) and out[m + 1:m + 2] == [","]), None)
    if when:
        time = ["at", "the", "start" if out[when] in START_WORDS else "end"]
        read.append((" ".join(out[:when + 1]), " ".join(time)))
        out = time + out[when + 1:]
    then = next((k for k in range(1, len(out)) if out[k - 1] == "," and out[k] == "then"), None)
    if then is not None:
        read.append(("then", "nothing"))
        out = out[:then] + out[then + 1:]
    return out, tuple(read)


# A change told as another version of the story ('In another telling, the airliner hovers from the start. Would
# ...?', 'Spin a tale in which the bike begins fast.', 'Under an alternative ruling where ...'): the grammar's
# 'imagine' and 'in a world where' (they were read as what happens in the video)
OTHERWISE = {"another", "different", "alternative", "alternate", "other"}
TOLD = {"version", "telling", "retelling", "tale", "story", "ruling", "timeline", "universe", "reality", "world",
        "account", "cut", "edit"}
TOLD_OF = (("of", "this", "tale"), ("of", "the", "tale"), ("of", "this", "story"), ("of", "the", "story"),
           ("of", "events"), *(("of", d, f) for d in ("the", "this") for f in ("video", "clip", "footage", "replay")))
TELLING = {("spin", "a", "tale"), ("tell", "a", "tale"), ("tell", "a", "story"), ("write", "a", "story"),
           ("picture", "a", "story"), ("imagine", "a", "story"), ("imagine", "a", "version"),
           ("imagine", "a", "tale"), *((r, *the, o) for r in ("rewrite", "retell", "redo", "rerun", "replay")
                                       for the in ((), ("the",), ("this",))
                                       for o in ("opening", "story", "start", "beginning", "tale", "clip", "video",
                                                 "scene", "footage"))}
WHICH = (("in", "which"), ("where",), ("so", "that"), ("such", "that"))


def told_otherwise_as_imagined(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'in another telling , the bus is parked from the start . would ...' -> 'imagine the bus is parked ...';
    'under an alternative ruling where ...' -> 'in a world where ...'; 'spin a tale in which ...' -> 'imagine ...'.
    With the words read so, or the words as they are and ()."""
    j = next((len(t) for t in TELLING if tuple(words[:len(t)]) == t), 0)
    if j:
        which = next((w for w in WHICH if tuple(words[j:j + len(w)]) == w), None)
        if which:
            end = j + len(which)
            return ["imagine", *words[end:]], ((" ".join(words[:end]), "imagine"),)
        return words, ()
    if words[:1] not in (["in"], ["under"]):
        return words, ()
    k = 1 + (words[1:2] in (["a"], ["an"], ["some"]))
    other = words[k:k + 1] and words[k] in OTHERWISE
    k += bool(other)
    if not other or not words[k:k + 1] or words[k] not in TOLD:
        return words, ()
    k += 1 + next((len(o) for o in TOLD_OF if tuple(words[k + 1:k + 1 + len(o)]) == o), 0)
    which = next((w for w in WHICH if tuple(words[k:k + len(w)]) == w), None)
    if which:
        end = k + len(which)
        return ["in", "a", "world", "where", *words[end:]], ((" ".join(words[:end]), "in a world where"),)
    if words[k:k + 1] == [","]:
        return ["imagine", *words[k + 1:]], ((" ".join(words[:k + 1]), "imagine"),)
    return words, ()


def owners_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is my purple road bike faster ...' -> 'is the purple road bike faster ...': a vehicle said as someone's
    ('my', 'our toy', 'your little') is the video's, named by its article; 'toy' after its name goes too. With the
    words read so, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        j = k + (words[k] in OWNERS)
        while words[j:j + 1] and words[j] in TOYS:
            j += 1
        # ('the red little jet': after the colour too, fondness, not CLEVR's size)
        if j > k and words[j:j + 1] and words[j] in NAMING and (words[k] in OWNERS or out[-1:] in (["the"], ["a"])
                                                                or out[-1:] and out[-1] in COLOR_NAMES):
            said = ["the"] if words[k] in OWNERS else []
            read.append((" ".join(words[k:j]), " ".join(said) or "nothing"))
            out += said
            k = j
            while words[k:k + 1] and words[k] in NAMING:
                out.append(words[k])
                k += 1
            if words[k:k + 1] and words[k] in TOYS - {"little", "wee"}:
                read.append((words[k], "nothing"))
                k += 1
            continue
        out.append(words[k])
        k += 1
    return out, tuple(read)


# A note's shorthand: an answer's form after the question ('? y/n', '(yes/no)'), 'w/' for 'with', '+' or 'vs' for 'and',
# choices split by slashes ('(static/slow/fast)'), as the grammar says them; read so, the decoder sees no unknown '/'.
ANSWER_FORMS = (["y", "/", "n"], ["yes", "/", "no"], ["true", "/", "false"])   # ', yes or no?': `tail_as_question`


def _decoration(word: str) -> bool:
    """An emoji or a mark that only decorates ('"red sedan"', '*slow*', '#crash', '🚗')."""
    return word in ('"', "*", "#", "~", "`", "_") or len(word) == 1 and unicodedata.category(word) in (
        "So", "Sk", "Mn", "Me", "Cf", "Co", "Cs")


def _complete(words: list[str], k: int) -> bool:
    """Whether a vehicle's name that begins with the colour at k goes on with a sub-type or category."""
    return words[k + 1:k + 2] != [] and words[k + 1] in NAMING and words[k + 1] not in COLOR_NAMES


def quoted_question(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question quoted by someone who relays it ('The quiz card reads "Is the blue motorbike standing still ...?" -
    help!', 'My teacher wrote this on the board: "..." What should I put down?'): the quoted question, where the
    words around it name no vehicle. With the words around it read as nothing, or the words as they are and ()."""
    marks = [k for k, w in enumerate(words) if w == '"']
    if len(marks) != 2:
        return words, ()
    a, b = marks
    quoted, around = words[a + 1:b], words[:a] + words[b + 1:]
    if not quoted or not around or NAMING & set(around) or not (quoted[-1] == "?" or quoted[0] in QUESTION_OPENERS):
        return words, ()
    return quoted + ["?"] * (quoted[-1] not in ("?", ".")), ((" ".join(around), "nothing, the question relayed"),)


def archaic_as_said(words: list[str], readable) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A verb's Early Modern '-eth' as its '-s' ('floateth' -> 'floats', 'goeth' -> 'goes', 'stoppeth' -> 'stops'),
    where the parser reads that form; with the words read so."""
    out, read = list(words), []
    for k, w in enumerate(out):
        if w in readable or len(w) < 5 or not w.endswith("eth"):
            continue
        said = next((f for f in (w[:-3] + "s", w[:-3] + "es", w[:-4] + "s") if f in readable), None)
        if said:
            read.append((w, said))
            out[k] = said
    return out, tuple(read)


# A word autocorrect changed, put right after the question as a phone's user does ('Is the green sub static? *SUV',
# '... bust ...? bus*', '... (cyan)', '... meant collided') or in brackets after it ('the red bruiser (cruiser)'): the
# word said wrong is the one the correction is most like; only a word the parser reads corrects, and only one it is
# like (half its letters at least).
STARRED = (["*", None], [None, "*"], ["(", None, ")"], ["meant", None], ["i", "meant", None], ["*", "*", None])


def corrections_starred(words: list[str], readable) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the green sub statistic when the video starts ? * static' -> 'is the green sub static when the video
    starts ?'; 'the red bruiser ( cruiser )' -> 'the red cruiser'. With the words read so, or the words as they are
    and ()."""
    end = len(words)
    while end and words[end - 1] in ("!", "."):
        end -= 1
    for form in STARRED:
        tail = words[end - len(form):end] if end >= len(form) else []
        if len(tail) != len(form) or any(f is not None and f != w for f, w in zip(form, tail)):
            continue
        said = tail[form.index(None)]
        before = words[:end - len(form)]
        if said not in readable or not said.isalpha() or said in before or not before:
            continue
        like = lambda w: SequenceMatcher(None, w, said).ratio()
        unread = [(like(w), k) for k, w in enumerate(before) if w.isalpha() and w not in readable and like(w) >= 0.5]
        candidates = unread or [(like(w), k) for k, w in enumerate(before) if w.isalpha() and len(w) > 2
                                and w not in DETERMINERS and like(w) >= 0.6]
        if not candidates:
            continue
        _, k = max(candidates)
        out = [*before[:k], said, *before[k + 1:]]
        return out, ((f"{before[k]} ... {' '.join(tail)}", said),)
    # in brackets after the word ('the grey sedate (sedan!!)')
    for k in range(1, len(words) - 2):
        if words[k] == "(" and words[k + 2:k + 3] in ([")"], ["!"]) and words[k + 1] in readable and \
                words[k - 1] not in readable and words[k - 1].isalpha() and \
                SequenceMatcher(None, words[k - 1], words[k + 1]).ratio() >= 0.5:
            close = words.index(")", k) if ")" in words[k:k + 5] else None
            if close is None or any(w != "!" for w in words[k + 2:close]):
                continue
            return [*words[:k - 1], words[k + 1], *words[close + 1:]], \
                ((" ".join(words[k - 1:close + 1]), words[k + 1]),)
    return words, ()


def shorthand_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is it fast ? y/n' -> 'is it fast ?', 'collides w/ the bus' -> 'collides with the bus', 'the car + the bus'
    (or 'vs') -> 'the car and the bus', 'its speed (static/slow/fast)' -> 'its speed : static , slow or fast'. With
    the words read so, or the words as they are and ()."""
    # a chat's decorations: emoji, quotes and asterisks around words, a hashtag's '#', '!' beside '?', '??'
    out = [w for w in words if not _decoration(w)]
    out = [w for k, w in enumerate(out) if not (w in ("!", "?") and "?" in out[k + 1:k + 2] + out[k - 1:k] and
                                                 (w == "!" or out[k + 1:k + 2] == ["?"]))]
    read = [(" ".join(w for w in words if _decoration(w) or w == "!") or "?", "nothing, a decoration")] \
        if len(out) < len(words) else []
    end = len(out) - (out[-1:] in (["?"], ["."]))
    while end > 0 and out[end - 1] in CLOSING_INTERJECTIONS and any(   # 'yes/no pls'
            out[end - 1 - len(form):end - 1] == form for form in ANSWER_FORMS):
        end -= 1
    for form in ANSWER_FORMS:
        for bracketed in (["(", *form, ")"], form):
            if out[end - len(bracketed):end] == bracketed:
                start = end - len(bracketed) - (out[end - len(bracketed) - 1:end - len(bracketed)] in ([","], [":"]))
                read.append((" ".join(out[start:end]), "nothing, an answer's form"))
                out = out[:start] + out[end:]
                end = start
    k = 0
    while k < len(out):
        if out[k:k + 2] == ["w", "/"]:
            out[k:k + 2] = ["with"]
            read.append(("w /", "with"))
        elif (out[k] in ("+", "&", "vs", "versus") or out[k] == "x" and out[k - 1:k] and out[k - 1] in NAMING and
              out[k + 1:k + 2] and out[k + 1] in NAMING) and 0 < k < len(out) - 1 and out[k - 1].isalnum() and \
                (out[k + 1].isalpha() or out[k + 1:k + 2] == ["."] and out[k] == "vs"):   # 'bus x purple car'
            read.append((out[k], "and"))
            out[k:k + 1 + (out[k + 1] == ".")] = ["and"]
        elif out[k] == "/" and 0 < k < len(out) - 1 and {out[k - 1], out[k + 1]} <= SLASHED:
            last = not (out[k + 2:k + 3] == ["/"])
            out[k] = "or" if last else ","
            read.append(("/", out[k]))
        k += 1
    # a search box's two vehicles side by side ('blue bus green truck collide'), where a collision is asked
    if asks_impact(out):
        k = 1
        while k < len(out) - 1:
            if out[k] in COLOR_NAMES and _complete(out, k) and out[k - 1] in NAMING and \
                    out[k - 1] not in COLOR_NAMES:
                out.insert(k, "and")
                read.append((f"{out[k - 1]} {out[k + 1]}", f"{out[k - 1]} and {out[k + 1]}"))
            k += 1
    # choices in brackets inside the question ('identify the speed (static, slow, or fast) of the suv when ...')
    a = out.index("(") if "(" in out else None
    b = out.index(")", a) if a is not None and ")" in out[a:] else None
    if b is not None and out[b + 1:] not in ([], ["?"], ["."]) and set(out[a + 1:b]) <= SLASHED | {",", "or", "/"} \
            and len(set(out[a + 1:b]) & SLASHED) >= 2:
        read.append((" ".join(out[a:b + 1]), "nothing, the choices"))
        out = out[:a] + out[b + 1:]
    if "(" in out and ")" in out[out.index("("):] and any(w == "/" for w, _ in read):
        a = out.index("(")
        b = out.index(")", a)
        if out[b + 1:] in ([], ["?"], ["."]):
            out = [*out[:a], ":", *out[a + 1:b], *out[b + 1:]]
    # choices said as a sentence of their own ('How fast is the bus at the start. Stationary, slow or fast?'): the
    # question's own (the last sentence was read as the question)
    stop = max((k for k, w in enumerate(out[:-1]) if w in (".", "?")), default=None)
    if stop and out[-1:] == ["?"] and "or" in out[stop + 1:] and \
            set(out[stop + 1:-1]) <= SLASHED | {",", "or"} and len(set(out[stop + 1:-1]) & SLASHED) >= 2:
        read.append((out[stop], ":"))
        out = [*out[:stop], ":", *out[stop + 1:]]
    if not read:
        return words, ()
    return out, tuple(dict.fromkeys(read))


# A label the question is put under ('Q1:', 'Question 3:', 'Quick question:'), and an aside in brackets that only
# says again what the object is ('the red sedan (the car)'): they ask nothing ('quick' read as a speed, and each
# bracket is an unknown word).
LABEL_WORDS = {"q", "question", "quick", "simple", "short", "small", "one", "another", "next", "last", "final",
               "first", "second", "third", "follow", "up", "-", "#", "no", "number", "a", "my", "here", "s", "'",
               "is", "the", "an", "easy", "hard", "tough", "tricky", "bonus", "query", "check", "hypothetical"}
# ('Here's an easy one:': 'easy' is slow; 'Hi, quick check - is ...': a greeting before it, 'quick' is fast)
ASIDE_WORDS = {"the", "a", "an", "that", "this", "one", "vehicle", "thing", "object"} | NOUNS_SAID


# ... after a greeting, or naming which clip it is about ('Hi team, re clip 3: at the moment ...')
CLIP_NAMED = {",", "re", "regarding", "concerning", "about", "on", "for", "video", "clip"} | {
    str(n) for n in range(100)}


def _label(word: str) -> bool:
    return word in LABEL_WORDS or re.fullmatch(r"q?\d+[a-z]?", word) is not None


def _decimal(words: list[str], k: int) -> bool:
    """Whether words[k] is the point of a number ('3 . 2 s')."""
    return words[k] == "." and 0 < k < len(words) - 1 and words[k - 1].isdigit() and words[k + 1][:1].isdigit()


QUICK_LABELS = {"one", "check", "question", "q", "note", "thing", "query"}


def _purpose(heading: list[str], rest: list[str]) -> bool:
    """Whether a heading before a colon only says who asks or what for, the question after it whole: it names no
    vehicle and no time, and a collision or a condition it speaks of the question says itself ('For my
    accident-reconstruction class: at the instant the pickup and the wagon collide, ...')."""
    return bool(heading) and "?" in rest and bool(OBJECT_WORDS.intersection(rest)) and \
        not set(heading) & (OBJECT_WORDS | HEADING_KEPT | START_WORDS | FILM_WORDS | FLOATING_WORDS - {"up"}) and \
        (not asks_impact(heading) or asks_impact(rest)) and \
        (not (CONDITION_OPENERS | IMAGINING | IMAGINED_SAID | CONDITION_LABELS).intersection(heading)
         or bool(CONDITION_WORDS.intersection(rest)))


# A prompt's wrapping around the question, as people paste it to an assistant ('Act as a mechanic: ...', 'Yes or no
# only: ...', 'Q: ... ? A (yes/no):'): a role, and a heading of instructions that asks nothing
PROMPT_WORDS = {"yes", "or", "no", "only", "answer", "respond", "reply", "with", "one", "word", "a", "an", "the",
                "single", "step", "by", "-", "reasoning", "is", "welcome", "fine", "but", "end", "think", "query",
                "question", "q", "task", "and", "/", "(", ")", "vehicle", "type", "colour",
                "color", "output", "format", "please", "briefly", "just", "your", "final", "instruction", "prompt",
                "following", "true", "false", "in", "words", "short", "answers", "aloud", "first", "then"}
ROLE_ENDS = {"and", ":", ",", "."}
POST_LABELS = (["thread"], ["psa"], ["hot", "take"], ["genuine", "question"], ["honest", "question"],
               ["serious", "question"], ["asking", "for", "a", "friend"], ["update"], ["edit"])


def prompt_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'act as a physics expert and tell me how fast ...' -> 'tell me how fast ...'; 'yes or no only : is it ...' ->
    'is it ...'; '... ? a ( yes / no ) :' -> '... ?'. With the wrapping read as nothing, or the words as they are
    and ()."""
    out, read = list(words), []
    # a post's labels said first ('thread', '1/', 'PSA', 'hot take:', 'genuine question:', 'asking for a friend')
    while label := next((p for p in POST_LABELS if out[:len(p)] == p), None) or \
            (out[:2] if out[:1] and out[0].isdigit() and out[1:2] == ["/"] else None):
        read.append((" ".join(label), "nothing, a label"))
        out = out[len(label) + (out[len(label):len(label) + 1] == [":"]):]
    if out[:2] == ["act", "as"]:
        end = next((k for k in range(2, min(len(out), 10)) if out[k] in ROLE_ENDS), None)
        if end is not None and not OBJECT_WORDS.intersection(out[:end]):
            read.append((" ".join(out[:end + 1]), "nothing, a role"))
            out = out[end + 1:]
    colon = out.index(":") if ":" in out[:12] else None
    if colon and set(out[:colon]) <= PROMPT_WORDS and out[colon + 1:]:
        read.append((" ".join(out[:colon + 1]), "nothing, an instruction"))
        out = out[colon + 1:]
    asked = max((k for k, w in enumerate(out) if w == "?"), default=None)
    if asked is not None and out[asked + 1:] and out[asked + 1] == "a" and set(out[asked + 1:]) <= PROMPT_WORDS | {
            ":"}:
        read.append((" ".join(out[asked + 1:]), "nothing, an answer's place"))
        out = out[:asked + 1]
    return (out, tuple(read)) if read else (words, ())


def asides_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question without its label, the remarks before it and its asides ('q1 : there are many vehicles here .
    how fast is this red sedan ( the car ) ...' -> 'how fast is the red sedan ...'). A remark is a first sentence,
    or a heading before a colon ('cycling coach here :'), that names no vehicle, motion or collision and imagines
    nothing; a heading that says a time stays. With the words read as nothing, or the words as they are and ()."""
    read = []
    while True:
        end = next((k for k, w in enumerate(words) if w in (".", "!", ":") and not _decimal(words, k)), None)
        heading = [w for j, w in enumerate(words[:end or 0]) if not (w == "quick" and words[j + 1:j + 2] and
                                                                     words[j + 1] in QUICK_LABELS)]   # 'quick one'
        if end is not None and _purpose(words[:end], words[end + 1:]) and words[end] == ":":
            pass   # 'For my accident-reconstruction class:', 'Teacher here, setting up a what-if for my class:'
        elif end is None or end + 1 == len(words) or set(heading) & (
                OBJECT_WORDS | GENERIC_NOUNS | CONDITION_OPENERS | IMAGINING | MOTION_WORDS | MOTION_DESCRIPTIONS
                | FLOATING_WORDS | STATIC_SAID) or asks_impact(heading) or _video_end(words[:end + 1]):
            break   # one that says what is asked stays, and one that says the video stopped ('video stops here .')
        # and so does a heading that says when or how to answer ('at the start :', 'true or false :'), and a first
        # sentence that says when the question's 'then' is ('Think about the last moment of the clip. ... then?')
        if words[end] == ":" and set(words[:end]) & (HEADING_KEPT | START_WORDS | FILM_WORDS) or \
                words[end] == "." and "then" in words[end + 1:] and \
                set(words[:end]) & (HEADING_KEPT | START_WORDS) - {"true", "false", "yes", "no"}:
            break
        read.append((" ".join(words[:end + 1]), "nothing, a remark"))
        words = words[end + 1:]
    if any(a == "this" and b in OBJECT_WORDS for a, b in zip(words, words[1:])):   # 'is this green bus ...'
        read.append(("this", "the"))
        words = ["the" if w == "this" and b in OBJECT_WORDS else w for w, b in zip(words, words[1:] + [""])]
    end = next((k for k, w in enumerate(words[:9]) if w in (":", ".", "-")), None)
    if end and all(_label(w) or w in INTERJECTIONS | VOCATIVES | CLIP_NAMED for w in words[:end]) and \
            any(map(_label, words[:end])) and words[end + 1:end + 2] and \
            words[end + 1] in QUESTION_OPENERS | TIME_OPENERS | CONDITION_WORDS:   # 'Q2: at the start, is ...'
        read.append((" ".join(words[:end + 1]), "nothing, a label"))
        words = words[end + 1:]
    out, k = [], 0
    while k < len(words):
        close = next((j for j in range(k + 1, min(k + 10, len(words))) if words[j] == ")"), None) \
            if words[k] == "(" and out and out[-1] in OBJECT_WORDS else None
        # ... or the vehicle named again in other words ('the blue suv ( the big car on the left )')
        if close and close > k + 1 and (ASIDE_WORDS.issuperset(words[k + 1:close]) or words[k + 1] in DETERMINERS
                                        and RENAMING.issuperset(words[k + 1:close]) and _coloured_before(out, len(out))
                                        and set(words[k + 1:close]) & set(COLOR_NAMES) <= set(out[-4:])):
            read.append((" ".join(words[k:close + 1]), "nothing, an aside"))
            k = close + 1
            continue
        # ... or the start said again ('at the outset ( frame 0 )')
        close = words.index(")", k) if words[k] == "(" and ")" in words[k:k + 5] else None
        if close and words[k + 1:close] in (*TIME_ZERO, ["the", "start"], ["at", "the", "start"]) and \
                START_WORDS & set(out):
            read.append((" ".join(words[k:close + 1]), "nothing, the start said again"))
            k = close + 1
            continue
        out.append(words[k])
        k += 1
    # a clause or appositive between commas after a vehicle already named by colour and type ('the red sedan , which
    # later hits the bus ,'): it says more about a vehicle it does not pick out
    k = 0
    while k < len(out):
        close = next((j for j in range(k + 2, min(k + 12, len(out))) if out[j] == ","), None) \
            if out[k] == "," and out[k + 1:k + 2] and out[k + 1] in ASIDE_STARTS and _coloured_before(out, k) else None
        # not where only the asking follows it ('..., the fighter it is going slow, yes or no?': the question itself)
        if close and "?" not in out[k:close] and set(out[close + 1:]) - ASKING_ONLY:
            read.append((" ".join(out[k:close + 1]), "nothing, an aside"))
            out[k:close + 1] = []
            continue
        k += 1
    # what a floating vehicle does, said again ('floating up in the air , not touching the floor ,'), or a 'not' said
    # again to stress it ('did not move at all , not one bit ,')
    for k in reversed(range(1, len(out) - 2)):
        gloss = next((g for g in (*GROUND_GLOSSES, *STRESSED_NOTS) if out[k:k + len(g)] == list(g) and (
            out[k - 1] == "," and out[k + len(g):k + len(g) + 1] in ([","], ["?"], ["."])
            or out[k - 1] == "(" and out[k + len(g):k + len(g) + 1] == [")"])), None)
        if gloss and (FLOATING_WORDS & set(out[:k]) if gloss in GROUND_GLOSSES else "not" in out[:k - 1]):
            read.append((out[k - 1] + " " + " ".join(gloss), "nothing, said again"))
            out[k - 1:k + len(gloss) + (out[k - 1] == "(")] = []
    # the ground a floating vehicle is not on, said as the other choice ('floating rather than sitting on the ground')
    for k in reversed(range(1, len(out) - 3)):
        other = next((o for o in (["rather", "than"], ["instead", "of"]) if out[k:k + 2] == o), None)
        j = k + 2 + (out[k + 2:k + 3] != [] and out[k + 2] in RESTING)
        fall = other and out[k + 2:k + 3] in (["falling"], ["dropping"], ["descending"], ["sinking"])
        if other and (out[j:j + 2] == ["on", "the"] and out[j + 2:j + 3] in (["ground"], ["floor"]) or fall) and \
                FLOATING_WORDS & set(out[:k]):
            end = k + 3 if fall else j + 3 + (out[k - 1] == "," and out[j + 3:j + 4] == [","])
            read.append((" ".join(out[k:end]), "nothing, said again"))
            out[k - (out[k - 1] == ","):end] = []
    # a condition's consequence closed by 'then' ('Would the bike crash into the dirt bike then?'); not the 'then' of
    # a moment, read from the context (`context_as_question`)
    if out[-2:] == ["then", "?"] and {"would", "if", "had", "suppose", "imagine", "were"} & set(out):
        read.append(("then", "nothing"))
        out[-2:-1] = []
    return out, tuple(read)


RESTING = {"sitting", "resting", "standing", "being", "parked", "lying", "staying", "sat", "stood"}
GROUND_GLOSSES = tuple((*n, t, s) for n in (("not", "touching"), ("not", "on")) for t in ("the", "any")
                       for s in ("floor", "ground")) + (("off", "the", "ground"), ("off", "the", "floor"))
STRESSED_NOTS = (("not", "one", "bit"), ("not", "a", "bit"), ("not", "even", "a", "little"), ("not", "an", "inch"),
                 ("not", "at", "all"), ("not", "even", "a", "bit"))


RENAMING = ASIDE_WORDS | OBJECT_WORDS | set(COLOR_NAMES) | {"gray", "grey"} | {
    w for name in EVERYDAY_NAMES for w in name.split()} | {"big", "small", "little", "large", "long", "on", "in", "at",
                                                          "near", "by", "left", "right", "front", "back", "top",
                                                          "bottom", "side", "two", "seater", "-", "one", "far",
                                                          "middle", "centre", "center", "of", "picture", "frame"}
HEADING_KEPT = {"end", "ends", "finish", "after", "before", "once", "when", "while", "later", "future", "beyond",
                "first", "last", "moment", "instant", "frame", "frames", "time", "true", "false", "yes", "no",
                "past", "predicted", "rollout", "cutoff"}
ASIDE_STARTS = {"which", "who", "the", "a", "an", "by", "currently", "also", "incidentally", "with"}
ASKING_ONLY = {"yes", "or", "no", "true", "false", "right", "correct", "?", ".", "!"}
# A time or a frequency said between commas after the subject ('does the red biplane , at some point , hit ...', 'is
# the red car , when it hits the bus , fast ?'): the grammar says it last
INSERTED_TIMES = {"at", "in", "during", "ever", "right", "initially", "once", "when", "while", "after", "before",
                  "later", "from"}


def inserted_time_last(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question with a time between commas after its first vehicle put last ('does the red biplane , at any
    point , collide with the green sedan ?' -> '... collide with the green sedan at any point ?'), where the sentence
    goes on after it. With the words read so, or the words as they are and ()."""
    for k in range(1, len(words) - 2):
        if words[k] != "," or words[k - 1] not in OBJECT_WORDS or words[k + 1] not in INSERTED_TIMES:
            continue
        close = next((j for j in range(k + 2, min(k + 10, len(words))) if words[j] in (",", "?", ".")), None)
        if close is None or words[close] != "," or close + 1 == len(words) or words[close + 1] in QUESTION_OPENERS:
            return words, ()
        end = len(words) - (words[-1] in ("?", "."))
        moved = words[:k] + words[close + 1:end] + words[k + 1:close] + words[end:]
        return moved, ((" ".join(words[k:close + 1]), f"'{' '.join(words[k + 1:close])}' said last"),)
    return words, ()


def _coloured_before(words: list[str], k: int) -> bool:
    """Whether the words before k end with a vehicle named by its colour and type ('the red sedan')."""
    j = k
    while j and words[j - 1] in OBJECT_WORDS and words[j - 1] not in COLOR_NAMES:
        j -= 1
    return j < k and j > 0 and words[j - 1] in COLOR_NAMES


def type_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'what kind of plane is ...' -> 'what type of plane is ...': the grammar asks a vehicle's kind or sort only of a
    'vehicle', its type of any noun (the decoder read 'what kind of plane is floating?' as whether it floats). With
    the words read so, or the words as they are and (). 'the category of' and 'the class of' ask it too ('identify
    the category of the object that floats' was read as its colour)."""
    for k in range(1, len(words) - 2):
        if words[k - 1] in ASKING and words[k] in ("kind", "sort") and words[k + 1] == "of" and \
                words[k + 2] in NAMING and words[k + 2] not in COLOR_NAMES or \
                words[k - 1] in ASKING | {"the"} and words[k] in ("category", "class") and words[k + 1] == "of":
            return words[:k] + ["type"] + words[k + 1:], ((f"{words[k]} of", "type of"),)
    return words, ()


AFLOAT_SAID = {"floating", "hovering", "airborne", "flying"}
PLANE_SAID = {"plane", "aeroplane", "airplane", "aircraft"}


def floating_plane_as_vehicle(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the floating plane' -> 'the floating vehicle': only aeroplanes float, so the noun says nothing more, and the
    decoder read a bare plane after 'floating' as a second object ('what colour is the floating plane?' as a collision
    partner's). With the words read so, or the words as they are and ()."""
    for k in range(2, len(words)):
        if words[k] in PLANE_SAID and words[k - 1] in AFLOAT_SAID and words[k - 2] in DETERMINERS:
            return words[:k] + ["vehicle"] + words[k + 1:], ((f"{words[k - 1]} {words[k]}", f"{words[k - 1]} vehicle"),)
        # 'what kind of aircraft was hovering?' (read as whether one was, where 'is floating' read right)
        after = words[k + 1 + (words[k + 1:k + 2] in (["is"], ["was"], ["are"], ["were"])):][:1]
        if words[k] in PLANE_SAID and words[k - 2:k] in ([t, "of"] for t in SHAPE_ASKED) and after and \
                after[0] in AFLOAT_SAID:
            return words[:k] + ["vehicle"] + words[k + 1:], ((f"of {words[k]}", "of vehicle"),)
    return words, ()


# A preamble that frames the question and asks nothing ('Thinking about the whole clip, do ...', 'Not sure about this
# one, but is ...'): the question is what follows it ('thinking' would be WordNet's 'imagine', a counterfactual's).
FRAMING = {"thinking", "looking", "watching", "considering", "judging", "going", "seeing", "observing", "viewing",
           "based"}
TIME_SAID = {"moment", "instant", "when", "while", "during"}   # a preamble saying when stays
POLITE = {"trouble", "mind", "possible", "bother"}
QUESTION_OPENERS = {"is", "was", "are", "were", "do", "does", "did", "will", "would", "can", "could", "has", "have",
                    "how", "what", "which", "where"}


def framing_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question after a framing preamble that names no object (its 'it' would lose what it stands for): a
    participle's phrase, of one or more commas ('looking at the video ,'), a hedge ('if you had to guess ,'), or any
    phrase before ', but' ('not sure about this one , but'), where a question follows it and the preamble sets no
    condition and no time ('thinking only about the moment they collide ,' says when). With the preamble read as
    nothing, or the words as they are and ()."""
    # 'from the footage , at what speed ...': where the question looks, which is the video (the start was read)
    j = 1 + (words[1:2] in (["the"], ["this"]))
    if words[:1] == ["from"] and words[j:j + 2] and words[j] in FILM_WORDS and words[j + 1] == ",":
        return words[j + 2:], ((" ".join(words[:j + 2]), "nothing, a preamble"),)
    k = next((k for k, w in enumerate(words) if w == "," and words[k + 1 + (words[k + 1:k + 2] == ["but"]):][:1]
              and words[k + 1 + (words[k + 1:k + 2] == ["but"])] in QUESTION_OPENERS), None)
    if k is None:
        return words, ()
    main = words[k + 1 + (words[k + 1:k + 2] == ["but"]):]
    # 'if you had to guess', 'if it is not too much trouble': no counterfactual's condition
    hedge = words[:2] in (["if", "you"], ["if", "i"]) or words[:1] == ["if"] and bool(POLITE.intersection(words[:k]))
    framed = (words[0] in FRAMING or hedge or words[k + 1:k + 2] == ["but"]) and \
        not OBJECT_WORDS.intersection(words[:k])
    if not framed or (CONDITION_WORDS.intersection(words[:k]) and not hedge) or asks_impact(words[:k]) or \
            TIME_SAID.intersection(words[:k]):
        return words, ()
    return main, ((" ".join(words[:k]), "nothing, a preamble"),)


# A preamble before a colon or a dash (or a comma, before the question's opener) that says nothing the question needs:
# an office's ('Looping in the wider group -', 'Per the brief from leadership,', 'FYI, need a yes/no for the deck:'),
# or a reason given in jest ('Because obviously a school bus has nowhere to be:', 'As if gravity were optional:'),
# where the question names its own vehicles.
REASONS = (["because"], ["cause"], ["cos"], ["since"], ["as", "if"], ["given", "how"])
TAGGING = {"right", "yeah", "innit", "eh"}
PLACE_OPENERS = {"at", "in", "on", "during", "upon", "by", "from", "over", "throughout", "near", "around"}


def preamble_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'per the brief from leadership , what colour is ...' -> 'what colour is ...'. With the preamble read as
    nothing, or the words as they are and ()."""
    # (a reason's tag closes it: 'because slowing down solves everything , right ? if ...')
    k = next((k for k in range(1, min(len(words) - 1, 16)) if words[k] in (":", "-") or words[k] == "," and (
        words[k + 1] in QUESTION_OPENERS or words[k + 1] == "which") or words[k] == "?" and words[k - 1] in TAGGING),
             None)
    if k is None:
        return words, ()
    pre, main = words[:k], words[k + 1:]
    named = mentions(main) and (not {"it", "they"} & set(main) or not NAMING & set(pre))
    reason = any(pre[:len(r)] == r for r in REASONS) and named and not {"had", "?"} & set(pre)
    pre = pre[2 + (pre[2:3] == [","]):] if pre[:2] == ["going", "forward"] else pre   # an office's 'going forward'
    # ('need a yes / no for the deck :', 'per the brief from leadership ,'; not 'in the final frame ,')
    said = [w for w in pre if w not in ("yes", "no", "/", "from", "in", "at", "on", "to", "of", "per")]
    # (a clause of time, its word perhaps misspelt: 'at the very beginnng ,')
    quiet = words[k] != "?" and pre[0] not in TIME_OPENERS | PLACE_OPENERS and not _says_something(said) and not (
        STOP_CUES | FUTURE_CUES | CONDITION_LABELS | {"?", ".", "top", "bottom"}) & set(said) or set(pre) <= TAGGING
    if not (reason or quiet) or not main or not (main[0] in QUESTION_OPENERS | {"which", "tell", "if", "when"}
                                                  or named):
        return words, ()
    return main, ((" ".join(words[:k + 1]), "nothing, a preamble"),)


# A first sentence or phrase that points at an object ('Watch the yellow bus. Does it hit anything?', 'How about the
# blue bus, is it fast?', 'This is about the red sedan. Does it ...', 'There is a red sedan in the video. Is it ...'):
# the question about it. A sentence of pointing words only: one that says more ('The red sedan is parked.', 'The
# cruiser shows up at some point.') may set what the question asks, and stays.
ATTENDING = (["look", "at"], ["look", "closely", "at"], ["look", "carefully", "at"], ["watch"], ["consider"],
             ["circling", "back", "on"], ["circling", "back", "to"], ["following", "up", "on"],
             ["focus", "on"], ["observe"], ["notice"], ["check"],
             ["how", "about"], ["what", "about"], ["about"], ["regarding"], ["concerning"], ["as", "for"],
             ["as", "to"])
POINTING_ENDS = {".", ":", ";", ",", "?", "-"}
POINTING_WORDS = {"this", "that", "it", "is", "s", "'", "am", "m", "are", "i", "we", "you", "my", "our", "me", "one",
                  "question", "questions", "about", "regarding", "concerning", "concerns", "interested", "in", "have",
                  "has", "got", "a", "an", "the", "quick", "let", "us", "talk", "look", "at", "watch", "consider",
                  "focus", "on", "observe", "notice", "check", "out", "take", "there", "here", "now", "want", "to",
                  "ask", "see", "saw", "spot", "video", "clip", "scene", "of", "please", "just", "ve", "d", "like"}
DEFINITE = {"the", "that", "this", "a", "an"}


def _pointed_at(words: list[str]) -> int | None:
    """Where the object begins in a first sentence of pointing words ('this is about the red sedan .'), or None."""
    k = 0
    while k < len(words) and words[k] in POINTING_WORDS and words[k] not in OBJECT_WORDS and not (
            words[k] in DEFINITE and words[k + 1:k + 2] and words[k + 1] in OBJECT_WORDS):
        k += 1
    return k if k < len(words) and (words[k] in DEFINITE or words[k] in OBJECT_WORDS) else None


def attention_as_subject(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'watch the yellow bus . does it hit anything ?' -> 'does the yellow bus hit anything ?': the object a first
    sentence or phrase points at ('how about the blue bus , is it ...', 'this is about the blue bus . is it ...') put
    for the question's first 'it' (or its 'its'), two objects ('how about the red car and the bus , do they ...') for
    its first 'they', and the pointing left out. With the words read so, or the words as they are and ()."""
    verb = next((v for v in ATTENDING if words[:len(v)] == v), None)
    start = len(verb) if verb else _pointed_at(words)
    if start is None:
        return words, ()

    def mention(k: int) -> tuple[list[str], int]:
        """The object named from word k on ('the', 'a', 'that' or 'this' first) and where it ends."""
        j = k = k + (words[k:k + 1] != [] and words[k] in DEFINITE)
        while words[j:j + 1] and words[j] in OBJECT_WORDS:
            j += 1
        return ["the", *words[k:j]] if j > k else [], j

    first, j = mention(start)
    second = []
    if first and words[j:j + 1] == ["and"]:
        second, j = mention(j + 1)
        if not second:
            return words, ()
    named = j
    while verb is None and j < len(words) and words[j] in POINTING_WORDS:   # 'there is a red sedan in the video .'
        j += 1
    # after pointing words a sentence ends ('this is about X .'); the object alone is set off by a comma too ('X , is
    # it ...')
    ends = POINTING_ENDS if verb or start == 0 and j == named else POINTING_ENDS - {",", "?"}
    if not first or words[j:j + 1] == [] or words[j] not in ends or not words[j + 1:j + 2] or \
            words[j + 1] not in QUESTION_OPENERS:
        return words, ()
    thing, question = first + (["and", *second] if second else []), words[j + 1:]
    pronouns = ("they", "them") if second else ("it", "its")
    for n, w in enumerate(question):
        if w in pronouns:
            question = question[:n] + thing + (["'", "s"] if w == "its" else []) + question[n + 1:]
            break
    else:
        if second or verb is None:
            return words, ()
    return question, ((" ".join(words[:j + 1]), f"nothing; '{pronouns[0]}' as " + " ".join(thing)),)


# A question asked as a request for it: 'Could you tell me ...', 'Do you know ...', 'I'd like to know ...',
# 'I wonder ...', 'I'm curious, ...' (after 'please', 'so', 'hey' or 'ok' said first). The grammar words requests as
# 'Tell me ...'.
REQUEST = re.compile(r"^(?:(?:please|so|hey|ok|okay|well|and|but) (?:, )?)*"
                     r"(?:(?:can|could|would|will) you (?:please |kindly )?"
                     r"(?:tell me|let me know|advise(?: me)?"
                     r"|describe(?: for me| to me)?(?= (?:which|what|how|whether)))"
                     r"|do you (?:happen to )?know"
                     r"|i (?:would |' d |want to |need to |should )(?:very much |so much |really )?"
                     r"(?:like to |love to )?know"
                     r"|i (?:am |' m |was )?(?:wondering|wonder) (?:if|whether) you (?:could|would|might|can) "
                     r"(?:possibly |kindly |please )?(?:tell me|let me know|say)"
                     r"|i (?:am |' m |was )?(?:wondering|wonder) (?:if|whether) you (?:could|would|might|can) "
                     r"(?:settle|answer|help me with|clear up) (?:something|a question|a little question|a matter)"
                     r"(?: for me)?(?: :)?"
                     r"|i (?:am |' m |was )?wondering|i wonder|tell me(?= ,)"
                     r"|(?:would|could|will|can) you be able to (?:tell me|say|tell)"
                     r"|(?:can|could|would|will) you (?:please |kindly )?tell (?:an?|this|your) (?:old |elderly |poor )?"
                     r"(?:man|woman|lady|gentleman|fellow|person|pensioner|granny|grandad|grandpa|grandma)"
                     r"|(?:i (?:am |' m )|just )curious(?: to know)?|please tell me|let me know"
                     r"|i (?:would |' d )be (?:most |very |really |so )?grateful (?:to know|if you could tell me)"
                     r"|(?:[a-z]+ ){1,4}(?:want|wants|wanted|would like|' d like|need|needs) to know"
                     r"|(?:[a-z]+ ){1,3}(?:is|are|was|were) (?:asking|wondering)"
                     r"|(?:i |we )?need(?= the )|(?:customer|user|client|caller|reporter) asks(?= wh| if| how))"
                     r" (?:, )?(?:please )?")
# whether a statement holds, asked formally ('Can it be established that ...', 'Am I right that ...'): the grammar's
# 'is it true that'
CERTAINTY = re.compile(r"^(?:(?:can|could|would) (?:it|one|we|you) (?:please |kindly )?(?:be )?"
                       r"(?:established|shown|confirmed|verified|determined|"
                       r"concluded|said|demonstrated|establish|show|confirm|verify|determine|conclude|say|tell|"
                       r"demonstrate) (?:that|whether|if)"
                       r"|(?:am i|are we) (?:right|correct) (?:in thinking |to think |to say )?that"
                       # a ticket's ('Need confirmation whether ...', 'Please verify that ...')
                       r"|(?:please )?(?:(?:i |we )?need (?:to )?)?(?:confirm|verify|confirmation|verification)"
                       r"(?: of| on| as to)? (?:that|whether|if)) ")


def request_as_imperative(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question that opens with a request for it, the request read as the grammar's 'tell me': 'can you tell me
    the speed of the red car at the start ?' -> 'tell me the speed of ...'; with the words read so (`Parse.read_as`),
    or the words as they are and ()."""
    m = CERTAINTY.match(" ".join(words) + " ")
    if m:
        rest = " ".join(words)[m.end():].split()
        return ["is", "it", "true", "that"] + rest, ((" ".join(words[:len(words) - len(rest)]), "is it true that"),)
    m = REQUEST.match(" ".join(words) + " ")
    if not m:
        return words, ()
    rest = " ".join(words)[m.end():].split()
    said = " ".join(words[:len(words) - len(rest)]).replace(" ' ", "'")
    # 'I'd like to know, is the bus fast?', '... , at the start, is it fast?': the question itself
    asked = rest.index(",") + 1 if rest[:1] and rest[0] in TIME_OPENERS and "," in rest else \
        next((j for j in range(2, 7) if rest[:1] and rest[0] in TIME_OPENERS and rest[j:j + 1] and rest[j] in
              YES_NO_OPENERS and rest[j + 1:j + 2] and rest[j + 1] in SUBJECT_STARTS | set(COLOR_NAMES)), 0)
    if rest[asked:asked + 1] and rest[asked] in YES_NO_OPENERS:
        return rest, ((said, "nothing, a request"),)
    return ["tell", "me"] + rest, ((said, "tell me"),)


IMPERATIVES = (["tell", "me"], ["describe"], ["give", "me"], ["state"], ["name"])   # not "say": "say it had been ..."
# requests for a property or a vehicle, never for yes or no ('identify the colour of the plane that floats')
ASKING_FOR = (*IMPERATIVES, ["identify"], ["determine"], ["report"], ["find"], ["give"], ["list"])


def imperative_as_stated(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A request closed by a question mark ('Describe the speed of the bus at the start?') as the grammar closes
    one, with a full stop: the question mark made the decoder read it as yes or no. With the words read so, or the
    words as they are and ()."""
    if words[-1:] != ["?"] or not any(words[:len(i)] == i for i in IMPERATIVES):
        return words, ()
    return [*words[:-1], "."], (("?", "."),)


# A yes/no question asked with its auxiliary negated ('Isn't the red car fast?', 'Doesn't it hit the bus?') asks
# the same as without: English answers it yes where the car is fast. So does a statement with a tag ('The red car is
# fast, isn't it?', '..., right?'). Only a negation inside the clause ('Is the red car not moving?') denies.
SUBJECT_STARTS = {"the", "a", "an", "any", "anything", "something", "anyone", "it", "there", "its", "this", "that",
                  "these", "those", "either", "both", "they", "some", "all"}
TAG_PRONOUNS = {"it", "they", "there", "he", "she"}
AGREEING_TAGS = (["right"], ["correct"], ["true"], ["yes"], ["no"], ["or", "not"], ["or", "nah"], ["or", "nope"],
                 ["is", "that", "right"], ["is", "that", "correct"], ["am", "i", "right"], ["am", "i", "correct"],
                 ["would", "you", "say", "so"], ["right", "or", "wrong"])


def negative_question_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is not the red car fast ?' -> 'is the red car fast ?' (the negation on the auxiliary put before the subject,
    first or after a clause said first: 'when they collide , is not the sedan faster ?'); 'the red car is fast , is
    not it ?' and '... , right ?' -> 'the red car is fast ?' (a tag after a statement with no negation of its own).
    With the words read so, or the words as they are and ()."""
    for k in range(len(words) - 2):
        if (k == 0 or words[k - 1] == ",") and words[k] in YES_NO_OPENERS and words[k + 1] == "not" and \
                (words[k + 2] in SUBJECT_STARTS or words[k + 2] in OBJECT_WORDS) and words[k + 3:] not in ([], ["?"]):
            return words[:k + 1] + words[k + 2:], ((f"{words[k]} not", words[k]),)
    end = words[-1:] if words[-1:] in (["?"], ["."]) else []
    body = words[:len(words) - len(end)]
    if body[-2:] == [",", "or"]:   # 'is it slower than the bus , or ?' (a learner's tag)
        return body[:-2] + ["?"], ((", or", "?"),)
    negative = [[w, "not", p] for w in sorted(YES_NO_OPENERS) for p in sorted(TAG_PRONOUNS)]
    for tag in negative + list(AGREEING_TAGS):
        n = len(tag) + 1
        statement = body[:-n]
        # 'is it going left , right ?' offers a choice: only a statement takes an agreeing tag
        asked = tag[1:2] != ["not"] and statement[:1] and statement[0] in YES_NO_OPENERS | ASKING | {"how"}
        if len(body) <= n or body[-n:] != [","] + tag or asked:
            continue
        # a statement's own negation only as 'not moving', which reads as static ('it is not moving , is not it ?')
        if not any(w in NEGATIONS and not (w == "not" and statement[k + 1:k + 2] and statement[k + 1] in MOTION_WORDS)
                   for k, w in enumerate(statement)):
            return statement + ["?"], ((" ".join(body[-n:]), "?"),)
    return words, ()


MOTION_NOUNS = {"speed", "velocity", "direction", "heading"}
ATTRIBUTE_NOUNS = {"color", "shape", "type", "kind", "sort"}
QUERY_NOUNS = MOTION_NOUNS | ATTRIBUTE_NOUNS


def noun_phrase_as_question(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question said as the noun phrase it asks for ('speed of the red car at the start?', 'the colour of the
    thing that floats?', 'blue scooter speed at the start?'), or asked for by 'tell me' where the grammar's 'tell me'
    never does ('tell me the speed of the red car', 'tell me the red car's direction'; it says 'tell me how fast
    ...'), read as 'what is ...'; with the words read so, or the words as they are and ()."""
    told = words[:2] == ["tell", "me"]
    k = 2 * told + (words[2 * told:2 * told + 1] == ["the"])
    nouns = MOTION_NOUNS if told else QUERY_NOUNS
    if words[k:k + 1] and words[k] in nouns and words[k + 1:k + 2] == ["of"]:
        return ["what", "is", "the"] + words[k:], ((" ".join(words[:k + 2]), f"what is the {words[k]} of"),)
    if told and k == 3:   # 'tell me the red car's speed'
        end = next((i for i in range(k, len(words)) if words[i] not in OBJECT_WORDS), k)
        if end > k and words[end:end + 2] == ["'", "s"] and words[end + 2:end + 3] and words[end + 2] in nouns:
            return ["what", "is"] + words[2:], (("tell me", "what is"),)
    # a note's 'speed at start , purple chopper ?': the noun and its time, then the vehicle alone
    cut = next((i for i in range(k + 2, len(words)) if words[i] in (",", ":", "-")), None)
    if not told and words[k:k + 1] and words[k] in MOTION_NOUNS and cut is not None:
        j = cut + 1 + (words[cut + 1:cut + 2] == ["the"])
        end = next((i for i in range(j, len(words)) if words[i] not in OBJECT_WORDS), len(words))
        if end > j and words[end:] in ([], ["?"], ["."]):
            return ["what", "is", "the", words[k], "of", "the", *words[j:end], *words[k + 1:cut], "?"], \
                ((" ".join(words[k:end]), f"what is the {words[k]} of the {' '.join(words[j:end])} "
                  + " ".join(words[k + 1:cut])),)
    # a label's 'blue scooter speed at the start?' (not 'the bus speed up ...', a learner's verb)
    end = next((i for i in range(k, len(words)) if words[i] not in OBJECT_WORDS), k)
    if not told and end > k and words[end:end + 1] and words[end] in MOTION_NOUNS and \
            words[end + 1:end + 2] not in (["up"], ["down"], ["of"]):
        said = " ".join(words[:end + 1])
        return ["what", "is", "the", words[end], "of", "the", *words[k:end], *words[end + 1:]], \
            ((said, f"what is the {words[end]} of the {' '.join(words[k:end])}"),)
    return words, ()


ALOFT_AFTER = {"above", "over", "in", "up", "off", "aloft"}   # words after "high" that make it a height


def height_as_aloft(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'high above the ground', 'high in the sky', 'high up' said of a vehicle: up in the air, which the grammar
    says 'up in the air' ('high' alone is the grammar's speed, as in 'at high speed'); not 'how high up', which
    asks a height."""
    out, read = [], []
    for k, w in enumerate(words):
        after = words[k + 1] if k + 1 < len(words) else ""
        if w == "high" and after in ALOFT_AFTER and words[k - 1:k] != ["how"]:
            read.append((f"high {after}", "up" if after == "up" else f"up {after}"))
            if after != "up":
                out.append("up")
        else:
            out.append(w)
    return out, tuple(read)


def heading_as_direction(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'heading' as a noun ('the heading of the red car', 'its heading', 'the car's heading'): its direction. The
    grammar says 'heading' only as a verb, of motion ('is the red car heading left'), and reads the noun so too
    ('what is the heading of' was read as the speed). 'how is it heading?' asks which way (it was read as its
    speed)."""
    h = len(words) - len(_head(words))
    if words[h:h + 1] == ["how"] and words[h + 1:h + 2] and words[h + 1] in AUXILIARIES and \
            {"heading", "headed"} & set(words):
        return [*words[:h], "which", "way", *words[h + 1:]], (("how", "which way"),)
    out, read = list(words), []
    for k, w in enumerate(words):
        if w == "heading" and k and (words[k - 1] in ("the", "its") or words[k - 2:k] == ["'", "s"]):
            out[k] = "direction"
            read.append(("heading", "direction"))
    return out, tuple(read[:1])


# A time said by its frame or its clock ('at t = 0', 'at frame 0'), and the first frame that shows an object ('in
# the first frame in which it is visible'): the grammar's start and its coming into view.
TIME_ZERO = (["t", "=", "0"], ["t", "0"], ["t0"], ["time", "0"], ["time", "zero"], ["frame", "0"], ["frame", "zero"],
             ["frame", "1"], ["frame", "one"])
SEEN = (["is", "visible"], ["is", "seen"], ["appears"], ["shows", "up"], ["becomes", "visible"], ["is", "in", "view"],
        ["comes", "into", "view"], ["is", "in", "sight"])


# Idioms of this domain's properties, read whole before any word is, as the words the grammar says them in: read
# word by word they meant something else ('flat out' was 'floating' through a typo fix, 'tearing along' slow,
# 'sitting tight' fast, 'right off the bat' a direction). The longest phrase at a place wins.
_START = ("at", "the", "start")
STAYED = ("stayed", "remained", "kept", "stood")
STILL = ("still", "put", "stationary", "motionless", "parked", "stopped")
IDIOMS = phrase_table({
    **{p: _START for p in (("right", "off", "the", "bat"), ("off", "the", "bat"), ("from", "the", "get", "-", "go"),
                           ("from", "the", "get", "go"), ("from", "the", "word", "go"), ("out", "of", "the", "gate"),
                           ("out", "of", "the", "gates"), ("out", "of", "the", "blocks"), ("outta", "the", "gate"),
                           ("outta", "the", "gates"), ("outta", "the", "blocks"), ("when", "things", "kick", "off"),
                           ("as", "things", "kick", "off"), ("when", "it", "all", "kicks", "off"),
                           ("when", "everything", "kicks", "off"), ("from", "the", "off"))},
    **{p: ("fast",) for p in (("flat", "out"), ("at", "full", "tilt"), ("at", "full", "throttle"), ("at", "a", "clip"),
                              ("at", "a", "good", "clip"), ("at", "a", "fair", "clip"), ("at", "quite", "a", "clip"),
                              ("like", "a", "rocket"), ("like", "the", "wind"),
                              ("like", "a", "bat", "out", "of", "hell"), ("at", "full", "pelt"), ("full", "pelt"))},
    **{(pootle, "along"): (moving, "slowly") for pootle, moving in (
        ("pootling", "moving"), ("pootles", "moves"), ("pootled", "moved"), ("pootle", "move"))},
    # a reviewer's stress ('whether the chopper is in fact standing still': 'fact' was fixed to 'fast')
    **{p: () for p in (("in", "fact"), ("in", "actual", "fact"), ("as", "a", "matter", "of", "fact"))},
    **{("following", "the", "point", *at): ("after",) for at in (("at", "which"), ("where",), ("when",))},
    # 'when first the scene begins to play', a poet's start
    **{("when", "first", "the", film, begins): _START for film in ("scene", "video", "clip", "film", "play", "show")
       for begins in ("begins", "starts", "opens", "began", "started", "opened", "beginneth", "openeth")},
    # 'the picture' as older people say the film ('when the picture first began'), not 'comes into the picture'
    **{("the", "picture", *v): ("the", "video", *v) for v in (
        ("began",), ("begins",), ("started",), ("starts",), ("opened",), ("opens",), ("first", "began"),
        ("first", "started"), ("stopped",), ("stops",), ("halted",), ("ended",), ("ends",), ("has",), ("is",), ("was",),
        ("froze",), ("freezes",), ("cuts",), ("cut",))},
    # the video going on, a bettor's or a commentator's ('once the clip carries on', 'when the action resumes')
    **{(when, "the", film, *resumes): ("after", "the", "video", "ends") for when in ("once", "when", "after")
       for film in ("video", "clip", "footage", "film", "tape", "recording", "feed", "action", "play")
       for resumes in (("resumes",), ("carries", "on"), ("continues",), ("picks", "up", "again"), ("restarts",),
                       ("starts", "again"), ("plays", "on"), ("rolls", "on"), ("goes", "on"), ("keeps", "going"))},
    **{(verb + ending, "along"): (moving, "fast") for verb in ("tear", "belt", "bomb", "barrel", "bowl", "motor",
                                                                 "pelt", "streak", "rocket", "haul", "scream", "zoom",
                                                                 "whizz", "whiz", "race")
       for ending, moving in (("ing", "moving"), ("s", "moves"), ("ed", "moved"))},
    ("hauling",): ("moving", "fast"),
    ("at", "a", "fast", "clip"): ("fast",), ("at", "speed"): ("fast",),
    **{p: ("at", "high", "speed") for p in (("at", "a", "great", "speed"), ("at", "great", "speed"))},
    **{p: _START for p in (("at", "the", "commencement"), ("at", "the", "very", "commencement"))},
    ("manner", "of", "vehicle"): ("kind", "of", "vehicle"),
    # a category by an older name of two words (one word: synonyms.txt)
    ("motor", "car"): ("car",), ("flying", "machine"): ("aeroplane",),
    ("the", "pair", "of", "them"): ("the", "two", "of", "them"),
    ("stock", "-", "still"): ("still",), ("stock", "still"): ("still",),
    # falling behind in speed ('is the airliner lagging behind the suv at the beginning?')
    **{(lag, "behind"): (moving, "slower", "than") for lag, moving in (
        ("lagging", "moving"), ("lags", "moves"), ("lagged", "moved"), ("trailing", "moving"), ("trails", "moves"),
        ("trailed", "moved"))},
    **{p: _START for p in (("right", "off", "the", "gun"), ("off", "the", "gun"), ("from", "the", "gun"),
                           ("right", "off", "the", "top"), ("off", "the", "top"),
                           *(("at", "the", "top", "of", "the", f) for f in ("clip", "video", "footage", "tape")))},
    # a ship's words for moving and standing ('dead in the water', 'making less way than')
    ("dead", "in", "the", "water"): ("static",), ("making", "way"): ("moving",), ("make", "way"): ("move",),
    **{("making", more, "way", "than"): ("moving", said, "than") for more, said in (("less", "slower"),
                                                                                    ("more", "faster"))},
    **{(crash, "together"): (collide,) for crash, collide in (
        ("crash", "collide"), ("crashes", "collides"), ("crashed", "collided"), ("smash", "collide"),
        ("bump", "collide"), ("come", "collide"), ("came", "collided"))},
    ("in", "mid", "-", "air"): ("in", "the", "air"), ("in", "midair"): ("in", "the", "air"),
    # a physics class's and a simulation's words for the start, floating and collisions
    **{p: _START for p in (("under", "the", "initial", "conditions"), ("under", "initial", "conditions"),
                           ("at", "the", "first", "timestep"), ("at", "the", "first", "time", "step"),
                           ("at", "the", "initial", "timestep"), ("at", "the", "first", "time", "-", "step"),
                           ("in", "the", "initial", "conditions"))},
    **{(*no, "the", "influence", "of", "gravity"): ("floating",) for no in (("not", "under"), ("free", "from"),
                                                                             ("free", "of"), ("outside"))},
    ("unaffected", "by", "gravity"): ("floating",), ("free", "of", "gravity"): ("floating",),
    ("contact", "event"): ("collision",), ("contact", "events"): ("collisions",),
    **{(have, "zero", v): (stand, "still") for v in ("velocity", "speed") for have, stand in (
        ("have", "stand"), ("has", "stands"), ("had", "stood"), ("having", "standing"))},
    **{(w, "zero", v): ("static",) for v in ("velocity", "speed") for w in ("at", "with")},
    # a speed class said as a simulation's bin ('the actor in the fast speed bin', 'does it fall in the slow bin')
    **{(*fall, p, "the", c, *n, b): (*verb, moving if fall else c)
       for c, moving in (("static", "static"), ("slow", "slowly"), ("fast", "fast"))
       for n in ((), ("speed",), ("velocity",)) for b in ("bin", "bucket", "class", "category") for p in ("in", "into")
       for fall, verb in (((), ()), (("fall",), ("move",)), (("falls",), ("moves",)))},
    **{(be, passed, "by"): (be, "slower", "than") for be in ("is", "was", "be", "being")
       for passed in ("outpaced", "outrun", "outran", "overtaken", "outstripped")},
    # acceleration said as a noun ('what kind of vehicle is undergoing acceleration at the start?')
    **{(verb, "acceleration"): ("accelerating",) for verb in ("undergoing", "experiencing", "showing", "under")},
    # on a screen is in view ('when it first shows up on screen')
    **{("on", *the, "screen"): ("in", "view") for the in ((), ("the",))},
    **{p: ("fast",) for p in (("full", "speed"), ("at", "full", "speed"), ("full", "throttle"), ("fast", "fast"))},
    ("bombing", "it"): ("moving", "fast"),
    ("budging",): ("moving",),
    **{(punch, *gas): (accelerate,) for punch, accelerate in (("punching", "accelerating"), ("punches", "accelerates"),
                                                              ("punched", "accelerated"), ("punch", "accelerate"))
       for gas in (("the", "gas"), ("it",))},
    # a vehicle as its rider calls it ('what kinda ride is ...', 'the ride that's ...')
    **{(*before, "ride"): (*said, "vehicle") for before, said in (
        (("the",), ("the",)), (("kind", "of"), ("kind", "of")), (("sort", "of"), ("sort", "of")),
        (("type", "of"), ("type", "of")), (("kinda",), ("kind", "of")), (("sorta",), ("sort", "of")))},
    **{(verb, "along"): (moving, "slowly") for forms in (("poking", "pokes", "poked"), ("inching", "inches", "inched"),
                                                          ("puttering", "putters", "puttered"),
                                                          ("pottering", "potters", "pottered"),
                                                          ("trundling", "trundles", "trundled"),
                                                          ("plodding", "plods", "plodded"))
       for verb, moving in zip(forms, ("moving", "moves", "moved"))},
    # coming into view said of the picture's edge ('enters the field of view', 'comes first into the picture')
    **{(enter, *seen): (come, "into", "view") for enter, come in (("enters", "comes"), ("entered", "came"),
                                                                  ("enter", "come"), ("entering", "coming"))
       for seen in (("the", "field", "of", "view"), ("the", "camera", "'", "s", "field", "of", "view"),
                    ("the", "frame"), ("the", "shot"), ("the", "image"),
                    ("first", "in", "the", "view"), ("first", "into", "the", "view"), ("first", "into", "view"))},
    **{(come, "first", "into"): ("first", come, "into") for come in ("comes", "came", "come", "coming")},
    **{(make, its, *grand, "entrance"): (come, "into", "view") for make, come in (("makes", "comes"), ("made", "came"),
                                                                              ("make", "come"), ("making", "coming"))
       for its in ("its", "an", "his", "her") for grand in ((), ("grand",), ("big",))},
    # a small collision by its everyday name
    **{("fender", *dash, bender): (crash,) for bender, crash in (("bender", "collision"), ("benders", "collisions"))
       for dash in ((), ("-",))},
    **{(clip, the): (hit, the) for clip, hit in (("clips", "hits"), ("clipped", "hit"), ("clipping", "hitting"),
                                                 ("clip", "hit")) for the in ("the", "a", "an", "into")},
    # a game's words: a vehicle spawns at the start, is afk (away from the keyboard: still), full-sends (fast),
    # trades paint (collides), has its turbo on (accelerating)
    **{p: _START for p in (("at", "spawn"), ("on", "spawn"), ("off", "spawn"), ("right", "at", "spawn"),
                           ("at", "the", "spawn"), *((w, "it", spawned) for w in ("when", "as", "once")
                                                     for spawned in ("spawned", "spawns", "spawn")))},
    **{(p, *the, "spawn"): (p, "the", "start") for p in ("from", "since") for the in ((), ("the",))},
    **{(spawn, *how): (start, *how) for spawn, start in (("spawned", "started"), ("spawns", "starts"),
                                                        ("spawn", "start"), ("spawning", "starting"))
       for how in (("slow",), ("fast",), ("static",), ("moving",), ("parked",), ("still",), ("floating",),
                   ("hovering",), ("accelerating",))},
    ("afk",): ("static",),
    # a referee's start ('at kick-off', 'on the whistle'), an engine's power, a clause's start ('as things get under
    # way'), a stop said 'dead still'
    **{(*at, *kick): (("from", "the", "start") if at[:1] == ("from",) else _START)
       for at in (("at",), ("at", "the"), ("right", "at", "the"), ("right", "at"), ("from",), ("from", "the"))
       for kick in (("kick", "-", "off"), ("kickoff",), ("kick", "off"))},
    **{p: _START for p in (("on", "the", "whistle"), ("at", "the", "whistle"), ("at", "the", "opening", "whistle"),
                           ("at", "the", "first", "whistle"), ("on", "the", "opening", "whistle"))},
    **{("under", *own, "power"): ("with", "its", "engine", "on") for own in ((), ("its", "own"), ("engine",),
                                                                              ("its", "engine's"))},
    **{(w, "things", get, *way): _START for w in ("as", "when") for get in ("get", "got", "are", "were")
       for way in (("under", "way"), ("underway",))},
    ("dead", "still"): ("still",),
    # a show's start ('right when our show begins')
    **{(w, our, show, begins): _START for w in ("when", "as") for our in ("our", "the", "this")
       for show in ("show", "episode", "programme", "program") for begins in ("begins", "starts", "opens")},
    **{("let", *us, v): (v,) for us in (("us",), ("'", "s")) for v in ("suppose", "assume", "imagine", "pretend")},
    ("let", "us", "say"): ("suppose",),
    **{(draw, "to", its, close): (ends,) for draw, ends in (("draws", "ends"), ("drew", "ended"), ("drawing", "ending"))
       for its in ("its", "a", "an") for close in ("close", "end")},
    **{(t, p): (c, p) for t, c in (("tangle", "collide"), ("tangles", "collides"), ("tangled", "collided"))
       for p in (",", "?", ".")},
    ("going", "back", "over"): ("looking", "at"),
    **{(*at, than, *dash, "speed"): (said,) for than, said in (("lower", "slower"), ("higher", "faster"))
       for dash in ((), ("-",)) for at in ((), ("at", "a"))},
    **{("speed", "check", on): ("what", "is", "the", "speed", "of") for on in ("on", "for")},
    **{("full", send): said for send, said in (("send", ("fast",)), ("sending", ("going", "fast")),
                                               ("sent", ("gone",)), ("sends", ("goes", "fast")))},
    **{(trade, "paint"): (collide,) for trade, collide in (("trade", "collide"), ("trades", "collides"),
                                                          ("traded", "collided"), ("trading", "colliding"))},
    **{(*had, "turbo", "on"): said for had, said in (((), ("accelerating",)), (("had",), ("had", "been",
                                                                                           "accelerating")),
                                                     (("has",), ("is", "accelerating")),
                                                     (("with",), ("accelerating",)))},
    **{("w", the): ("with", the) for the in ("the", "a", "an", "anything", "something", "any")},
    **{(verb, "along"): (moving, "fast") for verb, moving in (("barrelling", "moving"), ("barrelled", "moved"),
                                                             ("flying", "moving"), ("flies", "moves"),
                                                             ("flew", "moved"),
                                                             ("haring", "moving"), ("careering", "moving"),
                                                             ("careening", "moving"))},
    **{(verb, adverb): (stay, "still") for verb, stay in (("sitting", "staying"), ("sits", "stays"), ("sit", "stay"),
                                                          ("going", "staying"), ("goes", "stays"), ("go", "stay"))
       for adverb in (("tight",) if verb.startswith("s") else ("nowhere",))},
    ("on", "the", "move"): ("moving",),
    ("stayed", "where", "it", "was"): ("been", "static"),
    **{(stay, "put"): (stay, "still") for stay in ("stay", "stays", "stayed", "staying")},
    # a counterfactual's condition: 'had it stayed still' was read as had it stayed in the air
    **{("had", stayed, still): ("had", "been", "static") for stayed in STAYED for still in STILL},
    # said of a plane: 'does it come down on the wagon?' (on the ground, a landing: refused as one)
    **{(come, "down", "on", *top): (crash, "into") for come, crash in (("come", "crash"), ("comes", "crashes"),
                                                                      ("came", "crashed"), ("coming", "crashing"))
       for top in ((), ("top", "of"))},
    # within the video, not after it ('has it hit anything by the end of the video?')
    **{("by", "the", "end", "of", "the", film): ("during", "the", "video") for film in ("video", "clip", "footage",
                                                                                       "film", "recording", "movie")},
    # a learner's 'how much fast' asks how fast (not how many)
    **{("how", "much", pace): ("how", pace) for pace in ("fast", "quickly", "quick", "speedy", "rapidly")},
    # 'quick' is 'fast' ('the quick car', 'is it quick' were read as nothing); 'non-moving' is 'stationary'
    ("quick",): ("fast",),
    **{("non", *dash, "moving"): ("stationary",) for dash in ((), ("-",))},
    **{(gather, "speed"): (accelerate,) for gather, accelerate in (
        ("gathering", "accelerating"), ("gathers", "accelerates"), ("gathered", "accelerated"),
        ("gather", "accelerate"))},
    # a comparative said as a class ('the slower-moving vehicle'), as the grammar says the class
    **{(comparative, *dash, "moving"): said for comparative, said in (("slower", ("slow", "-", "moving")),
                                                                     ("faster", ("quickly", "moving")))
       for dash in ((), ("-",))},
    **{("rear", "-", end): (hit,) for end, hit in (("end", "hit"), ("ends", "hits"), ("ended", "hit"),
                                                   ("ending", "hitting"))},
    **{("t", "-", bone): (hit,) for bone, hit in (("bone", "hit"), ("bones", "hits"), ("boned", "hit"),
                                                  ("boning", "hitting"))},
    # 'does it end up hitting' is 'does it hit', said of the verbs of a collision
    **{(end, "up", gerund): (forms[k],) for k, end in enumerate(("end", "ends", "ended"))
       for gerund, forms in {"hitting": ("hit", "hits", "hit"), "colliding": ("collide", "collides", "collided"),
                             "crashing": ("crash", "crashes", "crashed"), "smashing": ("smash", "smashes", "smashed"),
                             "bumping": ("bump", "bumps", "bumped"), "running": ("run", "runs", "ran"),
                             "striking": ("strike", "strikes", "struck"), "slamming": ("slam", "slams", "slammed"),
                             "ramming": ("ram", "rams", "rammed")}.items()},
    **{(adverb, verb): (verb, "slowly") for adverb in ("barely", "hardly", "scarcely")
       for verb in ("moving", "moves", "move", "moved")},
    **{(verb, *rest): (accelerate,) for verb, accelerate in (("hitting", "accelerating"), ("hits", "accelerates"),
                                                              ("hit", "accelerate"), ("stepping", "accelerating"),
                                                              ("steps", "accelerates"), ("step", "accelerate"),
                                                              ("stepped", "accelerated"))
       for rest in ((("the", "gas"),) if verb.startswith("hit") else (("on", "the", "gas"), ("on", "it")))},
    **{(verb, *rest): (accelerate,) for verb, accelerate in (("putting", "accelerating"), ("puts", "accelerates"),
                                                              ("put", "accelerate"), ("flooring", "accelerating"),
                                                              ("floors", "accelerates"), ("floor", "accelerate"),
                                                              ("gunning", "accelerating"), ("guns", "accelerates"),
                                                              ("gun", "accelerate"), ("having", "accelerating"),
                                                              ("has", "accelerates"), ("have", "accelerate"),
                                                              ("floored", "accelerated"), ("gunned", "accelerated"),
                                                              ("had", "accelerated"))
       for rest in ((("its", "foot", "down"),) if verb.startswith("put") else (("it",),) if verb[0] in "fg"
                    else (("its", "foot", "on", "the", "gas"),) if verb != "had" else (("its", "foot", "down"),))},
    ("had", "put", "its", "foot", "down"): ("had", "accelerated"),
    **{p: ("fast",) for p in (("at", "a", "lick"), ("at", "a", "fair", "lick"), ("at", "a", "good", "lick"),
                              ("at", "quite", "a", "lick"))},
    # a collision as an idiom says it ('did it come to grief with the bus?', 'tangled with', 'ploughed into')
    **{(*come, "with"): (collide, "with") for come, collide in (
        (("come", "to", "grief"), "collide"), (("comes", "to", "grief"), "collides"),
        (("came", "to", "grief"), "collided"), (("coming", "to", "grief"), "colliding"), (("tangle",), "collide"),
        (("tangles",), "collides"), (("tangled",), "collided"), (("tangling",), "colliding"))},
    **{(plough, "into"): (crash, "into") for plough, crash in (
        ("plough", "crash"), ("ploughs", "crashes"), ("ploughed", "crashed"), ("ploughing", "crashing"),
        ("plow", "crash"), ("plows", "crashes"), ("plowed", "crashed"), ("plowing", "crashing"))},
    # a translator's time of the video ('in the beginning time', 'at the end time of video')
    **{(at, *the, when, "time"): ("at", "the", "end") if when == "end" else _START
       for at in ("at", "in") for the in ((), ("the",)) for when in ("beginning", "start", "starting", "end")},
    # a translator's comparison ('faster compared with the bus') and direction ('heading for what direction')
    **{(comparative, "compared", to): (comparative, "than") for comparative in ("faster", "slower", "quicker")
       for to in ("with", "to")},
    **{(prep, which, "direction"): ("in", which, "direction") for prep in ("for", "to", "toward", "towards")
       for which in ("what", "which")},
    ("how", "much", "speed"): ("how", "fast"),
    **{("this", film): ("the", film) for film in ("video", "clip", "footage", "film", "recording", "movie")},
    **{("right", "when", "it", starts): _START for starts in ("starts", "begins", "opens")},
    # a race's start ('right off the line') and a commentator's speed ('carrying more speed than the cruiser')
    **{(*right, "off", "the", *starting, "line"): _START for right in ((), ("right",))
       for starting in ((), ("starting",))},
    **{(carrying, "more", "speed", "than"): (going, "faster", "than") for carrying, going in (
        ("carrying", "going"), ("carries", "goes"), ("carried", "went"), ("carry", "go"))},
    # a researcher's time of the video ('during the observation window', 'in the post-observation window')
    **{(*the, "observation", window): (*the, "video") for the in ((), ("the",)) for window in ("window", "period")},
    **{(*at, "the", "post", "-", "observation", window): ("after", "the", "video") for at in ((), ("in",), ("during",))
       for window in ("window", "period")},
    **{(into, *the, "screen"): ("into", "view") for into in ("into", "onto") for the in ((), ("the",))},
    **{(when, "it", "all", *began): ("at", "the", "start") for when in ("when", "as") for began in (
        ("started",), ("starts",), ("began",), ("begins",), ("kicked", "off"), ("kicks", "off"))},
    # 'jam' said for 'hit' ('when it jammed the bike', 'will they jam each other?'; a traffic jam is refused)
    **{(jam, after): (hit, after) for jam, hit in (("jam", "hit"), ("jams", "hits"), ("jammed", "hit"),
                                                   ("jamming", "hitting")) for after in ("the", "each", "into")},
    **{p: ("accelerating",) for p in (("on", "the", "gas"), ("with", "its", "foot", "on", "the", "gas"),
                                      ("pedal", "to", "the", "metal"), ("with", "the", "pedal", "to", "the", "metal"))},
}.items())


IMAGINING = {"picture", "envision", "envisage", "visualise", "visualize"}   # said first: 'imagine' (not 'the picture')
COMING = ("comes", "come", "came", "coming")
SPEED_CARRIED = {"carrying": "moving", "carry": "move", "carried": "moved", "carries": "moves"}
APPEARING = ("appears", "appear", "appeared", "appearing")


def idioms_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is it going flat out right off the bat' -> 'is it going fast at the start'. With the idioms read so."""
    read = ()
    if words[:1] and words[0] in IMAGINING | {"imagine", "suppose"} and words[1:3] in (["this", ":"], ["this", ","],
                                                                                   ["that", ":"], ["this", "-"]):
        read, words = ((" ".join(words[:3]), "imagine"),), ["imagine", *words[3:]]   # 'Picture this: the bus ...'
    if words[:1] and words[0] in IMAGINING:
        out, more = phrases_as_said(words[1:], IDIOMS)
        return ["imagine", *out], (*read, (words[0], "imagine"), *more)
    out, more = phrases_as_said(words, IDIOMS)
    read += more
    # 'imagine the bus was parked the whole time. would ...?': the condition said in the simple past (or, a sentence
    # of its own, in the present) is the grammar's 'had been' (it was read as whether the bus is parked at the
    # collision)
    if out[:1] and out[0] in ("imagine", "suppose", "supposing"):
        end = next((k for k, w in enumerate(out) if w in (".", ",", ";", ":", "-", "?")), len(out))
        now = ("is", "are") if out[end:end + 1] in ([":"], ["."], [";"]) else ()
        k = next((k for k in range(1, end) if out[k] in ("was", "were", *now)), None)
        if k is not None:
            read += ((out[k], "had been"),)
            out[k:k + 1] = ["had", "been"]
    # the same condition inverted: 'had the plane stayed still , would it ...' (read as had it stayed in the air)
    if out[:1] == ["had"]:
        end = next((k for k, w in enumerate(out) if w in (",", "?")), len(out))
        k = next((k for k in range(2, end - 1) if out[k] in STAYED and out[k + 1] in STILL), None)
        if k is not None:
            read += ((f"{out[k]} {out[k + 1]}", "been static"),)
            out[k:k + 2] = ["been", "static"]
    # 'what speed was the suv carrying' is the speed it moves at (refused as what a vehicle carries)
    for k in range(1, len(out)):
        if out[k] in SPEED_CARRIED and "speed" in out[:k] and out[k + 1:k + 2] in ([], ["?"], ["-"], [","], ["."],
                                                                                    [":"]):
            read += ((out[k], SPEED_CARRIED[out[k]]),)
            out[k] = SPEED_CARRIED[out[k]]
    # 'when it comes into view for the first time' is the grammar's 'when it first comes into view' (it was read as
    # the start)
    for k in range(len(out)):
        if out[k:k + 4] == ["for", "the", "first", "time"]:
            seen = next((n for n in (4, 3, 2, 1) if k >= n and (out[k - n:k] in (
                [c, "into", "view"] for c in COMING) or out[k - n:k] in ([a] for a in APPEARING))), None)
            if seen:
                read += ((f"{' '.join(out[k - seen:k])} for the first time", f"first {' '.join(out[k - seen:k])}"),)
                out[k - seen:k + 4] = ["first", *out[k - seen:k]]
                break
    # 'speeding' alone is going fast, as the grammar's 'speeding along' ('is the car speeding?' was read as
    # accelerating, the grammar's 'speeding up')
    speeding = [k for k, w in enumerate(out) if w == "speeding" and out[k + 1:k + 2] not in (["up"], ["along"])]
    for k in reversed(speeding):
        out[k + 1:k + 1] = ["along"]
    return out, read + (("speeding", "speeding along"),) * bool(speeding)


def first_frames_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'at t = 0' -> 'at the start'; 'in the first frame in which it is visible' -> 'when it first appears';
    'during the opening moments' -> 'in the opening moments' (a time 'during' the video is refused as another than
    the start). With the words read so, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        if words[k] == "during" and words[k + 1:k + 2] == ["the"] and words[k + 2:k + 3] and \
                words[k + 2] in START_ADJECTIVES | {"early", "earliest", "very"}:
            out.append("in")
            read.append(("during", "in"))
            k += 1
            continue
        zero = next((z for z in TIME_ZERO if words[k:k + len(z)] == z), None)
        if zero and out[-1:] in (["at"], ["from"], ["in"]):
            out += ["the", "start"]
            read.append((" ".join(zero).replace(" = ", "="), "the start"))
            k += len(zero)
            continue
        if words[k:k + 4] in (["in", "the", "first", "frame"], ["at", "the", "first", "frame"]):
            j = k + 4
            j += next((len(r) for r in (["in", "which"], ["where"], ["that"], ["when"]) if words[j:j + len(r)] == r), 0)
            seen = next((v for v in SEEN if words[j:j + 1] == ["it"] and words[j + 1:j + 1 + len(v)] == v), None)
            if seen:
                end = j + 1 + len(seen)
                out += ["when", "it", "first", "appears"]
                read.append((" ".join(words[k:end]), "when it first appears"))
                k = end
                continue
        out.append(words[k])
        k += 1
    return out, tuple(read)


def tail_as_question(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question whose asking comes last: '..., yes or no?' and the other answer offered in a clause of its own
    ('..., or did it miss it?', '... or is it on the ground?', '... or not?': the asking dropped, a yes/no question
    says it) and '... is what?' (the question word put first: 'the red sedan speed at the start is what?' -> 'what
    is the red sedan speed at the start?'). With the words read so, or the words as they are and ()."""
    end = words[-1:] if words[-1:] in (["?"], ["."]) else []
    body = words[:len(words) - len(end)]
    for tail in ([",", "yes", "or", "no"], ["?", "yes", "or", "no"], ["yes", "or", "no"]):
        if body[-len(tail):] == tail and len(body) > len(tail):
            return body[:-len(tail)] + (end or ["?"]), ((" ".join(tail), "?"),)
    k = max((i for i, w in enumerate(body) if w == "or"), default=0)
    other = body[k + 1:]
    clause = other == ["not"] or other[:1] and other[0] in YES_NO_OPENERS and other[1:2] and (
        other[1] in TAG_PRONOUNS or other[1:3] in (["not", "it"], ["not", "they"]))   # shares none of the question
    if k > 1 and clause and not OBJECT_WORDS.intersection(other) and (NEGATIONS | OPPOSITES).intersection(other):
        return body[:k - (body[k - 1] == ",")] + (end or ["?"]), ((" ".join(body[k:]), "?"),)
    if body[-2:] in (["is", "what"], ["was", "what"]) and len(body) > 2 and body[0] not in ASKING | {"how"}:
        return ["what", body[-2], *body[:-2], *end], ((f"... {body[-2]} what", f"what {body[-2]} ..."),)
    # '(at the start ,) the red sedan is moving at what speed ?': the asking where a statement has its answer
    k = next((i for i in range(len(body)) if body[i:i + 3] in IN_PLACE), None)
    first = body.index(",") + 1 if "," in body[:k or 0] else 0
    c = next((i for i in range(first + 1, k or 0) if body[i] in ("is", "was")), None)
    if c is not None and body[first] not in ASKING | YES_NO_OPENERS | {"how", "tell"}:
        phrase = body[k:k + 3]
        return ([*body[:first], *phrase, body[c], *body[first:c], *body[c + 1:k], *body[k + 3:], *end],
                ((" ".join(phrase), "said first"),))
    return words, ()


IN_PLACE = (["at", "what", "speed"], ["at", "which", "speed"], ["at", "what", "velocity"], ["with", "what", "speed"],
            ["with", "which", "speed"], ["with", "what", "velocity"])


# Comparisons of speed: offered as a choice ('is X faster or slower than Y?') they ask which, which no family answers
SPEED_ORDER = {"faster": 1, "quicker": 1, "speedier": 1, "slower": -1}
COMPARISONS = set(SPEED_ORDER)


# A comparative said with 'more' or 'less' ('is the red car more fast than the bus?'), as the grammar says it
COMPARATIVES = {("more", "fast"): "faster", ("more", "quick"): "quicker", ("more", "slow"): "slower",
                ("less", "fast"): "slower", ("less", "quick"): "slower", ("less", "slow"): "faster"}
# longest first
PAIR_SAID = (["of", "the", "two", "vehicles"], ["of", "the", "two"], ["of", "both"], ["of", "the", "pair"])


def comparative_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'more fast' -> 'faster', 'less fast' -> 'slower' (the decoder read 'more fast' as 'fast'), 'the faster of the
    two' -> 'the faster one' (no family was read). With the words read so, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        said = COMPARATIVES.get(tuple(words[k:k + 2]))
        pair = next((p for p in PAIR_SAID if words[k:k + len(p)] == p), None) if out and out[-1] in COMPARISONS \
            else None
        if said:
            out.append(said)
            read.append((" ".join(words[k:k + 2]), said))
            k += 2
        elif pair:
            out.append("one")
            read.append((" ".join(pair), "one"))
            k += len(pair)
        else:
            out.append(words[k])
            k += 1
    return out, tuple(read)


# What a question offers to choose from ('is it fast or slow?', 'is it going left or right?'), each by the words that
# say it; the grammar's list of the choices asks which one
SPEED_CHOICES = {**{(w,): "static" for w in ("static", "stationary", "still", "parked", "motionless", "stopped")},
                 **{("not", *m, *a): "static" for m in (("moving",), ("going",), ("travelling",), ("traveling",),
                                                          ("in", "motion")) for a in ((), ("at", "all"))},
                 # 'moving fast, slowly, or not at all', 'or standing still'
                 ("not", "at", "all"): "static", ("standing", "still"): "static", ("at", "rest"): "static",
                 ("slow",): "slow", ("slowly",): "slow", ("fast",): "fast", ("quickly",): "fast", ("quick",): "fast",
                 ("rapidly",): "fast", ("chill",): "slow"}   # a game's chat: 'afk, chill or full send?'
VIEWER = (("us",), ("me",), ("the", "camera"), ("the", "viewer"))
DIRECTION_CHOICES = {**{(w,): w for w in ("left", "right", "up", "down", "front", "back")},
                     ("upwards",): "up", ("upward",): "up", ("downwards",): "down", ("downward",): "down",
                     ("forward",): "front", ("forwards",): "front", ("backward",): "back", ("backwards",): "back",
                     ("away",): "back", **{(t, *v): "front" for t in ("towards", "toward") for v in VIEWER},
                     **{("away", "from", *v): "back" for v in VIEWER}}
# the words a note offers split by slashes ('static/slow/fast', 'left/right')
SLASHED = {w for choices in (SPEED_CHOICES, DIRECTION_CHOICES) for said in choices for w in said}
OFFERS = ((SPEED_CHOICES, "static , slow or fast", {"slow", "fast"}),
          (DIRECTION_CHOICES, "front , back , left , right , up or down", set(DIRECTION_CHOICES.values())))
# 'to the left or right of the bus' says where it is, not where it goes
PLACE_BEFORE = {"the", "to", "its", "of", "on"}


def _at_viewer(words: list[str], k: int) -> bool:
    """Whether words[k:] name the viewer ('the camera', 'us'), or 'it' after the viewer was named ('towards the
    camera or away from it'): a direction front or back."""
    return any(words[k:k + len(v)] == list(v) for v in VIEWER) or words[k:k + 1] == ["it"] and any(
        words[j:j + len(v)] == list(v) for j in range(k) for v in VIEWER if len(v) > 1)


def _choice(words: list[str], k: int, choices: dict) -> tuple[str, int] | None:
    """The choice said at words[k] and how many words say it (the longest), or None."""
    return max(((c, len(w)) for w, c in choices.items() if tuple(words[k:k + len(w)]) == w),
               key=lambda hit: hit[1], default=None)


def attributes_offered_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'what sort of aeroplane is hovering at the start , airliner , fighter , jet or biplane ?' -> '... at the start
    ?': the colours or types offered to choose from by a question asking for one, which its answer names anyway.
    With the choices read as nothing, or the words as they are and ()."""
    if words[-1:] != ["?"] or not ATTRIBUTE_NOUNS & set(words[:8]) or not {"what", "which"} & set(words[:6]):
        return words, ()
    for k in (j for j, w in enumerate(words) if w in (",", ":")):
        listed = words[k + 1:-1]
        names = [w for w in listed if w not in {",", "or", "a", "an", "the", "one", "of", "those", "these", "old"}]
        if "or" in listed and len(names) >= 2 and all(w in OBJECT_WORDS or w[:-1] in OBJECT_WORDS for w in names):
            return words[:k] + ["?"], ((" ".join(words[k:-1]), "nothing, the choices offered"),)
    return words, ()


def alternatives_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the red car fast or slow ...?' -> 'is the red car static, slow or fast ...?', 'is it going left or right?'
    -> 'is it going front, back, left, right, up or down?': speed classes or directions offered as alternatives ask
    which one, as the grammar's lists of them do (the decoder read 'fast or slow' as 'is it fast?', 'left or right'
    as the speed). Two choices at least, of speeds one slow or fast. With the words read so, or the words as they
    are and ()."""
    # asked as yes or no: an auxiliary first, or before its subject after the vehicle or a clause said first ('the
    # red car at the start , is it fast or slow')
    asking = [m for m, w in enumerate(words) if w in AUXILIARIES and (m == 0 or words[m + 1:m + 2] and (
        words[m + 1] in SUBJECT_STARTS or words[m + 1] in OBJECT_WORDS))]
    if not asking:
        return words, ()
    for i in range(asking[0] + 1, len(words)):
        for choices, listed, needed in OFFERS:
            first = _choice(words, i, choices)
            if not first or choices is DIRECTION_CHOICES and words[i - 1:i] and words[i - 1] in PLACE_BEFORE:
                continue
            said, k = [first[0]], i + first[1]
            while True:
                sep = next((s for s in ([",", "or"], ["or"], [","]) if words[k:k + len(s)] == s), None)
                nxt = _choice(words, k + len(sep), choices) if sep else None
                if not nxt:
                    break
                said.append(nxt[0])
                k += len(sep) + nxt[1]
                if "or" in sep:
                    break
            if len(set(said)) >= 2 and set(said) & needed and "or" in words[i:k]:
                return (words[:i] + listed.split() + words[k:],
                        ((" ".join(words[i:k]).replace(" ,", ","), listed.replace(" ,", ",")),))
    return words, ()


# The video's end said by another time word ('once the video is over', 'when the clip is done'): the grammar's
# 'after the video ends', the future (a 'when' or 'once' clause reads as the video's own time otherwise).
END_SAID = {"ends", "ended", "finishes", "finished", "stops", "stopped"}
END_OPENERS = (["once"], ["when"], ["as", "soon", "as"], ["by", "the", "time"], ["after"], ["as"], ["since"],
               ["given", "that"], ["given"], ["now", "that"], ["with"],
               *([p, "the", "point", w] for p in ("beyond", "past", "after") for w in ("where", "at", "when")))
FILM_WORDS = {"video", "clip", "footage", "film", "recording", "movie", "sequence", "cartoon", "animation", "stream",
              "replay", "feed", "tape", "playback", "livestream"}
# a video stopped part-way, as a predictive question says it ('given that the video is halted partway through')
STOPPED_SAID = (["stop"], ["stops"], ["stopped"], ["halted"], ["paused"], ["frozen"], ["froze"], ["freezes"],
                *([e, early] for e in ("ends", "ended", "finishes", "finished") for early in ("early", "abruptly")),
                ["cut", "off"],
                ["cuts", "off"], ["cuts", "out"], ["cut", "out"], ["cuts"], ["cut"], ["terminates"], ["terminated"],
                ["cut", "short"], ["is", "cut", "short"], ["was", "cut", "short"], ["'", "s", "cut", "off"],
                ["'", "s", "cut", "short"], ["is", "truncated"], ["was", "truncated"],
                *([v, p] for v in ("is", "was", "gets", "got")
                  for p in ("stopped", "halted", "paused", "frozen", "cut")),
                *(["has", "been", p] for p in ("stopped", "halted", "paused", "frozen", "cut")),
                *([*v, "cut", "off"] for v in (["is"], ["was"], ["gets"], ["got"], ["has", "been"])),
                *(["'", "s", *been, p] for p in ("stopped", "halted", "paused", "frozen") for been in ((), ("been",))))
PART_WAY = (["mid", "-", "way", "through"], ["mid", "-", "way"], ["partway", "through"],
            ["part", "-", "way", "through"], ["part", "way", "through"], ["partway"],
            ["halfway", "through"], ["halfway"], ["half", "way"], ["midway", "through"], ["midway"], ["there"],
            ["part", "of", "the", "way", "through"], ["part", "of", "the", "way"],
            ["early"], ["in", "the", "middle"])
END_PREDICATES = (["is", "over"], ["is", "done"], ["is", "finished"], ["is", "complete"], ["has", "ended"],
                  ["has", "finished"], ["ends"], ["finishes"], ["stops"], ["is", "through"], ["runs", "out"],
                  ["has", "stopped"], ["comes", "to", "an", "end"],
                  # as learners say them ('when video is finish')
                  ["is", "finish"], ["is", "end"], ["is", "ended"], ["end"], ["finish"], ["ended"], ["finished"],
                  ["over"], ["wraps", "up"], ["winds", "down"],
                  *(["'", "s", e] for e in ("over", "done", "finished", "ended", "through")))


# the video imagined going on past its end ('had the footage continued past the point where it is cut off, ...'):
# the time after it, as 'if the video went on' reads (the video otherwise, 'if it were longer', stays refused)
CONTINUED = (["continued"], ["kept", "going"], ["kept", "running"], ["kept", "rolling"], ["gone", "on"], ["went", "on"],
             ["run", "on"], ["ran", "on"], ["carried", "on"], ["played", "on"], ["not", "stopped"], ["not", "ended"],
             ["not", "been", "cut", "off"], ["not", "been", "cut"], ["not", "cut", "off"], ["to", "continue"],
             ["to", "keep", "going"], ["to", "go", "on"], ["to", "run", "on"], ["to", "carry", "on"],
             *([let, *to] for let in ("allowed", "left") for to in (["to", "carry", "on"], ["to", "continue"],
                                                                   ["to", "run", "on"], ["to", "play", "on"],
                                                                   ["to", "run"], ["to", "go", "on"])))
CONTINUING = (["had"], ["if"], ["were"])


def _video_continued(words: list[str], before: list[str] = ()) -> tuple[int, int] | None:
    """Where a clause imagining the video going on lies ('had the video continued, ...'; 'had it played on' once the
    video is named, here or in the words `before`), to its comma."""
    for i in range(len(words)):
        if [words[i]] not in CONTINUING:
            continue
        j = i + 1 + (words[i + 1:i + 2] in (["the"], ["this"]))
        # ('had it played on': only a video plays)
        named = words[j:j + 1] == ["it"] and (FILM_WORDS.intersection([*before, *words[:i]])
                                              or words[j + 1:j + 3] == ["played", "on"])
        if words[j:j + 1] == [] or words[j] not in FILM_WORDS and not named:
            continue
        j += 1 + (words[i] == "if" and words[j + 1:j + 2] == ["had"])
        were = words[i] == "were" or words[i] == "if" and words[j:j + 1] == ["were"]   # 'if the film were allowed to'
        j += words[i] == "if" and words[j:j + 1] == ["were"]
        going = next((c for c in CONTINUED if words[j:j + len(c)] == c), None)
        if going and were == (going[0] in ("to", "allowed", "left")):
            k = j + len(going)
            comma = words.index(",", k) if "," in words[k:k + 12] else k
            return i, comma
    return None


# where a simulation's or an engineer's video stops ('in the predicted rollout after the cutoff', 'past the stop point')
CUT_POINTS = tuple([*roll, p, "the", *c] for roll in ((), ("in", "the", "predicted", "rollout"),
                                                     ("in", "the", "rollout"), ("predicted", "rollout"))
                   for p in ("after", "past", "beyond") for c in (("cutoff",), ("cut", "-", "off"), ("cut", "off"),
                                                                   ("stop", "point"), ("stopping", "point"),
                                                                   ("cut", "point"), ("cut",), ("truncation",),
                                                                   ("truncation", "point"), ("cutoff", "point"),
                                                                   ("cut", "-", "off", "point"), ("freeze",)))


def _at_cut(words: list[str]) -> tuple[int, int] | None:
    at = _at(words, sorted(map(tuple, CUT_POINTS), key=len, reverse=True))
    return (at[0], at[0] + len(at[1])) if at else None


CLAUSE_SEPARATORS = {",", "-", ":", ";", "."}
FILM_KINDS = {"broadcast", "camera", "live", "video", "traffic", "tv", "news", "security", "dashcam"}


def _video_end(words: list[str], before: list[str] = ()) -> tuple[int, int] | None:
    """Where a clause of the video's end lies ('once the video is over'; a sentence of its own said first, 'stream
    froze halfway , ...'; 'after it cuts' once the video is named, here or in the words `before`), as (first,
    past-last) word."""
    for i in range(len(words)):
        opener = next((o for o in END_OPENERS if words[i:i + len(o)] == o), None)
        alone = not opener and (i == 0 or words[i - 1] in CLAUSE_SEPARATORS)
        if not opener and not alone:
            continue
        j = i + len(opener or []) + (words[i + len(opener or []):i + len(opener or []) + 1] in (["the"], ["this"]))
        j += words[j:j + 1] != [] and words[j] in FILM_KINDS and words[j + 1:j + 2] != [] and words[j + 1] in FILM_WORDS
        named = words[j:j + 1] == ["it"] and opener and FILM_WORDS.intersection([*before, *words[:i]])
        if words[j:j + 1] == [] or words[j] not in FILM_WORDS and not named:
            continue
        # said alone, the video stopped ('clip's cut off early , ...'), not ended ('the video is over . did ...?'
        # may ask about the video)
        end = next((e for e in sorted(STOPPED_SAID if alone else END_PREDICATES + STOPPED_SAID, key=len, reverse=True)
                    if words[j + 1:j + 1 + len(e)] == e), None)
        if end:
            k = j + 1 + len(end)
            part = next((p for p in PART_WAY if words[k:k + len(p)] == p), [])
            k += len(part)
            # '... before the play finishes ,': what the video stopped before
            sep = next((m for m in range(k + 1, min(k + 9, len(words))) if words[m] in CLAUSE_SEPARATORS), None)
            if words[k:k + 1] == ["before"] and sep and not NAMING.intersection(words[k:sep]) and \
                    not asks_impact(words[k:sep]):
                k = sep
            if alone and words[k:k + 1] and words[k] not in CLAUSE_SEPARATORS:
                continue   # 'the video stops before they collide': the clause is the question's own
            return i, k
    return None


def asks_impact(words: list[str]) -> bool:
    """Whether the question is about collisions: an impact's word ('collides', 'struck'), or 'into' not of coming
    into view ('runs into', 'bangs into')."""
    return any(w.startswith(IMPACT_STEMS) or w == "into" and not set(words[k + 1:k + 3]) & SIGHT_WORDS
               for k, w in enumerate(words))


def video_end_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'once the video is over, does it hit ...' -> 'after the video ends, does it hit ...', in a question about
    collisions (the only ones asked after the video; of any other it asks at the video's end, which
    `unknown_property` refuses). With the words read so, or the words as they are and ()."""
    if not asks_impact(words):
        return words, ()
    read, start = [], 0
    # the clause said first, of the video's end, its going on or its cut ('had the footage continued past the point
    # where it is cut off, ...' is one clause)
    while where := min(filter(None, (_video_end(words[start:], words[:start]),
                                     _video_continued(words[start:], words[:start]), _at_cut(words[start:]))),
                       default=None):
        i, k = start + where[0], start + where[1]
        if words[i:k] != ["after", "the", "video", "ends"]:
            read.append((" ".join(words[i:k]), "after the video ends"))
            words = words[:i] + ["after", "the", "video", "ends"] + words[k:]
        start = i + 4
    return words, tuple(read)


# A speed said as the subject of a yes/no question ('is the red car's speed low?'), by the word the grammar says
SPEED_PREDICATES = {"low": "slow", "slow": "slow", "high": "fast", "fast": "fast", "great": "fast", "zero": "static",
                    "0": "static", "nil": "static"}
START_ADJECTIVES = {"initial", "starting", "start", "beginning", "first", "opening"}


def speed_as_subject(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the red car's (initial) speed low ?', 'is the (initial) speed of the red car high at the start ?': the
    object as the subject, 'is the red car slow (at the start) ?', which the grammar says; the decoder read the speed
    as the subject as a question about accelerating or a query of the speed. With the words read so, or the words as
    they are and ()."""
    if words[:1] not in (["is"], ["was"]) or words[1:2] != ["the"]:
        return words, ()
    k = 2
    while words[k:k + 1] and words[k] in OBJECT_WORDS:
        k += 1
    if k > 2 and words[k:k + 2] == ["'", "s"]:                  # 'is the red car 's initial speed low'
        thing, k = words[1:k], k + 2
        start = words[k:k + 1] != [] and words[k] in START_ADJECTIVES
        k += start
        if words[k:k + 1] not in (["speed"], ["velocity"]):
            return words, ()
        k += 1
    else:                                                        # 'is the initial speed of the red car low'
        start = words[2:3] != [] and words[2] in START_ADJECTIVES
        k = 2 + start
        if words[k:k + 1] not in (["speed"], ["velocity"]) or words[k + 1:k + 3] != ["of", "the"]:
            return words, ()
        j = k + 2
        k += 3
        while words[k:k + 1] and words[k] in OBJECT_WORDS:
            k += 1
        thing = words[j:k]
        if len(thing) < 2:
            return words, ()
    if not words[k:k + 1] or words[k] not in SPEED_PREDICATES:
        return words, ()
    rest = words[k + 1:]
    when = ["at", "the", "start"] if start and not {"start", "beginning", "first", "initially"} & set(rest) else []
    end = len(rest) - (rest[-1:] == ["?"])
    out = ["is", *thing, SPEED_PREDICATES[words[k]], *rest[:end], *when, *rest[end:]]
    return out, ((" ".join(words[:k + 1]).replace(" ' ", "'"), " ".join(out[:len(thing) + 2])),)


# No operation negates, and the grammar words each question one way round: a model reads a reversed wording ('is it
# moving?', 'is it not accelerating?', 'does it miss the bus?') as its nearest phrase, the unreversed one, and its
# answer would be the opposite. So a reading is kept only where the question's words say what its program asks.
REST_OPERATIONS = {"is_static", "filter_static", "Counterfactual_static"}
REST_WORDS = {"static", "stationary", "still", "stop", "stops", "stopped", "stopping", "parked", "park", "rest",
              "motionless", "standing", "stand", "stands", "stood", "standstill", "halt", "halted", "idle", "stay",
              "stays", "stayed", "put", "kept", "frozen", "immobile", "unmoving", "resting", "without"}
MOTION_WORDS = {"moving", "move", "moves", "moved", "motion", "driving", "going", "travelling", "traveling",
                "rolling", "flying", "running", "underway"}
NEGATIONS = {"not", "never", "nothing", "neither", "nor", "non"}
# what a negation may deny in the grammar's own questions: motion ('not moving': rest) and a fall ('had never come
# down': floating); 'X or not' offers both answers
DENIABLE = MOTION_WORDS | {"fall", "falls", "fell", "fallen", "falling", "come", "came", "drop", "dropped", "land",
                           "landed", "descend", "descended", "sink", "sank", "sunk"}
PAST = {"been", "have", "has", "had", "even", "at", "all", "ever", "once", "yet", "really", "actually", "-"}
# words that reverse a predicate, by the operations that ask it
REVERSERS = {
    ("filter_collision",): {"miss", "misses", "missed", "missing", "avoid", "avoids", "avoided", "avoiding",
                            "dodge", "dodges", "dodged", "evade", "evades", "evaded", "escape", "escapes"},
    ("is_accelerating", "filter_accelerating", "Counterfactual_accelerating"):
        {"braking", "brake", "brakes", "braked", "off"},
    ("is_floating", "filter_floating", "Counterfactual_floating"): {"grounded", "landed", "landing", "ground", "fall",
                                                                   "falls", "fell", "fallen", "falling", "descend",
                                                                   "descends", "descended", "descending", "dropping",
                                                                   "sinking", "plunging", "plummeting"},
}
OPPOSITES = {w for reversers in REVERSERS.values() for w in reversers}
ALOFT = {"off", "above", "over", "from"}   # 'off the ground' is floating; 'on the ground', 'grounded' are not
ENGINE_WORDS = {"engine", "motor", "power", "throttle"}   # 'its engine off': not accelerating


# What a question asks is said at its head ('what is the speed of', 'how fast is', 'what colour is', 'where is it
# heading'): a word there the parser does not know is the property asked, and no other word tells the decoder what
# it is ('what is the mass of the jet' read as a collision partner's colour, 'how heavy is it' as its speed).
ASKING = {"what", "which"}
COPULAS = {"is", "was", "are", "were", "s", "'"}
AUXILIARIES = COPULAS | {"does", "did", "do"}
BARE_MENTION = {"a", "an", "any", "some", "the", "in", "this", "video", "clip", "scene", "?", "."}
WHERE_MOTION = MOTION_WORDS | {"heading", "headed", "head", "heads", "go", "goes", "went", "travel", "travels",
                               "drive", "drives", "fly", "flies", "proceed", "proceeds", "proceeding", "bound"}


# What a question may ask of a place or a size, which no question here asks, however the lexicon reads the word
# ('position' would be WordNet's 'state', 'far' its 'right', 'close' its 'next', 'high' the grammar's speed)
PARTS = {"part", "parts", "side", "sides", "section", "portion", "area", "corner", "edge", "end"}   # of a vehicle
SPATIAL = PARTS | frozenset({"distance", "position", "location", "place", "height", "altitude", "gap", "separation",
                            "size", "length", "width", "weight", "mass", "far", "close", "near", "high", "low", "tall",
                            "big", "large", "small", "long", "wide", "heavy", "apart"})
TIME_ASKED = frozenset({"when", "frame", "time", "moment", "point", "instant", "second"})   # 'at which frame ...'


ROUGHLY = (["exactly"], ["precisely"], ["just"], ["about"], ["roughly"], ["around"])   # 'at about what time'


def _head(words: list[str]) -> list[str]:
    """The question's words after a clause of time said first ('at the start , what ...'), else all of them; after
    a request for what follows ('tell me at what second ...' asks as 'at what second ...')."""
    opener = next((o for o in ASKING_FOR if words[:len(o)] == o and words[len(o):len(o) + 1] in (
        ["at"], ["in"], ["on"], ["during"])), None)
    words = words[len(opener):] if opener else words
    # 'at what time , in seconds , does ...' (or 'at about what time') asks at its first words
    k = 1 + (words[1:2] in ROUGHLY)
    return words[words.index(",") + 1:] if words[:1] and words[0] in TIME_OPENERS and "," in words and not (
        words[k:k + 1] and words[k] in ASKING) else words


def _asked(words: list[str]) -> tuple[str | None, str]:
    """The word a question's head asks about, and how it says it: 'what is the _ of' (or 'for', 'between'), 'tell
    me the _ of', 'what _ is', 'what is the red sedan's _', 'at what _', 'how _ is', 'when does' (after a clause of
    time said first); (None, '') where the head is none of these."""
    head = _head(words)
    head = head[1:] if head[:1] == ["please"] else head   # 'please state the height above ...'
    asked = None
    if head[:1] and head[0] in ASKING:
        rest = head[1:]
        while rest[:1] and rest[0] in COPULAS:
            rest = rest[1:]
        if rest[:1] == ["the"] and rest[2:3] in (["of"], ["for"], ["between"]):
            asked = rest[1]
        elif rest[1:2] and rest[1] in AUXILIARIES or rest[1:2] == ["of"] and rest[0] in PARTS:
            asked = rest[0]   # 'what colour is', 'what part of the bus'
    for opener in ASKING_FOR:
        if head[:len(opener)] == opener and head[len(opener):len(opener) + 1] == ["the"] and \
                head[len(opener) + 2:len(opener) + 3] in (["of"], ["above"], ["at"], ["from"], ["between"], ["over"]):
            asked = head[len(opener) + 1]
    if head[:1] and head[0] in ASKING and head[1:2] and head[1] in COPULAS:   # 'what is the red sedan's _'
        k = 2 + (head[2:3] == ["the"])
        while head[k:k + 1] and head[k] in OBJECT_WORDS:
            k += 1
        if k > 2 and head[k:k + 2] == ["'", "s"] and head[k + 2:k + 3]:
            asked = head[k + 2]
    exactly = 1 + (head[1:2] in ROUGHLY)
    if head[:1] and head[0] in ("at", "in", "on", "during") and head[exactly:exactly + 1] and \
            head[exactly] in ASKING and head[exactly + 1:exactly + 2]:
        # 'at what height', 'in which frame', 'at exactly what second', 'at what approx. height'
        rest = head[exactly + 1 + (head[exactly + 1:exactly + 2] in ROUGHLY):]
        asked = rest[0] if rest else head[exactly + 1]

    what = f"the '{asked}'" if asked else ""
    if head[:1] == ["how"] and head[1:2] and (head[2:3] and head[2] in AUXILIARIES or head[1] in SPATIAL):
        asked, what = head[1], f"how '{head[1]}'"
    if head[:1] == ["when"] and head[1:2] and head[1] in AUXILIARIES | {"will", "would"}:   # not 'when X hits Y, ...'
        asked, what = "when", "when"
    return asked, what


def unknown_property(words: list[str], known, said: list[str]) -> str:
    """Why the question `words` (`said`: before unknown words were read as known ones) asks a property no question
    here asks ('' when it does not): its head (`_asked`) turns on a word the parser does not know, or asks a place
    or size (SPATIAL) as said or read; it asks whether an object is there ('is there a red sedan?', nothing said
    but the object), or where an object is rather than where it is going (no word of motion, said or read, and no
    verb's '-ing' or '-ed' form)."""
    head = _head(words)
    asked, what = _asked(words)
    as_said, what_said = _asked(said)
    labelled, _ = _asked(said[len(said) - said[::-1].index(":"):]) if ":" in said else (None, "")
    if {asked, as_said, labelled} & TIME_ASKED:   # 'Replay time: at what second does ...'
        return ("the question asks when something happens, which no question here asks (they ask about the start, "
                "a collision or what comes after the video)")
    why = ("which no question here asks" if {asked, as_said} & SPATIAL else "a word the parser does not know"
           if asked is not None and asked not in known and not asked.startswith("<") else "")
    if why:
        return (f"the question asks {what_said if as_said in SPATIAL else what}, {why} (the questions here ask a "
                "vehicle's speed, direction of motion, colour or type, and about its collisions)")
    # an unknown word a possessive names is a part or property of the object's ('its headlights', the sedan's
    # 'tyres'), which the decoder would look past ('does it have its headlights on?' read as its engine)
    owned = next((w for k, w in enumerate(words) if k and w not in known and w.isalpha()
                  and (words[k - 1] == "its" or words[k - 2:k] == ["'", "s"] and words[k - 3:k - 2] and
                       words[k - 3] in OBJECT_WORDS)), None)
    if owned:
        return (f"the question asks about its '{owned}', a word the parser does not know (the questions here ask a "
                "vehicle's speed, direction of motion, colour or type, and about its collisions)")
    if head[:2] in (["is", "there"], ["are", "there"]) and set(head[2:]) <= OBJECT_WORDS | BARE_MENTION:
        return "the question asks whether an object is there, which no question here asks (they ask what it does)"
    if head[:1] == ["where"] and not WHERE_MOTION & set(head + said) and \
            not any(w.endswith(("ing", "ed")) and w not in OBJECT_WORDS for w in head + said):
        return ("the question asks where an object is, which no question here asks (they ask which way it is "
                "moving)")
    later = next((" ".join(said[k:k + 2]) for k in range(len(said) - 1) if said[k] in ORDINALS and (
        said[k + 1] in GENERIC_NOUNS | OBJECT_WORDS | {"time", "partner"} or asks_impact(said[k + 1:k + 2]))), None) \
        or next((" ".join(said[k - 1:k + 1]) for k in range(1, len(said)) if said[k] in ORDINALS - {"next"}
                 and asks_impact(said[k - 1:k])), None)   # 'what does the truck hit third?'
    if later:
        return (f"the question asks for one of several in turn ('{later}'), which no question here asks (a collision "
                "partner's question asks the first)")
    relative = next((w for k, w in enumerate(said) if w in RELATIVE_MOTION | PASSING and
                     said[k + 1 + (said[k + 1:k + 2] == ["the"]):][:1] in ([v] for v in VEHICLE_SAID)), None) or \
        next((f"{a} {b}" for k, (a, b) in enumerate(zip(said, said[1:])) if a in ("cut", "cuts", "cutting")
              and b in ("off", "in") and said[k - 1:k] not in ([w] for w in FILM_WORDS)
              and said[k + 2 + (said[k + 2:k + 3] == ["the"]):][:1] in ([v] for v in VEHICLE_SAID | set(COLOR_NAMES))),
             None)   # 'does it cut off the bus?', not 'after the video cuts off' nor 'once the video's cut off'
    if relative:
        return (f"the question asks how a vehicle moves relative to another ('{relative}'), which no question here "
                "asks: ask whether it is faster, or whether they collide")
    near = next((" ".join(said[k:k + 1 + (w == "close")]) for k, w in enumerate(said) if (w in NEAR_MISS or
                 said[k:k + 2] == ["close", "to"]) and asks_impact(said[k + 1:k + 4])), None)
    if near:
        return (f"the question asks about a near miss ('{near}'), which no question here asks: ask whether they "
                "collide")
    if any(a in LOSING and b == "control" for a, b in zip(said, said[1:])):
        return "the question asks whether a vehicle loses control, which no question here asks"
    order = next((" ".join(said[k:k + 2]) for k, w in enumerate(said) if w in COMES_IN_WORDS and
                  said[k + 1:k + 2] in (["before"], ["after"], ["first"], ["last"]) and not (
                      said[k + 1] == "after" and FILM_WORDS & set(said[k + 2:k + 4]))), None)
    if order:
        return (f"the question asks the order in which vehicles appear ('{order}'), which no question here asks (they "
                "ask how fast a vehicle is moving when it comes into view)")
    scenery = next((w for k, w in enumerate(said) if w in SCENERY and asks_impact(said[max(k - 4, 0):k])), None)
    if scenery:
        return (f"the question asks about a collision with the '{scenery}', which is no vehicle here (they ask about "
                "collisions between vehicles)")
    path = next((w for w in said if w in PATH_SHAPES), None)
    if path:
        return (f"the question asks about the shape of a vehicle's path ('{path}'), which no question here asks (they "
                "ask which way it is moving)")
    if any(a in TAKING and b == "off" for a, b in zip(said, said[1:])):
        return ("the question asks whether a plane takes off, which no question here asks (they ask whether it is "
                "floating at the start)")
    facing = next((w for w in said if w in FACING), None)
    if facing and not (WHERE_MOTION | {"sets", "starts", "started", "moving"}) & set(said):
        return (f"the question asks which way a vehicle faces ('{facing}'), which no question here asks (they ask "
                "which way it moves)")
    pose = next((w for w in said if w in POSE), None) or next(
        (" ".join(said[k:k + 2]) for k, w in enumerate(said) if w in KNOCKING and "over" in said[k + 1:k + 6]), None)
    if pose:
        return (f"the question asks how a vehicle lies ('{pose}'), which no question here asks (they ask how it "
                "moves)")
    landing = any((w in GROUND and asks_impact(said[max(k - 4, 0):k]) or w in LANDING)
                  and not NEGATIONS & set(said[max(k - 6, 0):k]) for k, w in enumerate(said)) or \
        any(said[k:k + 2] == [t, "down"] for k in range(len(said)) for t in ("touch", "touches", "touched", "touching"))
    if landing:     # ... but 'had it never touched the ground' is a counterfactual's floating
        return ("the question asks whether a vehicle lands or hits the ground, which no question here asks (they ask "
                "whether a plane is floating at the start)")
    turn = next((w for k, w in enumerate(said) if w in TURNING and said[k + 1:k + 2] not in (["on"], ["off"])
                 and not (w.startswith("drift") and {"air", "sky"} & set(said[k + 1:k + 5]))), None) \
        or next((w for w in said if w in LANES), None)   # 'drifting in the air' floats
    if turn and not ENGINE_WORDS & set(said):
        return (f"the question asks whether a vehicle turns ('{turn}'), which no question here asks (they ask which "
                "way it is moving)")
    kind = next((why.format(w) for words_of_kind, why in NO_FAMILY_WORDS for w in said if w in words_of_kind), None)
    if kind:
        return kind
    other = next((k for k, w in enumerate(said) if w in OTHER_VEHICLES), None)
    if other is not None:
        start = other
        while start and said[start - 1] in COLOR_NAMES:
            start -= 1
        return f"the question names the {' '.join(said[start:other + 1])}: no vehicle here is called '{said[other]}'"
    # 'who is driving the bus?' asks a person ('who is driving faster?' compares vehicles)
    driving = next((said[j] for k, w in enumerate(said) if w == "who" for j in range(k + 1, min(k + 4, len(said)))
                    if said[j] in DRIVING and set(said[k + 1:j]) <= COPULAS and said[j + 1:j + 2]
                    and said[j + 1] in DEFINITE | {"it", "them"}), None)
    if driving:
        return (f"the question asks about a person ('who ... {driving}'), and the videos show only vehicles (questions "
                "ask how they move and what they hit)")
    opinion = next((w for k, w in enumerate(said) if w in OPINION
                    and said[k - 2:k] not in (["in", "your"], ["in", "my"])), None)   # 'in your opinion': a hedge
    if opinion:
        return f"the question asks an opinion ('{opinion}'), which no question here asks (they ask what happens)"
    stop = next((w for k, w in enumerate(said) if w in ("stop", "stops", "stopping") and k
                 and said[k - 1] not in FILM_WORDS), None)   # not 'after the video stops'
    if stop:
        return (f"the question asks whether a vehicle comes to a stop ('{stop}'), which no question here asks (they "
                "ask whether it is static at the start or at a collision)")
    if said[:2] in (["are", "you"], ["were", "you"]) or any(   # not 'can you see whether ...': a request
            said[k:k + 3] in ([a, "you", b] for a in ("can", "could", "do", "did") for b in ("see", "spot", "notice"))
            and said[k + 3:k + 4] and said[k + 3] in DEFINITE for k in range(len(said))):
        return "the question asks about the one answering, which no question here asks (they ask about the video)"
    intent = next((w for w in said if w in INTENT), None) or next(
        (w for k, w in enumerate(said) if w in TRYING and k and said[k - 1] in VEHICLE_SAID), None)
    if intent:
        return (f"the question asks what a vehicle means to do ('{intent}'), which no question here asks (they ask "
                "what it does)")
    height = next((f"{a} {b}" for a, b in zip(said, said[1:]) if a in HEIGHT_CHANGES and b in HEIGHT_NOUNS), None)
    if height:
        return (f"the question asks about a change of height ('{height}'), which no question here asks (they ask "
                "whether a plane is floating, and which way a vehicle moves)")
    compared = next((" ".join(said[k:k + len(a) + 1]) for k in range(len(said)) for a in ACCELERATION_SAID
                     if said[k:k + len(a)] == a and said[k + len(a):k + len(a) + 1] and
                     said[k + len(a)] in COMPARISONS | {"more", "less", "harder"}), None)
    if compared:
        return (f"the question compares how fast vehicles accelerate ('{compared}'), which no question here asks: ask "
                "whether one is accelerating, or which is faster")
    around = next((w for k, w in enumerate(said) if w in ("before", "after") and asks_impact(said[k + 1:k + 5])
                   and not FILM_WORDS & set(said[k + 1:k + 3])), None)
    if around:
        return (f"the question asks about the time {around} a collision, which no question here asks (they ask at "
                "the collision itself)")
    place = next((" ".join(p) for k in range(len(said)) for p in PLACE_PHRASES if said[k:k + len(p)] == p), None)
    if place:
        return (f"the question asks where a vehicle is ('{place}'), which no question here asks (they ask which way "
                "it is moving)")
    ended = _video_end(said) or any(said[k:k + len(e)] == e for k in range(len(said)) for e in END_TIMES)
    if ended and not asks_impact(said) and not asks_impact(words):   # 'colide' as read, typos fixed
        return ("the question asks about the video's end, which no question here asks (they ask about the start, "
                "an object's coming into view, a collision, and collisions after the video)")
    return ""


def offered(words: list[str], k: int) -> bool:
    """Whether word k is in an alternative offered after 'or' ('in the air or on the ground?', '... or is it on the
    ground', 'or is it not?'): the question offers both answers, and asks the first; or denied after 'and' ('fast
    and not slowly', 'in the air and not on the ground': `properties_joined` refuses two kinds of motion)."""
    return "or" in words[max(k - 5, 0):k] or words[k - 1:k] == ["and"]


def reversed_reading(words: list[str], abstract: list[str]) -> str:
    """Why the program asks the opposite of the question ('' when it does not): motion asked as rest, a negation
    the grammar never says, or a word that reverses the program's predicate ('miss', 'braking', 'grounded')."""
    ops = {operation(t) for t in abstract}
    if ops & REST_OPERATIONS and MOTION_WORDS.intersection(words) and not (REST_WORDS | NEGATIONS).intersection(words):
        return ("the question asks whether an object is moving, which no question here asks (ask whether it is "
                "static, or slow or fast)")
    if ops & REST_OPERATIONS and (SPEED_CLASS_WORDS - COMPARISONS - {"still"}).intersection(words) and \
            not (REST_WORDS | NEGATIONS).intersection(words):
        return "the question asks a speed (slow or fast), but its nearest reading asks whether the vehicle is static"
    # 'what colour is it at the start?' was read as the colour of the static one
    if ops & REST_OPERATIONS and not (REST_WORDS | NEGATIONS | UNMOVED | RESTING).intersection(words):
        return ("the question says nothing of standing still, but its nearest reading asks about it: ask whether the "
                "vehicle is static, slow or fast")
    for k, w in enumerate(words):
        if w not in NEGATIONS or offered(words, k):
            continue
        after = [v for v in words[k + 1:k + 5] if v not in PAST]
        if not after or after[0] not in DENIABLE and after[:2] != ["in", "motion"]:
            said = " ".join(words[k:k + 3])
            return (f"the question is negated ('{said}'), which no question here asks: ask it without the "
                    "negation and take the opposite answer")
    if not NEGATIONS.intersection(words):
        for asked, reversers in REVERSERS.items():
            hit = [w for k, w in enumerate(words) if w in reversers and not offered(words, k)
                   and not (w == "off" and not ENGINE_WORDS.intersection(words))     # 'it starts off slowly'
                   and not (w == "ground" and ALOFT.intersection(words[max(k - 2, 0):k]))]
            if ops.intersection(asked) and hit:
                return (f"the question asks the opposite of what the parser can read ('{hit[0]}'): ask it the other "
                        "way round and take the opposite answer")
    return ""


# Words that open a counterfactual's condition, its vehicle said within a few words after them ('if the bus had been
# parked', 'suppose that the bus', 'in a world where the bus'); 'had' only as 'had the bus been'
CONDITION_MARKERS = {"if", "suppose", "supposing", "assuming", "assume", "imagine", "pretend", "where", "had"}


def condition_subject(words: list[str]) -> str | None:
    """The placeholder of the vehicle a counterfactual's condition changes, wherever the condition stands, or None
    where it says none (a pronoun: 'if it had been parked')."""
    for k, w in enumerate(words):
        if w not in CONDITION_MARKERS:
            continue
        for j in range(k + 1, min(k + 4, len(words))):
            if words[j].startswith("<obj"):
                if w != "had" or words[j + 1:j + 2] in (["been"], ["not"], ["never"], ["instead"]):
                    return words[j]
                break
            if words[j] not in ("the", "a", "an", "that", "only", "we", "say"):
                break
    return None


def condition_subject_first(words: list[str], abstract: list[str]) -> list[str]:
    """A counterfactual program whose changed vehicle is the one the condition names. 'Would the car have hit the bus
    if the bus had been parked?' was read as the car parked: the decoder takes the main clause's subject. A
    collision is one event of the pair, so the program with the two vehicles swapped asks the question."""
    if len(abstract) != 7 or not abstract[1].startswith("Counterfactual"):
        return abstract
    x, y = abstract[0], abstract[4]
    if condition_subject(words) != y or x == y:
        return abstract
    return [y, abstract[1], y, abstract[3], x, *abstract[5:]]


def named_attribute(words: list[str], abstract: list[str]) -> str:
    """Why an attribute query asks what the question itself names ('What is the color of the red sedan?', 'What shape
    is the blue bus?': no question here asks it; the decoder's nearest reading is a collision partner's), or ''."""
    if not any(t.startswith("query_attributes") for t in abstract):
        return ""
    for k, w in enumerate(words):
        if w not in ATTRIBUTE_NOUNS:
            continue
        rest = [v for v in words[k + 1:k + 4] if v not in ("of", "is", "the", "a", "an")]
        if rest[:1] and rest[0].startswith("<obj") and words[k + 1] in ("of", "is") and \
                words[words.index(rest[0], k) + 1:][:1] in ([], ["?"], ["."]):
            return (f"the question asks the {w} of an object it names itself, which no question here asks (ask the "
                    f"{w} of the object that collides with it, or that is static, slow, fast, accelerating or "
                    "floating)")
    return ""


SPEED_COMPARISONS = ("faster_velocity", "slower_velocity")
# the words that say a comparison of speed, the grammar's phrasings of FASTER and SLOWER among them
COMPARING = COMPARISONS | {"than", "more", "less", "higher", "lower", "greater", "swifter", "compared", "compare"}


def compared_unsaid(words: list[str], abstract: list[str], refs: list) -> str:
    """Why a speed comparison is not what the question asks, or '': the two vehicles are said side by side, each
    once, and nothing compares them ('Is the red car or the blue bus moving?', 'Are the car and the bus moving?').
    That asks about each of them; the decoder read it as whether the first is faster. ('Which is faster, X or Y?'
    compares, and is the grammar's yes/no question.)"""
    pair = sorted(placeholders(abstract))
    if operation(abstract[-1]) not in SPEED_COMPARISONS or len(pair) != 2 or \
            COMPARING.intersection(words) or any(words.count(f"<obj{k}>") != 1 for k in pair):
        return ""
    a, b = (k - 1 for k in pair)
    if (a, b) not in coordinated(words):
        return ""
    x, y = (" ".join(refs[k]).replace("_", " ") for k in (a, b))
    return (f"the question names the {x} and the {y} side by side and compares nothing, which no question here asks: "
            f"ask about one of them, or whether the {x} is faster than the {y}")


# Words of a direction or a place: only the direction queries ask about them (no question asks whether a vehicle
# moves one way, or where it is); 'up' and 'down' say other things too ('speeding up', 'slowing down'), and 'right'
# a time ('right at the start')
DIRECTION_WORDS = {"left", "right", "front", "back", "forward", "forwards", "backward", "backwards", "leftward",
                   "leftwards", "rightward", "rightwards", "upward", "upwards", "downward", "downwards", "reverse",
                   "reversing", "reversed", "reverses"}
# 'up' and 'down' said of the motion ('is the jet going up?' was read as accelerating), not of a speed ('speeding up',
# 'its speed going up', 'slowing down') nor a place ('flying up in the air')
HEIGHT_MOTIONS = {"moving", "going", "flying", "heading", "headed", "travelling", "traveling", "climbing", "rising",
                  "move", "go", "fly", "head", "moves", "goes", "flies", "heads"}
# Where a vehicle is, said by its neighbour or its distance: never a question here, whatever the lexicon reads them as
# ('behind' is its 'down')
PLACE_PHRASES = (["behind"], ["beside"], ["alongside"], ["next", "to"], ["in", "front", "of"], ["further"],
                 ["farther"], ["closer"], ["nearer"], ["nearest"], ["closest"], ["furthest"], ["farthest"],
                 # a learner's comparative of a place ('which one is more close to the camera?' was read as faster)
                 *(["more", w] for w in ("close", "near", "far", "distant")), ["close", "to"], ["near", "to"],
                 *(["parking", w] for w in ("spot", "space", "lot", "bay")))
RIGHT_AS_TIME = {"at", "when", "as", "after", "before", "away", "then", "from", "in", "on", "upon"}


def _direction_said(words: list[str]) -> str | None:
    """The first words that say a direction or a place ('left', 'towards the camera', 'away from us'), or None."""
    for k, w in enumerate(words):
        as_time = w == "right" and words[k + 1:k + 2] != [] and words[k + 1] in RIGHT_AS_TIME and \
            words[k - 1:k] not in (["the"], ["to"])   # 'right at the start', not 'to the right at the start'
        if w in DIRECTION_WORDS and not as_time:
            return w
        if w in ("up", "down") and words[k - 1:k] and words[k - 1] in HEIGHT_MOTIONS and \
                not {"speed", "velocity"} & set(words[max(k - 3, 0):k + 2]) and words[k + 1:k + 2] != ["in"]:
            return " ".join(words[k - 1:k + 1])
        j = k + 1 if w in ("towards", "toward") else k + 2 if words[k:k + 2] == ["away", "from"] else None
        viewer = next((v for v in VIEWER if j and words[j:j + len(v)] == list(v)), None)
        if viewer:
            return " ".join(words[k:j + len(viewer)])
    return None


DIRECTION_ASKED = (["which", "way"], ["what", "way"], ["what", "direction"], ["which", "direction"])


def direction_unasked(words: list[str], abstract: list[str]) -> str:
    """Why a reading that asks no direction is not the question's ('' when it is): the question asks which way
    ('which way is it going when it appears?', read as its speed then: no family asks a direction there) or turns
    on a direction or a place ('is the red car moving left?', 'is it on the left?'; the decoder read them as its
    speed or its engine)."""
    if "query_moving_direction" in abstract:
        return ""
    asked = next((" ".join(p) for k in range(len(words)) for p in DIRECTION_ASKED if words[k:k + len(p)] == p), None)
    if asked:
        return (f"the question asks '{asked}', but its nearest reading asks another property: no question here asks "
                "which way a vehicle moves but at the start or at a collision")
    said = _direction_said(words)
    if said is None:
        return ""
    return (f"the question turns on '{said}', a direction or a place, which no question here asks but 'which way "
            "is it moving' (at the start or at a collision)")


ORDINALS = {"second", "third", "fourth", "fifth", "last", "final", "next", "previous"}   # 'the second vehicle it hits'
TURNING = {"turn", "turns", "turning", "turned", "swerve", "swerves", "swerving", "steer", "steers", "steering", "veer",
           "veers", "veering", "u-turn", "rotate", "rotates", "rotating", "rotated", "spin", "spins", "spinning",
           "spun", "drift", "drifts", "drifting", "drifted", "barrel", "nosedive", "nosedives", "nosediving"}
# how a vehicle lies ('is the motorbike upright?' was read as static, 'has it toppled over?' as a collision)
POSE = {"upright", "upside", "overturned", "overturn", "overturns", "toppled", "topple", "topples", "tipped", "tip",
        "tips", "capsized", "flipped", "flip", "flips", "flipping", "tilted", "tilting", "leaning"}
# the ground is no object: 'does the plane hit the ground?', 'touch down' (a landing) read as a collision
GROUND = {"ground", "floor"}
# which way a vehicle faces, said without its motion ('which direction is the car facing at the end?')
FACING = {"facing", "faces", "pointing", "pointed", "points", "oriented", "orientated", "orientation"}
KNOCKING = {"knock", "knocks", "knocked", "knocking", "keel", "keels", "keeled"}   # '... over': a pose
LANDING = {"land", "lands", "landed", "landing"}   # said of a plane: 'is it about to land?' (a landing)
LANES = {"lane", "lanes"}   # 'does it change lanes?': a turn
# no person is in the videos ('is the scooter ridden by anyone?' was read as whether it hits anything)
PEOPLE = {"anyone", "anybody", "someone", "somebody", "driver", "drivers", "rider", "riders", "pilot", "pilots",
          "person", "people", "passenger", "passengers", "pedestrian", "pedestrians", "man", "woman", "child"}
DRIVING = {"driving", "drives", "drove", "driven", "riding", "rides", "rode", "ridden", "piloting", "pilots",
           "piloted", "flying", "flies", "flew", "steering", "steers", "steered", "operating", "operates",
           "controlling", "controls", "in", "inside", "on", "aboard"}
# a change of height ('does the plane lose height?' was read as a collision)
HEIGHT_CHANGES = {"lose", "loses", "losing", "lost", "gain", "gains", "gaining", "gained"}
HEIGHT_NOUNS = {"height", "altitude", "elevation"}
# the picture's light and weather, not the vehicles ('does the jet cast a shadow?' was read as whether it is fast)
PICTURE = {"shadow", "shadows", "reflection", "reflections", "lighting", "sun", "sunlight", "sunny", "cloud", "clouds",
           "cloudy", "rain", "raining", "rainy", "snow", "snowing", "weather", "fog", "foggy"}
# what a vehicle means to do ('does it hit the bus on purpose?' was read as whether it does)
INTENT = {"purpose", "deliberately", "intentionally", "purposely", "purposefully", "intend", "intends", "intended",
          "intending", "aiming", "aims"}
TRYING = {"try", "tries", "tried", "trying", "attempt", "attempts", "attempted", "attempting"}
# how vehicles are arranged ('are they in a queue?' was read as whether they collide), and a stall
ARRANGEMENT = {"queue", "queues", "queued", "queueing", "queuing", "convoy", "convoys", "formation", "traffic", "jam",
               "lined"}
STALLING = {"stall", "stalls", "stalled", "stalling"}
# what a vehicle has that no question asks ('what's the license plate on the truck' was read as its speed), and
# vehicles no video shows ('what colour is the boat floating ...' as the floating vehicle's colour)
FITTINGS = {"license", "licence", "plate", "plates", "registration", "brand", "logo", "logos", "wheel", "wheels",
            "tire", "tires", "tyre", "tyres", "window", "windows", "door", "doors", "headlight", "headlights", "price",
            "owner", "horsepower", "fuel", "mileage", "seat", "seats", "propeller", "propellers", "wing", "wings"}
OTHER_VEHICLES = {"boat", "boats", "ship", "ships", "train", "trains", "tram", "trams", "tractor", "tractors",
                  "helicopter", "helicopters", "drone", "drones", "balloon", "balloons", "rocket", "rockets",
                  "skateboard", "skateboards", "submarine", "yacht", "canoe", "kayak", "horse", "horses", "cart",
                  "carts", "blimp", "zeppelin", "spaceship", "ufo", "taxi", "ambulance", "limo", "limousine",
                  "locomotive", "locomotives", "glider", "gliders", "hovercraft"}
# who caused a collision ('which vehicle was at fault in the collision ...' was read as whether they collide)
FAULT = {"fault", "faults", "blame", "blamed", "blameworthy", "liable", "liability", "guilty", "culpable"}
# an opinion of a vehicle ('would you recommend the bus?' was read as whether it collides), how the video was made
# ('what physics engine made this video?' as the accelerating vehicle's colour), a physical quantity ('is gravity
# acting on the jet?' as a collision)
OPINION = {"opinion", "opinions", "recommend", "recommended", "designed", "design", "favourite", "favorite", "prefer",
           "ugly", "beautiful", "cool", "safe", "dangerous", "reckless", "recklessly", "nervous", "quality"}
MAKING = {"physics", "simulator", "simulation", "simulated", "renderer", "rendered", "rendering", "generated"}
QUANTITIES = {"gravity", "force", "forces", "energy", "momentum", "friction", "inertia", "torque", "pressure",
              "elastic", "inelastic", "bouncy", "bounciness", "restitution", "vector", "vectors", "angular",
              "rotational", "kinetic", "mass", "weight", "weighs", "altitude", "coordinates", "coordinate"}
# what is heard ('what sound does the bus make when it hits the van?' was read as its speed there)
SOUNDS = {"sound", "sounds", "noise", "noises", "noisy", "loud", "loudly", "honk", "honks", "honked", "honking", "horn",
          "horns", "beep", "beeps", "siren", "sirens", "hear", "hears", "heard", "audible", "screech", "screeches"}
# each word of a kind no family asks, and why it is refused ('{}': the word)
NO_FAMILY_WORDS = (
    (PEOPLE, "the question asks about a person ('{}'), and the videos show only vehicles (questions ask how they move "
             "and what they hit)"),
    (PICTURE, "the question asks about the picture ('{}'), not the vehicles (questions ask how they move and what "
              "they hit)"),
    (ARRANGEMENT, "the question asks how vehicles are arranged ('{}'), which no question here asks (they ask how each "
                  "moves and what it hits)"),
    (MAKING, "the question asks how the video was made ('{}'), which no question here asks"),
    (QUANTITIES, "the question asks about a physical quantity ('{}'), which no question here asks (they ask speed "
                 "classes, directions, colours, types and collisions)"),
    (STALLING, "the question asks whether a vehicle stalls ('{}'), which no question here asks"),
    (FAULT, "the question asks who is to blame ('{}'), which no question here asks (they ask who collides)"),
    (FITTINGS, "the question asks about a vehicle's '{}', which no question here asks (they ask how it moves, its "
               "colour and its type)"),
    (SOUNDS, "the question asks what is heard ('{}'), and the videos are silent (questions ask how the vehicles move "
             "and what they hit)"),
)
SCENERY = {"wall", "walls", "barrier", "barriers", "fence", "building", "buildings", "tree", "trees", "curb", "kerb",
           "pole", "sign"}   # 'does the jet hit the wall?' was read as whether it hits anything
# one vehicle's motion relative to another's ('is it chasing the bike?', 'does it overtake the bus?' were read as
# collisions), said of a vehicle ('passes the bus'; not 'passed by', 'the frames that follow')
RELATIVE_MOTION = {"overtake", "overtakes", "overtook", "overtaking", "chase", "chases", "chased", "chasing", "follow",
                   "follows", "followed", "following", "pursue", "pursues", "pursued", "pursuing", "tailing",
                   "tailgate", "tailgates", "tailgated", "tailgating", "cross", "crosses", "crossed", "crossing"}
PASSING = {"pass", "passes", "passing", "passed"}
VEHICLE_SAID = OBJECT_WORDS | {"it", "another", "vehicle", "object", "one", "thing"}
NEAR_MISS = {"nearly", "almost", "narrowly", "barely"}   # 'does it nearly hit the bus?' asks whether it does not
PATH_SHAPES = {"straight", "circle", "circles", "circular", "curve", "curves", "curved", "curving", "zigzag", "zigzags",
               "zigzagging", "diagonally", "diagonal", "sideways", "loop", "loops", "arc", "swerving", "lap", "laps",
               "circuit", "circuits", "route", "routes", "path", "paths"}
TAKING = {"take", "takes", "took", "taking", "taken", "lift", "lifts", "lifted", "lifting"}   # '... off': a take-off


# A time that is not the start, said of a motion the program reads at the start: no question asks a vehicle's motion
# in the middle, at the 2-second mark, throughout or ever (they ask at the start, when it comes into view, at a
# collision)
NOT_START = (["middle"], ["halfway"], ["half", "way"], ["midway"], ["throughout"], ["during"], ["later"], ["ever"],
             ["always"], ["eventually"], ["afterwards"], ["sometimes"], ["at", "some", "point"], ["at", "any", "point"],
             ["at", "any", "time"], ["at", "one", "point"], ["most", "of", "the", "time"], ["all", "the", "time"],
             ["the", "whole", "time"], ["whole"], ["entire"], ["now"], ["currently"], ["presently"])
CLOCK_WORDS = {"second", "seconds", "frame", "frames", "s", "sec", "secs"}
ORDINAL_WORDS = {"first", "1", "0", "one", "zero"}   # 'frame 1', 'the first second': the start


def time_unasked(words: list[str], program: list[str]) -> str:
    """Why a reading at the start is not the question's ('' when it is): the question says no word of the start but
    another time ('in the middle of the video, is the red car fast?', 'after two seconds', 'at frame 50', 'ever'),
    which the decoder read as the start."""
    if "start" not in program or START_WORDS & set(words) or "first" in words:
        return ""
    said = next((" ".join(t) for k in range(len(words)) for t in (*NOT_START, ["before"], ["until"])
                 if words[k:k + len(t)] == t), None) or _future_said(words)   # 'faster than the bus after the video?'
    clock = next((f"{a} {b}" for a, b in zip(words, words[1:]) if (a in CLOCK_WORDS and b.isdigit() or
                                                                   b in CLOCK_WORDS and (a.isdigit() or a in NUMBERS))
                  and not {a, b} & ORDINAL_WORDS), None)
    if not (said or clock):
        return ""
    return (f"the question asks at a time other than the start ('{said or clock}'), which no question here asks of a "
            "vehicle's motion (they ask at the start, when it comes into view, or at a collision)")


VISIBILITY = {"visible", "invisible", "hidden", "occluded"}   # not 'see': 'based on what you see, will ...'


def visibility_unread(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question asks whether a vehicle can be seen ('is
    the red sedan visible at the start?' was read as accelerating), which only the time of its coming into view
    reads."""
    said = next((w for w in words if w in VISIBILITY), None)
    if said is None or "come_in_frame" in program:
        # ... or goes out of it ('goes out from the view'; 'comes out from behind' is coming into it)
        leaving = next((w for w in words if w in LEAVING), None) or next(
            (f"{a} out" for a, b in zip(words, words[1:]) if a in GOING_OUT and b == "out"), None)
        if leaving and "come_in_frame" in program:   # 'when it leaves the view' was read as when it comes into it
            return (f"the question asks when a vehicle leaves the view ('{leaving}'), which no question here asks "
                    "(they ask how fast it moves when it comes into view)")
        return ""
    return (f"the question asks whether a vehicle can be seen ('{said}'), which no question here asks (they ask how "
            "fast it moves when it comes into view)")


GOING_OUT = {"go", "goes", "going", "went", "gone", "move", "moves", "moving", "moved", "drive", "drives", "driving",
             "drove", "fly", "flies", "flying", "flew", "get", "gets", "getting", "got", "pass", "passes", "passed"}
LEAVING = {"leave", "leaves", "leaving", "left", "exit", "exits", "exiting", "exited", "disappear", "disappears",
           "disappearing", "disappeared", "vanish", "vanishes", "vanished", "departs", "departed"}


def onset_asked(words: list[str]) -> str:
    """A vehicle described by its motion's beginning or end ('the vehicle that starts floating', 'that stops
    accelerating', read at the start), or ''; not a time ('after it starts moving', 'as it starts to move')."""
    said = next((f"{a} {b}" for k, (a, b) in enumerate(zip(words, words[1:])) if a in ONSETS and k and (
        words[k - 1] in PARTNER_SAID | GENERIC_NOUNS) and (b.endswith("ing") and not b.endswith("thing") or b == "to")),
                None)   # not 'the stopped thing'
    if said is None:
        return ""
    return (f"the question asks when a motion begins or ends ('{said}'), which no question here asks (they ask the "
            "motion at the start, when a vehicle comes into view, or at a collision)")


ONSETS = {"start", "starts", "started", "begin", "begins", "began", "stop", "stops", "stopped", "quit", "quits",
          "finish", "finishes", "finished"}


def collision_unread(words: list[str], program: list[str]) -> str:
    """Why a reading at the start is not the question's ('' when it is): the question (as said: 'by any chance' is
    no 'bump') also speaks of a collision ('is the red car at the start faster than the bus at the collision?' was
    read at the start alone)."""
    if "start" not in program or COLLISION_OPERATIONS.intersection(map(operation, program)) or not asks_impact(words):
        return ""
    return ("the question speaks of a collision, but its nearest reading asks at the start alone: no question here "
            "reads both")


GOING = {"go", "goes", "going", "went"}   # 'pushing it to go faster'


SPEED_READINGS = {"is_accelerating", "filter_accelerating", "query_moving_velocity", "is_moving_velocity",
                  "filter_moving_velocity"}


def uncompared(words: list[str], program: list[str]) -> str:
    """Why a reading of accelerating or of a speed is not the question's ('' when it is): it says 'faster' of nothing
    ('is the red car faster?' was read as accelerating, 'is it slower, yes or no at the start?' as its speed; 'getting
    faster', 'faster and faster' are accelerating)."""
    ops = set(map(operation, program))
    if not SPEED_READINGS & ops or {"faster_velocity", "slower_velocity"} & ops or \
            any(t.startswith("Counterfactual") for t in program):
        return ""
    said = next((w for k, w in enumerate(words) if w in COMPARISONS and not (k and words[k - 1] in BECOMING | GOING)
                 and words[k + 1:k + 2] != ["and"]), None)
    if said is None:
        return ""
    return (f"the question says '{said}' of nothing to compare with, which no question here asks: ask whether it is "
            "faster than another vehicle, or accelerating")


def collision_at_start(words: list[str], program: list[str]) -> str:
    """Why a reading of whether vehicles collide is not the question's ('' when it is): the question asks it at the
    start ('are the jet and the bus touching at the start?', read as at any time), and says no motion there for the
    start to be the time of ('does the car, parked at the start, hit the bus?')."""
    if not COLLISION_OPERATIONS.intersection(map(operation, program)) or "start" in program or \
            any(t.startswith("Counterfactual") for t in program):   # a partner's too: 'what hits it at the start?'
        return ""
    if not START_WORDS & set(words) or (SPEED_CLASS_WORDS | set(MOTION_KINDS)) & set(words):
        return ""
    return ("the question asks about a collision at the start, which no question here asks (they ask whether vehicles "
            "collide during the video or after it)")


VIDEO_PARTS = (["early", "in"], ["late", "in"], ["later", "in"], ["halfway"], ["midway"], ["in", "the", "middle"])
PART_ORDINALS = {"first", "last", "final", "next", "second", "latter"}
PART_NOUNS = {"half", "part", "few", "moments", "moment"}


def clock_unasked(words: list[str], program: list[str]) -> str:
    """Why a reading of the whole video, or of its future, is not the question's ('' when it is): the question asks
    within a time ('in the first 3 seconds', 'within 2 seconds', 'in the next 40 frames', 'in the first second'), or
    of the video's collisions within a part of it ('in the last second', 'at the end', 'in the second half'), which
    no program reads."""
    if "start" in program:
        return ""
    # a counterfactual's condition speaks of the start ('had it been slow in the first frames', '... second')
    imagined = any(t.startswith("Counterfactual") for t in program)
    clock = next((f"{a} {b}" for a, b in zip(words, words[1:]) if b in CLOCK_WORDS and (
        a.isdigit() or a in NUMBERS or not imagined and a in ORDINAL_WORDS and not b.endswith("s"))), None)
    if clock is None and "Events" in program:   # a part of the video ('in the last second', 'at the end')
        clock = next((" ".join(t) for k in range(len(words)) for t in (*END_TIMES, *VIDEO_PARTS)
                      if words[k:k + len(t)] == t), None) or next(
            (f"{a} {b}" for a, b in zip(words, words[1:]) if a in PART_ORDINALS and b in CLOCK_WORDS | PART_NOUNS),
            None)
    if clock is None:
        return ""
    return (f"the question asks within a time ('{clock}'), which no question here asks: collisions are asked over the "
            "whole video, or after it")


# A speed said as a number: '5 m/s', '20 mph', '10kph', 'five metres per second'
SPEED_UNITS = (["m", "/", "s"], ["km", "/", "h"], ["mph"], ["kph"], ["kmh"], ["mps"], ["knots"],
               ["cm", "/", "s"], *([unit, "per", time] for unit in (
                   "metres", "meters", "m", "km", "kilometres", "kilometers", "miles", "centimetres", "centimeters",
                   "cm", "millimetres", "millimeters", "mm", "feet", "foot", "ft", "inches", "pixels", "units")
                   for time in ("second", "sec", "s", "hour", "h", "minute", "min", "frame")))
SPEED_NUMBER = re.compile(r"^\d+(?:\.\d+)?(?:mph|kph|kmh|mps|m|km)$")   # a number run together with its unit


def speed_measured(words: list[str]) -> str:
    """The speed a question says as a number ('5 m / s', '20mph') or asks in a unit ('in km / h'), or ''."""
    for k, w in enumerate(words):
        unit = next((u for u in SPEED_UNITS if words[k + 1:k + 1 + len(u)] == u), None) if w == "in" else None
        if unit:
            return " ".join(["in", *unit]).replace(" / ", "/")
        number = w.isdigit() or w in NUMBERS or w in ("one", "six", "seven", "eight", "nine", "ten", "twenty")
        unit = next((u for u in SPEED_UNITS if words[k + 1:k + 1 + len(u)] == u), None) if number else None
        if unit:
            whole = words[k - 2:k] if k >= 2 and words[k - 1] == "." and words[k - 2].isdigit() else []   # '3.5'
            return " ".join(["".join([*whole, w]), *unit]).replace(" / ", "/")
        if SPEED_NUMBER.match(w) and (not w.endswith("m") or words[k + 1:k + 3] in (["/", "s"], ["/", "h"])):
            return "".join(words[k:k + (1 if w[-1] not in "m" else 3)])
    return ""


# the imagined collision compared with the real one ('would it have hit the bus sooner?' was read as whether it would)
IMAGINED_COMPARED = {"sooner", "earlier", "later", "harder", "softer", "gentler", "longer"}


def comparison_imagined(words: list[str], program: list[str]) -> str:
    """Why a counterfactual reading is not the question's ('' when it is): its condition compares the vehicle with
    itself ('if it had been slower', 'had it gone faster'), which no intervention sets (they set it static, slow or
    fast, or accelerating: 'getting faster'); the decoder read 'slower' as fast and 'faster' as accelerating."""
    if not any(t.startswith("Counterfactual") for t in program):
        return ""
    compared = next((w for w in words if w in IMAGINED_COMPARED), None)
    if compared:
        return (f"the question compares the imagined collision with the real one ('{compared}'), which no question "
                "here asks: ask whether it would have happened")
    said = next((" ".join(words[k:k + 1 + (w in ("more", "less"))]) for k, w in enumerate(words)
                 if (w in COMPARISONS or w in ("more", "less") and words[k + 1:k + 2] and words[k + 1] in PACE_WORDS)
                 and not (k and words[k - 1] in BECOMING or words[k + 1:k + 2] == ["and"])), None)
    if said is None:
        return ""
    return (f"the question imagines a vehicle {said} than it was, which no question here asks: ask as if it had been "
            "static, slow or fast, or accelerating")


# The words that say which way two speeds compare: a comparative ('faster', 'at a lower speed', 'a greater velocity'),
# or 'more' / 'less' before a word of pace ('less quickly', 'more speed')
COMPARED_SAID = {**dict.fromkeys(("faster", "quicker", "speedier", "swifter", "higher", "greater", "superior",
                                  "outpaces", "outpace", "outpacing", "outruns", "outrun", "outrunning"), 1),
                 **dict.fromkeys(("slower", "lower", "lesser", "inferior"), -1)}
PACE_SIGN = {**dict.fromkeys(("fast", "quick", "quickly", "rapid", "rapidly", "speedy", "speedily", "swiftly"), 1),
             **dict.fromkeys(("slow", "slowly"), -1), **dict.fromkeys(("speed", "velocity", "pace"), 1)}


def comparison_unsaid(words: list[str], program: list[str]) -> str:
    """Why a reading comparing two speeds is not the question's ('' when it is): no word says which way they compare
    ('is the chopper's speed inferior to the minivan's?', 'is the SUV the slowpoke?' were read as faster; the decoder
    guesses a side when the comparison is said in words it does not know), or every word that says it says the other
    way."""
    if not program or operation(program[-1]) not in SPEED_COMPARISONS:
        return ""
    asked = 1 if operation(program[-1]) == "faster_velocity" else -1
    signs = [COMPARED_SAID[w] for w in words if w in COMPARED_SAID] + [
        PACE_SIGN[b] * (1 if a == "more" else -1) for a, b in zip(words, words[1:]) if a in ("more", "less")
        and b in PACE_SIGN]
    if asked in signs:
        return ""
    return ("the question compares two speeds in words the parser does not read as faster or slower" if not signs else
            "the question compares the speeds the other way round than its nearest reading: ask whether one is "
            "faster (or slower) than the other")


# a cause asked ('did it hit the bus because it was fast?' was read as whether it was fast)
CAUSES = {"because", "due", "reason", "reasons"}
CAUSING = {"made", "makes", "caused", "causes", "cause", "led", "leads", "lead"}   # 'what made it turn?'
PACE_WORDS = {"fast", "quick", "quickly", "slow", "slowly", "rapid", "rapidly", "speedy"}
# A vehicle ranked among all ('the fastest', 'moves the most', 'is the wagon the first vehicle to collide?'): no
# program compares more than two; 'the first vehicle it hits' is a partner's question, and stays
SUPERLATIVES = {"fastest", "quickest", "slowest", "speediest", "swiftest", "highest", "lowest", "biggest", "largest",
                "smallest", "heaviest", "lightest", "longest", "shortest", "furthest", "farthest", "nearest",
                "closest", "earliest", "latest"}
RANKS = {"first", "only", "last"}
# what follows 'how' in a question here, besides how fast (however said): 'how is it moving', 'how about the jet',
# 'how come'
HOW_ASKED = {"about", "come", "would", "will", "can", "could", "has", "have", "had", "the", "it", "its", "many",
             "much"}


def speeds_alike(words: list[str]) -> str:
    """The words that ask whether two speeds are alike ('as quick as the bus', 'equally fast'), or '': not 'as slow as
    the video starts' nor 'as fast as it can'."""
    def vehicle_at(k: int) -> bool:
        k += bool(words[k:k + 1] and words[k] in DETERMINERS)
        return bool(words[k:k + 1]) and words[k] in OBJECT_WORDS | GENERIC_NOUNS | INDEFINITES | {"any", "other"}
    return next((" ".join(words[k:k + 3]) for k in range(len(words) - 2) if words[k] == words[k + 2] == "as"
                 and words[k + 1] in SPEED_CLASS_WORDS - REST_WORDS and vehicle_at(k + 3)), "") or \
        next((f"{a} {b}" for a, b in zip(words, words[1:]) if a == "equally" and b in SPEED_CLASS_WORDS), "")


# The motions a question asks one at a time, by the words that say them: 'is it moving fast and accelerating?' was
# read as one of them
MOTION_KINDS = {**{w: "speed" for w in ("moving", "fast", "quick", "quickly", "rapidly", "slow", "slowly", "static",
                                        "stationary", "parked", "stopped", "motionless")},
                **{w: "accelerating" for w in ("accelerating", "speeding", "gaining")},
                **{w: "floating" for w in ("floating", "hovering", "airborne", "afloat", "aloft")}}
PLURAL_ASKED = {"colours", "colors", "types", "kinds", "sorts", "shapes"}   # not 'compare the speeds of X and Y'
SUBJECTS = {"it", "they", "the", "that", "this", "he", "she", "there"}


def properties_joined(words: list[str]) -> str:
    """Two kinds of motion asked at once ('fast and accelerating', 'floating and moving fast'), or ''."""
    for k, w in enumerate(words):
        if w != "and":
            continue
        left = next((MOTION_KINDS[v] for v in reversed(words[max(k - 2, 0):k]) if v in MOTION_KINDS), None)
        right = next((MOTION_KINDS[v] for v in words[k + 1:k + 4] if v in MOTION_KINDS), None)   # '... and not ...'
        if left and right and left != right:
            return (f"the question asks two things at once ('{left}' and '{right}'), which the parser reads one "
                    "question at a time: ask them apart")
    return ""


POSSIBILITY = {"possible", "possibly", "possibility", "probability", "odds"}   # not 'likely': a hedge of 'will'


def possibility_asked(words: list[str]) -> str:
    """Whether a collision could happen asked ('is it possible for the red car to hit the bus?', 'could the red car
    have hit the bus?' were read as whether it will, or does), or ''."""
    said = next((w for w in words if w in POSSIBILITY), None) or (
        f"{words[0]} ... have" if words[:1] in (["could"], ["might"]) and "have" in words
        and not CONDITION_OPENERS.intersection(words) else None)
    if said is None:
        return ""
    return (f"the question asks what could happen ('{said}'), which no question here asks: ask whether it does, will "
            "after the video, or would have if ...")


def times_joined(words: list[str]) -> str:
    """Two times asked at once ('fast at the start and when it hits the bus'), or ''."""
    for k, w in enumerate(words[:-2]):
        if w == "and" and (words[k + 1] in ("when", "while", "once") or words[k + 1:k + 3] == ["at", "the"]) and (
                START_WORDS.intersection(words[:k]) or "when" in words[:k]):
            return (f"the question asks at two times at once ('and {' '.join(words[k + 1:k + 3])}'), which the parser "
                    "reads one question at a time: ask them apart")
    return ""


def several_asked(words: list[str]) -> str:
    """A property asked of several vehicles ('what colours are the floating planes?'), or ''."""
    said = next((w for k, w in enumerate(words) if w in PLURAL_ASKED and k and words[k - 1] in
                 {"what", "which", "the", "their"}), None)
    if said is None:
        return ""
    return (f"the question asks the {said} of several vehicles, which no question here asks: each asks about one "
            "vehicle")


CONDITION_OPENERS = {"if", "had", "suppose", "supposing", "imagine", "assuming"}
# what a collision was like ('is the collision violent?', 'avoidable', 'at an angle' were read as whether there
# is one)
COLLISION_MANNER = {"violent", "violently", "severe", "severely", "serious", "seriously", "minor", "powerful",
                    "forceful", "forcefully", "softly", "damaging", "destructive", "fatal", "catastrophic", "absorb",
                    "absorbs", "absorbed", "absorbing", "avoidable", "unavoidable", "preventable", "inevitable",
                    "angle", "angled", "glancing", "damage", "damaged", "damages", "dented", "dent", "dents",
                    "broken", "breaks", "wrecked", "injured", "hurt", "scratched"}
TRAVELLED = MOTION_WORDS | {"travel", "travels", "travelled", "traveled", "go", "goes", "went", "drive", "drives",
                            "drove"}
CARRYING = {"carry", "carries", "carried", "carrying", "cargo", "load", "loaded", "tow", "tows", "towed", "towing"}
ITSELF = {"itself", "before", "earlier", "previously", "later", "usual", "normal"}
ITSELF_THEN = {"was", "is", "had", "did", "were", "used"}   # 'than it was' (not 'than it?': its partner)


def _condition_clause(words: list[str]) -> tuple[int, int]:
    """Where a counterfactual's condition stands: from 'if' (or the opener it starts with: 'suppose', 'had') to the
    end of its clause; (0, 0) where there is none."""
    if not (words[:1] and words[0] in CONDITION_OPENERS or "if" in words):
        return 0, 0
    start = 0 if words[0] in CONDITION_OPENERS else words.index("if")
    return start, next((k for k in range(start, len(words)) if words[k] in (",", ":", ";", ".", "would", "will", "?")),
                       len(words))


# A change at a time after the start ('at the end', 'halfway', 'after the collision'); 'the whole time' and 'always'
# are from the start on, as every intervention here is
LATER_TIMES = (["middle"], ["halfway"], ["half", "way"], ["midway"], ["later"], ["eventually"], ["afterwards"],
               ["at", "some", "point"], ["at", "one", "point"], ["now"])
CLAUSE_TIMES = (["after"], ["before"], ["when"], ["once"], ["while"], ["until"])


def imagined_otherwise(words: list[str], read: list[str]) -> str:
    """A counterfactual this grammar has no program for, or '': a change at another time than the start ('if it had
    been static at the end'), two changes at once ('if the sedan had been fast and the bus parked' was read as the
    sedan's alone) or the video changed ('if the video were longer' as the future). `words` as said, `read` with
    typos fixed ('when the video begisn' is the start)."""
    if any(w == "if" and words[k + 1] == "the" and words[k + 2] in FILM_WORDS and words[k + 3:k + 4] and
           words[k + 3] in ("were", "was", "had") for k, w in enumerate(words[:-3])):   # not 'if the video went on'
        return "the question imagines the video itself otherwise, which no question here does"
    start, end = _condition_clause(words)
    clause = words[start:end]
    if not {"had", "were", "been"}.intersection(clause):   # 'do you know if X and Y ...'
        return ""
    other = next((" ".join(t) for k in range(len(clause)) for t in (*LATER_TIMES, *END_TIMES, *CLAUSE_TIMES)
                  if clause[k:k + len(t)] == t), None)
    if other and not START_WORDS.intersection(clause + read[slice(*_condition_clause(read))]) and "first" not in clause:
        return (f"the question imagines a change at a time other than the start ('{other}'), which no question here "
                "does: each changes a vehicle's motion from the start")
    second = next((k for k in range(start, end) if words[k] == "and" and OBJECT_WORDS.intersection(words[k + 1:k + 4])),
                  None)
    if second is None:
        return ""
    return (f"the question imagines two changes at once ('and {' '.join(words[second + 1:end])}'), which no question "
            "here does: each imagines one vehicle's motion changed")


# the words that say a question imagines its video otherwise (a label, an opener or 'instead')
IMAGINING_SAID = {"imagine", "imagining", "suppose", "supposing", "pretend", "hypothetically", "hypothetical",
                  "counterfactual", "counterfactually", "instead", "cf", "what-if", "whatif"}


def imagining_unread(words: list[str], program: list[str]) -> str:
    """Why a reading of what happened is not the question's ('' when it is): the question imagines otherwise ('brown
    motorbike starting slow instead, it hits the gray car?', 'cf: gray one starts slow instead -> ...' were read as
    whether it is slow at the collision), and no counterfactual was read. Only a reading about collisions, as every
    counterfactual is ('Picture this: ... is it crawling at the start?' imagines nothing), and not of the future
    ('suppose the clip went on for longer')."""
    if any(t.startswith("Counterfactual") for t in program) or "filter_collision" not in program or \
            "futureEvents" in program:
        return ""
    said = next((w for w in words if w in IMAGINING_SAID | {"assume", "assuming"}), None) or \
        next(("what if" for a, b in zip(words, words[1:]) if (a, b) == ("what", "if")), None) or \
        next(("would" for k, w in enumerate(words) if w == "would" and words[k + 1:k + 2] != ["you"]),
             None)   # 'the engine is on from the very start. Would the SUV hit the bike?'
    if said is None:
        return ""
    return (f"the question imagines otherwise ('{said}'), but its nearest reading asks what happens in the video: "
            "ask as 'if X had been ... from the start, would it hit Y?'")


# the words that make a condition of what follows: a counterfactual reading needs one
CONDITION_SAID = IMAGINING_SAID | {"if", "had", "were", "would", "assume", "assuming", "say", "picture", "envision",
                                   "envisage", "imagined", "supposed", "hypothetical", "scenario", "intervention",
                                   "world", "case", "twist"} | CONDITION_LABELS


def condition_unsaid(words: list[str], program: list[str]) -> str:
    """Why a counterfactual reading is not the question's ('' when it is): nothing in it says a condition, as said or
    in a label the rules read away ('Video's been halted partway; from here on, will the chopper and the airliner
    collide?' was read as had the chopper been static)."""
    if not any(t.startswith("Counterfactual") for t in program) or CONDITION_SAID & set(words) or any(
            w == "from" and START_WORDS & set(words[k + 1:k + 3]) for k, w in enumerate(words)):   # 'fast from start'
        return ""
    return ("the question says no condition, but its nearest reading imagines one: ask 'if X had been ... from the "
            "start, would it hit Y?'")


# the words of floating a reading must read ('plane floating at the beginning or not' was read as fast)
AFLOAT_WORDS = {"floating", "float", "floats", "floated", "hovering", "hover", "hovers", "hovered", "airborne",
                "aloft"}


def floating_unread(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question says a vehicle floats, and the reading
    reads no floating."""
    said = next((w for w in words if w in AFLOAT_WORDS), None)
    if said is None or FLOATING_OPERATIONS.intersection(map(operation, program)):
        return ""
    return (f"the question says '{said}', but its nearest reading reads no floating: ask whether the vehicle is "
            "floating, or what it would have hit had it floated")


def otherwise_compared(words: list[str], read: list[str]) -> str:
    """A question (`words`; `read`: its typos fixed) of some other comparison or manner ('' when none): what a
    collision was like, how far vehicles move, a vehicle against itself at another time, what it carries, either of
    two."""
    manner = next((w for w in words if w in COLLISION_MANNER), None)
    if manner:
        return (f"the question asks what a collision was like ('{manner}'), which no question here asks: ask whether "
                "they collide")
    farther = next((f"{a} {b}" for k, (a, b) in enumerate(zip(read, read[1:])) if a in TRAVELLED and (
        b in ("further", "farther", "longer") or b in ("more", "less") and not (
            read[k + 2:k + 3] and (read[k + 2].endswith("ly") or read[k + 2] in SPEED_CLASS_WORDS)))), None)
    if farther:
        return (f"the question compares how far vehicles move ('{farther}'), which no question here asks: ask which "
                "is faster")
    itself = next((" ".join(words[k:k + 2 + (b == "it")]) for k, (a, b) in enumerate(zip(words, words[1:]))
                   if a == "than" and (b in ITSELF or b == "it" and words[k + 2:k + 3]
                                       and words[k + 2] in ITSELF_THEN)), None)
    if itself:
        return (f"the question compares a vehicle with itself at another time ('{itself}'), which no question here "
                "asks: ask how fast it is at the start or at a collision")
    carried = next((w for w in words if w in CARRYING), None)
    if carried:
        return f"the question asks what a vehicle carries ('{carried}'), which no question here asks"
    if "either" in words and "or" in words[words.index("either"):]:
        return "the question asks about either of two vehicles, which no question here asks: ask about each"
    return ""


def questions_joined(words: list[str]) -> str:
    """Two questions joined by 'and' ('is it fast at the start, and does it hit the bus?'), or ''."""
    said = next((" ".join(words[k:k + 2]) for k in range(len(words) - 2) if words[k] == "and"
                 and words[k + 1] in YES_NO_OPENERS and words[k + 2] in SUBJECTS), None)
    if said is None:
        return ""
    return (f"the question asks two questions ('{said}'), which the parser reads one at a time: ask them apart")


# sizes and materials (CLEVR's, not DynSuperCLEVR's: 'the small blue scooter' was read as the blue scooter)
LOOKS = {"small", "big", "large", "tiny", "huge", "little", "giant", "shiny", "metallic", "metal", "matte", "rubber",
         "plastic", "wooden"}
NORMATIVE = {"should", "must", "ought", "shall"}   # 'should the truck have stopped?' was read as whether it did


# 'given that the bus is parked, does the sedan hit it?' was read as whether the bus is parked at the collision
# ... but 'assuming the bus had been parked, would ...?' is the grammar's counterfactual
PREMISES = (["given", "that"], ["assuming", "that"], ["assuming"], ["provided", "that"], ["knowing", "that"])
IMAGINED = {"had", "were", "would"}
RELATIVES = {"that", "which", "who"}                    # 'the vehicle that ...'
PASSIVES = {"hit", "struck", "rammed", "bumped"}         # 'the vehicle hit by ...', not 'the gray vehicle struck'


def quantified(words: list[str]) -> str:
    """All or every vehicle asked about at once ('do all the cars collide?', 'which vehicles are parked?'), or ''."""
    said = next((" ".join(words[k:k + 2 + (words[k + 1:k + 2] == ["the"])]) for k, w in enumerate(words)
                 if w == "all" and words[k + 1 + (words[k + 1:k + 2] == ["the"]):][:1] in ([v] for v in PLURALS)
                 and words[k - 1:k] not in (["of"], ["among"], ["from"])   # 'of all the vehicles, which one ...'
                 or w in ("every", "each") and words[k + 1:k + 2] in ([v] for v in VEHICLE_SAID - {"it"})), None)
    head = _head(words)
    if said is None and head[:1] and head[0] in ASKING and head[1:2] and head[1] in PLURALS:
        said = " ".join(head[:2])
    if said is None:
        return ""
    return (f"the question asks about several vehicles at once ('{said}'), which no question here asks: each asks "
            "about one vehicle, or a pair")


def premised(words: list[str]) -> str:
    """A premise stated first ('given that the bus is parked, ...'), or ''."""
    said = next((" ".join(p) for k in range(len(words)) for p in PREMISES if words[k:k + len(p)] == p
                 and not IMAGINED & set(words[k + len(p):(words + [","])[k:].index(",") + k])), None)
    if said is None:
        return ""
    return (f"the question states a premise ('{said}'), which no question here reads: ask the question alone, or as "
            "a counterfactual ('if X had been ..., would ...')")


def impact_denied(words: list[str]) -> str:
    """A collision said not to happen ('the vehicle it passed without touching'), or '' ('without X moving' is rest,
    read as such)."""
    said = next((" ".join(words[k:k + 2]) for k in range(len(words) - 1) if words[k] == "without" and (
        words[k + 1].startswith(IMPACT_STEMS) or words[k + 1] in ("touching", "touch", "touched"))), None)
    if said is None:
        return ""
    return (f"the question asks about a vehicle passed without a collision ('{said}'), which no question here asks: "
            "ask whether they collide")


def ordered(words: list[str]) -> str:
    """An order of collisions or of vehicles ('what does it hit next', 'after the school bus'), or ''."""
    said = next((" ".join(words[k:k + 2]) for k in range(len(words) - 1)
                 if words[k + 1] == "next" and words[k].startswith(IMPACT_STEMS)), None) or \
        next((" ".join(words[k:k + 2 + j]) for k in range(len(words) - 2) if words[k] in ("after", "before")
              and words[k + 1] in DETERMINERS for j in (3, 2, 1) if words[k + 1 + j:k + 2 + j] and
              words[k + 1 + j] in OBJECT_WORDS - set(COLOR_NAMES) and all(
                  w in OBJECT_WORDS for w in words[k + 2:k + 1 + j])
              and words[k + 2 + j:k + 3 + j] in ([], ["?"], ["."], [","])), None)   # not 'after the bus ends'
    if said is None:
        return ""
    return (f"the question asks about an order of collisions or vehicles ('{said}'), which no question here asks: "
            "ask whether they collide")


def chained(words: list[str]) -> str:
    """A vehicle described through another described vehicle ('the vehicle hit by the vehicle that hits the bus'),
    or ''."""
    relatives = [k for k, w in enumerate(words[:-1]) if w in GENERIC_NOUNS and (
        words[k + 1] in RELATIVES or words[k + 1] in PASSIVES and words[k + 2:k + 3] == ["by"])]
    if len(relatives) < 2:
        return ""
    return ("the question describes a vehicle through another described vehicle, which no question here reads: ask "
            "about the one in between first")


# a speed other than the class at a time ('the top speed', 'the average speed', 'what speed does it reach', 'how
# does its speed change'), a degree of a comparison ('much faster'): no program measures them
MEASURES = {"top", "maximum", "max", "average", "mean", "peak", "minimum", "min", "highest", "lowest", "final"}
CHANGES = {"change", "changes", "changed", "changing", "vary", "varies", "varying", "varied"}
REACHING = {"reach", "reaches", "reached", "reaching", "attain", "attains"}
DEGREES = {"much", "slightly", "far", "way", "significantly", "somewhat", "considerably", "marginally", "bit", "lot",
           "twice", "thrice"}


def speed_measure(words: list[str]) -> str:
    """A measure of a speed the speed classes do not give, or a comparison's degree, or ''."""
    nouns = SPEED_NOUNS | {"speeds"}
    said = next((" ".join(words[k:k + 2]) for k, w in enumerate(words[:-1]) if w in MEASURES and words[k + 1] in nouns
                 and words[k - 1:k] in (["the"], ["its"], ["s"])), None) or \
        next((w for w in words if w in CHANGES and nouns & set(words)), None) or \
        next((f"{w} speed" for k, w in enumerate(words) if w in REACHING and nouns & set(words[:k])
              and words[:1] in (["what"], ["which"])), None) or \
        next((f"{a} {b}" for a, b in zip(words, words[1:]) if a in DEGREES and b in COMPARISONS), None) or \
        next((f"{a} {b}" for a, b in zip(words, words[1:]) if a in nouns and b in ("limit", "limits")), None)
    if said is None:
        return ""
    return (f"the question asks a measure of speed ('{said}'), which no question here asks: ask whether a vehicle is "
            "static, slow or fast, or faster than another")


def checked_attribute(words: list[str]) -> str:
    """A yes/no question whether a described vehicle is of a colour ('is the accelerating vehicle blue?') or of a
    type ('is the vehicle that hits the red car a bus?', read as whether the bus hits it), or ''; or one that asks
    two attributes at once ('what is the colour and type of ...')."""
    two = next((f"{a} and {c}" for a, b, c in zip(words, words[1:], words[2:])
                if b == "and" and a in ATTRIBUTE_SAID and c in ATTRIBUTE_SAID), None)
    if two:
        return (f"the question asks two things at once ('{two}'), which the parser reads one question at a time: ask "
                "them apart")
    end = len(words) - (words[-1:] == ["?"])
    said = next((words[k + 1] for k in range(end - 1) if k + 2 == end and words[k] in GENERIC_NOUNS | NOUNS_SAID
                 and words[k + 1] in COLOR_NAMES), None)
    typed = words[1:2] == ["the"] and words[2:3] and words[2] in GENERIC_NOUNS and next(
        (" ".join(words[k + 1:end]) for k in range(3, end - 1) if words[k] in ("a", "an")
         and all(w in OBJECT_WORDS for w in words[k + 1:end])), None)
    if not words[:1] or words[0] not in YES_NO_OPENERS or not (said or typed):
        return ""
    if typed:
        return (f"the question asks whether a vehicle is a '{typed}', which no question here asks: ask what type it "
                "is")
    return f"the question asks whether a vehicle is '{said}', which no question here asks: ask what colour it is"


def ranking(words: list[str]) -> str:
    """Why the question ranks a vehicle among all ('' when it does not)."""
    said = next((w for w in words if w in SUPERLATIVES), None) or next(
        (f"{a} {b}" for a, b in zip(words, words[1:]) if a == "the" and b in ("most", "least")), None) or next(
        (" ".join(words[k - 1:k + 2]) for k in range(2, len(words) - 1) if words[k] in RANKS and words[k - 1] == "the"
         and (words[k + 1] in GENERIC_NOUNS | NOUNS_SAID or words[k + 1] == "to")   # 'the first to move'
         and words[k - 2] in OBJECT_WORDS | {"it", "one"}),
        None) or next((f"the {b}" for k, (a, b) in enumerate(zip(words, words[1:])) if a == "the" and (
            b == "others" or b == "rest" and words[k + 2:k + 3] != ["of"]) and not asks_impact(words)),
        None)   # 'fast compared with the others' (not 'the rest of the video': after it)
    if said is None:
        return ""
    return (f"the question ranks a vehicle among all ('{said}'), which no question here asks: ask whether one is "
            "faster (or slower) than another, or whether it collides")
# 'getting faster', 'faster and faster': accelerating, an intervention
BECOMING = {"getting", "get", "gets", "got", "grow", "grows", "growing", "grew", "become", "becomes", "becoming",
            "became", "and"}
WHO = {"who", "whom", "whose"}
YES_NO_OPENERS = AUXILIARIES | {"will", "would", "can", "could", "has", "have", "had", "should", "are", "were"}


def form_unmatched(words: list[str], program: list[str]) -> str:
    """Why a reading answers in another form than the question asks for ('' when it does not): a yes/no question
    (its head after a clause of time said first) read as asking which ('does the red car change direction?' read as
    which way it moves; but 'is it static, slow or fast?' offers its answers). The other way round is
    `form_unasked`'s."""
    head = _head(words)
    returns = OPS[operation(program[-1])].output
    if head[:1] and head[0] in YES_NO_OPENERS and returns is str and "or" not in head:
        return ("the question asks yes or no, but its nearest reading asks which (a speed, a direction, a colour or a "
                "type): no question here asks it as yes or no")
    # 'what type of aeroplane is it at the start?' read as its direction: a type or colour asked is no motion
    kind = head[1] if head[:1] in (["what"], ["which"]) and head[1:2] and head[1] in ATTRIBUTE_NOUNS else None
    if kind and head[2:4] != ["of", "speed"] and operation(program[-1]) in ("query_moving_velocity",
                                                                              "query_moving_direction"):
        return (f"the question asks the {kind}, but its nearest reading asks a speed or a direction: no question here "
                "reads it")
    # '..., zzq colour is it' read as whether the plane floats: a colour or type asked of 'it' is no yes or no
    asked = next((a for a, b, c in zip(words, words[1:], words[2:]) if a in ATTRIBUTE_NOUNS and b in ("is", "was")
                  and c in ("it", "that", "this", "they")), None)
    if asked and returns is not str and "or" not in words:
        return (f"the question asks the {asked}, but its nearest reading asks yes or no: no question here reads "
                "it")
    # 'after the video ends , which vehicle will the green car run into ?' read as whether it hits anything
    which = next((words[j + 1] for j in range(len(words) - 1) if words[j] in ("which", "what") and (
        j == 0 or words[j - 1] == ",") and (words[j + 1] in OBJECT_WORDS or words[j + 1] in GENERIC_NOUNS)), None)
    # ('which one is faster , is it the sedan ?' asks whether the sedan is)
    if which and returns is not str and not {"faster_velocity", "slower_velocity"} & set(map(operation, program)):
        return f"the question asks which {which}, but its nearest reading asks yes or no: no question here reads it"
    # 'which vehicle hits the bus first?' read as the bus's direction: a vehicle asked for is its colour or type
    if head[:1] == ["which"] and head[1:2] and (head[1] in OBJECT_WORDS or head[1] in GENERIC_NOUNS) and \
            operation(program[-1]) in ("query_moving_velocity", "query_moving_direction"):
        return (f"the question asks which {head[1]}, but its nearest reading asks a speed or a direction: ask for the "
                "colour or the type of the vehicle")
    return ""


COLLISION_OPERATIONS = {"filter_collision", "get_all_col_partners"}
# besides IMPACT_STEMS, the words a collision is said with: 'run into', 'drive into', 'each other'
IMPACT_SAID = {"into", "onto", "run", "runs", "ran", "running", "other", "another"}


def impact_like(word: str) -> bool:
    """Whether an unknown word may be an impact's word misspelt ('collied', 'crahsed', 'tocuh'), which the decoder
    reads a collision in from the rest of the question; 'too', 'while' are not."""
    return any(SequenceMatcher(None, word[:len(s) + 1], s).ratio() >= 0.7 for s in IMPACT_STEMS)


def impact_unsaid(words: list[str], program: list[str]) -> str:
    """Why a reading of a collision is not the question's ('' when it is): the question says nothing of one ('what
    colour is the parked car?' read as the colour of what the car hits)."""
    if not COLLISION_OPERATIONS.intersection(operation(t) for t in program):
        return ""
    if asks_impact(words) or any(w in IMPACT_SAID - {"into"} for w in words):   # not 'comes into view'
        return ""
    return ("the question says nothing of a collision, but its nearest reading asks about one: no question here "
            "reads it")


SPEED_CLASS_OPERATIONS = {"is_moving_velocity", "filter_moving_velocity", "Counterfactual_moving_slow",
                          "Counterfactual_moving_fast"}
# The words that say a speed class: those of the grammar's seen slow and fast phrases but the motion itself ('moving',
# 'at a high speed': 'high'), and English's other words for a pace; the lexicon, WordNet and the idioms read more
# words as these.
SPEED_CLASS_WORDS = (frozenset(w for key in ("SLOW", "FAST", "SLOW_ADJ", "FAST_ADJ")
                               for phrase in templates()["lexicon"][key]["seen"] for w in tokenize(phrase))
                     - frozenset(w for key in ("MOVING", "MOVE") for phrase in templates()["lexicon"][key]["seen"]
                                 for w in tokenize(phrase)) - {"at", "a", "-", "speed", "along"}) | {
    "quick", "swift", "swiftly", "brisk", "briskly", "hurried", "hurriedly", "full", "top", "breakneck", "sluggish",
    "sluggishly", "leisurely", "gentle", "gently", "snail", "inching", "ambling", "chugging", "puttering",
    "pottering", "idling", "speedily"} | COMPARISONS


def speed_unsaid(words: list[str], program: list[str]) -> str:
    """Why a reading of a speed class is not the question's ('' when it is): the question, as read, says no speed
    ('is the bus driving at the start?' asks whether it moves at all, which the decoder read as slow)."""
    if not SPEED_CLASS_OPERATIONS.intersection(map(operation, program)) or SPEED_CLASS_WORDS.intersection(words):
        return ""
    return ("the question says no speed (slow or fast), but its nearest reading asks about one: ask whether the "
            "vehicle is static, slow or fast")


FLOATING_OPERATIONS = {"is_floating", "filter_floating", "Counterfactual_floating"}
# the words that say a vehicle floats: the grammar's, people's ('afloat', 'off the ground', 'never touched the
# ground', 'above'), and what the lexicon reads as them
FLOATING_WORDS = {"floating", "float", "floats", "floated", "air", "airborne", "hovering", "hover", "hovers",
                  "hovered", "flying", "fly", "flies", "flew", "aloft", "afloat", "levitate", "levitating", "ground",
                  "above", "hanging", "midair", "sky", "up", "flight", "airplane"} | LANDING   # 'had it never landed'


def floating_unsaid(words: list[str], program: list[str]) -> str:
    """Why a reading of floating is not the question's ('' when it is): the question, as read, says nothing of it
    ('if the bus had stayed still, ...' was read as had it stayed in the air)."""
    if not FLOATING_OPERATIONS.intersection(map(operation, program)):
        return ""
    # a ground vehicle said 'flying' goes fast ('the dirtbike comes flying out of the gate' was read as had it
    # floated); the vehicle floating is the program's first
    first = program[:program.index("unique")] if "unique" in program else []
    grounded = next((t[len("filter_attributes["):-1] for t in first if t.startswith("filter_attributes[")
                     and CATEGORY_OF.get(t[len("filter_attributes["):-1], "aeroplane") != "aeroplane"), None)
    if grounded and FLOATING_WORDS.intersection(words) == {"flying"}:
        return (f"the question says the {grounded.replace('_', ' ')} is 'flying', which a vehicle on the ground is "
                "only as fast: ask whether it is fast, or floating")
    if FLOATING_WORDS.intersection(words):
        return ""
    return ("the question says nothing of floating, but its nearest reading asks about it: ask whether the vehicle "
            "is floating, or static, slow or fast")


MOTION_READ = ("velocity", "direction", "static", "floating", "accelerating", "Counterfactual")
# how a vehicle moves, said to describe one: no collision question picks its partner so ('hit a parked vehicle')
MOTION_DESCRIPTIONS = (SPEED_CLASS_WORDS - {"still"}) | {"parked", "stationary", "static", "stopped", "motionless",
                                                        "floating", "hovering", "airborne", "accelerating"}


def motion_unread(words: list[str], program: list[str]) -> str:
    """Why a reading of collisions alone is not the question's ('' when it is): the question describes a vehicle by its
    motion ('does it crash into a stationary vehicle?', 'is it hit by a floating plane?', read as whether it crashes at
    all), which no program reads beside a collision."""
    if not COLLISION_OPERATIONS.intersection(map(operation, program)) or \
            any(part in t for t in program for part in MOTION_READ):
        return ""
    said = next((w for w in words if w in MOTION_DESCRIPTIONS), None)
    if said is None:
        return ""
    return (f"the question describes a vehicle by its motion ('{said}'), which no question here reads beside a "
            "collision")


STATIC_OPERATIONS = {"is_static", "filter_static", "Counterfactual_static"}
STATIC_SAID = {"static", "stationary", "parked", "stopped", "motionless", "rest", "idle", "standing", "stand",
               "stands", "not", "never", "immobile", "unmoving"}


def still_continuing(words: list[str], program: list[str]) -> str:
    """Why a reading of rest is not the question's ('' when it is): its only word of rest is 'still' saying that a
    motion goes on ('is it still accelerating when it hits the bus?' was read as whether it is static there)."""
    if not STATIC_OPERATIONS.intersection(map(operation, program)) or STATIC_SAID.intersection(words):
        return ""
    going = next((f"still {b}" for a, b in zip(words, words[1:]) if a == "still" and b.endswith("ing")
                  and b not in GENERIC_NOUNS | {"thing", "something", "anything", "nothing"}), None)
    if going is None or sum(w == "still" for w in words) > 1:
        return ""
    return f"the question says a motion goes on ('{going}'), but its nearest reading asks whether the vehicle is static"


MOTION_FILTERS = {"filter_static", "filter_moving_velocity", "filter_accelerating", "filter_floating"}
# said before a vehicle to pick it ('the parked bus'); not a comparison ('the faster one' is the grammar's)
MOTION_PICKS = {w for w in MOTION_DESCRIPTIONS - COMPARISONS - {"full", "top", "high", "low"}
                if not w.endswith("ly")} | {"moving"}


def motion_unfiltered(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question picks a vehicle by its motion ('is the
    accelerating sedan faster than the bus?' was read about any sedan) and the program picks none so."""
    if MOTION_FILTERS.intersection(map(operation, program)):
        return ""
    said = next((" ".join(words[k:j + 1]) for k, w in enumerate(words) if w in MOTION_PICKS
                 and words[k - 1:k] in (["the"], ["that"], ["this"])
                 for j in (k + 2, k + 1) if words[j:j + 1] and words[j] in OBJECT_WORDS | GENERIC_NOUNS
                 and all(x in OBJECT_WORDS for x in words[k + 1:j])), None)
    if said is None:
        return ""
    return f"the question picks a vehicle by its motion ('{said}'), which no question here does so"


# the asked word and the query that answers it
ASKED_QUERIES = {**{w: "query_moving_velocity" for w in ("speed", "velocity")},
                 **{w: "query_moving_direction" for w in ("direction", "heading")},
                 **{w: "query_attributes[color]" for w in ("color", "colour")},
                 **{w: "query_attributes[shape]" for w in SHAPE_ASKED}}
PARTNER_SAID = {"that", "which", "who"}
# the grammar's words for accelerating: 'how quickly is it speeding up?' asks how much it accelerates
ACCELERATION_SAID = tuple(tokenize(phrase) for key in ("ACCELERATING", "ACCELERATE") for pool in ("seen", "heldout")
                          for phrase in templates()["lexicon"][key][pool])


def acceleration_unread(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question says a vehicle speeds up, and its reading
    asks no acceleration ('was it speeding up when it hit the sedan?' was read as whether it was fast there; only the
    start and a counterfactual's condition ask one)."""
    if any("accelerat" in t for t in program):
        return ""
    said = next((w for w in words if w.startswith("accelerat")), None) or next(
        (" ".join(a) for k in range(len(words)) for a in ACCELERATION_SAID if words[k:k + len(a)] == a), None)
    if said is None:
        return ""
    return (f"the question asks whether a vehicle speeds up ('{said}') where no question here asks it (they ask it "
            "at the start, or as what might have been)")


# the words, besides the grammar's phrases, that say a vehicle speeds up: a reading of accelerating needs one
SPEEDING_UP = {"engine", "engines", "throttle", "revving", "gaining", "picking", "faster", "quicker", "gathering",
               "increasing", "increase", "building", "thrust", "powered", "power", "speeding", "sped", "accelerator",
               "gas", "pedal", "boost", "boosting", "turbo", "gunning", "guns", "punching", "flooring", "hastening",
               "hasteneth"}


SIZES = {"size", "length", "width", "weight", "mass", "bigger", "smaller", "larger", "heavier", "lighter", "wider",
         "taller"}


def size_unread(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question compares or asks a size ('is the red car
    greater in size than the blue bus?' was read as faster), which no question here asks."""
    said = next((w for k, w in enumerate(words) if w in SIZES and words[k + 1:k + 2] not in (["speed"], ["velocity"])),
                None)   # not 'a smaller speed'
    return (f"the question asks about a size ('{said}'), which no question here asks (they ask speed classes, "
            "directions, colours, types and collisions)") if said else ""


def acceleration_unsaid(words: list[str], program: list[str]) -> str:
    """Why a reading of accelerating is not the question's ('' when it is): the question says nothing of speeding up
    ('which colour level corresponds to the vehicle whose initial speed is recorded as slow?' was read as the colour
    of what accelerates)."""
    if not {"is_accelerating", "filter_accelerating"} & set(map(operation, program)) or \
            any(w.startswith("accelerat") for w in words) or SPEEDING_UP & set(words) or \
            any(a == c and a.endswith("er") and b == "and" for a, b, c in zip(words, words[1:], words[2:])) or \
            any(words[k:k + 3] == ["speed", "going", "up"] for k in range(len(words))) or \
            any(words[k:k + len(a)] == list(a) for k in range(len(words)) for a in ACCELERATION_SAID):
        return ""
    return ("the question says nothing of speeding up, but its nearest reading asks about it: ask whether the vehicle "
            "is accelerating")


END_WORDS = {"end", "ends", "ended", "ending", "endeth", "finish", "finishes", "finished", "finale", "conclusion"}
LATER_WORDS = {"later", "subsequently", "afterwards", "afterward", "eventually"}
ENTERING = {"enters", "enter", "entering", "entered", "arrive", "arrives", "arrived"}   # not 'appear', also 'seem'


def end_unread(words: list[str], program: list[str]) -> str:
    """Why a reading at the start is not the question's ('' when it is): the question speaks of the video's end or a
    later time ('when the video endeth', 'at the video's close', 'at last', 'later on, after the first few seconds'),
    which no question asks of a vehicle's motion."""
    if "start" not in program or "futureEvents" in program:
        return ""
    # ... or its coming into view, where nothing says the start ('the biplane enters upon the stage! at what pace doth
    # it arrive?')
    entering = next((w for w in words if w in ENTERING), None)
    if entering and not START_WORDS & set(words) and "first" not in words:
        return (f"the question asks about a vehicle coming into view ('{entering}'), but its nearest reading asks at "
                "the start: ask how fast it moves when it comes into view")
    said = next((w for w in words if w in END_WORDS | LATER_WORDS), None) or next(
        (" ".join(p) for k in range(len(words)) for p in (["the", "close"], ["'", "s", "close"], ["at", "last"])
         if words[k:k + len(p)] == p), None)
    if said is None:
        return ""
    return (f"the question asks at a time other than the start ('{said}'), which no question here asks of a "
            "vehicle's motion (they ask at the start, when it comes into view, or at a collision)")


def property_unread(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): it answers another property than the one asked ('what is
    the speed of the vehicle that hits the truck?' read as that vehicle's colour), or asks about the object a
    question names where it asks about the vehicle that hits it ('what direction is the vehicle that hits the jet
    moving in?' read as the jet's)."""
    asked, _ = _asked(words)
    head = _head(words)
    # ('what colour is the vehicle with a positive acceleration?' asks a colour)
    if head[:1] and head[0] in ASKING and "acceleration" in head and \
            not ASKED_QUERIES.get(asked, "").startswith("query_attributes") or \
            head[:1] == ["how"] and head[1:2] and head[1] in SPEED_CLASS_WORDS and (
                any(w.startswith("accelerat") for w in head) or any(
                    head[k:k + len(a)] == a for k in range(2, len(head)) for a in ACCELERATION_SAID)):
        return ("the question asks how much a vehicle accelerates, which no question here asks: ask whether it is "
                "accelerating")
    query = program[-1] if program and program[-1].startswith("query_") else None
    if query and asked in ASKED_QUERIES and ASKED_QUERIES[asked] != query:
        return (f"the question asks the '{asked}', but its nearest reading asks another property: no question here "
                "asks it of that vehicle")
    partner = any(w in GENERIC_NOUNS and words[k + 1:k + 2] and words[k + 1] in PARTNER_SAID
                  and asks_impact(words[k + 2:k + 6]) for k, w in enumerate(words))
    if query and partner and "get_all_col_partners" not in program:
        return ("the question asks about the vehicle that collides with another, which no question here asks but its "
                "colour or its type")
    return ""


def form_unasked(words: list[str], program: list[str]) -> str:
    """Why a yes/no reading is not the question's ('' when it is): the question asks who ('who hits the bus?' read
    as whether anything does), what attribute ('what's the type of the car that is speeding up?', 'which bus is
    parked, what colour?' read as whether it speeds up or is parked) or what. 'which is faster, X or Y?' is the
    grammar's yes/no question, and so is 'what would happen if ...'."""
    if OPS[operation(program[-1])].output is not bool:
        return ""
    # a question after its context, read whole ('One of the planes is floating ... . What color is it?'), asks as its
    # last sentence asks too, or where speech without stops has its question ('... at the start what color is it')
    spans = _sentence_spans(words)
    run_on = _run_on_question(words) if len(spans) == 1 else None
    asked = words[spans[-1][0]:] if len(spans) > 1 and words[-1] == "?" else words[run_on:] if run_on else None
    return _form_unasked(words, program) or (_form_unasked(asked, program) if asked else "")


def _form_unasked(words: list[str], program: list[str]) -> str:
    head = _head(words)
    if any(head[:len(i)] == i for i in ASKING_FOR) and not {"whether", "if"} & set(head):
        return f"the question asks for something ('{head[0]}'), but its nearest reading asks yes or no"
    if head[:1] and head[0] in WHO and not OBJECT_WORDS.intersection(words[words.index("or"):] if "or" in words
                                                                    else []):   # not 'who is faster: X or Y?'
        return ("the question asks who, but its nearest reading asks yes or no: ask for the colour or the type of "
                "the vehicle")
    how = next((words[k + 1] for k in range(len(words) - 1) if words[k] == "how"
                and words[k + 1] not in ("about", "come")), None)   # 'if it had been parked, how fast would ...'
    if how:
        return f"the question asks how {how}, but its nearest reading asks yes or no"
    asked, _ = _asked(words)
    if asked in QUERY_NOUNS or head[:1] and head[0] in ASKING and head[1:2] and head[1] in QUERY_NOUNS:
        return f"the question asks the '{asked or head[1]}', but its nearest reading asks yes or no"
    compared = operation(program[-1]) in ("faster_velocity", "slower_velocity")   # 'which one is faster, is it X?'
    if head[:1] == ["which"] and head[1:2] and (head[1] in OBJECT_WORDS or head[1] in GENERIC_NOUNS) and \
            "or" not in head and not compared:
        return f"the question asks which {head[1]}, but its nearest reading asks yes or no"
    if head[:1] == ["what"] and not HAPPENING.intersection(head):   # 'what will the red car hit?'
        return "the question asks what, but its nearest reading asks yes or no"
    return ""


ATTRIBUTE_SAID = {w for w, query in ASKED_QUERIES.items() if query.startswith("query_attributes")} | {
    "coloured", "colored", "colours", "colors", "category", "make"}


def attribute_unsaid(said: list[str], read: list[str], program: list[str]) -> str:
    """Why a reading of a colour or a type is not the question's ('' when it is): the question names no attribute
    ('what does the red car hit?', 'name the vehicle that ...' ask which vehicle, and were read as its colour)."""
    if not program[-1].startswith("query_attributes") or ATTRIBUTE_SAID.intersection(said + read):
        return ""
    return ("the question asks which vehicle, which no question here answers but by its colour or its type: ask what "
            "colour (or type) it is")


def what_happens(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question (`words`: typos fixed) asks what a vehicle
    does ('what is the red car doing at the start?' was read as its speed), or what happens and asks no question
    after it ('what would happen if it were static?' was read as whether it is)."""
    head = _head(words)
    if head[:1] == ["what"] and head[1:2] and head[1] in AUXILIARIES | {"will", "would"} and (
            "doing" in head or "do" in head[2:]):   # not 'what speed is it doing'
        return ("the question asks what a vehicle does, which no question here answers: ask how fast it moves, which "
                "way, or whether it collides")
    if OPS[operation(program[-1])].output is not bool or head[:1] != ["what"] or \
            not HAPPENING.intersection(head) - {"if"} or \
            CLAUSE_ENDS.intersection(words[:-1]):   # a question after it: '..., would it hit the bus?'
        return ""
    return ("the question asks what happens, which no question here answers: ask whether a vehicle collides, or how "
            "it moves")


HAPPENING = {"if", "happen", "happens", "happened", "happening", "next"}   # 'what would happen if ...: would ...?'
CLAUSE_ENDS = {",", ":", ";", ".", "?", "-"}
FUTURE_SAID = (["after", "the"], ["in", "the", "future"], ["later", "on"], ["from", "now"])
FUTURE_CUES = {"will", "would", "going", "gonna", "later", "after", "future", "next", "predict", "predicted",
               "expect", "expected", "eventually", "soon", "continue", "continues", "continued", "kept", "keeps", "ll",
               "shall", "beyond", "afterwards", "afterward", "then", "upcoming", "remaining", "rest", "follow",
               "follows", "following", "anticipate", "ends", "end", "over", "finished", "done"}


# ... and the video stopped, said in words a predictive question may use alone ('once the clip is halted, does ...')
STOP_CUES = {w for stop in STOPPED_SAID for w in stop if w.isalpha() and w not in {"is", "was", "gets", "got", "s"}} \
    | {"hereafter", "thereafter", "past", "forecast", "forecasting", "projected", "extrapolate", "extrapolating", "ahead",
       "onward", "onwards", "resumes", "prediction", "predicting", "destined", "freeze", "paused", "cutoff",
       "truncation"}


def _future_said(words: list[str]) -> str:
    """The words that say the time after the video ('after the video', 'in the future'), or ''."""
    return next((" ".join(words[k:k + len(f) + (f[0] == "after")]) for k in range(len(words)) for f in FUTURE_SAID
                 if words[k:k + len(f)] == f and (f[0] != "after" or words[k + 2:k + 3] and
                                                  words[k + 2] in FILM_WORDS)), "")


def future_unread(words: list[str], program: list[str]) -> str:
    """Why a reading of the video's collisions is not the question's ('' when it is): the question asks after the
    video ('what colour is the vehicle that hits the red car after the video?': no family asks a partner there); or
    the other way round, a reading after the video where the question asks before its end, or a counterfactual's
    after the video ('if it had been static, will it hit the bus after the video ends?')."""
    before = next((" ".join(words[k:k + 3]) for k in range(len(words) - 2) if words[k] == "before" and (
        words[k + 1:k + 3] == ["the", "end"] or words[k + 1] == "the" and words[k + 2] in FILM_WORDS)), None)
    if before and "futureEvents" in program:   # 'will they collide before the video ends?' asks within it
        return (f"the question asks about the video ('{before}'), but its nearest reading asks after it: ask whether "
                "they collide in the video")
    if any(t.startswith("Counterfactual") for t in program) and _future_said(words):
        return (f"the question imagines the time after the video ('{_future_said(words)}'), which no question here "
                "does: a counterfactual asks about the video's own time")
    # 'the green sedan , it collide with something in the video ?': a learner's bare verb, within the video
    within = next((" ".join(words[k:k + 2 + (words[k + 1] == "the")]) for k in range(len(words) - 2)
                   if words[k] in ("in", "during", "throughout") and
                   words[k + 1 + (words[k + 1] == "the")] in FILM_WORDS), None)
    # 'does the sedan hit the airliner afterwards?' read within the video
    after = next((w for w in words if w in ("afterwards", "afterward", "hereafter", "thereafter")), None)
    if after and "Events" in program and "futureEvents" not in program:
        return (f"the question asks '{after}', but its nearest reading asks within the video: ask whether they "
                "collide after the video ends")
    if "futureEvents" in program and within and not FUTURE_CUES.intersection(words):
        return (f"the question asks about the video ('{within}'), but its nearest reading asks after it: ask whether "
                "it collides in the video")
    # 'can we get clarity on whether the pickup and the purple thing bump into each other?' read after the video
    if "futureEvents" in program and not (FUTURE_CUES | STOP_CUES).intersection(words):
        return ("the question says nothing of the time after the video, but its nearest reading asks after it: ask "
                "whether they collide in the video, or will after it ends")
    if "Events" not in program or "futureEvents" in program:
        return ""
    said = _future_said(words)
    if not said:
        return ""
    return (f"the question asks about the time after the video ('{said}'), but its nearest reading asks about the "
            "video: no question here reads it")


INDEFINITES = {"anything", "something", "anyone", "someone", "anybody", "somebody"}
ANY_NOUNS = {"vehicle", "vehicles", "object", "objects", "thing", "things", "other", "one", "else"}


def anything_unasked(words: list[str], program: list[str]) -> str:
    """Why a reading of two named objects drops an indefinite one ('' when it does not): 'does either the red car or
    the blue bus hit anything?' and 'do both ... collide with something?' ask about each object and anything else,
    which no family asks; the pair's reading ('do they hit each other?') answers another question."""
    named, current = set(), []
    for token in program:
        if token.startswith("filter_attributes["):
            current.append(token)
        elif token == "unique" and current:
            named.add(tuple(current))
            current = []
    indefinite = INDEFINITES.intersection(words) or any(a in ("any", "some") and b in ANY_NOUNS
                                                       for a, b in zip(words, words[1:]))
    if len(named) >= 2 and indefinite:
        return ("the question asks about two objects and anything else at once, which no question here asks: ask "
                "about each object alone, or whether the two hit each other")
    return ""


# Passive participles of outdoing: 'X is outpaced by Y' says Y is faster, the other way round from how the
# lexicon reads the word ('outpace' -> 'move faster than')
OUTDONE = {"outpaced", "outrun", "outran", "overtaken", "outstripped", "passed", "beaten", "outsped", "outdone",
           "surpassed", "outperformed", "bested", "exceeded", "outdistanced", "outraced"}


LOSING = {"lose", "loses", "losing", "lost", "shed", "sheds", "shedding", "drop", "drops", "dropping", "reduce",
          "reduces", "reducing", "reduced", "decrease", "decreases", "decreasing", "decreased", "cut", "cuts",
          "cutting", "bleed", "bleeds", "bleeding"}
SPEED_NOUNS = {"speed", "velocity", "pace", "momentum"}
FALLING = {"drop", "drops", "dropping", "dropped", "decrease", "decreases", "decreasing", "decreased", "fall", "falls",
           "falling", "fell"}
GETTING = {"get", "gets", "getting", "become", "becomes", "becoming", "grow", "grows", "growing"}
HALTS = {"stop", "halt", "standstill", "rest"}


def slowing_down(words: list[str]) -> bool:
    """'slowing (down)', 'losing (its) speed', 'its speed drops', 'getting slower', 'coming to a stop': a slowing
    down, which the lexicon would read as a speed ('slow') or as its opposite ('accelerating', 'static')."""
    for k, w in enumerate(words):
        after = words[k + 1:k + 4]
        if w == "slowing" or w in ("slow", "slows", "slowed") and after[:1] == ["down"]:
            return True
        if w in LOSING and SPEED_NOUNS.intersection(after[:2]):
            return True
        verb = after[1:3] if after[:1] == ["is"] else after[:2]
        if w in SPEED_NOUNS and (verb[:1] and verb[0] in FALLING or verb in (["goes", "down"], ["going", "down"])):
            return True
        if w in GETTING and (after[:1] == ["slower"] or after[:2] == ["more", "slowly"]) and "than" not in after:
            return True
        if w in ("come", "comes", "coming") and "had" not in words[max(k - 4, 0):k] and after[:1] == ["to"] and \
                HALTS.intersection(after[1:3]):     # 'had it come to a stop' is a counterfactual's rest
            return True
    return False


STEADY = {"constant", "steady", "steadily", "unchanged", "unchanging", "same", "uniform", "uniformly"}


def reversed_as_said(words: list[str]) -> str:
    """Reversals that the words standing in for unknown ones would hide, so read before they stand in: 'decelerate'
    (WordNet's 'slow', a speed; slowing down, however said, is what no question asks, the opposite of
    accelerating), a speed that stays the same (STEADY: 'at a constant speed' was read as slow, 'the same speed
    throughout' as fast) and a comparison in the passive ('Is the bus outpaced by the car?'). '' when there is
    none."""
    if any(w.startswith("decelerat") for w in words) or slowing_down(words):
        return ("the question asks whether an object slows down, which no question here asks: ask whether it is "
                "accelerating and take the opposite answer")
    if STEADY.intersection(words):
        return ("the question asks whether an object keeps its speed, which no question here asks: ask whether it is "
                "accelerating and take the opposite answer")
    passive = [w for k, w in enumerate(words) if w in OUTDONE and "by" in words[k + 1:k + 4]]
    if passive:
        return (f"the question compares in the passive ('{passive[0]} by'): ask whether the one named last is faster "
                "or slower than the other")
    return ""


# Words that open a clause saying when: 'At the moment the bus hits it, is the bike parked?'.
TIME_OPENERS = {"at", "when", "during", "in", "as", "on", "upon", "while", "just", "right", "once"}
# ... unless it is a counterfactual's condition ('In case X had stopped, would it hit Y?'), whose 'it' must follow it
CONDITION_WORDS = {"had", "were", "case", "world", "if", "suppose"}


def time_clause_last(words: list[str]) -> list[str] | None:
    """A question that opens with a clause of time, the clause put last: 'when it hits the bus , is the red car
    parked ?' -> 'is the red car parked when it hits the bus ?' (None if it does not open so). People front the
    clause; the grammar mostly says it last, and a pronoun in it ('when it hits') then follows its object. The
    reading is a second candidate, never a replacement: 'In a world where X had stopped, would it hit Y?' keeps its
    own reading wherever the decoder is surer of it; a condition is never moved."""
    if not words or words[0] not in TIME_OPENERS or "," not in words:
        return None
    k = words.index(",")
    clause, main = words[:k], words[k + 1:]
    if not main or CONDITION_WORDS.intersection(clause):
        return None
    end = main[-1:] if main[-1] in ("?", ".", "!") else []
    main, clause = _antecedent_first(main[:len(main) - len(end)], clause)
    return main + clause + end


DETERMINERS = {"the", "a", "an", "that", "this"}
GENERIC_NOUNS = {"thing", "object", "vehicle", "one"}


def _antecedent_first(main: list[str], clause: list[str]) -> tuple[list[str], list[str]]:
    """'once the cyan bike shows up , how fast is it moving' names the object in the clause and says 'it' in the
    main question: put last, the clause would follow its pronoun, so the object and the pronoun change places
    ('how fast is the cyan bike moving once it shows up'). Only where the main question names no object before its
    'it' and the clause says no 'it' of its own."""
    if "it" not in main or {"it", "its"}.intersection(clause):
        return main, clause
    k = main.index("it")
    start = next((i for i, w in enumerate(clause) if w in OBJECT_WORDS), None)
    if start is None or OBJECT_WORDS.intersection(main[:k]):
        return main, clause
    end = start
    while end < len(clause) and clause[end] in OBJECT_WORDS:
        end += 1
    if end < len(clause) and clause[end] in GENERIC_NOUNS:
        end += 1
    if start and clause[start - 1] in DETERMINERS:
        start -= 1
    return main[:k] + clause[start:end] + main[k + 1:], clause[:start] + ["it"] + clause[end:]


# What a clause of time says its time is, by the operation that asks at it
COMES_IN_WORDS = {"appear", "appears", "enter", "enters", "shows", "show", "comes", "come", "visible", "view"}
IMPACT_WORDS = {"impact", "collision", "collide", "collides", "hit", "hits", "crash", "crashes", "bump", "bumps",
                "strike", "strikes", "smash", "smashes", "slam", "slams", "contact", "meet", "meets"}
IMPACT_STEMS = ("impact", "collid", "collision", "hit", "crash", "bump", "strik", "struck", "smash", "slam", "contact",
                "touch", "bang", "knock", "ram", "accident", "meet", "fender", "wreck", "pileup")
SIGHT_WORDS = {"view", "sight", "frame", "picture", "scene", "shot", "camera"}   # 'comes into view'

# The video's end said as a time ('at the end of the clip', 'in the last frame')
END_TIMES = [[p, *the, *very, e] for p in ("at", "by", "towards", "toward", "near") for the in ((), ("the",))
             for very in ((), ("very",)) for e in ("end", "finish", "close", "conclusion", "finale", "ending")] + \
    [["end", "of", f] for f in ("video", "clip", "footage", "film")] + \
    [[*p, "the", *very, a, *few, f] for p in (("in",), ("at",), ("during",), ()) for very in ((), ("very",))
     for a in ("last", "final", "closing")
     for few in ((), ("few",), ("couple", "of")) for f in ("frame", "frames", "second", "seconds", "moment", "moments",
                                                         "timestep", "timesteps", "instant", "instants", "stage",
                                                         "stages", "part", "whistle", "shot", "shots", "scene",
                                                         "scenes")]
START_WORDS = {"start", "starts", "started", "beginning", "begins", "begin", "began", "begun", "initially", "opening",
               "outset", "onset"}
# the words a digression (`digressions_dropped`) never says
SAYING = (NAMING | GENERIC | GENERIC_NOUNS | MOTION_WORDS | MOTION_DESCRIPTIONS | SPEED_CLASS_WORDS | FLOATING_WORDS
          | STATIC_SAID | REST_WORDS | START_WORDS | END_SAID | FILM_WORDS | CONDITION_OPENERS | CONDITION_WORDS
          | IMAGINING | IMAGINED_SAID | TIME_SAID | NEGATIONS | DIRECTION_WORDS | ASKING | set(COLOR_NAMES)
          | OTHER_COLOURS | PLURALS | QUERY_NOUNS | COMPARING | {"would", "could", "had", "were", "should", "shall"}
          | {"at", "once", "upon", "how", "why", "where", "who", "whom", "whose", "then", "first", "after", "before",
             "until", "later", "end", "ends", "way", "each", "other", "both", "either", "anything", "something",
             "nothing", "same", "instead", "rather", "only", "just", "moment", "instant", "frame", "second", "seconds",
             "time", "point", "engine", "ground", "air", "sky", "future", "next", "last", "will", "gonna", "going",
             "frames", "from", "past", "beyond", "freeze", "afterwards", "afterward", "hereafter", "eventually",
             "through", "scale", "state", "tell", "give", "name", "describe", "identify", "determine", "report",
             "find", "list"}
          | {w for t in LATER_TIMES for w in t} | START_ADJECTIVES | DURATIONS | NUMBERS
          | {"partway", "halfway", "midway", "middle", "stop", "stopped", "halted", "paused", "frozen", "froze",
             "freezes", "cut", "cuts", "terminates", "terminated", "truncated"})


def clause_time(clause: list[str]) -> str | None:
    """The operation asking at the time a fronted clause names ('at impact': get_frame; 'once it appears':
    come_in_frame; 'right at the start': start), or None."""
    for op, cues in (("come_in_frame", COMES_IN_WORDS), ("get_frame", IMPACT_WORDS), ("start", START_WORDS)):
        if cues.intersection(clause):
            return op
    return None


def _chosen(parses: list[Parse], time: str | None, named: bool = False) -> Parse:
    """Of a question's readings, the one asking at the time its fronted clause names where exactly one of two
    different programs does ('At impact, is X slower than Y?' said as is reads as at the start); else, where the
    question after its fronted clause names its own objects and no pronoun (`named`), the clause put last: its
    subject is then the first object said, as in the grammar's questions ('When the blue suv hits the brown
    scooter, is the brown scooter stopped?' as said was read about the suv); else the one the decoder is surer of
    (max keeps the first of equals: the question as said, whose reason stands when no reading parses)."""
    parsed = [p for p in parses if p.program is not None]
    if time and len(parsed) == 2 and parsed[0].program != parsed[1].program:
        fit = [p for p in parsed if time in p.program]
        if len(fit) == 1:
            return fit[0]
    if named and len(parsed) == 2 and parses[1].program is not None:
        return parses[1]
    return max(parses, key=lambda p: p.confidence if p.program is not None else -1.0)


def _second_mentions(said: list[str], named: list, words: list[str], refs: list) -> tuple[tuple[str, str], ...]:
    """(shorter mention, the description it was read as) for each mention `corefer` merged into a fuller one."""
    def text(ref) -> str:
        return " ".join(ref).replace("_", " ")

    pairs = {(text(named[int(a[4:-1]) - 1]), text(refs[int(b[4:-1]) - 1]))
             for a, b in zip(said, words) if a.startswith("<obj")}
    return tuple(sorted((short, full) for short, full in pairs if short != full))


STEMMER = snowballstemmer.stemmer("english")
ENDINGS = ("ing", "ed", "es", "s", "ly")


def _same_ending(word: str, forms) -> str:
    """Of the forms of one stem, the one with the word's ending ('-ed', '-ing', ...), else the shortest."""
    same = [f for f in forms if any(f.endswith(e) and word.endswith(e) for e in ENDINGS)]
    return min(same or forms, key=lambda f: (len(f), f))


def _by_stem(words: dict[str, list[str]]) -> dict[str, dict[str, list[str]]]:
    """{word: known words} -> {stem: {word: known words}}. Object words have no stem: 'jets' is no vehicle of
    the catalogue's, and a copy-path word must come exactly or as a typo of one."""
    out: dict[str, dict[str, list[str]]] = {}
    for w, known in sorted(words.items()):
        if w not in OBJECT_WORDS and w.isalpha():
            out.setdefault(STEMMER.stemWord(w), {})[w] = known
    return out


def well_formed(tokens: list[str]) -> bool:
    """Every token an operation with an argument it accepts, and a postfix stack that ends with one value."""
    try:
        ops = parse_program(tokens)
    except ProgramError:
        return False
    depth = 0
    for name, _ in ops:
        n = len(OPS[name].inputs)
        if depth < n:
            return False
        depth += 1 - n
    return depth == 1
