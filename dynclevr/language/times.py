"""Times said another way, read as the grammar says them: the video's end, its going on past the end or its cut ('once
the video is over', 'had the footage continued', 'past the cutoff') as 'after the video ends' in a question about
collisions (`video_end_as_said`; its clause, `_video_end`, is found for the context, the asides and the refusals too),
the start by its frame or its clock ('at t = 0') and the first frame that shows an object (`first_frames_as_said`), and
a time said between commas after the subject put last (`inserted_time_last`), and a clause of time closed by a colon
(`time_clause_closed`). Each is one of `QuestionParser._words`'
rewrites, `f(words) -> (words, read_as)`."""

from __future__ import annotations

from dynclevr.language.references import OBJECT_WORDS
from dynclevr.language.tokenize import tokenize
from dynclevr.language.words import (CLAUSE_CONJUNCTIONS, NAMING, QUESTION_OPENERS, START_ADJECTIVES, STOPPED_SAID,
                                     YES_NO_OPENERS, asks_impact, _at)
from dynclevr.questions.generate import templates

# A time or a frequency said between commas after the subject ('does the red biplane , at some point , hit ...', 'is
# the red car , when it hits the bus , fast ?'): the grammar says it last
INSERTED_TIMES = {"at", "in", "during", "ever", "right", "initially", "once", "when", "while", "after", "before",
                  "later", "from", "anywhere"}


def inserted_time_last(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question with a time between commas after its first vehicle put last ('does the red biplane , at any
    point , collide with the green sedan ?' -> '... collide with the green sedan at any point ?'), where the sentence
    goes on after it; or after 'is there' ('is there , anywhere in the footage , a collision between ...'). With the
    words read so, or the words as they are and ()."""
    for k in range(1, len(words) - 2):
        if words[k] != "," or words[k - 1] not in OBJECT_WORDS and words[k - 2:k] not in (["is", "there"],
                                                                                            ["was", "there"]) \
                or words[k + 1] not in INSERTED_TIMES:
            continue
        close = next((j for j in range(k + 2, min(k + 10, len(words))) if words[j] in (",", "?", ".")), None)
        if close is None or words[close] != "," or close + 1 == len(words) or words[close + 1] in QUESTION_OPENERS:
            return words, ()
        end = len(words) - (words[-1] in ("?", "."))
        moved = words[:k] + words[close + 1:end] + words[k + 1:close] + words[end:]
        return moved, ((" ".join(words[k:close + 1]), f"'{' '.join(words[k + 1:close])}' said last"),)
    return words, ()


# A clause of time that opens the question, closed by a colon or a semicolon before what it asks ('at the moment it
# collides with the yellow tandem bike : was the car standing still ?'): a colon there is read as the comma the grammar
# writes (with it, the clause's 'it' was read as the tandem bike)
CLAUSE_OPENS = ([c] for c in sorted(CLAUSE_CONJUNCTIONS | {"as"}))
CLAUSE_OPENERS = (*CLAUSE_OPENS, ["at", "the", "moment"], ["at", "the", "instant"], ["right", "as"], ["just", "as"])


def time_clause_closed(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'at the moment it collides with the bus : is the car fast ?' -> '... with the bus , is the car fast ?'. With the
    words read so, or the words as they are and ()."""
    if not any(words[:len(c)] == c for c in CLAUSE_OPENERS):
        return words, ()
    k = next((k for k in range(2, min(len(words) - 1, 16)) if words[k] in (":", ";", ",", "?", ".", "-")), None)
    if k is None or words[k] not in (":", ";") or words[k + 1] not in YES_NO_OPENERS | QUESTION_OPENERS:
        return words, ()
    return [*words[:k], ",", *words[k + 1:]], ((words[k], ","),)


# A time said by its frame or its clock ('at t = 0', 'at frame 0'), and the first frame that shows an object ('in
# the first frame in which it is visible'): the grammar's start and its coming into view.
TIME_ZERO = (["t", "=", "0"], ["t", "0"], ["t0"], ["time", "0"], ["time", "zero"], ["frame", "0"], ["frame", "zero"],
             ["frame", "1"], ["frame", "one"],
             ["0000", "hours"], ["0000", "hrs"], ["0000"], ["zero", "hundred", "hours"])   # a watch log's clock
SEEN = (["is", "visible"], ["is", "seen"], ["appears"], ["shows", "up"], ["becomes", "visible"], ["is", "in", "view"],
        ["comes", "into", "view"], ["is", "in", "sight"])


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


# The video's end said by another time word ('once the video is over', 'when the clip is done'): the grammar's
# 'after the video ends', the future (a 'when' or 'once' clause reads as the video's own time otherwise).
END_SAID = {"ends", "ended", "finishes", "finished", "stops", "stopped"}
END_OPENERS = (["once"], ["when"], ["as", "soon", "as"], ["by", "the", "time"], ["after"], ["as"], ["since"],
               ["given", "that"], ["given"], ["now", "that"], ["with"], ["supposing"], ["supposing", "that"],
               ["provided"], ["provided", "that"], ["if"], ["assuming"], ["assuming", "that"], ["suppose"],
               ["suppose", "that"],
               *([p, "the", "point", w] for p in ("beyond", "past", "after") for w in ("where", "at", "when")),
               *([p, "where"] for p in ("beyond", "past", "after")))
END_OPENERS = tuple(sorted(END_OPENERS, key=len, reverse=True))   # 'after where it stops' before 'after'

FILM_WORDS = {"video", "clip", "footage", "film", "recording", "movie", "sequence", "cartoon", "animation", "stream",
              "replay", "feed", "tape", "playback", "livestream"}
# the verbs of a video's stop ('paused', 'cut', 'ends'), without the auxiliaries and particles said with them
CUT_VERBS = {w for stop in STOPPED_SAID for w in stop if w.isalpha()} - {
    "is", "was", "were", "gets", "got", "s", "has", "been", "in", "between", "off", "out", "short", "early", "abruptly"}


def cut_premise(clause: list[str]) -> bool:
    """Whether a premise's clause says the video stops ('assuming the footage stops partway through', 'if the video
    were paused midway'): the predictive questions' own premise, not a change to what is seen."""
    return any(w in FILM_WORDS and CUT_VERBS.intersection(clause[k + 1:k + 4]) for k, w in enumerate(clause))


PART_WAY = (["mid", "-", "way", "through"], ["mid", "-", "way"], ["partway", "through"],
            ["part", "-", "way", "through"], ["part", "way", "through"], ["partway"], ["part", "-", "way"],
            ["part", "way"],
            ["halfway", "through"], ["halfway"], ["half", "way"], ["midway", "through"], ["midway"], ["there"],
            ["here"], ["right", "there"], ["right", "here"],
            ["part", "of", "the", "way", "through"], ["part", "of", "the", "way"],
            ["early"], ["in", "the", "middle"])
END_PREDICATES = (["is", "over"], ["is", "done"], ["is", "finished"], ["is", "complete"], ["has", "ended"],
                  ["has", "finished"], ["ends"], ["finishes"], ["stops"], ["is", "through"], ["runs", "out"],
                  ["has", "stopped"], ["comes", "to", "an", "end"], ["is", "stopped"], ["is", "paused"],
                  ["is", "halted"],
                  # as learners say them ('when video is finish')
                  ["is", "finish"], ["is", "end"], ["is", "ended"], ["end"], ["finish"], ["ended"], ["finished"],
                  ["over"], ["wraps", "up"], ["winds", "down"],
                  *(["'", "s", e] for e in ("over", "done", "finished", "ended", "through")))


# the video imagined going on past its end ('had the footage continued past the point where it is cut off, ...'):
# the time after it, as 'if the video went on' reads (the video otherwise, 'if it were longer', stays refused)
CONTINUED = (["continued"], ["kept", "going"], ["kept", "running"], ["kept", "rolling"], ["gone", "on"], ["went", "on"],
             ["run", "on"], ["ran", "on"], ["carried", "on"], ["played", "on"], ["not", "stopped"], ["not", "ended"],
             # a learner's unmarked tense ('if video continue from where it stop, ...')
             ["continue"], ["continues"], ["keep", "going"], ["keeps", "going"], ["go", "on"], ["goes", "on"],
             ["not", "been", "cut", "off"], ["not", "been", "cut"], ["not", "cut", "off"], ["to", "continue"],
             ["to", "keep", "going"], ["to", "go", "on"], ["to", "run", "on"], ["to", "carry", "on"],
             *([let, *to] for let in ("allowed", "left") for to in (["to", "carry", "on"], ["to", "continue"],
                                                                   ["to", "run", "on"], ["to", "play", "on"],
                                                                   ["to", "run"], ["to", "go", "on"])))
# ... in a condition ('had the video ...', 'if ...', or a premise's 'assuming the clip continued past where it stops')
IF_SAID = {"if", "assuming", "supposing", "suppose"}
CONTINUING = (["had"], ["were"], *([w] for w in IF_SAID))


def _video_continued(words: list[str], before: list[str] = ()) -> tuple[int, int] | None:
    """Where a clause imagining the video going on lies ('had the video continued, ...'; 'had it played on' once the
    video is named, here or in the words `before`), to its comma."""
    for i in range(len(words)):
        if [words[i]] not in CONTINUING:
            continue
        j = i + 1 + (words[i] in IF_SAID and words[i + 1:i + 2] == ["that"])
        j += words[j:j + 1] in (["the"], ["this"])
        # ('had it played on': only a video plays)
        named = words[j:j + 1] == ["it"] and (FILM_WORDS.intersection([*before, *words[:i]])
                                              or words[j + 1:j + 3] == ["played", "on"])
        if words[j:j + 1] == [] or words[j] not in FILM_WORDS and not named:
            continue
        j += 1 + (words[i] in IF_SAID and words[j + 1:j + 2] == ["had"])
        # ('if the film were allowed to')
        were = words[i] == "were" or words[i] in IF_SAID and words[j:j + 1] == ["were"]
        j += words[i] in IF_SAID and words[j:j + 1] == ["were"]
        going = next((c for c in CONTINUED if words[j:j + len(c)] == c), None)
        if going and were == (going[0] in ("to", "allowed", "left")):
            k = j + len(going)
            comma = words.index(",", k) if "," in words[k:k + 12] else k
            return i, comma
    return None


# where a simulation's or an engineer's video stops ('in the predicted rollout after the cutoff', 'past the stop point')
CUT_POINTS = tuple([*roll, p, "the", *c, *of] for roll in ((), ("in", "the", "predicted", "rollout"),
                                                          ("in", "the", "rollout"), ("predicted", "rollout"))
                   for of in ((), *(("of", "the", f) for f in ("video", "clip", "footage")))
                   for p in ("after", "past", "beyond", "following")
                   for c in (("cutoff",), ("cut", "-", "off"), ("cut", "off"), ("stop", "point"), ("stopping", "point"),
                             ("cut", "point"), ("cut",), ("truncation",), ("truncation", "point"), ("cutoff", "point"),
                             ("cut", "-", "off", "point"), ("freeze",)))


CUT_POINTS_LONGEST = sorted(map(tuple, CUT_POINTS), key=len, reverse=True)


def _at_cut(words: list[str]) -> tuple[int, int] | None:
    at = _at(words, CUT_POINTS_LONGEST)
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
        j = i + len(opener or []) + (words[i + len(opener or []):i + len(opener or []) + 1] in (
            ["the"], ["this"], ["my"], ["our"], ["your"]))
        j += words[j:j + 1] != [] and words[j] in FILM_KINDS and words[j + 1:j + 2] != [] and words[j + 1] in FILM_WORDS
        if opener and opener[-1] == "where" and words[j - 1] == "this" and words[j:j + 1] != [] and \
                words[j] not in FILM_WORDS:
            j -= 1   # 'after where this stops': 'this' the video itself
        named = words[j:j + 1] in (["it"], ["this"]) and opener and (
            FILM_WORDS.intersection([*before, *words[:i]]) or
            # ('past where it stops' before any vehicle is named: only the video stops there)
            opener[-1] == "where" and not OBJECT_WORDS.intersection([*before, *words[:i]]))
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
            if alone and words[k:k + 1] and words[k] not in CLAUSE_SEPARATORS | {"(", "!"}:
                continue   # 'the video stops before they collide': the clause is the question's own
            return i, k
    return None


# who cuts a video, said as its subject ('They've cut the film short on us!', 'Someone paused the clip.')
CUTTERS = {"they", "someone", "somebody", "you", "we", "i", "the", "editor", "editors"}
CUT_AUXILIARIES = (["'", "ve"], ["have"], ["'", "d"], ["had"], ["has"], ["'", "s"], ["just"], ["'", "ve", "just"])


def active_cut_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'they 've cut the film short on us ! after it stops , ...' -> 'the film is cut short ! after it stops , ...':
    a sentence of someone cutting the video, said as the video cut (`_video_end` reads it so), where it names no
    vehicle and no collision. With the words read so, or the words as they are and ()."""
    for i in range(len(words)):
        if words[i] not in CUTTERS or i and words[i - 1] not in CLAUSE_SEPARATORS | {"!", "?"}:
            continue
        j = i + 1 + (words[i] == "the")   # 'the editors'
        j += next((len(a) for a in sorted(CUT_AUXILIARIES, key=len, reverse=True) if words[j:j + len(a)] == a), 0)
        if words[j:j + 1] == [] or words[j] not in CUT_VERBS:
            continue
        m = j + 1 + (words[j + 1:j + 2] == ["off"])
        m += words[m:m + 1] in (["the"], ["this"], ["our"])
        end = next((e for e in range(m, len(words)) if words[e] in CLAUSE_SEPARATORS | {"!", "?"}), len(words))
        if words[m:m + 1] == [] or words[m] not in FILM_WORDS or asks_impact(words[i:end]) or \
                OBJECT_WORDS.intersection(words[i:end]):
            continue
        return [*words[:i], "the", words[m], "is", "cut", "short", *words[end:]], \
            ((" ".join(words[i:end]), f"the {words[m]} is cut short"),)
    return words, ()


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
        # '..., (so) after that, will ...': the time after the end it has just said
        m = k + (words[k:k + 1] == [","])
        m += words[m:m + 1] in (["so"], ["and"])
        if words[m:m + 2] in (["after", "that"], ["after", "this"]):
            k = m + 2
        if words[i:k] != ["after", "the", "video", "ends"]:
            read.append((" ".join(words[i:k]), "after the video ends"))
            words = words[:i] + ["after", "the", "video", "ends"] + words[k:]
        start = i + 4
    return words, tuple(read)


# the grammar's times after the video that say its frames or their rest ('in the remaining frames', 'after the shown
# frames'; not 'later' or 'eventually', which may be said within it), and its end as `video_end_as_said` reads it
LATER_SAID = tuple(sorted({tuple(tokenize(p)) for pool in ("seen", "heldout")
                           for p in templates()["lexicon"]["LATER"][pool] if len(p.split()) >= 3
                           and not p.startswith("later")}
                          | {("after", "the", "video", "ends"), ("in", "the", "rest", "of", "the", "frames")},
                          key=len, reverse=True))


def present_asked_later(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'does the cyan tandem bike hit anything in the rest of the frames ?' -> 'will the cyan tandem bike hit ...': a
    collision after the video asked in the present tense (read within the video, then refused for its time). With
    the words read so, or the words as they are and ()."""
    if not asks_impact(words) or not _at(words, LATER_SAID):
        return words, ()
    k = next((j for j, w in enumerate(words) if w in ("does", "do") and (j == 0 or words[j - 1] in (",", ":"))), None)
    if k is None:
        return words, ()
    return words[:k] + ["will"] + words[k + 1:], ((words[k], "will"),)


# A moment pointed at by picturing it ('Picture the moment the green SUV runs into the bus; how fast is it then?',
# 'Imagine that instant when they smash together - at that point, ...'): a time in the video, not a change imagined
PICTURING = (["imagine"], ["picture"], ["consider"], ["envision"], ["visualise"], ["visualize"], ["take"],
             ["think", "of"], ["think", "about"], ["thinking", "of"], ["thinking", "about"], ["picturing"],
             ["imagining"], ["considering"], ["mark", "well"], ["mark"])   # (a quest giver's 'Mark well the moment')
MOMENTS = {"moment", "instant", "point", "second"}
NOT_BEFORE_MOMENT = {"at", "from", "since", "until", "till", "by", "to", "in", "on", "of", "for", "that", "this",
                     "the", "what", "which", "after", "before", "during", "just", "right", "exactly", "precisely"}
BARE_MOMENT_NEXT = {"it", "they", "the", "that", "when", "of", "both", "these", "those", "this"}


def moment_pictured(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'picture the moment the suv runs into the bus , ...' -> 'at the moment the suv runs into the bus , ...'.
    With the words read so, or the words as they are and ()."""
    for k in range(len(words)):
        said = next((p for p in PICTURING if words[k:k + len(p)] == p), None)
        j = k + len(said) if said else 0
        first = k - (k > 0 and words[k - 1] in ("now", "so", "ok", "okay", "and", "just", "first"))
        if said and (first == 0 or words[first - 1] in CLAUSE_SEPARATORS) and \
                words[j:j + 1] in (["the"], ["that"], ["this"]) \
                and words[j + 1:j + 2] and words[j + 1] in MOMENTS and words[j + 2:j + 3] != ["of"]:
            if words[j] != "the" and words[j + 2:j + 3] in ([","], ["."], ["!"], [";"], [":"]):
                # 'the bus hits the car . think about that moment . is ...': the moment said before, then
                return (words[:first] + ["at", "that", "moment", ","] + words[j + 3:],
                        ((" ".join(words[first:j + 3]), "at that moment ,"),))
            return (words[:first] + ["at", "the", "moment"] + words[j + 2:],
                    ((" ".join(words[first:j + 2]), "at the moment"),))
    # ... or the vehicle's own impact said first ('Striking the gray minivan, how fast was the cyan bicycle going?')
    if words[:1] and words[0].endswith("ing") and asks_impact(words[:1]) and "," in words[1:8] and "?" in words:
        return ["when", *words], ((words[0], f"when {words[0]}"),)
    # ... or said bare as a clause of time ('The moment it crashes into the school bus, what speed ...?')
    # (or after the words it says the time of: 'what was its speed the moment it first showed up ?')
    k = next((k for k in range(len(words) - 2) if words[k:k + 2] in (["the", "moment"], ["the", "instant"]) and (
        k == 0 or words[k - 1] in CLAUSE_SEPARATORS or words[k - 1].isalpha() and words[k - 1] not in NOT_BEFORE_MOMENT
        and words[k + 2] in ("it", "they")) and words[k + 2] in BARE_MOMENT_NEXT), None)
    if k is not None:
        return words[:k] + ["at"] + words[k:], ((" ".join(words[k:k + 2]), "at the moment"),)
    # ('The gray city bus, the second it appears, is it ...?'; not 'the second one')
    k = next((k for k in range(len(words) - 2) if words[k:k + 2] in (["the", "second"], ["the", "minute"])
              and words[k + 2] in ("it", "they") and (k == 0 or words[k - 1] in CLAUSE_SEPARATORS)), None)
    if k is not None:
        return words[:k] + ["at", "the", "moment"] + words[k + 2:], ((" ".join(words[k:k + 2]), "at the moment"),)
    return words, ()
