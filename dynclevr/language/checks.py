"""Checks that a decoded reading reads what the question's words say. No operation negates, and each family asks in one
form, of one property, at one time: the decoder reads a wording it never learnt as its nearest family's, and would
answer another question. `QuestionParser._check` runs `reversed_reading`, `named_attribute` and `compared_unsaid` on the
words decoded (and puts a counterfactual's changed vehicle where its condition names it, `condition_subject_first`);
`analyse_batch` runs the others on the reading chosen, against the words as said and as read.

A reading is unparsed with the reason of the first that fails: the opposite of the question (`reversed_reading`: motion
asked as rest, 'Is the red sedan moving at the start?' read as is_static; a negation the grammar never says, 'not
accelerating', 'never hit'; a word reversing the program's predicate, 'miss', 'braking', 'grounded'; a rest no word
says, a speed read as static); an attribute the question itself names (`named_attribute`); two vehicles said side by
side that nothing compares (`compared_unsaid`); a yes/no question read as asking which or how (`form_unmatched`), or one
of who or what read as yes or no (`form_unasked`); a direction or a place asked as yes or no ('is it moving left?':
`direction_unasked`); the video's end or another time than the start ('in the middle', 'after two seconds':
`time_unasked`), a time window ('within 2 seconds': `clock_unasked`), a collision at the start (`collision_at_start`); a
reading of two named objects that drops an indefinite one (`anything_unasked`); a collision no word says
(`impact_unsaid`, unless an unknown word may be an impact's misspelt: `words.impact_like`) or one left unread
(`collision_unread`); what a vehicle does or what happens (`what_happens`); a colour or a type no word asks
(`attribute_unsaid`); 'faster' of nothing (`uncompared`); 'afterwards' read within the video or a reading after the
video no word says (`future_unread`); a speed, floating or a comparison no word says (`speed_unsaid`, `floating_unsaid`,
`comparison_unsaid`); a counterfactual that compares a vehicle with itself ('had it been slower':
`comparison_imagined`), a change imagined read as what happened (`imagining_unread`), a counterfactual no word makes a
condition (`condition_unsaid`); floating said and not read (`floating_unread`); a partner described by its motion ('a
stationary vehicle': `motion_unread`) or a vehicle picked by its motion and not so read (`motion_unfiltered`); 'still'
said of a motion read as rest (`still_continuing`); another property than the one asked, an amount of acceleration among
them (`property_unread`); whether a vehicle is visible (`visibility_unread`); speeding up unread, or read where no word
says it (`acceleration_unread`, `acceleration_unsaid`); the video's end, a later time or a vehicle entering read at the
start (`end_unread`); a size (`size_unread`)."""

from __future__ import annotations

from difflib import SequenceMatcher

from dynclevr.language.context import _instructs, _run_on_question, _sentence_spans
from dynclevr.language.references import OBJECT_WORDS, coordinated, generalises, mentions, placeholders
from dynclevr.language.refusals import _asked
from dynclevr.language.times import END_SAID, FILM_WORDS
from dynclevr.language.words import (ACCELERATION_SAID, AFLOAT_SAID, ASKED_QUERIES, ASKING, ASKING_FOR, ATTRIBUTE_NOUNS,
                                     ATTRIBUTE_SAID, AUXILIARIES, CATEGORY_OF, CLAUSE_CONJUNCTIONS, COMES_IN_WORDS,
                                     COMPARING, COMPARISONS, CONDITION_LABELS, DETERMINERS, DIRECTION_WORDS, END_TIMES,
                                     END_WORDS, ENGINE_WORDS, FLOATING_WORDS, FUTURE_CUES, GENERIC_NOUNS,
                                     IMAGINING_LABELS, INDEFINITES, MOTION_DESCRIPTIONS, MOTION_KINDS, MOTION_WORDS,
                                     NAMING, NEGATIONS, NUMBERS, PARTNER_SAID, QUERY_NOUNS, RESTING, REST_WORDS,
                                     REVERSERS, CLAUSE_MARKS, SENTENCE_ENDS, SPEED_CLASS_WORDS, START_ADJECTIVES,
                                     START_WORDS, STATIC_SAID, STOPPED_SAID, STOP_CUES, UNMOVED, VIEWER, YES_NO_OPENERS, _at, _head,
                                     asks_impact)
from dynclevr.questions.programs import OPS


def operation(token: str) -> str:
    """'filter_attributes[red]' -> 'filter_attributes': a program token without its argument."""
    return token.split("[", 1)[0]


# No operation negates, and the grammar words each question one way round: a model reads a reversed wording ('is it
# moving?', 'is it not accelerating?', 'does it miss the bus?') as its nearest phrase, the unreversed one, and its
# answer would be the opposite. So a reading is kept only where the question's words say what its program asks.
REST_OPERATIONS = {"is_static", "filter_static", "Counterfactual_static"}
STILL_GOING = {"still", "kept", "keeps", "keep", "stay", "stays", "stayed"}   # before a motion, it goes on
# what a negation may deny in the grammar's own questions: motion ('not moving': rest) and a fall ('had never come
# down': floating); 'X or not' offers both answers
DENIABLE = MOTION_WORDS | {"fall", "falls", "fell", "fallen", "falling", "come", "came", "drop", "dropped", "land",
                           "landed", "descend", "descended", "sink", "sank", "sunk"}
PAST = {"been", "have", "has", "had", "even", "at", "all", "ever", "once", "yet", "really", "actually", "-"}
ALOFT = {"off", "above", "over", "from"}   # 'off the ground' is floating; 'on the ground', 'grounded' are not


def offered(words: list[str], k: int) -> bool:
    """Whether word k is in an alternative offered after 'or' ('in the air or on the ground?', '... or is it on the
    ground', 'or is it not?'): the question offers both answers, and asks the first; or denied after 'and' ('fast
    and not slowly', 'in the air and not on the ground': `properties_joined` refuses two kinds of motion)."""
    return "or" in words[max(k - 5, 0):k] or words[k - 1:k] == ["and"]


def reversed_reading(words: list[str], abstract: list[str]) -> str:
    """Why the program asks the opposite of the question ('' when it does not): motion asked as rest, a negation
    the grammar never says, or a word that reverses the program's predicate ('miss', 'braking', 'grounded')."""
    ops = {operation(t) for t in abstract}
    # the words that say rest, but for one that goes on ('is it still fast ...?', 'had it kept moving ...')
    rests = {w for k, w in enumerate(words) if w not in STILL_GOING or not (
        words[k + 1:k + 2] and words[k + 1] in SPEED_CLASS_WORDS - {"still"} | MOTION_WORDS | COMPARISONS)}
    if ops & REST_OPERATIONS and MOTION_WORDS.intersection(words) and not (REST_WORDS | NEGATIONS).intersection(rests):
        return ("the question asks whether an object is moving, which no question here asks (ask whether it is "
                "static, or slow or fast)")
    if ops & REST_OPERATIONS and (SPEED_CLASS_WORDS - COMPARISONS - {"still"}).intersection(words) and \
            not (REST_WORDS | NEGATIONS).intersection(rests):
        return "the question asks a speed (slow or fast), but its nearest reading asks whether the vehicle is static"
    # 'what colour is it at the start?' was read as the colour of the static one
    if ops & REST_OPERATIONS and not (REST_WORDS | NEGATIONS | UNMOVED | RESTING).intersection(words):
        return ("the question says nothing of standing still, but its nearest reading asks about it: ask whether the "
                "vehicle is static, slow or fast")
    for k, w in enumerate(words):
        if w not in NEGATIONS or offered(words, k):
            continue
        after = [v for v in words[k + 1:k + 5] if v not in PAST]
        # (motion denied is rest, but in a question a speed denied is no family's: 'is the red car not moving
        # fast?', nor an engine's running: 'is its engine not running?'; a statement's, tagged, asks it: 'the scooter
        # is not going slowly , is it ?')
        asked = words[:1] and words[0] in YES_NO_OPENERS and (
            after[1:2] and after[1] in SPEED_CLASS_WORDS - {"still"} or ENGINE_WORDS.intersection(words[k - 3:k]))
        # motion denied is read only as rest: 'which direction is the red car not moving?' has no family ('not
        # moving , slow or fast ?' offers it)
        unrested = after[:1] and after[0] in MOTION_WORDS and not ops & REST_OPERATIONS and \
            "or" not in words[k + 2:k + 7] and not (after[1:2] and after[1] in SPEED_CLASS_WORDS | COMPARISONS | {
                ",", "?", "more", "less", "as", "so", "too", "very", "really", "that"})
        if not after or after[0] not in DENIABLE and after[:2] != ["in", "motion"] or asked or unrested:
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


# 'up' and 'down' said of the motion ('is the jet going up?' was read as accelerating), not of a speed ('speeding up',
# 'its speed going up', 'slowing down') nor a place ('flying up in the air')
HEIGHT_MOTIONS = {"moving", "going", "flying", "heading", "headed", "travelling", "traveling", "climbing", "rising",
                  "move", "go", "fly", "head", "moves", "goes", "flies", "heads"}
RIGHT_AS_TIME = {"at", "when", "as", "after", "before", "away", "then", "from", "in", "on", "upon"}


def _direction_said(words: list[str]) -> str | None:
    """The first words that say a direction or a place ('left', 'towards the camera', 'away from us'), or None."""
    for k, w in enumerate(words):
        as_time = w == "right" and words[k + 1:k + 2] != [] and words[k + 1] in RIGHT_AS_TIME and \
            words[k - 1:k] not in (["the"], ["to"])   # 'right at the start', not 'to the right at the start'
        # ... nor a caller's 'right there at the start', 'is it right that ...', 'they collide , right , and ...'
        as_time = as_time or w == "right" and (
            words[k + 1:k + 2] == ["there"] and words[k - 1:k] not in (["the"], ["to"])
            or words[k - 2:k] == ["is", "it"] and words[k + 1:k + 2] == ["that"]
            or words[k - 1:k] == [","] and words[k + 1:k + 3] in ([",", "and"], [",", "so"], [",", "now"])
            and words[k - 2] not in DIRECTION_WORDS)
        # ... nor a yarn's 'back at the outset', 'back when it started' (a time gone by)
        as_time = as_time or w == "back" and k == 0 and words[1:2] in (["at"], ["when"], ["in"], ["then"])
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


# Words that ask which way without naming a direction ('where is it headed', 'what bearing', 'whither')
DIRECTION_ASKING = {"direction", "directions", "way", "ways", "heading", "headed", "head", "heads", "where", "whither",
                    "toward", "towards", "bearing", "course", "orientation", "facing", "pointing", "pointed", "aimed",
                    "path", "trajectory", "route", "compass", "side", "sideways", "forth"}


def direction_unsaid(said: list[str], read: list[str], program: list[str]) -> str:
    """Why a reading of a direction is not the question's ('' when it is): the question says no direction and no
    word that asks one ('In what state of motion does the green scooter find itself right at the start?' was read
    as which way it moves: 'right' there is a time's)."""
    if program[-1] != "query_moving_direction" or DIRECTION_ASKING.intersection(said + read) or \
            _direction_said(said) or _direction_said(read):
        return ""
    return ("the question says no direction, but its nearest reading asks which way a vehicle moves: ask 'which way "
            "is it moving' (or how fast)")


# 'holding' alone is a vehicle holding still to a driver and one in a holding pattern (in the air) to a pilot
# ('Say the green one had been holding from the start, ...' was read as standing still); said with what is held
# ('holding still', 'holding a hover', 'in a holding pattern') the idioms read it first
HOLDING = {"holding", "holds", "held", "hold"}
HOLDING_READ = {"is_static", "filter_static", "Counterfactual_static", "is_floating", "filter_floating",
                "Counterfactual_floating"}


def holding_unsaid(said: list[str], program: list[str]) -> str:
    """Why a reading of rest or floating is not the question's ('' when it is): it turns on a bare 'holding'."""
    if not HOLDING_READ.intersection(map(operation, program)) or (AFLOAT_SAID | REST_WORDS) & set(said) or not any(
            w in HOLDING and said[k + 1:k + 2] in ([], ["?"], [","], ["."], ["from"], ["at"], ["when"], ["on"])
            and not (w == "hold" and (k == 0 or said[k - 1] in (",", ".", "!", "?")))   # 'hold on, was ...'
            for k, w in enumerate(said)):
        return ""
    return ("the question says 'holding', which may be holding still or holding in the air: say 'standing still' or "
            "'floating'")


# A time that is not the start, said of a motion the program reads at the start: no question asks a vehicle's motion
# in the middle, at the 2-second mark, throughout or ever (they ask at the start, when it comes into view, at a
# collision)
NOT_START = (["middle"], ["halfway"], ["half", "way"], ["midway"], ["midpoint"], ["mid", "-", "point"],
             ["throughout"], ["during"], ["later"], ["ever"], ["always"], ["eventually"], ["afterwards"],
             ["sometimes"], ["at", "some", "point"], ["at", "any", "point"],
             ["at", "any", "time"], ["at", "one", "point"], ["most", "of", "the", "time"], ["all", "the", "time"],
             ["the", "whole", "time"], ["whole"], ["entire"], ["now"], ["currently"], ["presently"])
CLOCK_WORDS = {"second", "seconds", "frame", "frames", "s", "sec", "secs"}
ORDINAL_WORDS = {"first", "1", "0", "one", "zero"}   # 'frame 1', 'the first second': the start


STOPPING = END_SAID | {"paused", "pauses", "cut", "cuts", "froze", "freezes", "halted", "halts"}


def time_unasked(words: list[str], program: list[str]) -> str:
    """Why a reading at the start is not the question's ('' when it is): the question says no word of the start but
    another time ('in the middle of the video, is the red car fast?', 'after two seconds', 'at frame 50', 'ever'),
    which the decoder read as the start."""
    if "start" in program and not START_WORDS & set(words) and any(
            w == "first" and COMES_IN_WORDS & set(words[k + 1:k + 3]) for k, w in enumerate(words)):
        return ("the question asks when a vehicle comes into view ('first ... " + next(
            v for k, w in enumerate(words) if w == "first" for v in words[k + 1:k + 3] if v in COMES_IN_WORDS)
                + "'), but its nearest reading asks at the start: ask how fast it moves when it first comes into view")
    if "start" not in program or START_WORDS & set(words) or "first" in words:
        return ""
    # (or when it comes into view: 'does the car come into view fast?' was read at the start)
    said = next((" ".join(t) for k in range(len(words)) for t in (*NOT_START, ["before"], ["until"], ["into", "view"])
                 if words[k:k + len(t)] == t), None) or _future_said(words) or next(
        # 'faster than the bus after the video?', 'moving slowly at the moment the video was paused?'
        (f"the {w} {s}" for k, w in enumerate(words) if w in FILM_WORDS for s in words[k + 1:k + 4] if s in STOPPING),
        None)
    clock = next((f"{a} {b}" for a, b in zip(words, words[1:]) if (a in CLOCK_WORDS and b.isdigit() or
                                                                   b in CLOCK_WORDS and (a.isdigit() or a in NUMBERS))
                  and not {a, b} & ORDINAL_WORDS), None)
    if not (said or clock):
        return ""
    if said == "into view":
        return ("the question asks when a vehicle comes into view, but its nearest reading asks at the start: ask how "
                "fast it moves when it first comes into view")
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
        # 'when it leaves the view' was read as when it comes into it, 'at the instant it leaves the frame' at the
        # start
        left_view = next((f"{w} the {v}" for w, t, v in zip(words, words[1:], words[2:]) if w in LEAVING
                          and t == "the" and v in VIEW_NOUNS), None)
        if leaving and "come_in_frame" in program or left_view and "start" in program:
            return (f"the question asks when a vehicle leaves the view ('{left_view or leaving}'), which no question "
                    "here asks (they ask how fast it moves when it comes into view)")
        return ""
    return (f"the question asks whether a vehicle can be seen ('{said}'), which no question here asks (they ask how "
            "fast it moves when it comes into view)")


VIEW_NOUNS = {"frame", "view", "picture", "screen", "shot", "scene", "image"}
GOING_OUT = {"go", "goes", "going", "went", "gone", "move", "moves", "moving", "moved", "drive", "drives", "driving",
             "drove", "fly", "flies", "flying", "flew", "get", "gets", "getting", "got", "pass", "passes", "passed"}
LEAVING = {"leave", "leaves", "leaving", "left", "exit", "exits", "exiting", "exited", "disappear", "disappears",
           "disappearing", "disappeared", "vanish", "vanishes", "vanished", "departs", "departed"}


COLLIDING = ("collid", "collision", "hit", "crash", "struck", "strik", "smash", "slam")


def collision_unread(words: list[str], program: list[str]) -> str:
    """Why a reading at the start or as a vehicle comes into view is not the question's ('' when it is): the question
    (as said: 'by any chance' is no 'bump') also speaks of a collision ('is the red car at the start faster than the
    bus at the collision?' was read at the start alone, 'red plane go fast when hit?' as it comes into view)."""
    moment = next((m for m in ("start", "come_in_frame") if m in program), None)
    # (as it comes into view, only an impact's own verb: 'slides into view', 'bang on the drum' say none)
    if moment is None or COLLISION_OPERATIONS.intersection(map(operation, program)) or not asks_impact(words) or \
            moment == "come_in_frame" and not any(w.startswith(COLLIDING) for w in words):
        return ""
    said = "at the start" if moment == "start" else "as it comes into view"
    return (f"the question speaks of a collision, but its nearest reading asks {said} alone: no question here reads "
            "both")


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


def instruction_unread(words: list[str], program: list[str]) -> str:
    """Why a reading of what the video shows is not the question's ('' when it is): a sentence of the question tells
    a change to a vehicle ('swap in a fast speed for the biplane . does it then crash into ...?'), which no reading
    of the video asks."""
    if any(t.startswith("Counterfactual") for t in program):
        return ""
    told = next((told for s in (words[a:b] for a, b in _sentence_spans(words)) if (told := _instructs(s))
                 and mentions(s)), None)
    if told is None:
        return ""
    return (f"the question tells a change ('{told}'), but its nearest reading asks what the video shows: ask 'if X "
            "had been ... from the start, would it hit Y?'")


VIDEO_PARTS = (["early", "in"], ["late", "in"], ["later", "in"], ["halfway"], ["midway"], ["in", "the", "middle"])
END_OR_PARTS = (*END_TIMES, *VIDEO_PARTS)
PART_ORDINALS = {"first", "last", "final", "next", "second", "latter"}
PART_NOUNS = {"half", "part", "few", "moments", "moment"}


def time_symbol_said(words: list[str]) -> str:
    """Why the question (its words as written) cannot be read ('' when it can): it asks at a time named by a symbol
    ('at t_c', 'for t > T_cut', 'at t*'), which the rules would drop as a decoration or a remark and the decoder
    read at the start or in the video; 't = 0', 't0' and 't_0' are the start, which the parser reads."""
    symbol = next((f"t {b}" for k, (a, b) in enumerate(zip(words, words[1:])) if a == "t" and (
        b in ("*", ">", "<", "'") or b == "_" and words[k + 2:k + 3] not in (["0"], ["start"]))), None)
    if symbol is None:
        return ""
    return (f"the question asks at a time named by a symbol ('{symbol}'), which no question here reads: say it in "
            "words ('at the start', 'when the red car hits the bus', 'after the video ends')")


def pointed_back(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question says what it asks first and points back at
    it with 'that' ('Slowly, right as the video begins, is that how the motorbike is moving?', read as which speed;
    'Faster than the motorbike, ..., is that what the blue bicycle is?' and 'Collide with the green mountain bike:
    would the red motorbike do that, ...?', read with the vehicles turned round)."""
    # (as yes or no, 'Hovering in the air at the start: is that what the green plane is doing?' reads right; read
    # as which, or as a comparison, it may not; 'did that purple SUV ...' points at a vehicle)
    turned = program[-1:] and (program[-1].startswith("query") or program[-1] in ("faster_velocity", "slower_velocity"))
    said = next((" ".join(words[k:k + 3]) for k in range(1, len(words) - 2) if words[k] in ("is", "was") and
                 words[k + 1] == "that" and words[k + 2] in ("how", "what")), None) if turned else None
    # ('what color does that object have', 'what shape does that floating object have': 'that' before a noun)
    said = said or next((f"{words[k]} {words[k + 1]}" for k in range(len(words) - 1)
                         if words[k] in ("do", "does", "did") and words[k + 1] in ("that", "so")
                         and not (NAMING | GENERIC_NOUNS).intersection(words[k + 2:k + 4] if words[k + 1] == "that"
                                                                       else [])), None)
    return (f"the question points back at what it said first ('{said}'): ask it in one clause, without 'that'"
            ) if program and said else ""


def _compared(program: list[str]) -> list[tuple[str, ...]]:
    """A speed comparison's two vehicles in the order compared, each as the filter tokens that name it."""
    refs, run = [], []
    for t in program:
        if t.startswith("filter_attributes["):
            run.append(t)
        elif t == "unique" and run:
            if tuple(run) not in refs:
                refs.append(tuple(run))
            run = []
        elif t != "Objects":
            run = []
    return refs


def _said_after_than(words: list[str]) -> tuple[str, ...] | None:
    """The values of the vehicle said just after 'than' ('than the brown bendy bus' -> ('brown',))."""
    k = words.index("than")
    return next((ref for i, _, ref in mentions(words) if k < i <= k + 2), None)


def than_turned(words: list[str], program: list[str]) -> str:
    """Why a comparison's reading is not the question's ('' when it is): the vehicle said after 'than' is read as the
    one compared ('When yellow bus hit purple articulated bus, its speed lower than purple articulated bus or not?'
    was read as whether the purple bus is slower: 'its' taken for the vehicle it is compared with). `words`: as
    said, before any rule read a pronoun as a vehicle."""
    if not program or program[-1] not in SPEED_COMPARISONS or "than" not in words:
        return ""
    after, refs = _said_after_than(words), _compared(program)
    values = [tuple(t[len("filter_attributes["):-1] for t in ref) for ref in refs]
    turned = after is not None and bool(values) and generalises(after, values[0]) and not any(
        generalises(after, v) for v in values[1:])
    return ("the question compares a vehicle with the one its reading compares: ask whether X is faster (or slower) "
            "than Y, naming X") if turned else ""


def than_as_said(words: list[str], program: list[str] | None) -> list[str] | None:
    """A comparison of two vehicles read turned round (`than_turned`) as the question says it: the vehicle after
    'than' is the one compared with ('When the gray bus hits the blue SUV, is this guy faster than the SUV?', Welsh
    English's 'Quicker than the yellow double-decker it's going, the blue SUV, is it?'). None where it is not so
    read, or where more than two vehicles are named."""
    if not program or not than_turned(words, program) or len(refs := _compared(program)) != 2:
        return None
    swap = {refs[0]: refs[1], refs[1]: refs[0]}
    out, i = [], 0
    while i < len(program):
        ref = next((r for r in refs if tuple(program[i:i + len(r)]) == r and (i + len(r) == len(program) or not
                    program[i + len(r)].startswith("filter_attributes["))), None)
        if ref is None:
            out.append(program[i])
            i += 1
        else:
            out.extend(swap[ref])
            i += len(ref)
    return out


SLOW_SAID = {"slow", "slowly", "low", "slower", "sluggish", "sluggishly", "crawl", "crawling", "leisurely", "gently"}
FAST_SAID = {"fast", "quick", "quickly", "high", "rapid", "rapidly", "speedy", "speedily", "faster", "swift",
             "swiftly", "zooming", "racing", "full", "top", "flat"}


def speed_class_turned(words: list[str], program: list[str]) -> str:
    """Why a reading of a speed class is not the question's ('' when it is): the question says only the other class
    ('If articulated bus when video begins at low speed had been moving, ...' was read as had it been fast)."""
    read = next((c for op in program for c in ("fast", "slow") if op.startswith(("Counterfactual_moving_", "is_moving",
                                                                              "filter_moving")) and op.endswith(
        (f"_{c}", f"[{c}]"))), None)
    said = {"fast": bool(FAST_SAID.intersection(words)), "slow": bool(SLOW_SAID.intersection(words))}
    if read is None or said[read] or not said["slow" if read == "fast" else "fast"]:
        return ""
    return (f"the question says a speed, but its nearest reading asks the other ('{read}'): ask whether the vehicle is "
            "slow or fast in the grammar's words")


def class_asked_as_which(words: list[str], program: list[str]) -> str:
    """Why a reading of which speed is not the question's ('' when it is): the question asks whether the vehicle
    moves at one speed, saying no word that asks which ('Blue articulated bus when into tandem bike bumps, slow it
    was moving?' was read as how fast)."""
    if not program or program[-1] != "query_moving_velocity" or "or" in words or {
            "how", "what", "which", "speed", "velocity", "pace", "tell", "describe", "classify"} & set(words):
        return ""
    classes = {"slow": "slow", "slowly": "slow", "fast": "fast", "quickly": "fast", "static": "static",
               "stationary": "static", "still": "static", "parked": "static"}
    said = [w for w in words if w in classes]
    # (two classes said are choices offered, their 'or' perhaps read away: 'sitting still, pottering along slow')
    return (f"the question asks whether the vehicle is '{said[0]}', but its nearest reading asks which speed: ask "
            "whether it is static, slow or fast") if len({classes[w] for w in said}) == 1 else ""


def start_speed_at_collision(words: list[str], program: list[str]) -> str:
    """Why a reading of a speed at a collision is not the question's ('' when it is): the speed is said of the start
    ('Green pickup starting slow: hits red motorbike?', a premise or a condition, was read as slow at the
    collision)."""
    if "get_frame" not in program or not any(op.startswith(("is_moving_velocity", "is_static")) for op in program):
        return ""
    said = next((f"{a} {b}" for a, b in zip(words, words[1:]) if a in ("start", "starting", "started") and
                 (b in SPEED_CLASS_WORDS or b in STATIC_SAID)), None)
    return (f"the question says a speed at the start ('{said}'), but its nearest reading asks it at a collision: ask "
            "'if X had been ... from the start, would it hit Y?' or how fast X is when it hits Y") if said else ""


# a clause of a collision's time: its conjunction, then an impact's words before the clause ends
_COLLISION_CLAUSE = CLAUSE_CONJUNCTIONS | {"as", "moment", "instant"}   # ('rest on the moment they collide; is ...')
_CLAUSE_ENDS = {",", "?", ".", "!", ":", ";", "is", "was", "are", "were", "does", "did", "will", "would", "what",
                "which", "how"}


def collision_time_dropped(said: list[str], program: list[str]) -> str:
    """Why a reading at the start is not the question's ('' when it is): the question, as said (`said`: before any
    rule read it), asks at a collision in a clause that a rule read away ('gyatt when the blue bicycle smashes into
    the green airliner is it going fast?' lost its clause as context after an unknown first word, and was read at the
    start)."""
    if "start" not in program or START_WORDS.intersection(said):
        return ""
    for k, w in enumerate(said):
        if w not in _COLLISION_CLAUSE or w == "as" and said[k + 1:k + 2] not in (["they"], ["it"], ["the"]):
            continue
        end = next((j for j in range(k + 1, len(said)) if said[j] in _CLAUSE_ENDS), len(said))
        if asks_impact(said[k + 1:end]):
            return (f"the question asks at a collision ('{' '.join(said[k:end])}'), but its nearest reading asks at "
                    "the start: ask 'when X hits Y, is X ...'")
    return ""


def moment_unread(said: list[str], program: list[str]) -> str:
    """Why a reading at the start is not the question's ('' when it is): the question, as the rules left it, asks at
    the moment of something it says in words no rule read ('At the moment of the 10-50, was the utility bike running
    faster ...?', a dispatcher's collision, was read at the start), or at a moment said before ('X hits Y ; in that
    tense moment , ...')."""
    if "start" not in program or START_WORDS.intersection(said):
        return ""
    moment = next((" ".join(said[k - 1:k + 4]) for k in range(1, len(said) - 1) if said[k] in (
        "moment", "instant", "time", "point") and said[k - 1] == "the" and said[k + 1] == "of"), None) or next(
        # ... or at a moment said before, that no rule read ('X hits Y ; in that tense moment , ...')
        (" ".join(said[k - 2:k + 1]) for k in range(2, len(said)) if said[k] in ("moment", "instant")
         and {"that", "this"} & set(said[k - 2:k])), None)
    if moment is None:
        return ""
    return (f"the question asks at a moment ('{moment}'), but its nearest reading asks at the start: ask 'at the start' "
            "or 'when X hits Y'")


def heading_unread(said: list[str], program: list[str]) -> str:
    """Why a reading within the video is not the question's ('' when it is): the question opens on a 'post-'
    heading no rule read ('Post-trial, do we expect contact ...?' was read within the video)."""
    if any(t.startswith("future") for t in program) or said[:1] != ["post"]:
        return ""
    heading = " ".join(said[:3] if said[1:2] == ["-"] else said[:2])
    return (f"the question opens on '{heading}', which the parser does not read: ask 'after the video ends, ...' or "
            "'in the video, ...'")


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
        clock = " ".join(at[1]) if (at := _at(words, END_OR_PARTS)) else next(
            (f"{a} {b}" for a, b in zip(words, words[1:]) if a in PART_ORDINALS and b in CLOCK_WORDS | PART_NOUNS),
            None)
    if clock is None:
        return ""
    return (f"the question asks within a time ('{clock}'), which no question here asks: collisions are asked over the "
            "whole video, or after it")


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


THAN_SKIPPED = {"any", "the", "a", "an", "all", "every", "for", "of", "that", "this", "those"}
THAN_REFERRING = {"latter", "former", "other", "others", "rest"}


def compared_with_no_vehicle(words: list[str], program: list[str], known: set[str]) -> str:
    """Why a reading comparing two vehicles' speeds is not the question's ('' when it is): every speed said compared
    is compared with something the parser does not know ('... moving fast? Faster than any ice, surely.' was read as
    the minivan faster than the pickup)."""
    if not program or operation(program[-1]) not in SPEED_COMPARISONS:
        return ""
    compared = [next((w for w in words[k + 1:k + 4] if w not in THAN_SKIPPED), "") for k, w in enumerate(words)
                if w == "than"]
    odd = [w for w in compared if w.isalpha() and w not in known | OBJECT_WORDS | THAN_REFERRING]
    if not odd or len(odd) < len(compared):
        return ""
    return (f"the question compares a speed with '{odd[0]}', which is no vehicle here (questions compare two "
            "vehicles' speeds)")


PACE_WORDS = {"fast", "quick", "quickly", "slow", "slowly", "rapid", "rapidly", "speedy"}
GETTING = {"getting", "gets", "got", "get", "going", "becoming", "becomes", "became", "growing", "and"}


def comparison_unread(words: list[str], program: list[str]) -> str:
    """Why a reading of one vehicle's speed is not the question's ('' when it is): the question compares ('is the
    car moving more slowly when it and the bus collide?' was read as whether it is slow), but the reading compares
    nothing. Not a speed that changes ('getting faster', 'faster and faster')."""
    if not program or not program[-1].startswith(("is_moving_velocity", "query_moving_velocity", "is_static")):
        return ""
    said = next((w for k, w in enumerate(words) if w in COMPARED_SAID and words[k - 1:k] != [] and
                 words[k - 1] not in GETTING and words[k + 1:k + 2] != ["and"] or
                 w in ("more", "less") and words[k + 1:k + 2] and words[k + 1] in PACE_SIGN
                 and (not k or words[k - 1] not in GETTING)), None)
    if said is None:
        return ""
    return (f"the question compares speeds ('{said}'), but its nearest reading asks one vehicle's: ask whether it is "
            "faster (or slower) than the other")


# the words that say a question imagines its video otherwise (a label, an opener or 'instead')
# a story told again otherwise ('You rewrite the scene so ...', 'an alternate take'), never the video going on
REWRITING = {"rewrite", "rewrites", "rewriting", "rewritten", "reimagine", "reimagined", "reimagining", "alternate"}
IMAGINING_SAID = {"imagine", "imagining", "suppose", "supposing", "pretend", "hypothetically", "hypothetical",
                  "counterfactual", "counterfactually", "instead", "cf", "what-if", "whatif", "assumption",
                  "supposition",
                  *REWRITING}


HELD_STATES = SPEED_CLASS_WORDS | STATIC_SAID | FLOATING_WORDS | {"moving", "hover", "float", "accelerate",
                                                                   "accelerating", "speeding", "engine", "standing"}
START_MOMENTS = {"instant", "moment", "frame", "frames", "second", "seconds", "go", "off"}


def _from_start(after: list[str]) -> bool:
    """Whether the words after 'from' say the start ('the start', 'the very first instant', 'the initial frame')."""
    said = after[:4]
    said = said[:next((j for j, w in enumerate(said) if w in CLAUSE_MARKS), len(said))]
    return bool(START_WORDS & set(said) or START_ADJECTIVES & set(said) and START_MOMENTS & set(said))


def _state_from_start(words: list[str]) -> str | None:
    """A state held from the start said of a vehicle, as a condition without 'if' ('double decker not moving from
    beginning will it still collide blue cruiser', 'private jet hover from beginning do it still hit purple bus', a
    physicist's 'the school bus speeding up, engine on, from the very first instant. Under that assumption, ...')."""
    def around(k: int) -> list[str]:   # its clause, up to 8 words either side ('in place from the start, standing
        start = max((j + 1 for j in range(max(k - 8, 0), k) if words[j] in SENTENCE_ENDS | {":"}), default=0)
        end = next((j for j in range(k, min(k + 9, len(words))) if words[j] in SENTENCE_ENDS | {":"}), k + 9)
        return words[max(start, k - 8):end]   # still')
    return next((" ".join(words[k - 1:k + 2]) for k in range(1, len(words) - 1) if words[k] in ("from", "since")
                 and _from_start(words[k + 1:]) and HELD_STATES.intersection(around(k))), None)


# 'would' of a description asked, not of a change ('would the cyan car be described as static, slow or fast?', 'would
# it be accurate to say ...')
DESCRIBED = {"described", "considered", "classed", "classified", "characterised", "characterized", "called",
             "labelled", "labeled", "regarded", "deemed", "categorised", "categorized", "accurate", "correct", "fair",
             "true", "right"}


def _would_describe(after: list[str]) -> bool:
    return any(w == "be" and after[j + 1:j + 2] and after[j + 1] in DESCRIBED for j, w in enumerate(after))


def imagining_unread(words: list[str], program: list[str], said_first: list[str] = ()) -> str:
    """Why a reading of what happened is not the question's ('' when it is): the question imagines otherwise ('brown
    motorbike starting slow instead, it hits the gray car?', 'cf: gray one starts slow instead -> ...' were read as
    whether it is slow at the collision), and no counterfactual was read. Only a reading about collisions, as every
    counterfactual is ('Picture this: ... is it crawling at the start?' imagines nothing), and not of the future
    ('suppose the clip went on for longer')."""
    if any(t.startswith("Counterfactual") for t in program) or "filter_collision" not in program:
        return ""
    # (a story told again is read in the words as first said too: its sentence may have been read as context)
    told = next((w for w in [*words, *said_first] if w in REWRITING), None)
    if "futureEvents" in program:
        said = told or _state_from_start(words) or _state_from_start(list(said_first))
        # ... or a 'would have' that says no condition and no time after the video ('Would the red car have hit the
        # bus anyway?' was read as after the video)
        had = next(("would ... have" for k, w in enumerate(words) if w == "would" and "have" in words[k + 1:k + 6]),
                   None)
        if said is None and had and not (FUTURE_CUES - {"would"} | CONDITION_MARKERS | {"unless", "were"}
                                          ).intersection([*words, *said_first]):
            said = had
        return "" if said is None else (f"the question imagines the video otherwise ('{said}'), but its nearest "
                                        "reading asks what happens after it: ask as 'if X had been ... from the "
                                        "start, would it hit Y?'")
    # (a label said first, however the rules read the words after it: a surgeon's 'Counterfactual, team. Yellow plane
    # starts out fast: does it hit the city bus?' was read as how fast it is at the collision)
    said = told or next((w for w in words if w in IMAGINING_SAID | IMAGINING_LABELS), None) or \
        next((w for w in said_first if w in IMAGINING_LABELS), None) or \
        next(("what if" for a, b in zip(words, words[1:]) if (a, b) == ("what", "if")), None) or \
        next(("would" for k, w in enumerate(words) if w == "would" and words[k + 1:k + 2] != ["you"]
              and not _would_describe(words[k + 1:k + 6])), None) or next(
        # 'the engine is on from the very start. Would the SUV hit the bike?'
        # a state said straight after 'if' ('Tandem bike at beginning if moving slow, with purple car can collide?')
        (f"if {' '.join(words[k + 1:k + 3])}" for k, w in enumerate(words) if w == "if" and
         (SPEED_CLASS_WORDS | STATIC_SAID | FLOATING_WORDS).intersection(words[k + 1:k + 3])), None) or \
        _state_from_start(words) or _state_from_start(list(said_first))
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
    said = next((w for w in words if w in AFLOAT_WORDS), None) or next((
        "up in the air" for k in range(len(words)) if words[k:k + 3] == ["in", "the", "air"] and (
            words[k - 1:k] == ["up"] or words[k + 3:k + 4] in ([], ["?"]))), None)   # (its speed read from 'gently')
    if said is None or FLOATING_OPERATIONS.intersection(map(operation, program)):
        return ""
    return (f"the question says '{said}', but its nearest reading reads no floating: ask whether the vehicle is "
            "floating, or what it would have hit had it floated")


# 'getting faster', 'faster and faster': accelerating, an intervention
BECOMING = {"getting", "get", "gets", "got", "grow", "grows", "growing", "grew", "become", "becomes", "becoming",
            "became", "and"}
WHO = {"who", "whom", "whose"}


def form_unmatched(words: list[str], program: list[str]) -> str:
    """Why a reading answers in another form than the question asks for ('' when it does not): a yes/no question
    (its head after a clause of time said first) read as asking which ('does the red car change direction?' read as
    which way it moves; but 'is it static, slow or fast?' offers its answers). The other way round is
    `form_unasked`'s."""
    head = _head(words)
    returns = OPS[operation(program[-1])].output
    # a question word left where the answer goes ('... gets hit afterwards by what?'): no yes or no
    # (not a tag: '... at the start or what?')
    echo = words[-2] if words[-1:] == ["?"] and words[-2:-1] and words[-2] in ("what", "which", "who", "whom") and \
        words[-3:-2] not in (["or"], ["o"], [","]) else None
    if echo and returns is not str:
        return (f"the question asks '{echo}', but its nearest reading asks yes or no: no question here reads it")
    if head[:1] and head[0] in YES_NO_OPENERS and returns is str and "or" not in head:
        return ("the question asks yes or no, but its nearest reading asks which (a speed, a direction, a colour or a "
                "type): no question here asks it as yes or no")
    # 'what type of aeroplane is it at the start?' read as its direction: a type or colour asked is no motion
    kind = head[1] if head[:1] in (["what"], ["which"]) and head[1:2] and head[1] in ATTRIBUTE_NOUNS else None
    if kind and head[2:4] not in (["of", m] for m in ("speed", "motion", "movement", "pace")) and \
            operation(program[-1]) in ("query_moving_velocity", "query_moving_direction"):
        return (f"the question asks the {kind}, but its nearest reading asks a speed or a direction: no question here "
                "reads it")
    # '..., zzq colour is it' read as whether the plane floats: a colour or type asked of 'it' is no yes or no
    asked = next((a for a, b, c in zip(words, words[1:], words[2:]) if a in ATTRIBUTE_NOUNS and b in ("is", "was")
                  and c in ("it", "that", "this", "they")), None)
    if asked and returns is not str and "or" not in words:
        return (f"the question asks the {asked}, but its nearest reading asks yes or no: no question here reads "
                "it")
    # 'after the video ends , which vehicle will the green car run into ?' read as whether it hits anything (also
    # '..., with which vehicle will ...')
    at = next((j for j in range(len(words) - 1) if words[j] in ("which", "what") and (
        j == 0 or words[j - 1] == "," or words[j - 1] in ("with", "into") and (j == 1 or words[j - 2] == ","))
        and (words[j + 1] in OBJECT_WORDS or words[j + 1] in GENERIC_NOUNS)), None)
    # ('which one is faster , is it the sedan ?' asks whether the sedan is; 'when they collide , which one is
    # faster ?' was read as whether the first is)
    named = at is not None and any(words[m:m + 2] in (["is", "it"], ["was", "it"], ["is", "that"])
                                   for m in range(at + 2, len(words)))
    if at is not None and returns is not str and not (
            named and {"faster_velocity", "slower_velocity"} & set(map(operation, program))):
        return f"the question asks which {words[at + 1]}, but its nearest reading asks yes or no: no question here " \
            "reads it"
    # 'which vehicle hits the bus first?' read as the bus's direction: a vehicle asked for is its colour or type
    if head[:1] == ["which"] and head[1:2] and (head[1] in OBJECT_WORDS or head[1] in GENERIC_NOUNS) and \
            operation(program[-1]) in ("query_moving_velocity", "query_moving_direction"):
        return (f"the question asks which {head[1]}, but its nearest reading asks a speed or a direction: ask for the "
                "colour or the type of the vehicle")
    return ""


def answer_form_unmatched(read_as: tuple[tuple[str, str], ...], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question gives yes or no as its answer's form ('State
    @ start = not moving? (y/n)'), and its nearest reading asks which."""
    # (or a yes-or-no tag: a learner's 'fast he is going or not?'; or an instruction: '... = fast? yes or no.')
    yes_or_no = any(why == "nothing, an answer's form" or said.strip(" ,?") in ("or not", "or no", "or nah") and
                    why == "?" or (why.startswith("nothing") or why == "?") and {"yes", "no"} <= set(said.split())
                    for said, why in read_as)
    if yes_or_no and OPS[operation(program[-1])].output is str:
        return ("the question asks yes or no (its answer's form), but its nearest reading asks which (a speed, a "
                "direction, a colour or a type)")
    return ""


COLLISION_OPERATIONS = {"filter_collision", "get_all_col_partners"}
# besides IMPACT_STEMS, the words a collision is said with: 'run into', 'drive into', 'each other'
IMPACT_SAID = {"into", "onto", "run", "runs", "ran", "running", "other", "another"}


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


def speed_unsaid(words: list[str], program: list[str]) -> str:
    """Why a reading of a speed class is not the question's ('' when it is): the question, as read, says no speed
    ('is the bus driving at the start?' asks whether it moves at all, which the decoder read as slow)."""
    if not SPEED_CLASS_OPERATIONS.intersection(map(operation, program)) or SPEED_CLASS_WORDS.intersection(words):
        return ""
    return ("the question says no speed (slow or fast), but its nearest reading asks about one: ask whether the "
            "vehicle is static, slow or fast")


FLOATING_OPERATIONS = {"is_floating", "filter_floating", "Counterfactual_floating"}


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


def motion_unread(words: list[str], program: list[str]) -> str:
    """Why a reading of collisions alone is not the question's ('' when it is): the question describes a vehicle by its
    motion ('does it crash into a stationary vehicle?', 'is it hit by a floating plane?', read as whether it crashes at
    all), which no program reads beside a collision."""
    if not COLLISION_OPERATIONS.intersection(map(operation, program)) or \
            any(part in t for t in program for part in MOTION_READ):
        return ""
    # (not the video's: 'after the point where the video is stopped')
    said = next((w for k, w in enumerate(words) if w in MOTION_DESCRIPTIONS
                 and not FILM_WORDS & set(words[max(k - 2, 0):k])), None)
    if said is None:
        return ""
    return (f"the question describes a vehicle by its motion ('{said}'), which no question here reads beside a "
            "collision")


STATIC_OPERATIONS = {"is_static", "filter_static", "Counterfactual_static"}


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
                 and (words[k - 1:k] in (["the"], ["that"], ["this"])
                      # ... or an indefinite one, not said of the vehicle itself ('is it a slow one?', 'is the bus
                      # a stationary one?')
                      or words[k - 1:k] in (["a"], ["an"], ["any"], ["another"], ["some"]) and words[k - 2:k - 1]
                      and words[k - 2] not in {"is", "was", "be", "s", "are", "were", "it"} | OBJECT_WORDS)
                 for j in (k + 2, k + 1) if words[j:j + 1] and words[j] in OBJECT_WORDS | GENERIC_NOUNS
                 and all(x in OBJECT_WORDS for x in words[k + 1:j])
                 and not (words[k - 1] in ("a", "an", "any", "another", "some") and words[j] == "one")), None)
    if said is None:
        return ""
    return f"the question picks a vehicle by its motion ('{said}'), which no question here does so"


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
SPEED_SIZED = {"bigger", "smaller", "larger"}   # ... which a speed can be said to be


def size_unread(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question compares or asks a size ('is the red car
    greater in size than the blue bus?' was read as faster), which no question here asks."""
    # not 'a smaller speed', 'its speed smaller than', 'the magnitude of its velocity smaller than'
    said = next((w for k, w in enumerate(words) if w in SIZES and words[k + 1:k + 2] not in (["speed"], ["velocity"])
                 and not (w in SPEED_SIZED and {"speed", "velocity"} & set(words[max(k - 3, 0):k]))), None)
    return (f"the question asks about a size ('{said}'), which no question here asks (they ask speed classes, "
            "directions, colours, types and collisions)") if said else ""


ADDRESSED = {"you", "u", "ya", "y"}      # 'will you tell me ...': a request, not the future
FORETOLD_VERBS = {"speed", "accelerate", "be", "move", "stop", "stay", "keep", "slow", "go", "get", "start", "float",
                  "hover", "fly", "gain", "pick", "drive", "remain", "come", "land", "fall", "turn", "head"}


def motion_foretold(words: list[str], program: list[str]) -> str:
    """Why a reading of the video's own time is not the question's ('' when it is): it asks what a vehicle will do
    ('Will the purple chopper speed up?', 'Is the bus going to stop?'), which no family asks but of collisions (the
    grammar says the future only there)."""
    if any(t in ("Events", "futureEvents") or t.startswith("Counterfactual") for t in program):
        return ""
    if START_WORDS.intersection(words):   # 'which way was it fixing to go at the very start?'
        return ""
    said = next((w for k, w in enumerate(words) if w == "will" and words[k + 1:k + 2]
                 and words[k + 1] not in ADDRESSED), None) or next(
        (" ".join(words[k:k + 3]) for k in range(len(words) - 2)
         if words[k:k + 2] == ["going", "to"] and words[k + 2] in FORETOLD_VERBS), None)
    return (f"the question asks what a vehicle will do ('{said}'), which no question here asks (they ask how it moves "
            "in the video, and whether it will collide)") if said else ""


def acceleration_unsaid(words: list[str], program: list[str]) -> str:
    """Why a reading of accelerating is not the question's ('' when it is): the question says nothing of speeding up
    ('which colour level corresponds to the vehicle whose initial speed is recorded as slow?' was read as the colour
    of what accelerates)."""
    if not {"is_accelerating", "filter_accelerating", "Counterfactual_accelerating"} & set(map(operation, program)) or \
            any(w.startswith("accelerat") for w in words) or SPEEDING_UP & set(words) or \
            any(a == c and a.endswith("er") and b == "and" for a, b, c in zip(words, words[1:], words[2:])) or \
            any(words[k:k + 3] in (["speed", "going", "up"], ["speed", "-", "up"]) or words[k:k + 2] == ["speed", "up"]
                for k in range(len(words))) or \
            any(words[k:k + len(a)] == list(a) for k in range(len(words)) for a in ACCELERATION_SAID) or \
            any(_slip_of_speeding_up(w) for w in words):
        return ""
    return ("the question says nothing of speeding up, but its nearest reading asks about it: ask whether the vehicle "
            "is accelerating")


def _slip_of_speeding_up(word: str) -> bool:
    """Whether a word may be a long word of speeding up slipped ('ganing', 'acelerating'), which the decoder reads."""
    return len(word) >= 5 and word not in SPEEDING_UP and any(
        SequenceMatcher(None, word, s).ratio() >= 0.85 for s in SPEEDING_UP | {"accelerating", "accelerate"}
        if len(s) >= 6)


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


def attribute_unsaid(said: list[str], read: list[str], program: list[str]) -> str:
    """Why a reading of a colour or a type is not the question's ('' when it is): the question names no attribute
    ('what does the red car hit?', 'name the vehicle that ...' ask which vehicle, and were read as its colour)."""
    if not program[-1].startswith("query_attributes") or ATTRIBUTE_SAID.intersection(said + read):
        return ""
    return ("the question asks which vehicle, which no question here answers but by its colour or its type: ask what "
            "colour (or type) it is")


def own_attribute_asked(said: list[str], program: list[str]) -> str:
    """Why a reading of a partner's colour or type is not the question's ('' when it is): the vehicle whose colour is
    asked is named, and it does the hitting ('what colour is the scooter that does the bumping?' asks the scooter's
    own, and was read as its partner's; 'what colour is the car that hit the bus?' names the partner)."""
    if "get_all_col_partners" not in program or not program[-1].startswith("query_attributes"):
        return ""
    for k in range(len(said) - 3):
        if said[k:k + 2] not in (["is", "the"], ["was", "the"]):
            continue
        j = k + 2
        while said[j:j + 1] and said[j] in OBJECT_WORDS:
            j += 1
        if j > k + 2 and said[j:j + 1] in (["that"], ["which"]) and said[j + 1:j + 2] and \
                said[j + 1] not in DETERMINERS | {"it", "they", "he", "she"} and not OBJECT_WORDS & set(said[j:]):
            return ("the question asks the colour or type of a vehicle it names, which it answers itself: ask what "
                    "colour (or type) the vehicle it hits is")
    return ""


def what_happens(words: list[str], program: list[str]) -> str:
    """Why a reading is not the question's ('' when it is): the question (`words`: typos fixed) asks what a vehicle
    does ('what is the red car doing at the start?' was read as its speed), or what happens and asks no question
    after it ('what would happen if it were static?' was read as whether it is). What it does among speeds offered
    asks its speed ('what's the scooter doing at the start, parked, crawling or booking it?')."""
    head = _head(words)
    speeds_offered = "or" in words and len({"static", "slow", "fast"}.intersection(words)) >= 2
    if head[:1] == ["what"] and head[1:2] and head[1] in AUXILIARIES | {"will", "would"} and (
            "doing" in head or "do" in head[2:]) and not speeds_offered:   # not 'what speed is it doing'
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


def _future_said(words: list[str]) -> str:
    """The words that say the time after the video ('after the video', 'in the future'), or ''."""
    return next((" ".join(words[k:k + len(f) + (f[0] == "after")]) for k in range(len(words)) for f in FUTURE_SAID
                 if words[k:k + len(f)] == f and (f[0] != "after" or words[k + 2:k + 3] and
                                                  words[k + 2] in FILM_WORDS)), "")


# words of a stop's phrases ('cut off', 'has stopped', 'ended early') that say nothing of it alone ('at any point in
# the session' was read after the video: its 'in' was taken for a stop's); 'the frames still to come' says the future
_WEAK_STOP_CUES = {"in", "has", "been", "were", "out", "off", "between", "early", "short"}


def future_unread(words: list[str], program: list[str], context: list[str] = ()) -> str:
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
    # ('over' as a preposition says no end: 'over the whole recorded history of the clip, first moment to last')
    cues = FUTURE_CUES.intersection(w for w, nxt in zip(words, [*words[1:], ""])
                                    if not (w == "over" and nxt in DETERMINERS | {"its", "their", "this"}))
    if "futureEvents" in program and within and not cues:
        return (f"the question asks about the video ('{within}'), but its nearest reading asks after it: ask whether "
                "it collides in the video")
    # 'can we get clarity on whether the pickup and the purple thing bump into each other?' read after the video
    # (nor in the sentences read as its context: 'The clip's been cut short. Is the jet headed for a crash ...?')
    if "futureEvents" in program and not (FUTURE_CUES | STOP_CUES - _WEAK_STOP_CUES).intersection(
            [*words, *context]) and not any(words[k:k + 2] == ["to", "come"] for k in range(len(words))):
        return ("the question says nothing of the time after the video, but its nearest reading asks after it: ask "
                "whether they collide in the video, or will after it ends")
    if "Events" not in program or "futureEvents" in program:
        return ""
    said = _future_said(words)
    if not said:
        return ""
    return (f"the question asks about the time after the video ('{said}'), but its nearest reading asks about the "
            "video: no question here reads it")


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


# The video said to stop before what is asked ('The clip's been cut short. Is the jet headed for a crash with the
# bus?', 'The video ends before we find out: does ...?', 'We only get the first bit of the video.'): a collision asked
# in the present is one after the cut
CUT_SAID = (*STOPPED_SAID, ["stops", "short"], ["runs", "out"], ["ran", "out"], ["ends", "before"],
            ["ended", "before"])
FIRST_PART = {"bit", "part", "half", "stretch", "portion", "section", "chunk", "few"}
PAST_ASKED = {"did", "was", "were", "had", "has"}


def cut_said(said_first: list[str], words: list[str]) -> str:
    """The words of `said_first` (the question as written) that say the video stops before what is asked, where the
    question (`words`, as read) asks in the present or the future; '' where none do."""
    if PAST_ASKED.intersection(words):
        return ""
    for k, w in enumerate(said_first):
        if w not in FILM_WORDS:
            continue
        if k and said_first[k - 1] in ("paused", "stopped", "frozen", "truncated", "halted"):   # 'the paused video'
            return f"{said_first[k - 1]} {w}"
        after = said_first[k + 1:k + 6]
        # (not a telegram's 'STOP' that ends the text: '... during the film STOP')
        stop = next((" ".join(after[:j + len(c)]) for j in range(len(after)) for c in CUT_SAID
                     if after[j:j + len(c)] == c and not set(after[:j]) & {",", ".", "?", ":", "-"} and
                     set(said_first[k + 1 + j + len(c):]) - {"?", ".", "!"}), None)
        if stop:
            return f"{w} {stop}"
        before = said_first[max(0, k - 6):k]
        if "first" in before and FIRST_PART.intersection(before) and ("only" in said_first or "half" in before):
            return " ".join(before[before.index("first"):]) + f" {w}"
    return ""


def both_imagined(words: list[str], program: list[str]) -> str:
    """Why a counterfactual reading is not the question's ('' when it is): its condition changes two vehicles at once
    ('if both of them had been standing still', 'had they both been parked'), which no question here does."""
    if not any(t.startswith("Counterfactual") for t in program):
        return ""
    said = next((" ".join(words[k:k + 4]) for k, w in enumerate(words) if w in CONDITION_MARKERS and
                 {"both", "each", "all"} & set(words[k + 1:k + 4])), None)
    return "" if said is None else (f"the question changes several vehicles at once ('{said}'), which no question "
                                    "here does: a counterfactual changes one")
