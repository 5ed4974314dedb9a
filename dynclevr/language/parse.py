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
- it asks what no family asks, however near a family's its words are (refusals.py, from the words before decoding:
  a count, a cause, how often, a ranking, two questions at once, ...), or its reading does not read what the words
  say (checks.py: the opposite of the question, since no operation negates, another form, property or time than
  the one asked, ...);
- the program leaves out an object the question names (a sentence read as a question about fewer objects), or
  refers to one it does not name. Object words reach the program only through the
  copy path (references.py): the sequence model may generalise a sentence, never invent or change an object.

Before decoding, `_words` reads the question through a fixed pipeline of rewrites, each `f(words) -> (words,
read_as)`: how its words are written or said (surface.py), what is said around it (asides.py), its context and what
is said after it (context.py), times said another way (times.py) and wordings the grammar says otherwise
(wordings.py); the word sets several of them read are in words.py. A clause of time said first is read both as said
and put last (`time_clause_last`, `clause_time`, `_chosen`, here).
"""

from __future__ import annotations

import io
import json
import pickle
import re
from dataclasses import dataclass, replace
from pathlib import Path

import snowballstemmer
import torch

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import ArtifactError, atomic_path, write_json_atomic
from dynclevr.colors import COLOR_NAMES
from dynclevr.language.asides import (addressed_as_named, addressees_dropped, asides_dropped, calls_read,
                                      corrections_dropped, dashed_aside_dropped, description_dropped,
                                      digressions_dropped, dislocated_as_asked, distractors_dropped,
                                      examination_as_asked, forecast_dropped, framing_dropped, grumble_dropped,
                                      heading_dropped, headlines_dropped, hedges_dropped, hooks_dropped,
                                      hypothesis_as_asked, in_verse, interjections_dropped, log_stamp_dropped,
                                      owners_dropped, person_remark_dropped, preamble_dropped, prompt_dropped,
                                      proof_as_asked, radio_as_asked, ramble_dropped, reference_dropped,
                                      remark_after_dropped, requested_as_asked, restatements_read, riddles_dropped,
                                      script_cues_dropped, simile_closing_dropped, soothing_dropped,
                                      speaker_asides_dropped, speaker_clauses_dropped, ticket_fields_read,
                                      verse_joined, wagers_read, word_given_dropped)
from dynclevr.language.checks import (acceleration_unread, acceleration_unsaid, answer_form_unmatched, anything_unasked,
                                      attribute_unsaid, both_imagined, class_asked_as_which, clock_unasked,
                                      collision_at_start, collision_time_dropped, collision_unread, compared_unsaid,
                                      compared_with_no_vehicle, comparison_imagined, comparison_unread,
                                      comparison_unsaid, condition_subject_first, condition_unsaid, cut_said,
                                      direction_unasked, direction_unsaid, end_unread, floating_unread, floating_unsaid,
                                      form_unasked, form_unmatched, future_unread, heading_unread, holding_unsaid,
                                      imagining_unread, impact_unsaid, instruction_unread, moment_unread,
                                      motion_foretold, motion_unfiltered, motion_unread, named_attribute, operation,
                                      own_attribute_asked, pointed_back, property_unread, reversed_reading, size_unread,
                                      speed_class_turned, speed_unsaid, start_speed_at_collision, still_continuing,
                                      than_as_said, than_turned, time_symbol_said, time_unasked, uncompared,
                                      visibility_unread, what_happens)
from dynclevr.language.code import code_as_said
from dynclevr.language.context import (afterthoughts_read, change_as_imagined, check_ins_stated, closing_mark_added,
                                       context_as_question, found_then_asked, fragments_joined,
                                       impact_given_as_context, impact_said_first, inverted_condition_as_if,
                                       part_labels_read, possibility_as_supposed, retold_as_imagined,
                                       scenario_as_asked, settings_as_imagined, someone_as_something,
                                       told_otherwise_as_imagined, transcript_as_asked, variables_named)
from dynclevr.language.english import real_words
from dynclevr.language.params import QParserParams
from dynclevr.language.references import (OBJECT_WORDS, attributes_as_named, catalogue_names, concrete_program,
                                          corefer, delexicalise, described_as_named, description_as_said,
                                          heard_as_said, is_description, placeholders, shared_noun_as_two)
from dynclevr.language.refusals import (CAUSES, CAUSING, HEIGHT_COMPARISONS, HOW_ASKED, NORMATIVE, REPEATS, REVERSING,
                                        TOWARD, _at_viewer, chained, checked_attribute, imagined_otherwise,
                                        impact_denied, onset_asked, ordered, otherwise_compared, possibility_asked,
                                        premised, properties_joined, quantified, questions_joined, ranking,
                                        reversed_as_said, several_asked, speed_measure, speed_measured, speeds_alike,
                                        times_joined, unknown_property, _unknown_vehicle)
from dynclevr.language.seq2seq import Dims, Ensemble, Seq2Seq, one_thread, pad_batch
from dynclevr.language.surface import (SPELT_BY_EAR, archaic_as_said, code_switched_as_said, colour_clause_as_named,
                                       corrections_starred, creole_as_said, emoji_as_said, glosses_read,
                                       homophones_as_said, quoted_question, she_as_it, shorthand_as_said, spelt_by_ear,
                                       still_as_adjective, telegram_as_said, trailing_off_read, worksheet_as_said)
from dynclevr.language.times import (active_cut_as_said, first_frames_as_said, inserted_time_last, moment_pictured,
                                     present_asked_later, time_clause_closed, video_end_as_said)
from dynclevr.language.tokenize import SPELLINGS, tokenize
from dynclevr.language.vocab import (SPECIALS, UNK_ID, Vocab, dropped_g, rejoined, run_together, scanned, slipped,
                                     slips, sound_index, stretched)
from dynclevr.language.wordings import (alternatives_as_asked, attention_as_subject, attributes_offered_dropped,
                                        clause_comma_added, choices_as_which, class_as_asked, classed_as_asked,
                                        cleft_as_asked, comparative_as_said, condition_named_as_said,
                                        contact_made_as_active, contest_as_compared, drive_on_as_hit,
                                        floating_plane_as_vehicle, pair_colour_shared, fronted_value_as_asked,
                                        fronted_whether_as_asked, heading_as_direction, height_as_aloft, idioms_as_said,
                                        imperative_as_stated, inverted_as_asked, let_dropped,
                                        negative_question_as_asked, noun_phrase_as_question, opposed_dropped,
                                        request_after_setting, request_as_imperative, restated_dropped, similes_dropped,
                                        speed_as_subject, struck_as_active, tail_as_question, trajectory_as_collision,
                                        type_as_said, type_of_category_as_vehicle, verbless_comparison_asked)
from dynclevr.language.words import (AUXILIARIES, COMES_IN_WORDS, COMPARISONS, CONDITION_WORDS, DETERMINERS, DURATIONS,
                                     GENERIC, GENERIC_NOUNS, LOOKS, MOTION_NOUNS, NAMING, NUMBERS, OTHER_COLOURS,
                                     PLURALS, SPEED_CLASS_WORDS, SPEED_NOUNS, SPEED_ORDER, START_WORDS, TIME_OPENERS,
                                     _at, impact_like)
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


def _unknown_named(reason: str) -> set[str]:
    """The words a refusal names as unknown to the parser ("unknown words: 'i', 'want'", "... turns on 'crew', a word
    the parser does not know")."""
    if not (reason.startswith("unknown words: ") or "a word the parser does not know" in reason):
        return set()
    return set(re.findall(r"'([^']+)'", reason.split(", a word the parser does not know")[0]))


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
        # ... and a word spelt as it sounds, as the vehicle's name or the word of the questions' own it sounds like
        self.sounds = sound_index(SPELT_BY_EAR)
        # ... but never a common English word the parser does not know, which the writer meant (english.py)
        self.real_words = real_words()
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
        parses = self._analysed(texts)
        # a question refused for a word the parser does not know, read again without the clauses of the speaker's
        # own that hold it ('..., and I want to know: what kind of vehicle is it?')
        retries = {i: cut for i, (text, p) in enumerate(zip(texts, parses)) if p.program is None and
                   (unknown := _unknown_named(p.reason)) and (cut := speaker_clauses_dropped(text, unknown))}
        for (i, (_, dropped)), again in zip(retries.items(), self._analysed([cut for cut, _ in retries.values()])):
            if again.program:
                said = "nothing, a verse's filler" if in_verse(texts[i]) else "nothing, the speaker's own words"
                parses[i] = replace(again, read_as=((dropped, said), *again.read_as))
        # ... and one refused with a remark after it, a simile closing it, a heading before it, a screenplay's
        # scene heading and cue, a heading's flourish or an aside between dashes, read again without them
        for cutter, said in ((remark_after_dropped, "nothing, a remark after the question"),
                             (simile_closing_dropped, "nothing, a simile"),
                             (heading_dropped, "nothing, a heading that says nothing the question does not"),
                             (script_cues_dropped, "nothing, a screenplay's heading and cue"),
                             (description_dropped, "nothing, a heading's flourish"),
                             (dashed_aside_dropped, "nothing, an aside between dashes"),
                             (headlines_dropped, "nothing, a ticker's headlines"),
                             (riddles_dropped, "nothing, a riddle before the question")):
            self._read_cut(texts, parses, cutter, said)
        return parses

    def _read_cut(self, texts: list[str], parses: list[Parse], cutter, said: str) -> None:
        """Each refused question that `cutter` cuts read again without what it cuts (and then without the clauses
        of its own that hold a word the parser does not know); where that reads, the reading, the cut as `said`."""
        retries = {i: cut for i, (text, p) in enumerate(zip(texts, parses)) if p.program is None and
                   (cut := cutter(text))}
        for (i, (cut, dropped)), again in zip(retries.items(), self._analysed([cut for cut, _ in retries.values()])):
            remark = (dropped, said)
            if again.program is None and (unknown := _unknown_named(again.reason)) and \
                    (cut_again := speaker_clauses_dropped(cut, unknown)):
                again = replace(self._analysed([cut_again[0]])[0], read_as=(
                    (cut_again[1], "nothing, the speaker's own words"), *again.read_as))
            if again.program:
                parses[i] = replace(again, read_as=(remark, *again.read_as))

    def _analysed(self, texts: list[str]) -> list[Parse]:
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
        # a collision asked in the present after the video is said to stop is one after the cut (the stop's sentence
        # is read as context, and 'does the jet hit the bus?' then read within the video)
        chosen = [_cut_as_future(c, t, said) for c, t, said in zip(chosen, texts, said_words)]
        chosen = [_than_as_said(c, t) for c, t in zip(chosen, texts)]
        # checked against the words as said: the lexicon reads some as others ('away' as 'off', 'turn' as 'turned');
        # a collision against the words as read, typos fixed ('colide'), where no word it does not know may be an
        # impact's misspelt (the decoder reads a collision in 'collied' from the rest of the question)
        return [replace(c, program=None, reason=why) if c.program and (
            why := form_unmatched(said, c.program) or answer_form_unmatched(c.read_as, c.program)
            or direction_unasked(said, c.program) or direction_unsaid(said, read, c.program)
            or holding_unsaid(said, c.program) or moment_unread(said, c.program) or heading_unread(said, c.program)
            or time_unasked(said, c.program) or collision_at_start(said, c.program) or clock_unasked(said, c.program)
            or instruction_unread(said, c.program)
            or anything_unasked(said, c.program)
            or (not any(map(impact_like, set(read) - self.known)) and impact_unsaid(read, c.program))
            or form_unasked(said, c.program)
            or what_happens(read, c.program) or attribute_unsaid(said, read, c.program)
            or own_attribute_asked(said, c.program)
            or collision_unread(said, c.program) or uncompared(read, c.program)
            or future_unread(said, c.program, cut_said(tokenize(text), said).split() + read)
            or both_imagined(said, c.program) or speed_unsaid(read, c.program) or floating_unsaid(read, c.program)
            or comparison_imagined(read, c.program) or comparison_unsaid(read, c.program)
            or compared_with_no_vehicle(read, c.program, self.known)
            or comparison_unread(read, c.program)
            or imagining_unread(said, c.program, tokenize(text)) or floating_unread(said, c.program)
            or condition_unsaid(said + [w for a, _ in c.read_as for w in a.split()], c.program)
            or motion_unread(said, c.program)
            or motion_unfiltered(said, c.program) or still_continuing(read, c.program)
            or property_unread(said, c.program) or visibility_unread(said, c.program)
            or acceleration_unread(said, c.program) or acceleration_unsaid(read, c.program)
            or motion_foretold(read, c.program)
            or end_unread(said + read, c.program) or size_unread(said, c.program)
            or start_speed_at_collision(said, c.program) or pointed_back(said, c.program)
            or than_turned(tokenize(text), c.program) or speed_class_turned(read, c.program)
            or collision_time_dropped(tokenize(text), c.program)
            or class_asked_as_which(read, c.program)) else c
            for c, said, read, text in zip(chosen, said_words, read_words, texts)]

    def _words(self, text) -> tuple[list[str], str, tuple[tuple[str, str], ...], list[str]]:
        """The question's words, unknown ones read as known ones where it can and typos fixed, or a reason it cannot
        be parsed; the words read as others; and the words as the rules left them, before any was read as another."""
        if not isinstance(text, str) or not text.strip():
            return [], "empty question", (), []
        text, coded = code_as_said(verse_joined(text))
        words = tokenize(text)
        if not words:
            return [], "empty question", (), []
        if len(words) > MAX_WORDS:
            return [], f"too long ({len(words)} words, at most {MAX_WORDS})", (), []
        if symbol := time_symbol_said(words):
            return [], symbol, (), []
        words = rejoined(words, self.readable, SPELLINGS)
        words, parts = part_labels_read(words)   # (before a label is read as a word: '[B4]' is no 'before')
        # 'sloooow', 'sooo': chat's held letters; 'rnotorbike', 's1ower': a scanner's misread print (read only as a
        # word the parser knows, never a synonym's: 'tell' is two confusions from 'teh')
        held = {w: stretched(w, self.readable) or dropped_g(w, self.readable) or scanned(w, self.known, SPELLINGS)
                for w in words if w not in self.readable}
        held = {w: k for w, k in held.items() if k}
        words = [held.get(w, w) for w in words]
        words, trailed = trailing_off_read(words)
        words, given = word_given_dropped(words)
        words, stamped = log_stamp_dropped(words)
        words, referenced = reference_dropped(words)
        given += stamped + referenced
        trailed += given
        words = closing_mark_added(words)
        words, clause_comma = clause_comma_added(words)
        words, pictured = moment_pictured(words)
        words, starred = corrections_starred(words, self.readable)
        starred = trailed + clause_comma + pictured + starred
        words, archaic = archaic_as_said(words, self.readable)
        words, relayed = quoted_question(words)
        starred += archaic + relayed
        words, transcribed = transcript_as_asked(words)
        words, printed = worksheet_as_said(words)
        words, letters = variables_named(words)
        printed += letters
        words, called = calls_read(words)
        printed += called
        printed = transcribed + printed
        words, pictured_words = emoji_as_said(words)
        words, shorthand = shorthand_as_said(words)
        shorthand = pictured_words + shorthand
        words, telegram = telegram_as_said(words)
        words, creole = creole_as_said(words)
        creole = telegram + creole
        words, switched = code_switched_as_said(words)
        shorthand += creole + switched
        words, shared = shared_noun_as_two(words)   # before a plural is read as its singular
        words, heard = heard_as_said(words, self.known)
        words, sounded = homophones_as_said(words)
        words, by_ear = spelt_by_ear(words, self.sounds, self.readable, self.real_words)
        words, remark = person_remark_dropped(words)
        words, her = she_as_it(words)
        words, scenery = still_as_adjective(words)
        by_ear += remark + her + scenery
        shorthand = coded + tuple(held.items()) + starred + printed + shorthand + heard + sounded + by_ear
        words, named = catalogue_names(words)
        named = parts + named
        words, fragments = fragments_joined(words)
        words, addressees = addressees_dropped(words)
        named = shared + named + fragments + addressees
        words, looked = described_as_named(words)
        words, attributed = attributes_as_named(words)
        words, clause = colour_clause_as_named(words)
        words, glossed = glosses_read(words)
        named += looked + attributed + clause + glossed
        words, corrected = corrections_dropped(words)
        words, setting = settings_as_imagined(words)
        words, retold = retold_as_imagined(words)
        words, changed = change_as_imagined(words)
        words, inverted_if = inverted_condition_as_if(words)
        setting += retold + changed + inverted_if
        words, scenario = scenario_as_asked(words)
        words, told = told_otherwise_as_imagined(words)
        corrected += setting + scenario + told
        words, radioed = radio_as_asked(words)
        words, examined = examination_as_asked(words)
        examined = radioed + examined
        words, wagered = wagers_read(words)
        words, requested = requested_as_asked(words)
        words, tested = hypothesis_as_asked(words)
        words, proved = proof_as_asked(words)
        tested += proved
        wagered += requested + tested
        corrected += examined + wagered
        words, hedged = hedges_dropped(words)
        words, rambled = ramble_dropped(words)
        words, set_apart = distractors_dropped(words)
        set_apart = rambled + set_apart
        hedged += set_apart
        words, dislocated = dislocated_as_asked(words)
        corrected += hedged + dislocated
        words, ticket = ticket_fields_read(words)
        words, prompted = prompt_dropped(words)
        prompted = ticket + prompted
        words, kind = type_of_category_as_vehicle(words)
        words, restated = restated_dropped(words)
        words = request_after_setting(words)
        words, checked = check_ins_stated(words)
        words, found = found_then_asked(words)
        words, given = impact_given_as_context(words)
        words, cut = active_cut_as_said(words)
        found += given + cut
        words, someone = someone_as_something(words)
        checked += found + someone
        words, fronted_request = fronted_whether_as_asked(words)
        checked += fronted_request
        # (a vehicle spoken to in a sentence before the question: 'Brown aircraft, you hit the cyan chopper. Were you
        # slow at the moment of impact?')
        words, spoken_to = addressed_as_named(words)
        words, supposed = possibility_as_supposed(words)
        words, context = context_as_question(words, self.known)
        context = checked + spoken_to + supposed + context
        context = prompted + kind + restated + context
        words, after = afterthoughts_read(words, self.known)
        words, impact = impact_said_first(words)
        after += impact
        words, owned = owners_dropped(words)
        words, own_place = speaker_asides_dropped(words)
        owned += own_place

        words, teased = hooks_dropped(words)
        words, labelled = asides_dropped(words)
        words, grumbled = grumble_dropped(words)
        words, soothed = soothing_dropped(words)
        labelled += grumbled + soothed
        labelled = teased + labelled
        words, inserted = inserted_time_last(words)
        words, opened = interjections_dropped(words)
        words, inverted = inverted_as_asked(words)
        opened += inverted
        words, shared_colour = pair_colour_shared(words)
        words, similes = similes_dropped(words)
        words, idioms = idioms_as_said(words)
        idioms = shared_colour + similes + idioms
        words, meant = restatements_read(words)
        idioms += meant
        words, contest = contest_as_compared(words)
        words, active = contact_made_as_active(words)
        words, named_condition = condition_named_as_said(words)
        words, struck = struck_as_active(words)
        idioms += contest + active + named_condition + struck
        words, digressed = digressions_dropped(words)
        words, closed = time_clause_closed(words)
        idioms += digressed + closed
        words, described = description_as_said(words)
        words, typed = type_as_said(words)
        words, afloat = floating_plane_as_vehicle(words)
        words, end = video_end_as_said(words)
        words, later = present_asked_later(words)
        end += later
        words, framing = framing_dropped(words)
        words, forecast = forecast_dropped(words)
        words, preamble = preamble_dropped(words)
        preamble = forecast + preamble
        framing += preamble
        words, attended = attention_as_subject(words)
        words, request = request_as_imperative(words)
        words, stated = imperative_as_stated(words)
        words, verbless = verbless_comparison_asked(words)
        words, driven = drive_on_as_hit(words)
        verbless += driven
        words, fronted = fronted_value_as_asked(words)
        fronted = verbless + fronted
        words, negative = negative_question_as_asked(words)
        negative = fronted + negative
        words, asked = noun_phrase_as_question(words)
        words, classed = class_as_asked(words)
        words, classed_as = classed_as_asked(words)
        classed += classed_as
        asked += classed
        words, aloft = height_as_aloft(words)
        words, heading = heading_as_direction(words)
        words, subject = speed_as_subject(words)
        words, trajectory = trajectory_as_collision(words)
        words, let = let_dropped(words)
        subject += trajectory + let
        words, first = first_frames_as_said(words)
        words, cleft = cleft_as_asked(words)
        words, more = comparative_as_said(words)
        more = cleft + more
        words, tail = tail_as_question(words)
        words, choices = attributes_offered_dropped(words)
        words, which = choices_as_which(words)
        words, opposed = opposed_dropped(words)
        words, offered = alternatives_as_asked(words)
        offered = choices + which + opposed + offered
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
        # A common English word is none of these: the writer meant it (`english.py`: 'feast' is no 'fast').
        fixed = {w: self.typo_fixed(w, first=w == words[0]) for w in words if w not in self.known}
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
                said[:1] == ["count"] or said[:2] == ["number", "of"] or \
                any(said[k:k + 3] == ["the", "number", "of"] for k in range(len(said))):
            return [], "the question asks for a count ('how many'), which no question here answers", read_as, said
        lasting = next((w for w in said if w in DURATIONS), None)
        if lasting:
            return [], f"the question asks how long something lasts ('{lasting}'), which no question here answers", \
                read_as, said
        counted = next((" ".join(said[k:k + n]) for k, a in enumerate(said) for n in (2, 3)
                        if (a.isdigit() or a in NUMBERS) and said[k + n - 1:k + n] and said[k + n - 1] in PLURALS
                        and (n == 2 or said[k + 1] in ("other", "more", "different", "separate"))), None) or \
            next((" ".join(said[k:k + 3]) for k in range(len(said) - 2) if said[k] in ("more", "fewer", "less")
                  and said[k + 1] == "than" and (said[k + 2].isdigit() or said[k + 2] in NUMBERS | {"one", "once"})),
                 None)
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
        # 'is it fast at the start or when it hits the bus?' was read at the collision alone
        both = next((" ".join(said[k:k + 3]) for k in range(len(said) - 2) if said[k] in START_WORDS
                     and said[k + 1] in ("or", "and") and said[k + 2] in TIME_OPENERS), None) or \
            next((" ".join(said[k:k + 4]) for k in range(len(said) - 3) if said[k] in ("or", "and")
                  and said[k + 1:k + 3] == ["at", "the"] and said[k + 3] in START_WORDS
                  and {"when", "as", "while", "once"}.intersection(said[:k])), None)
        if both:
            return [], (f"the question asks at two times at once ('{both}'), which no question here asks: ask at "
                        "each time alone"), read_as, said
        # (also with the other vehicle between: 'does the red car go slower than the bus, or faster?'; or the other
        # asked again: 'is the bus faster than the red car, or is the red car faster?')
        offered = next((f"{a} or {next(c for c in said[j + 1:] if c in COMPARISONS)}" for k, a in enumerate(said)
                        if a in COMPARISONS for j in range(k + 1, min(k + 10, len(said) - 1)) if said[j] == "or" and (
                            said[j + 1] in COMPARISONS and SPEED_ORDER[a] != SPEED_ORDER[said[j + 1]] or
                            said[j + 1] in ("is", "was", "does", "did") and COMPARISONS & set(said[j + 2:j + 9]))),
                       None)
        if offered:
            return [], (f"the question offers '{offered}' to choose from, which no question here answers: ask "
                        "whether one is faster (or slower) than the other"), read_as, said
        reversal = " ".join(at[1]) if (at := _at(said, REVERSING)) else None
        if reversal:
            return [], (f"the question asks the opposite of what the parser can read ('{reversal}'): ask it the "
                        "other way round and take the opposite answer"), read_as, said
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
        # 'at the merge': a real word the parser does not know says when (it was read at the start)
        # (not an idiom's 'at the risk of')
        moment = next((f"{a} the {c}" for a, b, c, d in zip(words, words[1:], words[2:], words[3:] + [""])
                       if a in ("at", "during") and b == "the" and c in self.real_words and d != "of"), None)
        if moment:
            return [], (f"the question asks at a moment the parser does not know ('{moment}'): ask at the start, when "
                        "X hits Y or when X comes into view"), read_as, said
        # (a common English word kept as itself counts no more than when the typo fixing turned it into a known
        # word: the decoder's attention to it still refuses a question it carries)
        unknown = [w for w in words if w not in self.known and w not in self.real_words]
        if len(unknown) > self.params.max_unknown_words:
            return [], "unknown words: " + ", ".join(f"'{w}'" for w in dict.fromkeys(unknown)), read_as, said
        return words, "", read_as, said

    def typo_fixed(self, word: str, first: bool = False) -> str:
        """The known word an unknown `word` is a typo of (a slip of the fingers, two words run together, a misspelt
        colour or vehicle name unless it opens the question, a long word one edit away), or `word` itself; a common
        English word is kept (`english.py`)."""
        if word in self.real_words:
            return word
        return self._slipped(word) or run_together(word, self.readable) or (
            not first and OBJECT_LEXICON.closest(word)) or (len(word) >= TYPO_LETTERS and self.words.closest(word)) \
            or word

    def _slipped(self, word: str) -> str | None:
        """The one word `word` is a slip of (`vocab.slipped`); or, where it slips from a known word and from
        synonyms of it alone, that word ('fsat': 'fast', and 'fat', a swipe keyboard's 'fast')."""
        hit = slipped(word, self.readable, SPELLINGS)
        hits = [] if hit else slips(word, self.readable, SPELLINGS)
        meant = {self.synonyms[h][0] if len(self.synonyms.get(h, ())) == 1 else h for h in hits}
        return hit or (meant.pop() if len(meant) == 1 and self.known.intersection(hits) else None)

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
            # 'does the red bus hit another bus?': a vehicle told apart from the named one only as another of its
            # kind (`corefer` read it as the same one), which no program picks out
            if before in ("another", "other", "different") and w in words[:k]:
                return (f"the question tells a vehicle from the {named} only as another of its kind ('{before}'), "
                        "which no question here picks out: name that vehicle by its colour or type")
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
            # 'the pink suv': a colour the dataset does not use (not a learner's ', then biplane and ... collide ?')
            if before and before not in self.known and before != "then":
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
IMPACT_WORDS = {"impact", "collision", "collide", "collides", "hit", "hits", "crash", "crashes", "bump", "bumps",
                "strike", "strikes", "smash", "smashes", "slam", "slams", "contact", "meet", "meets"}


def clause_time(clause: list[str]) -> str | None:
    """The operation asking at the time a fronted clause names ('at impact': get_frame; 'once it appears':
    come_in_frame; 'right at the start': start), or None."""
    for op, cues in (("come_in_frame", COMES_IN_WORDS), ("get_frame", IMPACT_WORDS), ("start", START_WORDS)):
        if cues.intersection(clause):
            return op
    return None


def _cut_as_future(parse: Parse, text: str, said: list[str]) -> Parse:
    """A collision asked in the present, read within the video, where the question says the video stops before it
    (`checks.cut_said`): the same collision after the cut."""
    program = parse.program
    cut = cut_said(tokenize(text), said) if program and program[0] == "Events" and program[-1] == "exist" else ""
    if not cut:
        return parse
    return replace(parse, program=["futureEvents", *program[1:]],
                   read_as=(*parse.read_as, (cut, "after the video ends")))


def _than_as_said(parse: Parse, text: str) -> Parse:
    """A comparison read turned round, the vehicle said after 'than' taken for the one compared: the two swapped
    (`checks.than_as_said`)."""
    program = than_as_said(tokenize(text), parse.program) if parse.program else None
    return parse if program is None else replace(
        parse, program=program, read_as=(*parse.read_as, ("than", "compared with the vehicle after it")))


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
