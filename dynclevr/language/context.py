"""Context before the question, and what is said after it. The sentences before the question are read for what it refers
back to, and dropped (`context_as_question`): the vehicles its 'it', 'they', 'the former' or shorter names mean, a
counterfactual's condition said first, the moment its 'then' means; so is speech transcribed without stops
(`_run_on_question`). Before it, in `QuestionParser._words`, a change said as a setting, a tester's scenario or another
telling of the story is read as the grammar's condition (`settings_as_imagined`, `scenario_as_asked`,
`told_otherwise_as_imagined`); after it, what is said after the question is read into it (`afterthoughts_read`), and a
collision said first without its pair is said with the two vehicles (`impact_said_first`)."""

from __future__ import annotations

import re

from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.colors import COLOR_NAMES
from dynclevr.language.references import OBJECT_WORDS, generalises, mentions
from dynclevr.language.times import END_SAID, FILM_WORDS, _at_cut, _video_continued, _video_end
from dynclevr.language.words import (ASKING, CATEGORY_OF, CHAT, CHECKING_TAGS, COMES_IN_WORDS, CONDITION_LABELS,
                                     CONDITION_OPENERS, COPULAS, DETERMINERS, END_TIMES, END_WORDS, FILLERS, GENERIC,
                                     GENERIC_NOUNS, HEADING_KEPT, IMAGINED_BACK, IMAGINED_SAID, IMAGINING,
                                     IMPACT_STEMS, INTERJECTIONS, LOOKS, MOTION_DESCRIPTIONS, MOTION_WORDS, NAMING,
                                     NOUNS_SAID, OTHER_COLOURS, PEOPLE, QUERY_NOUNS, QUESTION_OPENERS, SENTENCE_ENDS,
                                     SHAPE_ASKED, SPEAKER_AND_LISTENER, SPEED_CLASS_WORDS, SPEED_NOUNS, START_WORDS,
                                     TIME_OPENERS, UNMOVED, UNNAMED, YES_NO_OPENERS, _at, asks_impact)

# Context said before the question ('The yellow school bus is near the left edge. I couldn't tell whether it was
# moving. How fast is it going right at the start?'). The question is the last sentence ending in '?'; the sentences
# before it are read for what the question refers back to, and dropped: the vehicles its 'it', 'they', 'the former'
# or shorter names mean, a counterfactual's condition ('Suppose the bus had been parked. ... Would it hit the car?'),
# the moment its 'then' means ('The SUV slams into the jet. How fast was the SUV going then?') and the start it says
# nothing of ('Beginning of the video. Is the first one slower than the second?').
CONTEXT_OPENERS = {"so", "ok", "okay", "and", "now", "but", "well", "alright", "right", "also", ",", "-", ":"}
CONDITIONS_SAID = {("what", "if"): ("if",), ("let", "'", "s", "say"): ("suppose",), ("lets", "say"): ("suppose",),
                   ("say",): ("suppose",), ("hypothetically", ":"): ("suppose",), ("hypothetically", ","): ("suppose",),
                   ("hypothetically",): ("suppose",), ("consider",): ("suppose",), ("think",): ("suppose",),
                   **{("in", a, world, *where): ("if",) for a in ("a", "another")
                      for world in ("world", "version", "timeline", "scenario", "universe", "reality")
                      for where in (("where",), ("in", "which"))},
                   **{(w,): (w,) for w in ("suppose", "supposing", "imagine", "assume", "assuming", "pretend", "if",
                                           "picture", "envision", "envisage", "visualise", "visualize")}}
WHETHER = {"tell", "know", "see", "sure", "wonder", "wondering", "check", "ask", "asking", "unsure", "clear", "say"}
# openers that may state a fact as well as imagine one, and the words that say they imagine
STATING = {"assume", "assuming", "consider", "think"}
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
NAMELESS = {"some", "a", "an", "another", "one"}
# a moment's words of feeling ('in that tense moment', 'at that fateful instant')
MOMENT_ADJECTIVES = ("very", "exact", "precise", "same", "tense", "fateful", "fatal", "critical", "crucial", "decisive",
                     "dramatic", "split", "key", "awful", "terrible", "unlucky", "unfortunate", "thrilling", "shocking")
THEN_SAID = (  # (the longest first: 'In that moment of impact, which direction ...?')
             *((p, d, *very, m, "of", n) for p in ("at", "in") for d in ("this", "that")
               for very in ((), *((v,) for v in MOMENT_ADJECTIVES)) for m in ("moment", "instant")
               for n in ("impact", "collision", "contact")),
             ("at", "that", "moment"), ("at", "that", "point"), ("at", "that", "instant"), ("at", "that", "time"),
             ("in", "that", "moment"), ("at", "that", "stage"), ("right", "then"), ("just", "then"),
             *((p, d, *very, m) for p in ("at", "in", "during") for d in ("this", "that", "the")
               if (p, d) != ("at", "the") for very in ((), *((v,) for v in MOMENT_ADJECTIVES))
               for m in ("moment", "instant", "point", "event", "collision", "crash", "impact")),
             *((w, d, h) for w in ("when", "as") for d in ("that", "this", "it") for h in ("happens", "happened")),
             # a signer's gloss ('... BUMP. THAT TIME SCHOOL BUS STAND STILL, TRUE?')
             ("that", "time"), ("that", "moment"), ("that", "instant"),
             ("then",))
# a collision said without its partner ('At the moment of impact, how fast is the bike?'), the context's
IMPACT_NOUNS = ("impact", "crash", "collision", "contact", "hit", "smash", "bump")
IMPACT_MOMENTS = sorted({(p, "the", m, "of", *the, n) for p in ("at", "in") for m in ("moment", "instant", "time")
                         for the in ((), ("the",), ("that",), ("this",)) for n in IMPACT_NOUNS}
                        | {(p, n) for p in ("at", "on", "upon") for n in ("impact", "contact")}
                        | {(p, "the", n) for p in ("at", "during", "in") for n in IMPACT_NOUNS}, key=len, reverse=True)
# a question's own time, besides the start and coming into view
OWN_TIMES = {"after", "end", "ends", "ended", "will", "future"}
FIRST_SPANS = {"moments", "moment", "frames", "frame", "seconds", "second", "instant", "instants"}


def closing_mark_added(words: list[str]) -> list[str]:
    """A question asked again after its question mark without one of its own ('what did the dirtbike hit ? like
    what kind of vehicle') closed with one, so that it is read as what is said after the question."""
    last = max((k for k, w in enumerate(words) if w == "?"), default=None)
    if last is None or words[-1] in SENTENCE_ENDS:
        return words
    after = words[last + 1:]
    after = after[1:] if after[:1] == ["like"] else after
    return words + ["?"] if after[:1] and after[0] in ASKING | {"how"} else words


def _time_then_asked(words: list[str], k: int) -> bool:
    """Whether words[k:] open on a clause of time and a question follows it ('... ; right at the beginning , does
    the green one ...?')."""
    return words[k:k + 1] != [] and words[k] in TIME_OPENERS | {"right", "over", "throughout"} and any(
        words[m] == "," and words[m + 1:m + 2] and (words[m + 1] in QUESTION_OPENERS or words[m + 1] in ASKING)
        for m in range(k + 1, min(k + 12, len(words))))


def _sentence_spans(words: list[str]) -> list[tuple[int, int]]:
    """(first, past-last) word of each sentence; a run of ends ('?!') closes one; an ellipsis after a statement
    closes it ('the bike seems to dodge everything... does it'), after a word or two ('well... is it') or a word
    that cannot end one ('which...') none; a point
    after a letter ('i.e.') or between digits closes none; a semicolon before a question, or a clause of time and a
    question, closes one ('a plane is hanging in the air ; which colour is ...'), except after a condition
    ('suppose it had ... ; would it ...')."""
    spans, start = [], 0
    for k, w in enumerate(words):
        before, after = words[k - 1] if k else "", words[k + 1] if k + 1 < len(words) else ""
        said = [v for v in words[start:k] if v != "."]
        if w == ";" and (after in QUESTION_OPENERS or after in ASKING or _time_then_asked(words, k + 1)) and not \
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


def _opener_said(sentence: list[str]) -> tuple[int, tuple, tuple] | None:
    """Where a sentence opens on a condition's opener (after a label: 'Game designer: suppose ...', or as a label:
    'Counterfactual: the pickup ...'): its place, its words and the opener it is read as; None where it does not."""
    colon = sentence.index(":") if ":" in sentence else None
    if sentence[1:2] == ["-"] and sentence[0] in CONDITION_LABELS:   # a note's 'counterfactual - ...'
        colon = 1
    # ('Counterfactual: ...', and a label that opens on its word: 'Change one thing: ...')
    # (not a label before a collision alone, with no motion to imagine: 'Scenario: the fighter strikes the cruiser.'
    # sets the scene of a question about it)
    said = sentence[(colon or 0) + 1:]
    event = asks_impact(said) and not (MOTION_DESCRIPTIONS | IMAGINED_SAID | UNMOVED).intersection(said) and \
        not any(w.startswith(("accelerat", "float", "speed")) for w in said)
    # (or a heading that names one and no vehicle: 'Here's a variation on the initial conditions: ...')
    heading = sentence[:colon] if colon else []
    labelled = colon and (sentence[colon - 1] in CONDITION_LABELS or colon <= 3 and sentence[0] in CONDITION_LABELS
                          or colon <= 10 and CONDITION_LABELS - {"if"} & set(heading) and not mentions(heading))
    if labelled and (mentions(sentence[colon:]) or "it" in sentence) and not event:
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
        or said[1][0] in ("assume", "assuming") and START_WORDS & set(sentence) and (
            SPEED_CLASS_WORDS | STATES_SAID - {"up", "in", "at", "already"}) & set(sentence))
    # ('assume the cruiser starts slow', 'assume the blue road bike static at the start')



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
REGULAR_VERBS = ("start", "move", "travel", "float", "hover", "accelerate", "remain", "roll", "cruise", "crawl", "zoom",
                 "race", "idle", "wait", "rest", "drift", "coast")
PARTICIPLES.update({form: v + ("d" if v.endswith("e") else "ed") for v in REGULAR_VERBS
                    for form in (v + "s", v + ("d" if v.endswith("e") else "ed"))})


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
    collision (one of them `of`, where given), a vehicle coming into view, or the start; None where none does."""
    for sentence in reversed(context):
        refs = list(dict.fromkeys(next((f for f in fullest if _fits(r, f)), r) for _, _, r in mentions(sentence)))
        if asks_impact(sentence) and len(refs) >= 2 and (of is None or of in refs[:2]):
            return ["when", *_said(refs[0]), "and", *_said(refs[1]), "collide"]
        if of is None and COMES_IN_WORDS & set(sentence) and refs:
            return ["when", *_said(refs[0]), "comes", "into", "view"]
        if of is None and START_WORDS & set(sentence):   # ('... swim into focus as the video starts.')
            return ["at", "the", "start"]
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
    the words read so, or the words as they are and (). A collision said first with its partner as an absolute clause
    is read as a clause of time (`_absolute_impact`)."""
    said = _at(words[:6], IMPACT_MOMENTS)
    if not said or said[0] != 0:
        return _absolute_impact(words)
    rest = words[len(said[1]):]
    rest = rest[(rest[:1] == [","]):]
    pair = list(dict.fromkeys(r for _, _, r in mentions(rest)))
    if len(pair) != 2 or not rest or rest[0] not in QUESTION_OPENERS:
        return words, ()
    clause = ["when", *_said(pair[0]), "and", *_said(pair[1]), "collide", ","]
    return clause + rest, ((" ".join(said[1]), " ".join(clause[:-1])),)


IMPACT_NOUNS = {"collision", "crash", "impact", "contact"}
HAPPENING = {"happen", "happening", "occurring", "occur"}


def _absolute_impact(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'collision with the green car happening , the gray bicycle ... ?' -> 'when colliding with the green car , ...':
    a translation's absolute clause (the question was read of the green car)."""
    runs = mentions(words)
    if words[:1] == [] or words[0] not in IMPACT_NOUNS or words[1:2] != ["with"] or not runs or \
            runs[0][0] - (words[2:3] == ["the"]) != 2:
        return words, ()
    end = runs[0][1]
    if words[end:end + 1] == [] or words[end] not in HAPPENING or words[end + 1:end + 2] != [","]:
        return words, ()
    clause = ["when", "colliding", *words[1:runs[0][1]]]
    return clause + words[end + 1:], ((" ".join(words[:end + 1]), " ".join(clause)),)


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


FLAT_SUBJECTS = {"it", "that", "this"}


def _flat_remark(said: list[str]) -> bool:
    """Whether a sentence only remarks on what was told ('it is bad .', 'it is not gentle .', 'it happens .'): a
    short one about 'it', naming no vehicle, motion, time, collision or condition."""
    return said[:1] != [] and said[0] in FLAT_SUBJECTS and 2 <= len(said) <= 7 and said[-1] in SENTENCE_ENDS and \
        not mentions(said) and not asks_impact(said) and not (
            MOTION_DESCRIPTIONS | MOTION_WORDS | SPEED_CLASS_WORDS | SPEED_NOUNS | START_WORDS | COMES_IN_WORDS
            | FILM_WORDS | IMAGINED_SAID | CONDITION_OPENERS | {"slowly", "quickly", "gently", "fast", "slow", "quick",
                                                               "stopped", "stops", "ends", "would", "will"}) & set(said)


def _checked(question: list[str], said: list[str]) -> list[str] | None:
    """A statement, then asked whether it is right ('the yellow chopper is tearing along fast . am I right ?' -> 'the
    yellow chopper is tearing along fast ?'); None where it is not."""
    asked = [w for w in question if w not in ECHO_CLOSERS]
    if question[-1:] != ["?"] or asked not in CHECKING_TAGS or not mentions(said) or \
            said[0] in QUESTION_OPENERS | YES_NO_OPENERS or SENTENCE_ENDS & set(said[:-1]):
        return None
    return [*said[:-1], "?"] if said[-1] in SENTENCE_ENDS else [*said, "?"]


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


# A chat pasted with its speakers' labels ('User: hi. Assistant: what would you like to know? User: was the red car
# slow at the start?', 'Q1: the cyan bus. A1: yes? Q2: what does it hit?'): the last speaker's turns are the question
# and its context; the other speaker's are dropped
SPEAKERS = {"user", "assistant", "human", "ai", "bot", "me", "you", "customer", "agent", "student", "tutor", "viewer",
            "helper", "teacher", "child", "parent", "kid", "mum", "mom", "dad", "system", "chatbot", "model"}


def _speaker(word: str) -> str | None:
    """The speaker a label names: 'user', and 'q' for 'q1', 'q2' (and 'a' for 'a1'); None for any other word."""
    return word if word in SPEAKERS else word[0] if re.fullmatch(r"[qa]\d{0,2}", word) else None


def transcript_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The last speaker's turns of a chat with labels, the last one the question (`SPEAKERS`). With the words read
    so, or the words as they are and ()."""
    labels = [k for k in range(len(words) - 1) if words[k + 1] == ":" and _speaker(words[k]) and (
        k == 0 or words[k - 1] in (".", "?", "!", ",", ";"))]
    # (a prompt's empty answer is no turn: 'Q: ... ? A:')
    labels = [k for k, end in zip(labels, labels[1:] + [len(words)]) if any(w.isalnum() for w in words[k + 2:end])]
    if len(labels) < 2 or len({_speaker(words[k]) for k in labels}) < 2:
        return words, ()
    asker = _speaker(words[labels[-1]])
    turns = [words[k + 2:end] for k, end in zip(labels, labels[1:] + [len(words)]) if _speaker(words[k]) == asker]
    # the asker's earlier turns as sentences of context ('Q1: the cyan bus.', 'me: watching the double-decker now,')
    ended = [turn if turn[-1] in (".", "?", "!") else [*turn[:len(turn) - (turn[-1] == ",")], "."]
             for turn in turns[:-1]]
    out = [w for turn in ended for w in turn] + turns[-1]
    return out, ((" ".join(words[:labels[-1] + 2]), "nothing, the chat before the question"),)


# A tutor's check-in before the question ('You saw the red sedan at the very start, didn't you? How fast ...?',
# 'Did you notice the blue biplane at the beginning? Was it floating?', 'Remember when the bus hit the car? ...'):
# asked only to be agreed with, it is context, said as a statement
CHECK_OPENERS = sorted(((*you, seen) for you in (("did", "you"), ("you",), ("do", "you"), ("can", "you"), ())
                        for seen in ("see", "seen", "saw", "notice", "noticed", "spot", "spotted", "catch", "caught",
                                     "remember", "recall") if you or seen in ("remember", "recall", "notice")),
                       key=len, reverse=True)
CHECK_TAGS = ((",", "right"), (",", "did", "not", "you"), (",", "do", "not", "you"), (",", "yes"), (",", "remember"),
              (",", "ok"), (",", "okay"), (",", "yeah"), (",", "is", "not", "it"), (",", "does", "not", "it"),
              (",", "did", "not", "it"), (",", "was", "not", "it"), (",", "correct"))
TURN_WORDS = {"your", "now", "over", "you", "if", "had", "tell"}
TURN_LABELS = (("your", "turn"), ("now", "your", "turn"), ("over", "to", "you"), ("you", "try"))


def check_ins_stated(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """Each sentence before the question that only checks what was seen (`CHECK_OPENERS`, `CHECK_TAGS`) said as a
    statement of it; a label handing the question over ('Your turn -') dropped. With the words read so, or the words
    as they are and ()."""
    spans = _sentence_spans(words)
    if len(spans) < 2 or words[-1] != "?" or not _opening(words[spans[-1][0]:])[:1] or \
            _opening(words[spans[-1][0]:])[0] not in QUESTION_OPENERS | TIME_OPENERS | TURN_WORDS:
        return words, ()   # (the question itself, not a tag after a claim: '..., right? Or no?')
    out, read = [], []
    for n, (a, b) in enumerate(spans):
        sentence = words[a:b]
        if n < len(spans) - 1 and sentence[-1] == "?" and (mentions(sentence) or asks_impact(sentence)):
            opened = next((o for o in CHECK_OPENERS if tuple(sentence[:len(o)]) == o), ())
            opened += ("when",) * (opened[-1:] in (("remember",), ("recall",)) and sentence[len(opened):][:1] ==
                                   ["when"])
            tag = next((t for t in CHECK_TAGS if tuple(sentence[-1 - len(t):-1]) == t), ())
            if opened or tag:
                stated = sentence[len(opened) - (opened[-1:] == ("when",)):len(sentence) - 1 - len(tag)] + ["."]
                read.append((" ".join(sentence), " ".join(stated)))
                sentence = stated
        label = next((t for t in TURN_LABELS if tuple(sentence[:len(t)]) == t and sentence[len(t):len(t) + 1]
                      and sentence[len(t)] in (":", "-", ",")), None)
        if label:
            read.append((" ".join(sentence[:len(label) + 1]), "nothing, a label"))
            sentence = sentence[len(label) + 1:]
        out += sentence
    return (out, tuple(read)) if read else (words, ())


# A vehicle to find, then its property asked of 'it' ('Find the vehicle that the biplane hits. What colour is it?'):
# 'it' is the vehicle found, not the one its clause names
FINDING = (("find",), ("identify",), ("locate",), ("spot",), ("consider",), ("take",), ("look", "at"), ("focus", "on"),
           ("pick", "out"), ("note",))
PRONOUNS_ASKED = {"it", "that", "this"}


def found_then_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'find the vehicle that the biplane hits . what colour is it ?' -> 'what colour is the vehicle that the biplane
    hits ?'. With the words read so, or the words as they are and ()."""
    found = next((f for f in FINDING if tuple(words[:len(f)]) == f), None)
    k = len(found) if found else 0
    if not found or words[k:k + 1] != ["the"] or words[k + 1:k + 2] == [] or words[k + 1] not in GENERIC_NOUNS or \
            words[k + 2:k + 3] not in (["that"], ["which"]) or "." not in words:
        return words, ()
    stop = words.index(".")
    asked = words[stop + 1:]
    be = next((j for j, w in enumerate(asked) if w in ("is", "was")), None)
    if be is None or asked[:1] not in (["what"], ["which"]) or asked[be + 1:] not in ([p, "?"] for p in PRONOUNS_ASKED):
        return words, ()
    out = [*asked[:be + 1], *words[k:stop], "?"]
    return out, ((" ".join(words), " ".join(out)),)


# A note's fragments ('The bus. Right at the start. Static, slow or fast?', 'Red scooter, blue cruiser. Any bump
# between them in the clip?'): vehicles said alone, then perhaps their time, then what is asked, none a sentence
FRAGMENT_TIMES = {"right", "just", "upon", "on", "in", "at", "as", "when", "once", "while", "during", "first", "the",
                  "from", "after", "before"}
NOT_FRAGMENT = {"is", "was", "are", "were", "does", "did", "do", "has", "have", "had", "will", "would", "can", "could",
                "i", "you", "we", "it", "they", "there", "'"}


def _named_only(fragment: list[str]) -> bool:
    """Whether a fragment only names vehicles ('the bus', 'red scooter , blue cruiser'), a time after a comma
    allowed ('the car , at the moment it collides with the bicycle')."""
    named = mentions(fragment)
    if not named or named[0][0] > (fragment[0] in ("the", "this", "that", "a", "an", "one")):
        return False
    k = 0
    for first, last, _ in named:
        if set(fragment[k:first]) - {",", "and", "the", "a", "an", "this", "that"}:
            return False
        last += fragment[last:last + 1] != [] and fragment[last] in GENERIC   # 'grey vehicle'
        if last == len(fragment) or fragment[last] == "," and fragment[last + 1:last + 2] != [] and \
                fragment[last + 1] in FRAGMENT_TIMES:
            return True
        k = last
    return False


def fragments_joined(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the bus . right at the start . static , slow or fast ?' -> 'the bus , right at the start , static , slow or
    fast ?': fragments before the question, the first naming its vehicles, joined into one as a comma joins them.
    With the words read so, or the words as they are and ()."""
    ends = [k for k, w in enumerate(words) if w in (".", ";", "?")]
    if len(ends) < 2 or words[ends[0]] == "?" or not _named_only(words[:ends[0]]):
        return words, ()
    start = 0
    for end in ends:
        fragment = words[start:end]
        if not fragment or NOT_FRAGMENT & set(fragment[:2]) or start and words[end] != "?" and \
                fragment[0] not in FRAGMENT_TIMES:
            return words, ()
        if words[end] == "?":   # (one that names its own vehicle is read with the fragments as its context)
            if fragment[0] in QUESTION_OPENERS or mentions(fragment):
                return words, ()
            joined = [w if k >= end or k not in ends else "," for k, w in enumerate(words)]
            return joined, ((" ".join(words[:end + 1]), " ".join(joined[:end + 1])),)
        start = end + 1
    return words, ()


# A mathematician's name for a vehicle ('Let V be the vehicle floating in the air there. Determine what kind of
# vehicle V is.'): one letter, never an article or the speaker
NAMING_VERBS = (["be"], ["denote"], ["stand", "for"], ["represent"])


def variables_named(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'let v be the vehicle floating in the air there . determine what kind of vehicle v is .' -> 'determine what
    kind of vehicle the vehicle floating in the air there is .': the letter read as what it names, wherever the
    question says it. With the words read so, or the words as they are and ()."""
    k = next((k for k in range(len(words) - 3) if words[k] == "let" and len(words[k + 1]) == 1
              and words[k + 1].isalpha() and words[k + 1] not in ("a", "i", "o")), None)
    verb = next((v for v in NAMING_VERBS if k is not None and words[k + 2:k + 2 + len(v)] == v), None)
    if verb is None:
        return words, ()
    start = k + 2 + len(verb)
    end = next((j for j in range(start, len(words)) if words[j] in (".", ";", "?", "!")), None)
    name = words[start:end] if end else []
    letter, asked = words[k + 1], words[end + 1:] if end else []
    if not name or letter not in asked or not (mentions(name) or GENERIC & set(name)):
        return words, ()
    before = words[:k]
    while before[-1:] in ([","], ["and"]):
        before = before[:-1]
    out = [*before, *(["."] if before else []), *(w for a in asked for w in (name if a == letter else [a]))]
    return out, ((" ".join(words[k:end + 1]), "nothing, a name"), (letter, " ".join(name)))


# A collision given as a premise and then asked about ('Given that the cyan scooter collides with the bus, find its
# speed at the moment of impact'): the question presupposes it, as a question of the collision always does
GIVEN = (["given", "that"], ["knowing", "that"], ["granted", "that"])
IMPACT_REFERENCES = {"vehicle", "object", "one", "instant", "moment", "point", "time", "partner"}


def impact_given_as_context(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'given that the red bike collides with a certain vehicle , find the kind of that vehicle .' -> 'the red bike
    collides with a certain vehicle . find ...': the premise as the context the question's 'that vehicle' or 'at
    impact' refers to. Not a premise of motion ('given that the bus is parked'), nor one imagined. With the words
    read so, or the words as they are and ()."""
    given = next((g for g in GIVEN if words[:len(g)] == g), None)
    end = next((k for k, w in enumerate(words) if w in (",", ";", ":", ".")), None)
    if not given or end is None:
        return words, ()
    premise, asked = words[len(given):end], words[end + 1:]
    refers = asks_impact(asked) or any(a == "that" and b in IMPACT_REFERENCES for a, b in zip(asked, asked[1:]))
    if not asks_impact(premise) or not mentions(premise) or \
            {"had", "were", "would", "if"} & set(premise) or not refers:
        return words, ()
    return premise + ["."] + asked, ((" ".join(words[:len(given)]), "nothing, a premise the question presupposes"),)


# 'someone' said of a vehicle whose kind or colour is then asked ('Someone's picking up speed off the line! What
# colour is that one?'): a commentator's vehicle, not a person
SOMEONE = {"someone", "somebody"}


def someone_as_something(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'someone 's up in the air ! what kind of vehicle is it ?' -> 'something 's up in the air ! ...'. With the
    words read so, or the words as they are and ()."""
    # (or a comma before the question: 'Someone's zooming off the line fast, what type is that fast thing?')
    end = max((k for k, w in enumerate(words[:-1]) if w in (".", "!", ";", "-", ":")
               or w == "," and words[k + 1] in ("what", "which")), default=None)
    said = [k for k, w in enumerate(words[:end or 0]) if w in SOMEONE]
    asked = words[end + 1:] if end is not None else []
    asked = asked[2 + (asked[2:3] == [","]):] if asked[:2] == ["tell", "me"] else asked   # ('... - tell me, what ...')
    if not said or asked[:1] not in (["what"], ["which"]) or not {"it", "that", "one"} & set(asked) or not (
            {"vehicle", "color", "colour", *SHAPE_ASKED} & set(asked)):
        return words, ()
    return ["something" if k in said else w for k, w in enumerate(words)], tuple((words[k], "something") for k in said)


def _turned_to(sentence: list[str], runs: list) -> list:
    """A sentence's mentions, those after its last 'but' first: the vehicle it turns to ('I was watching the red bus,
    but then this grey jet pops in.' -- 'How fast is it ...?' asks about the jet)."""
    turn = max((k for k, w in enumerate(sentence) if w == "but"), default=None)
    return runs if turn is None else [r for r in runs if r[0] > turn] + [r for r in runs if r[0] <= turn]


# A statement joined to the question by ', but' or ', so' (a narrator's 'The brown aeroplane bumps into the gray
# vehicle in a scene nobody will forget, but is the aeroplane going fast at that moment?'): its context
JOINING = ("but", "so")
NOT_STATED = {"if", "had", "suppose", "imagine", "when", "as", "after", "before", "once", "while", "whenever"}


def joined_as_context(words: list[str]) -> list[str]:
    """'X hits Y , but is X fast ?' -> 'X hits Y . is X fast ?', where what comes before is one statement without a
    comma and what comes after a whole question; the words as they are elsewhere ('Is the car fast, but is the bus
    slow?' asks twice; '..., but was it really?' asks whether the statement is so)."""
    k = next((k for k in range(3, len(words) - 3) if words[k] == "," and words[k + 1] in JOINING
              and words[k + 2] in QUESTION_OPENERS | YES_NO_OPENERS), None)
    if k is None or words[-1] != "?" or SENTENCE_ENDS & set(words[:k]) or "," in words[:k] or len(words) - k < 8 or \
            words[0] in QUESTION_OPENERS | YES_NO_OPENERS | CONDITION_OPENERS | TIME_OPENERS | NOT_STATED:
        return words
    return [*words[:k], ".", *words[k + 2:]]


def context_as_question(words: list[str], known=None) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question after its context, what it refers back to read from the context; with the context read as
    what it gave. The words as they are and () where there is no context; where the question needs more than the
    vehicles, a condition, a moment or the start (a vehicle the context describes: 'Something is speeding up. What
    colour is it?'; a vehicle said with a word the parser does not know, of `known`: 'the pink scooter'); or where
    the context asks a question of its own, or imagines otherwise than as a condition."""
    words = joined_as_context(words)
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
    # a narrator's flat remark on a collision just told ('The bikes crash. It is bad. When they do, ...'): nothing
    context = [s for j, s in enumerate(context) if not (j and asks_impact(context[j - 1]) and _flat_remark(s))]
    question = words[spans[asked_at][0]:spans[asked_at][1]]
    # ('Imagine this. The bike moves fast. Would ...?', 'Picture this. ...')
    conditions = [_condition_said(s, bool(j and ((IMAGINED_SAID | {"if"}) & set(context[j - 1])
                                                 or context[j - 1][0] in IMAGINING)
                                          and not mentions(context[j - 1]))) for j, s in enumerate(context)]
    # 'In that world, does it ...?': where no sentence imagines, the sentence before is what is imagined
    back = _at(question[:4], IMAGINED_BACK)
    back = back and back[0] == 0 and not any(conditions) and back[1]
    if back:
        question = question[len(back) + (question[len(back):len(back) + 1] == [","]):]
        conditions[-1] = _condition_said(context[-1], True)
    if any(c is None and not _stated(s) and not _imagining_only(s) and (
            s[-1] == "?" or mentions(s) and (IMAGINED_SAID & set(s) or _instructs(s)
                                             or _opening(s)[:1] == ["let"] and "be" in s
                                             or "if" in s and s[s.index("if") - 1] not in WHETHER))
           for s, c in zip(context, conditions)) or back and not conditions[-1]:
        return words, ()
    tail = words[spans[asked_at][1]:]
    question = _echoed(question, context[-1]) or _judged(question, context[-1]) or _checked(question, context[-1]) \
        or _wondered(question, context[-1]) or question
    condition = next((c for c in reversed(conditions) if c), None)
    own_condition = bool({"if", "suppose", "imagine", "had", "were"} & set(question))
    # a vehicle said 'he' or 'she', as learners and fond speakers do ('Does he crash with any other thing?')
    question = ["it" if w in ("he", "she") else "its" if w == "his" else w for w in question]
    asked = (condition if condition and not own_condition else []) + question
    # a sentence that says the video stopped ('video stops partway through . does the sedan hit ...?'): the question
    # asks after its end
    stopped = next((c for c in context if (e := _video_end(c)) and (e[0] == 0 or c[e[0] - 1] == ":")), None)
    # its 'it' the video the context names ('After it stops, will ...?', 'If it kept going, would ...?')
    ended = _video_end(asked, stopped or []) or (_video_continued(asked, stopped) if stopped else None)
    if stopped and asks_impact(question) and ended and not _video_end(asked):
        asked = [*asked[:ended[0]], "after", "the", "video", "ends", *asked[ended[1]:]]
    elif stopped and asks_impact(question) and not (_video_end(question) or _at_cut(question)):
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
              for _, _, r in _turned_to(s, runs) if r in fullest] + \
        [r for runs in reversed(said) for _, _, r in runs if r in fullest]
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
    # (not a vehicle's 'its' bound to the vehicle the question asks for: 'which vehicle has its engine on')
    pronoun = pronoun if pronoun is not None and not any(start < pronoun for start, _, _ in named) and not (
        out[pronoun] == "its" and {"which", "what"} & set(out[:pronoun]) and GENERIC_NOUNS & set(out[:pronoun])) \
        else None
    plural = _at(out, PLURAL_PRONOUNS)
    plural = plural if plural and len({r for _, _, r in named}) < 2 else None
    # 'what colour is that?', 'that vehicle', 'is that suspect?'
    pointed = any(a in ("that", "this") and (b in GENERIC | {"?"} or out[k - 1:k] in (["is"], ["was"])
                                            and out[k + 2:k + 3] == ["?"] and b not in OBJECT_WORDS)
                  for k, (a, b) in enumerate(zip(out, out[1:])))
    # 'what colour is it?', 'what is its colour?'
    asked_of = pronoun is not None and (out[pronoun + 1] in SENTENCE_ENDS | {","} or out[pronoun] == "its" and
                                        out[pronoun + 2:pronoun + 3] and out[pronoun + 2] in SENTENCE_ENDS | {","})
    if pointed or (asked_of or plural) and any(map(_unnamed, context)) or (pronoun is not None or plural) and strange:
        return words, ()
    if pronoun is not None:
        # said before the question's own mentions, it may be one of them ('Had it been floating ..., would the jet
        # and the bike ...?')
        meant = next((r for r in latest if not _named(r, named)), latest[0] if latest else None)
        # (where the context names no vehicle, 'it' in a clause said first is the one the question names after it:
        # 'Where the heart goes, the meeting follows. At the moment it hits the brown scooter, which way is the cyan
        # cruiser heading?')
        if meant is None and not (not every and out[:1] and out[0] in TIME_OPENERS and "," in out[pronoun:]
                                  and named):
            return words, ()
        if meant is not None:
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
    # 'Compare the wagon with the pickup. Is the wagon the slower?': the comparison is with the context's other one
    compared = next((k for k in range(len(out) - 2) if out[k] == "the" and out[k + 1] in ("faster", "slower")
                     and out[k + 2] in ("?", "one", "vehicle", "of")), None)
    others = [r for r in fullest if not _named(r, named)]
    if compared is not None and len({r for _, _, r in named}) == 1 and len(fullest) == 2 and len(others) == 1:
        end = compared + 2 + (out[compared + 2] in ("one", "vehicle")) + \
            3 * (out[compared + 2:compared + 5] == ["of", "the", "two"])
        said = [out[compared + 1], "than", *_said(others[0])]
        read.append((" ".join(out[compared:end]), " ".join(said)))
        out[compared:end] = said
        used.add(others[0])
        named, plural = mentions(out), plural and _at(out, PLURAL_PRONOUNS)
    if plural:   # the context's two, none named in the question, in the order it names them ('Here is the bus.
        # Here is the car. Do they crash?')
        others = [r for r in (fullest if not named and len(fullest) == 2 else latest) if not _named(r, named)]
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
        # (the start said as 'at first' or 'the first moments': 'The yellow SUV appears as the vision opens. Is it
        # static, slow or fast at first?')
        own_time = bool(timed & set(out)) or any(a == "at" and b == "first" or a == "first" and b in FIRST_SPANS
                                                 for a, b in zip(out, out[1:]))
        then = _at(out, THEN_SAID)
        # ... or the question's own vehicle's impact said with no partner ('... travelling when it struck ?')
        impact = _at(out, IMPACT_MOMENTS) or next(((k, tuple(out[k:k + 3])) for k in range(len(out) - 3)
                                                    if out[k] in ("when", "as") and out[k + 1] in ("it", "they")
                                                    and out[k + 2].startswith(IMPACT_STEMS)
                                                    and out[k + 3] in ("?", ",", ":", "-")), None)
        own = {next((f for f in fullest if _fits(r, f)), r) for _, _, r in mentions(out)}
        # a collision of the question's vehicles (one or both) told just before, the question saying no time of its
        # own ('The yellow car came crashing into the motorbike, and then ... which direction was the yellow car
        # heading?', 'the bike and the wagon crash together ; is the bike going faster than the wagon ?')
        # (not a narrator's 'we meet a green wagon', nor a question of 'those first moments')
        told = {tuple(_moment(context[-1:], fullest, of=r) or ()) for r in own}
        told = not then and not impact and not (own_time or asks_impact(out)) and len(told) == 1 \
            and not {"first", "we", "i", "us"} & set(out + context[-1]) and list(told.pop())
        # a sentence that is a moment alone ('Think about the moment the bike hits the van.', read 'at the moment
        # the bike hits the van .'; 'Remember when the bus bumped into the car?'): the question's time, where it
        # says none
        pictured = not then and not impact and not (own_time or asks_impact(out)) and \
            (_opening(context[-1])[:1] in (["at"], ["when"], ["remember"]) or _opening(context[-1])[:2] in (
                ["the", "moment"], ["the", "instant"])) and asks_impact(context[-1])
        if then and not (own_time or asks_impact(out[:then[0]] + out[then[0] + len(then[1]):])):
            moment, (k, p) = _moment(context, fullest), then
        elif pictured:
            moment, k, p = _moment(context[-1:], fullest), out.index("?") if "?" in out else len(out), ()
        elif told:
            moment, k, p = told, out.index("?") if "?" in out else len(out), ()
        elif impact and len(own) == 1:
            moment, (k, p) = _moment(context, fullest, of=next(iter(own))), impact
        elif not then and not impact and not (own_time or asks_impact(out)) and len(own) == 1 and \
                COMES_IN_WORDS & set(context[-1]) and not asks_impact(context[-1]):
            # a vehicle looked at as it comes into view ('Look at the green vehicle when it first shows up. Is it
            # still, slow, or fast?': it was read at the start)
            moment, k, p = _moment(context[-1:], fullest), out.index("?") if "?" in out else len(out), ()
        else:
            moment, k, p = [], 0, ()
            started = next((s for s in reversed(context) if (START_WORDS | {"initial"}) & set(s)), None)
            # ... and the end, which no question asks: the whole text is read, and refused ('the red car zai zuihou
            # is it static ma?', 'zuihou' said 'at the end')
            if not started and not (own_time or asks_impact(out)) and any(
                    s[k:k + len(e)] == e for s in context for k in range(len(s)) for e in END_TIMES):
                return words, ()
            if started and not (own_time or asks_impact(out)):
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
ASKED_PROPERTY = {**dict.fromkeys(SHAPE_ASKED, "shape"), "colour": "color", "color": "color"}


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
    """A mention's values with what the words after the question say of it instead (a kind that only says the
    mention's again, more broadly, is none: '... the gray mountain bike ...? bike drama fr' is no bicycle)."""
    colour = [v for v in meant if v in COLOR_NAMES] or [v for v in ref if v in COLOR_NAMES]
    kind = [v for v in meant if v not in COLOR_NAMES and not generalises((v,), ref)] or \
        [v for v in ref if v not in COLOR_NAMES]
    return tuple(colour + kind)


def _compatible(ref: tuple, meant: tuple) -> bool:
    """Whether the vehicle a mention names can be the one said after the question (its category, or its colour
    where the mention has none)."""
    kinds = [CATEGORY_OF[v] for v in meant if v not in COLOR_NAMES]
    own = [CATEGORY_OF[v] for v in ref if v not in COLOR_NAMES]
    if kinds:
        return not own or own == kinds
    return not any(v in COLOR_NAMES for v in ref)


# a speed said again after the question, in its own words ('..., right? like not moving at all?')
SPEEDS_SAID = {"static": {"still", "stationary", "parked", "static", "stopped", "standing", "sitting", "motionless"},
               "fast": {"fast", "quick", "quickly", "speeding", "racing", "zooming"},
               "slow": {"slow", "slowly", "crawling", "creeping"}}
ELABORATING = {w for said in SPEEDS_SAID.values() for w in said} | {
    "not", "moving", "at", "all", "really", "totally", "completely", "just", "there", "very", "super", "going",
    "pretty"}


def _speeds_said(words: list[str]) -> set[str]:
    said = {speed for speed, ws in SPEEDS_SAID.items() if ws & set(words)}
    return said | {"static"} if any(words[k:k + 2] == ["not", "moving"] for k in range(len(words))) else said


def _elaborates(core: list[str], question: list[str]) -> bool:
    """Whether what is asked after the question only says again the speed it asks ('like not moving at all?' after
    'the green one is just sitting there when it starts, right?')."""
    core = [w for w in core if w not in AFTER_OPENERS]
    said = _speeds_said(core)
    return bool(core) and set(core) <= ELABORATING and bool(said) and said <= _speeds_said(question)


# a remark after the question, about the viewer or the scene ('I lost track.', 'There's a lot going on.', 'It was
# pretty low to the ground.'): read as nothing where it says nothing of what is asked or meant
REMARK_OPENERS = {"i", "we", "there", "it", "that", "this", "they", "my", "our", "honestly", "lol", "haha", "been"}
RESTATING = {"mean", "meant", "asking", "ask", "asked", "question", "talking", "referring", "want", "wanted", "need",
             "wonder", "wondering", "curious", "care", "d", "would", "wanna", "instead", "rather"}


def _remark(said: list[str]) -> bool:
    """Whether a sentence said after the question is a remark on it: a statement of the viewer's or of the scene,
    naming no one vehicle (a correction names one: 'It's the blue one, not the red.')."""
    words = [w for w in said if w not in (".", "!")]
    corrected = any(w == "not" and nxt in {"the", "a", "an", "that", "this", *COLOR_NAMES}
                    for w, nxt in zip(words, words[1:]))   # '..., not the red'
    # (or on people at large, whom no video shows: '? Back in my day bus drivers knew better.', '? Two people on one
    # bike, I ask you.')
    people = PEOPLE & set(words) and not set(COLOR_NAMES) & set(words)
    # (or praise of a vehicle named last: '? Real smooth ride, that bike.')
    praised = len(words) > 3 and words[-3] == "," and words[-2] in ("that", "this") and \
        not mentions(words[:-3]) and not set(COLOR_NAMES) & set(words) and words[0] not in AFTER_OPENERS
    # (or on the speaker or the listener, asking nothing: a cat's '? Hardly worth my notice, but tell me anyway.')
    personal = SPEAKER_AND_LISTENER & set(words) and not mentions(words) and not (
        RESTATING | ASKED_PROPERTY.keys() | START_WORDS | END_WORDS | MOTION_WORDS | SPEED_CLASS_WORDS
        | CONDITION_OPENERS) & set(words)
    # (or a likeness to the speaker's things: a gardener's '? Faster than my runner beans climb, I expect.', '? Yellow
    # like my courgette flowers, bless it.')
    likened = (words[1:2] in (["than"], ["like"], ["as"]) or words[:3] == ["same", "way", "as"]) and \
        SPEAKER_AND_LISTENER & set(words) and not (OBJECT_WORDS - set(COLOR_NAMES) | GENERIC_NOUNS) & set(words)
    return bool(words) and said[-1] != "?" and not corrected and (
        people or praised or personal or likened
        or words[0] in REMARK_OPENERS and not RESTATING & set(words) and not _one_vehicle(words))


def afterthoughts_read(words: list[str], known=None) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question with what is said after it read into it, and what was said after it read as nothing; the words
    as they are and () where nothing is said after it, it asks again, or what it says cannot be read so (a vehicle
    said with a word the parser does not know, of `known`: 'The white sedan, I mean.'). A last question that only
    says its speed again ('? like not moving at all ?') is read as nothing."""
    spans, again = _sentence_spans(words), ()
    if len(spans) > 1 and words[spans[-2][1] - 1] == words[-1] == "?" and \
            _elaborates(words[spans[-1][0]:-1], words[spans[-2][0]:spans[-2][1]]):
        again = ((" ".join(words[spans[-1][0]:]), "nothing, the question said again"),)
        words, spans = words[:spans[-1][0]], spans[:-1]
    asked_at = max((j for j, (a, b) in enumerate(spans) if words[b - 1] == "?"), default=None)
    if asked_at is None or asked_at == len(spans) - 1:
        return words, again
    start, end = spans[asked_at]
    out, read = words[:end], list(again)
    for a, b in spans[asked_at + 1:]:
        said = words[a:b]
        if said[-1] == "?":
            return words, again
        if _remark(said):
            read.append((" ".join(said), "nothing, a remark"))
            continue
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
            return words, again
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
                return words, again
        elif ASKED_PROPERTY.keys() & set(core):
            asked = ASKED_PROPERTY[next(w for w in core if w in ASKED_PROPERTY)]
            if question[:2] in (["which", "vehicle"], ["which", "one"]):   # 'which vehicle is ...? the type'
                question[:2] = ["what", "type", "of", "vehicle"] if asked == "shape" else \
                    ["what", "color", "is", "the", "vehicle", "that"]
        elif START_WORDS & set(core):
            if not (START_WORDS | COMES_IN_WORDS | OWN_TIMES) & set(question) and not asks_impact(question):
                question[-1:] = ["at", "the", "start", "?"]
        elif set(core) & (FILM_WORDS | HEADING_KEPT | MOTION_WORDS | MOTION_DESCRIPTIONS | QUERY_NOUNS):
            return words, again
        out = out[:start] + question
        read.append((" ".join(said), " ".join(question)))
    return out, tuple(read)


SET_VERBS = {"set", "sets", "setting", "initialise", "initialised", "initialize", "initialized", "reset", "change",
             "changed", "changing"}
START_TAILS = [[p, "the", *s] for p in ("from", "at") for s in (["start"], ["beginning"], ["first", "frame"])]
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
        end += next((len(t) for t in START_TAILS if words[end:end + len(t)] == t), 0)
        k -= bool(k) and words[k - 1] in ("we", "you", "i", "they")   # 'if we set ...'
        # a setting said as a sentence of its own ('Set the scooter's initial speed to fast. Does it then hit ...?')
        # is a condition, not a statement of what the video shows
        said = ["suppose", *said] if (k == 0 or words[k - 1] in (".", ":", ";", "!")) and \
            words[end:end + 1] in ([","], ["."], [";"], [":"]) else said
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
                                                 "scene", "footage")),
           # a speculator's ('Let's dream up a version where ...', 'cook up a world in which ...')
           *((*lets, *verb, "a", t) for lets in ((), ("let", "'", "s"), ("let", "us"))
             for verb in (("dream", "up"), ("cook", "up"), ("conjure", "up"), ("think", "up"), ("make", "up"),
                          ("invent",), ("imagine",), ("picture",))
             for t in ("version", "world", "scenario", "timeline", "universe", "reality"))}
WHICH = (("in", "which"), ("where",), ("so", "that"), ("such", "that"))


def told_otherwise_as_imagined(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'in another telling , the bus is parked from the start . would ...' -> 'imagine the bus is parked ...';
    'under an alternative ruling where ...' -> 'in a world where ...'; 'spin a tale in which ...' -> 'imagine ...'.
    With the words read so, or the words as they are and ()."""
    j = next((len(t) for t in TELLING if tuple(words[:len(t)]) == t), 0)
    # ('imagine a different version of this clip where ...')
    if not j and words[:1] in (["imagine"], ["picture"]) and words[1:2] in (["a"], ["an"]) and \
            words[2:3] and words[2] in OTHERWISE and words[3:4] and words[3] in TOLD:
        j = 4 + next((len(o) for o in TOLD_OF if tuple(words[4:4 + len(o)]) == o), 0)
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


# A story told again otherwise, as a condition ('You rewrite the scene so the bike is speeding up from the start.',
# 'You replay it in your head with the car launching fast', 'Alternate timeline where ...', 'DIRECTOR: Rewrite, ...')
RETELLING = {"rewrite", "rewrites", "rewrote", "reimagine", "reimagines", "reimagined", "replay", "replays",
             "replayed", "rerun", "reruns", "reran"}
RETOLD = {"scene", "video", "clip", "shot", "take", "story", "footage", "film", "it", "things", "events", "timeline"}
RETOLD_LINKS = (["so", "that"], ["such", "that"], ["so"], ["where"], ["with"], ["in", "which"], [":"], [","])
# An instruction that changes a vehicle from the start, then a collision asked ('Pin the gray mountain bike in place
# from the start, standing still. Would it collide with the green airliner then?', 'Give the dirtbike a running engine
# from the very start. Does it then collide ...?'): the grammar's condition, of the one state it says
CHANGING = {"pin", "give", "make", "have", "let", "set", "keep", "hold", "put", "fix", "freeze", "park", "send",
            "start", "launch", "leave", "change", "switch", "turn", "grant", "allow", "restate", "rerun", "replay",
            "swap", "switched"}   # a data scientist's 'swap in a fast initial speed for the biplane:'
# ... of them, those that say an instruction wherever they open a sentence (never a noun: 'Start of the clip.'): a
# context sentence of one is a change, never read as what the video shows
INSTRUCTING = {"pin", "set", "fix", "freeze", "change", "switch", "grant", "swap", "switched", "force"}
HELD = (("accelerating", ({"accelerating", "accelerate", "engine"}, (("speeding", "up"), ("picking", "up", "speed")))),
        ("static", ({"static", "stationary", "still", "motionless", "parked", "immobile", "unmoving", "standstill"},
                    (("in", "place"), ("at", "rest")))),
        ("floating", ({"floating", "hovering", "airborne", "aloft", "afloat"}, (("in", "the", "air"),))),
        ("fast", ({"fast", "quickly", "rapidly", "speeding"}, ())),
        ("slow", ({"slow", "slowly", "crawling", "creeping"}, ())))


def _held_state(sentence: list[str]) -> str | None:
    """The one state a sentence holds a vehicle in ('speeding up' and 'engine' are accelerating, 'fast' of speeding
    up is no second), or None."""
    said = {state for state, (words, phrases) in HELD if words & set(sentence)
            or any(sentence[k:k + len(p)] == list(p) for k in range(len(sentence)) for p in phrases)}
    said -= {"fast"} if "accelerating" in said and "fast" not in sentence else set()
    return said.pop() if len(said) == 1 else None


def change_as_imagined(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'pin the gray mountain bike in place from the start , standing still . would ...' -> 'suppose the gray
    mountain bike had been static from the start . would ...': a first sentence that tells a change at the start to
    a vehicle it names ('Grant the gray plane a slow start instead; would ...?'), before a question about a
    collision. With the words read so, or the words as they are and ()."""
    label = _labelled(words)
    end = next((k for k, w in enumerate(words) if k > label and w in (".", ";", ":", "!")), None)
    if end is None or words[label] not in CHANGING or words[label + 1:label + 2] == ["of"] or \
            not asks_impact(words[end + 1:]):   # ('Start of the clip, the bus is parked.' tells no change)
        return words, ()
    sentence = words[label:end]
    named = mentions(sentence)
    start = bool((START_WORDS | {"first", "initial", "initially"}) & set(sentence))   # 'from the start', 'a slow start'
    state = _held_state(sentence)
    if not named or not start or state is None or asks_impact(sentence):
        return words, ()
    first, last, _ = named[0]
    condition = ["suppose", "the", *sentence[first:last], "had", "been", state, "from", "the", "start", "."]
    return condition + words[end + 1:], ((" ".join(words[:end + 1]), " ".join(condition)),)


def _instructs(sentence: list[str]) -> str | None:
    """The verb a sentence opens on (after its label) that tells a change to a vehicle ('swap in a fast speed for the
    biplane', 'freeze the gray cruiser'; 'set' whatever follows: 'Set v0(yellow scooter) := fast.'), or None."""
    said = _opening(sentence[_labelled(sentence):])
    told = [w for w in said[1:4] if w not in ("the", "a", "an", "in", "up")][:1]
    return said[0] if said[:1] and said[0] in INSTRUCTING and (said[0] == "set" or told and (
        told[0] in NAMING | set(COLOR_NAMES) or told[0] in SET_VALUES)) else None   # not 'freeze the film'


def _labelled(sentence: list[str]) -> int:
    """Where a sentence says something after its condition's label ('ablation : freeze the cruiser ...' -> 2), or 0."""
    colon = sentence.index(":") if ":" in sentence[:4] else None
    return colon + 1 if colon and CONDITION_LABELS & set(sentence[:colon]) else 0


def inverted_condition_as_if(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'should the cyan scooter have been fast as the clip begins , would it have ...', 'should the cyan one have
    started out slow , ...' -> 'if the cyan scooter had been fast ...': a condition said by inverting 'should' (not
    'should the truck have stopped ?', which asks what ought to have been). With the words read so, or the words as
    they are and ()."""
    have = next((k for k in range(2, min(len(words) - 1, 8)) if words[k] == "have" and (
        words[k + 1].endswith("ed") or words[k + 1] in PARTICIPLES.values())), None)
    if words[:1] != ["should"] or have is None or not mentions(words[1:have]) or not any(
            a == "," and b in ("would", "will", "does", "did", "is", "was") for a, b in zip(words, words[1:])):
        return words, ()
    return ["if", *words[1:have], "had", *words[have + 1:]], ((" ".join(words[:have + 1]),
                                                               " ".join(["if", *words[1:have], "had"])),)


TELLERS = {"you", "we", "i", "they", "now", "so", "then", "ok", "okay"}


def retold_as_imagined(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'you rewrite the scene so the bike is speeding up ...' -> 'suppose the bike is speeding up ...'; 'you picture
    the minivan starting slow' -> 'picture the minivan starting slow' (which reads as imagined). With the words read
    so, or the words as they are and ()."""
    for k in range(len(words)):
        if k and words[k - 1] not in (".", ":", ";", "!", "?"):
            continue
        j = k
        while words[j:j + 1] and words[j] in TELLERS:
            j += 1
        if words[j:j + 1] and words[j] in ("picture", "imagine", "suppose", "envision", "pictured", "imagined") \
                and j > k:
            return words[:k] + words[j:], ((" ".join(words[k:j + 1]), words[j]),)
        alternate = words[j:j + 2] in (["alternate", w] for w in ("take", "timeline", "version", "world", "universe",
                                                                   "ending", "cut"))
        if words[j:j + 1] and words[j] in RETELLING or alternate:
            m = j + (2 if alternate else 1)
            m += words[m:m + 1] in (["the"], ["this"]) and words[m + 1:m + 2] != [] and words[m + 1] in RETOLD
            m += words[m:m + 1] != [] and words[m] in RETOLD and not alternate
            m += 3 * (words[m:m + 3] in (["in", "your", "head"], ["in", "my", "head"], ["in", "our", "heads"]))
            link = next((p for p in RETOLD_LINKS if words[m:m + len(p)] == p), None)
            if link and words[m + len(link):m + len(link) + 1] not in ([], ["?"]):
                n = m + len(link)
                return words[:k] + ["suppose", *words[n:]], ((" ".join(words[k:n]), "suppose"),)
    return words, ()


# A change said as what might have been, then supposed ('The car might have started fast. Say it had. Would it ...?',
# 'The fighter might have floated from the start. If it had, would it ...?'): the grammar's 'suppose ... had'
MIGHT_HAVE = {"might", "could", "may"}
SUPPOSED_SO = [[s, "it", v] for s in ("say", "suppose", "imagine", "assume") for v in ("had", "was", "did")]


def possibility_as_supposed(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the car might have started fast . say it had . would it have hit the bus ?' -> 'suppose the car had started
    fast . would it have hit the bus ?': a first sentence of a vehicle that might have done otherwise, where the
    question after it asks what would have been; the sentence that supposes it so ('say it had .', a question's 'if
    it had ,') read as nothing. With the words read so, or the words as they are and ()."""
    spans = _sentence_spans(words)
    if len(spans) < 2 or "would" not in words[spans[-1][0]:] or words[-1:] != ["?"]:
        return words, ()
    a, b = spans[0]
    k = next((k for k in range(a + 1, min(b - 2, a + 7)) if words[k] in MIGHT_HAVE and words[k + 1] == "have"), None)
    # (a change of its motion, the question asking what it would have hit: not 'The car could have hit the bus.
    # Would it have been going fast?')
    if k is None or not mentions(words[a:k]) or set(words[a:k]) & (SENTENCE_ENDS | {",", "not"}) or \
            "not" in words[k + 2:b] or asks_impact(words[k + 2:b]) or not asks_impact(words[spans[-1][0]:]):
        return words, ()
    said = ["suppose", *words[a:k], "had", *words[k + 2:b]]
    read = [(" ".join(words[a:b]), " ".join(said))]
    # ('Say it had.', 'Suppose it was.', and a question's 'If it had, would it ...?')
    supposed = {j for c, d in spans[1:-1] if words[c:d - 1] in SUPPOSED_SO for j in range(c, d)} | \
        (set(range(spans[-1][0], spans[-1][0] + 4)) if words[spans[-1][0]:spans[-1][0] + 4] == ["if", "it", "had", ","]
         else set())
    if supposed:
        read.append((" ".join(words[j] for j in sorted(supposed)), "nothing, the change supposed"))
    return [*said, *(w for j, w in enumerate(words[b:], b) if j not in supposed)], tuple(read)


# A manual's parts, labelled in brackets ('[A] brown pickup', '[Part V] bicycle', '[E1] yellow dirt bike') and then
# named by the label alone ('Is [A] moving slowly at impact?'); and a vehicle called a part ('one part is stopped',
# 'what colour does that part have')
PART_POINTERS = {"one", "that", "this", "which", "what", "each", "the"}


def part_labels_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'set [ c ] gray dirtbike next to [ d ] blue suv . check : is [ c ] slower than [ d ] ?' -> 'set the gray
    dirtbike next to the blue suv . check : is the gray dirtbike slower than the blue suv ?'. With the words read so,
    or the words as they are and ()."""
    labels, out, read, k = {}, [], [], 0
    while k < len(words):
        close = words.index("]", k) if words[k] == "[" and "]" in words[k + 2:k + 5] else None
        label = tuple(w for w in words[k + 1:close] if w != "part") if close else ()
        if not label or len(label) > 2 or not all(w.isalnum() and len(w) <= 6 for w in label):   # ('[B4]' is 'before')
            out.append(words[k])
            k += 1
            continue
        after = words[close + 1:]
        runs = mentions(after[:6])
        if runs and runs[0][0] == 0:
            end = runs[0][1] + (after[runs[0][1]:runs[0][1] + 1] in (["one"], ["vehicle"]))
            labels[label] = after[:end]
            read.append((" ".join(words[k:close + 1]), "the"))
            out += ["the"] if out[-1:] not in (["the"], ["a"]) else []
            k = close + 1
        elif label in labels:
            read.append((" ".join(words[k:close + 1]), " ".join(["the", *labels[label]])))
            out += ["the", *labels[label]]
            k = close + 1
        else:
            return words, ()
    # (where the parts are labelled or counted, 'one part is stopped'; not a part of the video: 'the part of the
    # clip', 'part-way', 'the part where they collide', 'the part we don't get to see')
    parts = [j for j, w in enumerate(out) if w == "part" and j and out[j - 1] in PART_POINTERS
             and out[j + 1:j + 2] not in (["of"], ["-"], ["way"], ["through"], ["where"], ["when"])
             and not (out[j + 1:j + 2] and out[j + 1] in SPEAKER_AND_LISTENER | {"they"})]
    if parts and (labels or any(out[j - 1] == "one" for j in parts)):
        read.append(("part", "vehicle"))
        out = ["vehicle" if j in parts else w for j, w in enumerate(out)]
    return (out, tuple(read)) if read else (words, ())
