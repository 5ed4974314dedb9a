"""Questions no family asks, found from their words before decoding: `QuestionParser._words` refuses them with a
one-line reason, however near a family's their words are, rather than let the decoder read them as the nearest family's.

`_words` refuses some itself (the sets it reads for them are here, or in words.py where others read them too): a count
('how many', 'two vehicles'), how long, how often ('twice': REPEATS), a height ('higher': HEIGHT_COMPARISONS), a
direction towards another vehicle (TOWARD, `_at_viewer`), speeds offered to choose from, a size or a material (CLEVR's),
what ought to happen (NORMATIVE), a cause (CAUSES, CAUSING), which event came first, 'how' with a word no family asks
('how hard does it hit': HOW_ASKED), and a vehicle the catalogue lacks where a question names one ('does the zamboni hit
...': `_unknown_vehicle`). The rules here refuse a property no question asks (`unknown_property`: a word at the
question's head the parser does not know, a place or a size, the time before or after a collision, the second or last of
its partners, a turn or a spin, a vehicle's pose, a landing, a path's shape, a take-off, a near miss, one vehicle
chasing or passing another, a loss of control, the order in which vehicles appear, a collision with scenery ('the
wall'), the video's end); a speed as a number ('20 mph': `speed_measured`), a vehicle ranked among all ('the fastest',
'the first vehicle to collide': `ranking`), two speeds alike ('as quick as the bus': `speeds_alike`), two kinds of
motion, two times or two questions at once (`properties_joined`, `times_joined`, `questions_joined`), whether a
collision could happen (`possibility_asked`), a vehicle described by its motion's beginning or end (`onset_asked`),
several vehicles' colours or types (`several_asked`), all or every vehicle at once (`quantified`), a premise
(`premised`), a vehicle described through another described one (`chained`), an order of collisions ('what does it hit
next': `ordered`), a collision said not to happen ('passed without touching': `impact_denied`), a measure of speed or a
comparison's degree (`speed_measure`), a colour checked (`checked_attribute`), a counterfactual no intervention makes
(`imagined_otherwise`), some other comparison or manner (`otherwise_compared`), and a reversal the words standing in for
unknown ones would hide ('decelerating', refused as said before WordNet reads it as 'slow': `reversed_as_said`)."""

from __future__ import annotations

import re

from dynclevr.colors import COLOR_NAMES
from dynclevr.language.references import OBJECT_WORDS
from dynclevr.language.times import FILM_WORDS, _video_end
from dynclevr.language.words import (ACCELERATION_SAID, ASKING, ASKING_FOR, ATTRIBUTE_SAID, AUXILIARIES, CLASS_NOUNS,
                                     COMES_IN_WORDS, COMPARISONS, CONDITION_OPENERS, COPULAS, DEFINITE, DETERMINERS,
                                     END_TIMES, ENGINE_WORDS, GENERIC_NOUNS, IMAGINED_BACK, IMAGINED_SAID, IMAGINING,
                                     IMPACT_STEMS, INDEFINITES, LANDING, LATER_TIMES, MOTION_KINDS, MOTION_WORDS,
                                     NEGATIONS, NOUNS_SAID, NUMBERS, OTHER_VEHICLES, PARTNER_SAID, PEOPLE, PLURALS,
                                     REST_WORDS, ROUGHLY, SPEED_CLASS_WORDS, SPEED_NOUNS, START_WORDS, STATIC_SAID,
                                     VIEWER, YES_NO_OPENERS, _at, _head, asks_impact)

# where a noun phrase names a vehicle: the subject of a yes/no question ('does the zamboni hit ...'), and what a
# collision's verb names last ('... made contact with the jumbo?')
SUBJECT_VERBS = {"hit", "hits", "collide", "collides", "crash", "crashes", "bump", "bumps", "move", "moves", "moving",
                 "start", "starts", "go", "goes", "going", "accelerate", "accelerates", "accelerating", "float",
                 "floats", "floating", "fast", "slow", "static", "faster", "slower", "and"}
PARTNER_WORDS = {"with", "into", "hit", "hits", "hitting", "struck", "strike", "strikes"}


# whatever is ending, a clause of time that says it ends ('when the show's wrapping up', 'once the picture is over',
# 'by the time the reel is done'): the video's end, whatever it is called
ENDING_CLAUSE = re.compile(r"\b(?:when|once|as|by the time|until) (?:the|this|that) [a-z]+ (?:' s |is |are )?(?:all )?"
                           r"(?:over|done|finished|ending|wrapping up|wraps up|winding down|winds down|about to end)\b")

def _unknown_vehicle(words: list[str], k: int) -> bool:
    """Whether the unknown word after the determiner at k is where the question names a vehicle."""
    after = words[k + 2:k + 3]
    subject = words[k] == "the" and words[k - 1:k] and words[k - 1] in YES_NO_OPENERS and after and \
        after[0] in SUBJECT_VERBS
    partner = words[k - 1:k] and words[k - 1] in PARTNER_WORDS and after in ([], ["?"], ["."], [","]) and \
        asks_impact(words[:k - 1])   # 'crashes into the zamboni', not 'pops into the shot'
    return bool(subject or partner)


# How often a thing happens ('twice', 'more than once', 'three times'): a count, which no program makes
REPEATS = (["twice"], ["thrice"], ["again"], ["more", "than", "once"], ["repeatedly"], ["multiple", "times"],
           ["several", "times"], ["many", "times"], ["at", "most"], ["only", "once"], ["just", "once"],
           *(["exactly", n] for n in ("once", "one", "two", "2", "1")))
# a comparison of height ('is the jet higher than the bus?' was read as faster: the grammar's 'at a higher speed');
# other words of place and size are unknown words, refused as such
HEIGHT_COMPARISONS = {"higher", "lower"}
TOWARD = {"toward", "towards", "approaching", "nearing"}   # 'heading towards the bus': a direction no family asks


def _at_viewer(words: list[str], k: int) -> bool:
    """Whether words[k:] name the viewer ('the camera', 'us'), or 'it' after the viewer was named ('towards the
    camera or away from it'): a direction front or back."""
    return any(words[k:k + len(v)] == list(v) for v in VIEWER) or words[k:k + 1] == ["it"] and any(
        words[j:j + len(v)] == list(v) for j in range(k) for v in VIEWER if len(v) > 1)


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
    # ... or asked in place, after a statement ('the plane is floating at which height from the ground?')
    asked = asked or next((c for a, b, c in zip(words, words[1:], words[2:]) if a in ("at", "in", "on", "from")
                           and b in ("which", "what") and c in HEIGHT_NOUNS | {"distance", "position", "location"}),
                          None)

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
    # 'Replay time: at what second does ...', a learner's 'Blue bus and green car collide at what second?'
    # (and 'what second' asked anywhere: a signer's 'Red sedan crash blue bus, what second happen?')
    if {asked, as_said, labelled} & TIME_ASKED or any(
            a in ("at", "in", "on") and b in ASKING and c in TIME_ASKED for a, b, c in zip(said, said[1:], said[2:])) \
            or any(a in ("what", "which") and b in TIME_ASKED - {"when"} for a, b in zip(said, said[1:])) \
            or any(a == "time" and (b, c) in (("in", "seconds"), ("in", "moments"), ("in", "frames"), ("of", "first"),
                                              ("of", "contact"), ("of", "impact"), ("of", "collision"))
                   and not {"at", "in", "on", "by"} & set(said[max(k - 2, 0):k])   # 'at the time of impact' is at it
                   for k, (a, b, c) in enumerate(zip(said, said[1:], said[2:]))):   # 'Say time in seconds of ...'

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
                 and asks_impact(said[k - 1:k])), None) \
        or next((" ".join(said[k - 1:k + 1]) for k in range(2, len(said)) if said[k] == "first" and
                 asks_impact(said[k - 1:k]) and said[k + 1:k + 2] in ([], ["?"], ["."], [","]) and (
                     said[k - 2] in ("was", "were", "is", "are", "got", "gets", "get", "be", "been")
                     or said[k - 1].startswith(("collid", "crash", "bump", "smash")))), None) \
        or next((" ".join(said[k - 1:k + 1]) for k in range(2, len(said)) if said[k] in ORDINALS - {"next"}
                 and said[k + 1:k + 2] in ([], ["?"], ["."], [","]) and asks_impact(said[max(k - 6, 0):k])), None)
    # ('what does the truck hit third?', 'which of the two was hit first?', 'the vehicle that hits the car last';
    # 'what does it hit first?' asks the first partner, as a partner's question does)
    if later:
        return (f"the question asks for one of several in turn ('{later}'), which no question here asks (a collision "
                "partner's question asks the first)")
    # 'does the red car hit only the bus?' (read as whether it hits the bus) asks that it hits nothing else
    alone = next((" ".join(said[k:k + 3]) for k in range(1, len(said) - 2) if said[k] == "only" and (
        asks_impact(said[k - 1:k]) and said[k + 1] in ("the", "a", "with", "into")
        or asks_impact(said[k + 1:k + 2]) and said[k + 2] in ("the", "a", "with", "into"))), None)
    if alone:
        return (f"the question asks whether a vehicle hits one and nothing else ('{alone}'), which no question here "
                "asks: ask whether it hits that one, or anything")
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
                      said[k + 1] == "after" and FILM_WORDS & set(said[k + 2:k + 4])
                      or said[k + 1] == "before" and (said[k + 2:k + 3] in (["us"], ["me"], ["you"], ["our"], ["my"],
                                                                             ["your"]) or said[k + 2:k + 3] == ["the"]
                                                      and said[k + 3:k + 4] in WATCHERS))), None)   # in sight
    if order:
        return (f"the question asks the order in which vehicles appear ('{order}'), which no question here asks (they "
                "ask how fast a vehicle is moving when it comes into view)")
    scenery = next((w for k, w in enumerate(said) if w in SCENERY and asks_impact(said[max(k - 4, 0):k])), None)
    if scenery:
        return (f"the question asks about a collision with the '{scenery}', which is no vehicle here (they ask about "
                "collisions between vehicles)")
    # the colour of what is no vehicle ('Which colour has the ground under the vehicles?' was read as a slow one's)
    # (or what is said of the grey ground, where no vehicle is named: 'what is the grey ground made of')
    ground = next((w for k, w in enumerate(said) if w in SCENE_PARTS and (said[k - 1:k] == ["the"] and
                   {"colour", "color", "colours", "colors"} & set(said[max(k - 4, 0):k]) or said[k - 1:k] and
                   said[k - 1] in COLOR_NAMES and not (OBJECT_WORDS - set(COLOR_NAMES)) & set(said))), None)
    if ground:
        return (f"the question asks about the '{ground}', which is no vehicle here (they ask a vehicle's colour, type "
                "and motion)")
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
    # a stall said beside a rest is a traffic report's stalled car, standing ('sitting stalled, not moving an inch')
    stood = (STATIC_SAID | {"still", "sitting"}) & set(said)
    kind = next((why.format(w) for words_of_kind, why in NO_FAMILY_WORDS for w in said if w in words_of_kind
                 and not (words_of_kind is STALLING and stood)), None)
    if kind:
        return kind
    # 'what make is it?' asks its maker, as 'brand' does ('make contact', 'what makes it stop' are verbs)
    if any(w == "make" and said[k - 1:k] and said[k - 1] in {"what", "which", "the", "its", "whose"}
           and said[k + 1:k + 2] and said[k + 1] in {"is", "was", "of", "?", "and"} for k, w in enumerate(said)):
        return ("the question asks about a vehicle's 'make' (its maker), which no question here asks (they ask how it "
                "moves, its colour and its type)")
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
    # (not 'after the video stops', nor a speed offered: 'slow or fast or stop ?', nor 'the stopping of the video')
    stop = next((w for k, w in enumerate(said) if w in ("stop", "stops", "stopping") and k
                 and said[k - 1] not in FILM_WORDS and not ("or" in (said[k - 1], said[k + 1:k + 2] and said[k + 1])
                                                         and {"slow", "fast"} & set(said[k - 4:k + 5]))
                 and not (said[k + 1:k + 3] == ["of", "the"] and said[k + 3:k + 4] and said[k + 3] in FILM_WORDS)),
                None)
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
    # (in the clause it opens: 'after the red car and the blue bus collide , which way does the bus rebound ?')
    around = next((w for k, w in enumerate(said) if w in ("before", "after") and asks_impact(
        said[k + 1:next((m for m in range(k + 1, len(said)) if said[m] in (",", "?", ".")), len(said))][:8])
                   and not FILM_WORDS & set(said[k + 1:k + 3]) and not {"frames", "shown", "observed", "given"} & set(
                       said[k + 1:k + 4])), None)   # ('will the cyan wagon after the shown frames be involved in ...')
    if around:
        return (f"the question asks about the time {around} a collision, which no question here asks (they ask at "
                "the collision itself)")
    place = next((" ".join(p) for k in range(len(said)) for p in PLACE_PHRASES if said[k:k + len(p)] == p
                  and not (p in (["further"], ["farther"]) and said[k - 1:k] and said[k - 1] in GOING_ON)
                  and not (p[0] in ("near", "close") and NEAR_TIMES.intersection(said[k + len(p):k + len(p) + 3]))
                  and not (p == ["near"] and not (said[k - 1:k] and said[k - 1] in OBJECT_WORDS))), None)
    if place:
        return (f"the question asks where a vehicle is ('{place}'), which no question here asks (they ask which way "
                "it is moving)")
    ended = _video_end(said) or _at(said, END_TIMES) or \
        ENDING_CLAUSE.search(" ".join(said))
    if ended and not asks_impact(said) and not asks_impact(words):   # 'colide' as read, typos fixed
        return ("the question asks about the video's end, which no question here asks (they ask about the start, "
                "an object's coming into view, a collision, and collisions after the video)")
    return ""


# Where a vehicle is, said by its neighbour or its distance: never a question here, whatever the lexicon reads them as
# ('behind' is its 'down')
NEAR_TIMES = {"start", "beginning", "outset", "end", "cut", "moment", "instant", "time", "when"}
PLACE_PHRASES = (["behind"], ["beside"], ["alongside"], ["next", "to"], ["in", "front", "of"], ["further"],
                 ["farther"], ["closer"], ["nearer"], ["nearest"], ["closest"], ["furthest"], ["farthest"],
                 # a learner's comparative of a place ('which one is more close to the camera?' was read as faster)
                 *(["more", w] for w in ("close", "near", "far", "distant")), ["close", "to"], ["near", "to"],
                 # a vehicle told by its place ('faster than the yellow pickup near it': 'near' was WordNet's 'left')
                 ["near"],
                 *(["parking", w] for w in ("spot", "space", "lot", "bay")),
                 # where a vehicle is found ('where located, left or right?', 'Where is parked the yellow bus?')
                 ["located"], ["location"], *(["where", *be, "parked"] for be in ((), ("is",), ("was",))))


# a video that goes on further is a later time, not a place ('if video would continue further, ...')
GOING_ON = {"continue", "continues", "continued", "continuing", "on", "play", "plays", "played", "playing", "run",
            "runs", "ran", "running", "rolling", "rolls", "rolled"}
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
LANES = {"lane", "lanes"}   # 'does it change lanes?': a turn
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
# what a vehicle has that no question asks ('what's the license plate on the truck' was read as its speed); vehicles
# no video shows are words.OTHER_VEHICLES
FITTINGS = {"license", "licence", "plate", "plates", "registration", "brand", "logo", "logos", "wheel", "wheels",
            "tire", "tires", "tyre", "tyres", "window", "windows", "door", "doors", "headlight", "headlights", "price",
            "owner", "horsepower", "fuel", "mileage", "seat", "seats", "propeller", "propellers", "wing", "wings"}
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
# a length in a unit ('hovering about ____ metres above the ground' was read as whether it floats)
LENGTHS = {"metre", "metres", "meter", "meters", "centimetres", "centimeters", "kilometres", "kilometers", "miles",
           "inches", "feet", "yards"}
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
    (LENGTHS, "the question asks a length in {} (a distance or a height), which no question here asks (they ask "
              "speed classes, directions, colours, types and collisions)"),
    (FAULT, "the question asks who is to blame ('{}'), which no question here asks (they ask who collides)"),
    (FITTINGS, "the question asks about a vehicle's '{}', which no question here asks (they ask how it moves, its "
               "colour and its type)"),
    (SOUNDS, "the question asks what is heard ('{}'), and the videos are silent (questions ask how the vehicles move "
             "and what they hit)"),
)
SCENERY = {"wall", "walls", "barrier", "barriers", "fence", "building", "buildings", "tree", "trees", "curb", "kerb",
           "pole", "sign"}   # 'does the jet hit the wall?' was read as whether it hits anything
SCENE_PARTS = SCENERY | {"ground", "floor", "sky", "background", "road", "surface", "scene", "shadow", "shadows"}
# one vehicle's motion relative to another's ('is it chasing the bike?', 'does it overtake the bus?' were read as
# collisions), said of a vehicle ('passes the bus'; not 'passed by', 'the frames that follow')
RELATIVE_MOTION = {"overtake", "overtakes", "overtook", "overtaking", "chase", "chases", "chased", "chasing", "follow",
                   "follows", "followed", "following", "pursue", "pursues", "pursued", "pursuing", "tailing",
                   "tailgate", "tailgates", "tailgated", "tailgating", "cross", "crosses", "crossed", "crossing"}
PASSING = {"pass", "passes", "passing", "passed"}
VEHICLE_SAID = OBJECT_WORDS | {"it", "another", "vehicle", "object", "one", "thing"}
NEAR_MISS = {"nearly", "almost", "narrowly", "barely"}   # 'does it nearly hit the bus?' asks whether it does not
# before whom a vehicle appears, not before which other vehicle ('when it first appears before the watcher')
WATCHERS = [["watcher"], ["watchers"], ["viewer"], ["viewers"], ["camera"], ["eye"], ["eyes"], ["lens"], ["audience"]]
PATH_SHAPES = {"straight", "circle", "circles", "circular", "curve", "curves", "curved", "curving", "zigzag", "zigzags",
               "zigzagging", "diagonally", "diagonal", "sideways", "loop", "loops", "arc", "swerving", "lap", "laps",
               "circuit", "circuits", "route", "routes", "path", "paths"}
TAKING = {"take", "takes", "took", "taking", "taken", "lift", "lifts", "lifted", "lifting"}   # '... off': a take-off


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


# a cause asked ('did it hit the bus because it was fast?' was read as whether it was fast)
CAUSES = {"because", "due", "reason", "reasons"}
CAUSING = {"made", "makes", "caused", "causes", "cause", "led", "leads", "lead"}   # 'what made it turn?'
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


PLURAL_ASKED = {"colours", "colors", "types", "kinds", "sorts", "shapes"}   # not 'compare the speeds of X and Y'
SUBJECTS = {"it", "they", "the", "that", "this", "he", "she", "there"}


def properties_joined(words: list[str]) -> str:
    """Two kinds of motion asked at once ('fast and accelerating', 'floating and moving fast', 'accelerating but
    slow'), or ''."""
    for k, w in enumerate(words):
        if w not in ("and", "but"):
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


CLAUSE_TIMES = (["after"], ["before"], ["when"], ["once"], ["while"], ["until"])
OTHER_TIMES = (*LATER_TIMES, *END_TIMES, *CLAUSE_TIMES)


def imagined_otherwise(words: list[str], read: list[str]) -> str:
    """A counterfactual this grammar has no program for, or '': a change at another time than the start ('if it had
    been static at the end'), two changes at once ('if the sedan had been fast and the bus parked' was read as the
    sedan's alone) or the video changed ('if the video were longer' as the future). `words` as said, `read` with
    typos fixed ('when the video begisn' is the start)."""
    back = _at(words, IMAGINED_BACK)
    if back and back[1][1] in ("that", "such") and not (IMAGINED_SAID | IMAGINING | {"if", "had", "were"}).intersection(
            words) and \
            not _video_end(words):   # ('suppose the video is cut off midway ; in that case , ...')
        return (f"the question asks about an imagined world ('{' '.join(back[1])}') it does not describe: say the "
                "change ('if the bus had been static from the start, would ...')")
    if any(w == "if" and words[k + 1] == "the" and words[k + 2] in FILM_WORDS and words[k + 3:k + 4] and
           words[k + 3] in ("were", "was", "had") for k, w in enumerate(words[:-3])):   # not 'if the video went on'
        return "the question imagines the video itself otherwise, which no question here does"
    start, end = _condition_clause(words)
    clause = words[start:end]
    if not {"had", "were", "been"}.intersection(clause):   # 'do you know if X and Y ...'
        return ""
    other = " ".join(at[1]) if (at := _at(clause, OTHER_TIMES)) else None
    if other and not START_WORDS.intersection(clause + read[slice(*_condition_clause(read))]) and "first" not in clause:
        return (f"the question imagines a change at a time other than the start ('{other}'), which no question here "
                "does: each changes a vehicle's motion from the start")
    second = next((k for k in range(start, end) if words[k] == "and" and OBJECT_WORDS.intersection(words[k + 1:k + 4])),
                  None)
    if second is None:
        return ""
    return (f"the question imagines two changes at once ('and {' '.join(words[second + 1:end])}'), which no question "
            "here does: each imagines one vehicle's motion changed")


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
    """Two questions joined by 'and' ('is it fast at the start, and does it hit the bus?'), or by 'or' where the
    second asks about a collision and the first not ('is the car fast or slow, or does it hit the bus?'; not 'is it
    fast, or is it slow?', 'does it hit something, or does it stay clean?'), or ''."""
    said = next((" ".join(words[k:k + 2]) for k in range(len(words) - 2) if words[k + 1] in YES_NO_OPENERS
                 and words[k + 2] in SUBJECTS and (words[k] == "and" or words[k] == "or" and
                                                   asks_impact(words[k:]) and not asks_impact(words[:k]))
                 # ('was its engine on and was it speeding up': the one question of accelerating)
                 and not ("engine" in words[:k] and {MOTION_KINDS.get(w) for w in words[k:]} >= {"accelerating"})),
                None)
    if said is None:
        return ""
    return (f"the question asks two questions ('{said}'), which the parser reads one at a time: ask them apart")


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
    # (nor a learner's 'assuming the bus was parked, it would hit ...?': the 'would' after it imagines it)
    said = next((" ".join(p) for k in range(len(words)) for p in PREMISES if words[k:k + len(p)] == p
                 and not IMAGINED & set(words[k + len(p):(words + [","])[k:].index(",") + k])
                 and "would" not in words[(words + [","])[k:].index(",") + k:]), None)
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
              and words[k + 2 + j:k + 3 + j] in ([], ["?"], ["."], [","], ["does"], ["did"], ["do"], ["has"])),
             None) or \
        next((" ".join(words[k:k + 3]) for k in range(len(words) - 2) if words[k] in ("first", "second", "last")
              and (words[k + 1] == "pair" or words[k + 1] == "to" and words[k + 2].startswith(IMPACT_STEMS))), None) \
        or next((f"{a} {b}" for a, b in zip(words, words[1:]) if b == "last" and a in ARRIVING), None)
    # (not 'after the bus ends'; 'who hits the van after the bus does?'; 'were they the first pair to collide?';
    # 'what kind of vehicle comes in last?', whose 'last' WordNet reads as 'lasting', standing)
    if said is None:
        return ""
    return (f"the question asks about an order of collisions or vehicles ('{said}'), which no question here asks: "
            "ask whether they collide")


ARRIVING = {"in", "comes", "came", "come", "coming", "enters", "entered", "arrives", "arrived", "appears", "appeared",
            "up"}


def chained(words: list[str]) -> str:
    """A vehicle described through another described vehicle ('the vehicle hit by the vehicle that hits the bus',
    'the collision partner of the collision partner of the SUV'), or ''."""
    relatives = [k for k, w in enumerate(words[:-1]) if w in GENERIC_NOUNS and (
        words[k + 1] in RELATIVES or words[k + 1] in PASSIVES and words[k + 2:k + 3] == ["by"])]
    if len(relatives) < 2 and sum(w in ("partner", "partners") for w in words) < 2:
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
         and (words[k - 2] in OBJECT_WORDS | {"it", "one"} or words[k] == "only" and words[k - 2] in COPULAS
              and words[k - 3] in OBJECT_WORDS | {"it", "one"})),   # 'the purple one is the only vehicle ...'
        None) or next((f"the {b}" for k, (a, b) in enumerate(zip(words, words[1:])) if a == "the" and (
            b == "others" or b == "rest" and words[k + 2:k + 3] != ["of"]) and not asks_impact(words)),
        None)   # 'fast compared with the others' (not 'the rest of the video': after it)
    if said is None:
        return ""
    return (f"the question ranks a vehicle among all ('{said}'), which no question here asks: ask whether one is "
            "faster (or slower) than another, or whether it collides")


# Passive participles of outdoing: 'X is outpaced by Y' says Y is faster, the other way round from how the
# lexicon reads the word ('outpace' -> 'move faster than')
OUTDONE = {"outpaced", "outrun", "outran", "overtaken", "outstripped", "passed", "beaten", "outsped", "outdone",
           "surpassed", "outperformed", "bested", "exceeded", "outdistanced", "outraced"}


# Words that turn what follows round ('is the red car anything but static?', 'is it false that ...', 'no faster
# than'): the decoder read the predicate after them as asked
REVERSING = (["anything", "but"], ["anything", "other", "than"], ["something", "other", "than"], ["anything", "except"],
             ["far", "from"], ["nowhere", "near"], ["by", "no", "means"], ["the", "opposite", "of"],
             ["false", "that"], ["untrue", "that"], ["incorrect", "that"], ["not", "the", "case", "that"],
             ["impossible", "that"], ["unlikely", "that"], ["rule", "out"], ["a", "mistake", "to"],
             *([wrong, "to", say] for wrong in ("wrong", "incorrect", "false") for say in ("say", "think", "claim")),
             *([deny, "that"] for deny in ("deny", "denies", "doubt", "doubts")),
             *(["no", c] for c in ("faster", "slower", "quicker", "speedier")),
             # a collision prevented, escaped, or not there ('would the crash have been prevented if ...?', 'does it
             # survive the video without a collision?', 'is there no collision between ...?')
             *([w] for w in ("prevented", "prevent", "averted", "avert", "escaped", "spared")), ["untouched", "by"],
             *([*without, hit] for without in (["without"], ["without", "a"], ["without", "any"], ["is", "there", "no"],
                                                ["was", "there", "no"], ["zero"])
               for hit in ("collision", "collisions", "crash", "crashes", "contact", "impact", "colliding", "hitting",
                           "crashing", "touching", "bumping", "striking")))


LOSING = {"lose", "loses", "losing", "lost", "shed", "sheds", "shedding", "drop", "drops", "dropping", "reduce",
          "reduces", "reducing", "reduced", "decrease", "decreases", "decreasing", "decreased", "cut", "cuts",
          "cutting", "bleed", "bleeds", "bleeding"}
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
        # (not a speed that falls into a class: 'into which speed category does its initial velocity fall?')
        if w in SPEED_NOUNS and (verb[:1] and verb[0] in FALLING or verb in (["goes", "down"], ["going", "down"])) \
                and not ({"into", "in"} & set(words[:k]) and CLASS_NOUNS & set(words[:k])):
            return True
        if w in GETTING and (after[:1] == ["slower"] or after[:2] == ["more", "slowly"]) and "than" not in after:
            return True
        if w in ("come", "comes", "coming") and "had" not in words[max(k - 4, 0):k] and after[:1] == ["to"] and \
                HALTS.intersection(after[1:3]):     # 'had it come to a stop' is a counterfactual's rest
            return True
    return False


STEADY = {"constant", "steady", "steadily", "unchanged", "unchanging", "same", "uniform", "uniformly"}
SPEEDING_UP = {"speeding", "accelerating", "gaining", "picking", "increasing", "building"}
ACCELERATING_SAID = {"up", "speed", "accelerate", "accelerates", "accelerated", "faster"}
TIME_NOUNS = {"time", "instant", "moment", "point", "frame", "second"}


def reversed_as_said(words: list[str]) -> str:
    """Reversals that the words standing in for unknown ones would hide, so read before they stand in: 'decelerate'
    (WordNet's 'slow', a speed; slowing down, however said, is what no question asks, the opposite of
    accelerating), a speed that stays the same (STEADY: 'at a constant speed' was read as slow, 'the same speed
    throughout' as fast) and a comparison in the passive ('Is the bus outpaced by the car?'). '' when there is
    none."""
    if any(w.startswith("decelerat") for w in words) or slowing_down(words):
        return ("the question asks whether an object slows down, which no question here asks: ask whether it is "
                "accelerating and take the opposite answer")
    # (not 'steadily speeding up' nor 'accelerating steadily', a speed that changes steadily, nor 'at that same
    # instant', a time said before; 'at the same time' may be two events at once)
    if any(w in STEADY and after not in SPEEDING_UP and not (w == "same" and before == "that" and after in TIME_NOUNS)
           and not (w == "steadily" and before in SPEEDING_UP | ACCELERATING_SAID)
           for before, w, after in zip([""] + words, words, words[1:] + [""])):
        return ("the question asks whether an object keeps its speed, which no question here asks: ask whether it is "
                "accelerating and take the opposite answer")
    passive = [w for k, w in enumerate(words) if w in OUTDONE and "by" in words[k + 1:k + 4]]
    if passive:
        return (f"the question compares in the passive ('{passive[0]} by'): ask whether the one named last is faster "
                "or slower than the other")
    return ""
