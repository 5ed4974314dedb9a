"""The copy path for object words. The sequence model never reads or writes a colour or a sub-type: each run of
attribute words in the question ('red sedan', 'school bus', 'purple') becomes a placeholder (<obj1>, <obj2>, in
order of first mention; the same words twice, the same placeholder, and at parse time a shorter mention of one
object, before or after its fuller one, too: `corefer`), the model writes the placeholder where the program refers
to that object, and the placeholder is copied back as the object's filter chain. So an object description the parser
never saw with a sentence, or in a sentence it never saw, is carried over exactly, and the model's capacity goes to
the sentence.
"""

from __future__ import annotations

import re
from difflib import SequenceMatcher

from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.colors import COLOR_NAMES
from dynclevr.questions.programs import ATTRIBUTE_VALUES

# Attribute values as words: 'school_bus' is said 'school bus'; longest first, so 'school bus' is not read as 'bus'.
# A lone 'bike', part of four sub-types' names, is what people call a bicycle.
_ALIASES = ((("bike",), "bicycle"),)
_NAMES = sorted([(tuple(v.split("_")), v) for v in ATTRIBUTE_VALUES] + list(_ALIASES), key=lambda kv: -len(kv[0]))
OBJECT_WORDS = frozenset(w for name, _ in _NAMES for w in name)
# What people call the catalogue's vehicles, and how they write its names of two words: read as its own names
# before anything else reads the words ('the cyan double-decker bus' is 'the cyan double bus', 'the red fighter
# plane' 'the red fighter'), so a name the grammar never says is neither unparsed nor read as a colour alone.
EVERYDAY_NAMES = {"double decker": "double bus", "double decker bus": "double bus", "double deck bus": "double bus",
                  "dirt bike": "dirtbike", "mini van": "minivan", "bendy bus": "articulated bus",
                  "city bus": "regular bus", "tandem": "tandem bike", "bi plane": "biplane", "air liner": "airliner",
                  "passenger jet": "airliner", "passenger plane": "airliner", "passenger aeroplane": "airliner",
                  "passenger aircraft": "airliner", "fighter jet": "fighter", "pickup truck": "truck",
                  "pick up truck": "truck", "station wagon": "wagon", "estate car": "wagon", "estate wagon": "wagon",
                  "sport utility vehicle": "suv", "sports utility vehicle": "suv", "motor scooter": "scooter",
                  "saloon": "sedan", "saloon car": "sedan", "people carrier": "minivan", "4x4": "suv",
                  "four by four": "suv", "racing bike": "road bike", "racing bicycle": "road bike",
                  "mtb": "mountain bike", "pickup": "truck", "pick - up": "truck", "pick - up truck": "truck",
                  # a vehicle's everyday noun (as synonyms.txt reads it), here so that the context of a question and
                  # what follows it are read for it ('The red airliner ... is the plane going slower?')
                  "plane": "aeroplane", "aircraft": "aeroplane", "automobile": "car", "motorcar": "car", "motor car": "car",
                  "lorry": "truck", "van": "minivan", "pushbike": "bicycle", "pushie": "bicycle",
                  "jetliner": "airliner", "warplane": "fighter", "war plane": "fighter",
                  # as plane spotters name them
                  "jumbo": "airliner", "jumbo jet": "airliner", "bizjet": "jet", "business jet": "jet",
                  "executive jet": "jet", "corporate jet": "jet", "warbird": "fighter", "fast jet": "fighter",
                  "stringbag": "biplane",
                  # as bikers and bus and car enthusiasts name them
                  "hog": "cruiser", "step - through": "scooter", "decker": "double bus", "bendy": "articulated bus",
                  "estate": "wagon", "whip": "car",   # London's car
                  "chopper bike": "chopper", "cruiser bike": "cruiser", "city bike": "utility bike",
                  "city bicycle": "utility bike", "commuter bike": "utility bike", "ute": "truck",
                  "bakkie": "truck", "mpv": "minivan",
                  "push bike": "bicycle", "cycle": "bicycle", "pedal bike": "bicycle", "motor cycle": "motorbike",
                  "push - bike": "bicycle", "cage": "car", "tin box": "car", "chelsea tractor": "suv",
                  # as older people name them (a category alone: synonyms.txt, wordings.IDIOMS)
                  "articulated omnibus": "articulated bus", "double decker omnibus": "double bus",
                  "school omnibus": "school bus", "city omnibus": "regular bus", "bendy omnibus": "articulated bus",
                  "town bike": "utility bike", "town bicycle": "utility bike", "scrambler": "dirtbike",
                  "pickup lorry": "truck", "urban bus": "regular bus", "off - road motorcycle": "dirtbike",
                  "off - road motorbike": "dirtbike", "dirt motorbike": "dirtbike", "dirt motorcycle": "dirtbike",
                  **{f"{t.split('_')[0]} {noun}": t.replace("_", " ") for noun in ("bicycle", "cycle")
                     for t in ("mountain_bike", "road_bike", "tandem_bike", "utility_bike")}}
# Shades people name that are one catalogue colour: the nearest of the eight in CIELAB to the shade's usual sRGB, by a
# margin (the second nearest at least 1.3 times as far, and within 45), and of that colour's hue by common usage.
# 'navy', 'teal', 'silver', 'tan' and 'khaki' fail the margin, 'magenta' is pink or red as often as purple by usage,
# and 'orange', 'pink', 'black' and 'white' are none of the eight: they stay unparsed ('no object here is ...'). A
# shade before its colour ('forest green'), 'dark', 'bright' or 'deep' before a colour, and '-ish' after it, leave
# the colour ('the dark blue sedan', 'the reddish bus').
COLOUR_SHADES = {**dict.fromkeys(("crimson", "scarlet", "maroon", "burgundy", "ruby", "cherry"), "red"),
                 **dict.fromkeys(("azure", "cobalt", "sapphire"), "blue"),
                 **dict.fromkeys(("indigo", "violet"), "purple"),
                 **dict.fromkeys(("turquoise", "aqua", "aquamarine"), "cyan"),
                 **dict.fromkeys(("charcoal", "slate"), "gray"),
                 **dict.fromkeys(("gold", "golden", "lemon", "mustard"), "yellow"),
                 **dict.fromkeys(("chocolate", "bronze"), "brown"), "forest": "green"}
_SHADES = {(said, colour) for shade, colour in COLOUR_SHADES.items() for said in ((shade,), (shade, colour))} | \
    {((tone, c), c) for tone in ("dark", "bright", "deep") for c in COLOR_NAMES} | \
    {(ish, c) for c in COLOR_NAMES for ish in ((c + "ish",), (c, "-", "ish"))} | \
    {(("reddish",), "red"), (("bluish",), "blue"), (("purplish",), "purple"), (("greyish",), "gray")}
# a bus glossed as the ordinary sort ('the purple omnibus (the ordinary sort)') is the catalogue's regular bus
_ORDINARY = {((bus, "(", "the", plain, sort, ")"), "regular bus") for bus in ("bus", "omnibus")
             for plain in ("ordinary", "regular", "normal", "usual", "standard", "plain")
             for sort in ("sort", "kind", "type", "variety")}
# a plane that is no aeroplane: an architect's 'the ground plane', 'the image plane'
_FLAT = {((f, "plane"), f) for f in ("ground", "image", "picture", "horizontal", "vertical", "floor", "focal")}
# A category as people say it, for a sub-type said with its category ('the fighter plane', 'the sedan car').
CATEGORY_SAID = {"aeroplane": ("aeroplane", "plane", "aircraft"), "bicycle": ("bicycle", "bike"),
                 "bus": ("bus", "coach"), "car": ("car", "automobile", "motorcar", "motor car"),
                 "motorbike": ("motorbike",)}


def _written(name: str) -> set[tuple[str, ...]]:
    """A name of several words as people also write it: hyphenated, or run together ('dirt-bike', 'dirtbike')."""
    out = {()}
    for k, word in enumerate(name.split()):
        out = {w + (word,) for w in out} if k == 0 else ({w + (word,) for w in out} | {w + ("-", word) for w in out}
                                                        | {w[:-1] + (w[-1] + word,) for w in out})
    return out


def phrase_table(pairs) -> dict[str, tuple[tuple[tuple[str, ...], tuple[str, ...]], ...]]:
    """(phrase, words it is read as) pairs by their phrase's first word, the longest phrase first: what
    `phrases_as_said` looks up at each word instead of scanning every phrase."""
    out: dict[str, list] = {}
    for phrase, said in sorted(pairs, key=lambda kv: -len(kv[0])):
        out.setdefault(phrase[0], []).append((tuple(phrase), tuple(said)))
    return {w: tuple(hits) for w, hits in out.items()}


_EVERYDAY = phrase_table((w, tuple(said.split())) for w, said in sorted(
    {(w, said) for name, said in [*((v.replace("_", " "), v.replace("_", " ")) for v in SUBTYPES),
                                  *EVERYDAY_NAMES.items()] for w in _written(name)}
    | {((*v.split("_"), *c.split()), v.replace("_", " ")) for v in SUBTYPES for c in CATEGORY_SAID[SUBTYPES[v][0]]}
    | _SHADES | _ORDINARY | _FLAT, key=lambda kv: (-len(kv[0]), kv)))


_PAIRED: dict[int, tuple[object, dict]] = {}


def _paired(table) -> dict[tuple[str, str], list]:
    """A `phrase_table`'s phrases by their first two words (one word's by (word, '')), made once, longest first as
    in the table: the commonest first words open thousands ('if', ',')."""
    made = _PAIRED.get(id(table))
    if made is None or made[0] is not table:
        pairs: dict[tuple[str, str], list] = {}
        for w, hits in table.items():
            for p, said in hits:
                pairs.setdefault((w, p[1] if len(p) > 1 else ""), []).append((p, said))
        made = _PAIRED[id(table)] = (table, pairs)
    return made[1]


def phrases_as_said(words: list[str], table) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """Every phrase of `table` (`phrase_table`) in `words` read as its words, the longest at a place; with the
    phrases read so, as written ('dirt-bike')."""
    out, read, i = [], [], 0
    pairs = _paired(table)
    while i < len(words):
        longer = pairs.get((words[i], words[i + 1]), ()) if i + 1 < len(words) else ()
        hit = next(((p, said) for p, said in (*longer, *pairs.get((words[i], ""), ()))
                    if tuple(words[i:i + len(p)]) == p), None)
        if hit is None:
            out.append(words[i])
            i += 1
            continue
        p, said = hit
        out += said
        if list(p) != list(said):
            read.append((" ".join(p).replace(" - ", "-"), " ".join(said)))
        i += len(p)
    return out, tuple(read)


# A speech recogniser's hearing of a vehicle's name said after its colour: split ('the yellow s u v', 'the gray
# station wag on', 'the green by plane'), or as words that sound alike ('the purple said an', 'the cyan crews her',
# 'the gray many van'). Read as the name whose letters they are, or whose consonants they sound (vowels and the
# glides h, w, y left out, a doubled letter once), where one name is.
_HEARD_NAMES = {"".join(w): said for said_words, said in
                [*((tuple(v.split("_")), v.replace("_", " ")) for v in SUBTYPES),
                 *((tuple(k.split()), k) for k in EVERYDAY_NAMES),
                 *((tuple(c.split()), c) for cs in CATEGORY_SAID.values() for c in cs)]
                for w in [said_words]}
_SOUNDLESS = re.compile(r"[aeiouhwy]")
# ... and its colour, before a name ('the read sedan', 'the blew bus'); one that is no other word needs no article
# before it ('yellow motor bike and sian by cycle')
HEARD_COLOURS = {"read": "red", "blew": "blue", "sian": "cyan", "scion": "cyan", "grey": "gray"}
HEARD_ONLY = {"sian"}


def _sounded(letters: str) -> str:
    return re.sub(r"(.)\1+", r"\1", letters[:1] + _SOUNDLESS.sub("", letters[1:]))


def _heard_name(heard: list[str]) -> str | None:
    letters = "".join("u" if w == "you" else w for w in heard) if len(heard) > 1 else heard[0]   # 's u v'
    if not letters.isalpha() or len(letters) < 3 or heard[0] in ("the", "a", "an", "and", "or", "of", "with"):
        return None
    if letters in _HEARD_NAMES:
        return _HEARD_NAMES[letters]
    if letters.endswith("a") and letters[:-1] + "er" in _HEARD_NAMES:   # a final 'er' said without its r: 'scoota'
        return _HEARD_NAMES[letters[:-1] + "er"]
    close = {said for name, said in _HEARD_NAMES.items()
             if len(_sounded(name)) >= 3 and _sounded(name) == _sounded(letters)
             or len(name) >= 6 and abs(len(name) - len(letters)) <= 1
             and SequenceMatcher(None, letters, name).ratio() >= 0.85}
    return close.pop() if len(close) == 1 else None


def heard_as_said(words: list[str], known: set[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A vehicle's name as a speech recogniser typed it, after its colour, as its name (and the colour before a name
    as its colour): ['the', 'read', 'said', 'an'] -> ['the', 'red', 'sedan']; with the words read so. Only where the
    words after the colour are no name already and are not all words of `known` that go on with the question."""
    out, read, k = list(words), [], 0
    while k < len(out) - 1:
        colour = out[k] in COLOR_NAMES or out[k] in HEARD_ONLY or out[k] in HEARD_COLOURS and k and out[k - 1] in (
            "the", "a", "an")
        if not colour:
            k += 1
            continue
        j = k + 1
        name = None
        named = out[j] in OBJECT_WORDS or any(tuple(out[j:j + len(p)]) == p for p, _ in _EVERYDAY.get(out[j], ()))
        if not named and out[j] not in ("one", "ones"):
            # the longest hearing first: 'station wag on' before 'station'
            name = next(((n, said) for n in (3, 2, 1) if (said := _heard_name(out[j:j + n]))
                         and (n > 1 or out[j] not in known)), None)
        if name:
            n, said = name
            read.append((" ".join(out[j:j + n]), said))
            out[j:j + n] = said.split()
        if out[k] in HEARD_COLOURS and (name or named):
            read.append((out[k], HEARD_COLOURS[out[k]]))
            out[k] = HEARD_COLOURS[out[k]]
        k += 1
    return out, tuple(read)


# A vehicle named by what it looks like or is for, by those who do not know its name ('the red plane with two sets
# of wings', 'the bus that takes kids to school', 'the bike built for two', 'the car with the open back', 'the family
# van', 'the military jet'): the words before its noun and a phrase after it that say one sub-type. Words that only
# describe ('little', 'skinny', 'chunky') go where a sub-type is said; said alone they stay, for the parser to refuse.
def _options(*parts) -> list[tuple[str, ...]]:
    """Every phrase of `parts`, each part a word or a tuple of alternatives ('' for none)."""
    phrases = [()]
    for part in parts:
        alternatives = part if isinstance(part, tuple) else (part,)
        phrases = [p + tuple(a.split()) for p in phrases for a in alternatives]
    return phrases


_THE = ("the", "a", "an", "")
DESCRIBED_AFTER = {
    "biplane": _options("with", ("two", "double", ""), ("sets of", "pairs of", "layers of", ""), "wings"),
    "double_bus": _options("with", ("two", "2"), ("floors", "decks", "levels", "storeys", "stories")) +
    _options("with", _THE, ("upstairs", "upper deck", "top deck")),
    "articulated_bus": _options(("that", "which"), ("bends", "folds", "bend"), ("in the middle", "")) +
    _options("with", _THE, ("concertina", "hinge", "joint", "bendy"), ("bit", "part", "section", ""),
             ("in the middle", "")),
    "school_bus": _options(("that", "which"), ("takes", "carries", "brings", "drives"), ("kids", "children", "pupils"),
                           "to school") +
    _options(("that", "which"), "picks", ("kids", "children", "pupils"), "up", ("for school", "")) +
    _options("for", ("school kids", "schoolkids", "school children", "schoolchildren", "school")),
    "tandem_bike": _options(("built", "made", "meant", ""), "for", "two", ("riders", "people", "")) +
    _options("-", ("built", "made", "meant"), "-", "for", "-", "two"),   # 'that bicycle-built-for-two'
    "mountain_bike": _options("with", _THE, ("big", ""), ("knobbly", "knobby", "chunky", "fat", "thick"),
                              ("tyres", "tires"), ("for hills", "")) + [("for", "hills")],
    "utility_bike": _options("with", _THE, ("big", ""), ("cargo", "luggage", "delivery", ""),
                             ("rack", "basket", "carrier", "box")),
    "scooter": _options("you", ("stand", "sit upright", "sit up"), "on") +
    _options(",", "with", _THE, "flat", "floor", ("for your feet", ""), ",") +
    _options("with", _THE, "flat", "floor", ("for your feet", "")),
    "chopper": _options("with", _THE, ("long", ""), ("stretched", "stretched - out", "stretched out", "extended"),
                        ("front", "front end", "forks")),
    "truck": _options("with", _THE, "open", ("cargo", ""), ("back", "bed", "box"), ("at the back", "")),
    "wagon": _options("with", _THE, ("long", "extended"), ("roof", "back")),
}
DESCRIBED_BEFORE = {
    **dict.fromkeys(("winged", "twin-winged"), "biplane"), **dict.fromkeys(("military", "war", "combat", "army"),
                                                                          "fighter"),
    **dict.fromkeys(("private", "business"), "jet"), "passenger": "airliner",
    **dict.fromkeys(("upstairs", "storey", "decked"), "double_bus"), **dict.fromkeys(("bendy", "concertina"),
                                                                                     "articulated_bus"),
    **dict.fromkeys(("ordinary", "normal", "plain", "regular", "standard", "everyday", "city"), "{plain}"),
    **dict.fromkeys(("racing", "racer", "road"), "road_bike"), **dict.fromkeys(("knobbly", "hill", "mountain"),
                                                                             "mountain_bike"),
    **dict.fromkeys(("delivery", "cargo", "utility"), "utility_bike"), "stand": "scooter",
    **dict.fromkeys(("slung",), "chopper"), **dict.fromkeys(("trail", "motocross", "offroad"), "dirtbike"),
    **dict.fromkeys(("cruising", "touring"), "cruiser"), "boxy": "suv", "estate": "wagon", "family": "minivan",
}
PLAIN = {"bus": "regular_bus", "car": "sedan"}   # an ordinary bus or car
_NAME_PAIRS = {tuple(v.split("_")) for v in SUBTYPES if "_" in v}
SIZES = {"little", "small", "big", "large", "tiny", "huge", "giant", "massive", "enormous"}
DESCRIBING = SIZES | {"skinny", "thin", "long", "low", "chunky", "sleek", "old", "fashioned", "double", "two", "twin",
                      "-", "up"}
# (a sub-type's own name too, described again: 'the cyan two-winged biplane')
DESCRIBED_NOUNS = {"aeroplane": "aeroplane", "jet": "aeroplane", "airliner": "aeroplane", "biplane": "aeroplane",
                   "bus": "bus", "bike": "bicycle", "bicycle": "bicycle", "motorbike": "motorbike", "car": "car",
                   "minivan": "car"}


def described_as_named(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """['the', 'red', 'aeroplane', 'with', 'two', 'sets', 'of', 'wings'] -> ['the', 'red', 'biplane']: a vehicle
    described by what it looks like or is for, where the description says one sub-type of the noun's category; with
    the description read so."""
    out, read, n = [], [], 0
    while n < len(words):   # 'off-road', 'off road': one word
        joined = next((m for m in (3, 2) if words[n:n + m] in (["off", "-", "road"], ["off", "road"])), 0)
        out.append("offroad" if joined else words[n])
        n += joined or 1
    n = 0
    while n < len(out):
        category = DESCRIBED_NOUNS.get(out[n])
        if category is None:
            n += 1
            continue
        start = n - (n > 0 and (out[n - 1], out[n]) in _NAME_PAIRS)   # 'road bike', 'regular bus'
        j = start
        while j > 0 and (out[j - 1] in DESCRIBED_BEFORE or out[j - 1] in DESCRIBING or out[j - 1] in COLOR_NAMES):
            j -= 1
        colours = [w for w in out[j:start] if w in COLOR_NAMES]
        before = [w for w in out[j:start] if w not in COLOR_NAMES]
        after = next(((len(p), t) for t, ps in DESCRIBED_AFTER.items() for p in sorted(ps, key=len, reverse=True)
                      if p and tuple(out[n + 1:n + 1 + len(p)]) == p and SUBTYPES[t][0] == category), (0, None))
        said = {PLAIN.get(out[n], "") if t == "{plain}" else t for t in map(DESCRIBED_BEFORE.get, before) if t}
        said = {t for t in said | {after[1]} if t in SUBTYPES and SUBTYPES[t][0] == category}
        named = "_".join(out[start:n + 1]) if start < n else out[n]
        # a sub-type's own name keeps it where the words only describe ('the skinny purple road bike')
        # (but not a size alone, which names no sub-type: 'the big red sedan' is left to `asides.owners_dropped`; a bus
        # or a plane is big by its kind: 'the big yellow school bus', 'the yellow big airliner')
        plain = DESCRIBING - SIZES | (SIZES - {"little", "small", "tiny"} if category in ("bus", "aeroplane")
                                      else set())
        said = said or ({named} if named in SUBTYPES and set(before) <= plain else set())
        if len(colours) > 1 or len(said) != 1 or not (before or after[0]):
            n += 1
            continue
        t = said.pop()
        new = colours + t.split("_")
        read.append((" ".join(out[j:n + 1 + after[0]]), " ".join(new)))
        out[j:n + 1 + after[0]] = new
        n = j + len(new)
    return (out, tuple(read)) if read else (words, ())


def _singular(word: str) -> str | None:
    """'buses' -> 'bus', 'jets' -> 'jet': a vehicle's noun said in the plural, or None."""
    return next((word[:-n] for n in (2, 1) if word.endswith("es"[2 - n:]) and word[:-n] in OBJECT_WORDS), None)


def shared_noun_as_two(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the green and blue articulated buses' -> 'the green articulated bus and the blue articulated bus': two
    colours sharing a plural noun are two vehicles (it was read as 'the green' one and the blue bus). With the words
    read so, or the words as they are and ()."""
    out, read, k = list(words), [], 0
    while k < len(out) - 3:
        b = k + 2 + (out[k + 2] == "the")
        end = next((e for e in range(b + 1, min(b + 5, len(out))) if _singular(out[e])), None)
        if out[k] not in COLOR_NAMES or out[k + 1] != "and" or b >= len(out) or out[b] not in COLOR_NAMES or \
                end is None or any(w in COLOR_NAMES or not w.isalpha() for w in out[b + 1:end]):
            k += 1
            continue
        noun = [*out[b + 1:end], _singular(out[end])]
        said = [out[k], *noun, "and", "the", out[b], *noun]
        read.append((" ".join(out[k:end + 1]), " ".join(said)))
        out[k:end + 1] = said
        k += len(said)
    return (out, tuple(read)) if read else (words, ())


def catalogue_names(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """['the', 'crimson', 'dirt', '-', 'bike'] -> (['the', 'red', 'dirtbike'], (('crimson', 'red'), ('dirt-bike',
    'dirtbike'))): every vehicle name of EVERYDAY_NAMES, a sub-type's name hyphenated or run together, a sub-type
    said with its category, and every shade of COLOUR_SHADES, as the catalogue's name; with the names read so."""
    out, read = phrases_as_said(words, _EVERYDAY)
    named = [k for k, w in enumerate(out) if w in NOUN_NAMES and 0 < k and (out[k - 1] in ("the", "a", "that", "this")
             or out[k - 1] in COLOR_NAMES) and not (out[k + 1:k + 2] and out[k + 1] in NAMES_AFTER)]
    for k in named:
        read += ((out[k], NOUN_NAMES[out[k]]),)
        out[k] = NOUN_NAMES[out[k]]
    return out, read


# a spotter's name that is an adjective elsewhere ('the grey heavy' is an airliner; 'the heavy bus', 'the heavy one'
# are not)
NOUN_NAMES = {"heavy": "airliner"}
CATEGORY_SUBTYPES = {c: {v for v, (c2, *_) in SUBTYPES.items() if c2 == c} for c, *_ in SUBTYPES.values()}
NAMES_AFTER = OBJECT_WORDS | {"vehicle", "one", "thing", "object", "-", "traffic", "load", "truck", "lorry", "bike"}


# A colour said after its vehicle ('the bus that is yellow', 'the SUV painted green', 'the scooter, the blue one,')
# or with a word the grammar never puts between colour and vehicle ('the green-coloured SUV'), as the grammar says
# it: colour first. Without it the colour is a second object that no family reads.
COLOUR_CLAUSES = (("that", "is"), ("which", "is"), ("that", "was"), ("which", "was"), ("that", "'", "s"),
                  ("painted",), ("coloured",), ("colored",), ("in",), ("of",), (",", "the"), (",", "a"),
                  ("(", "the"))
COLOUR_WORDS = ("coloured", "colored", "painted", "color")   # 'green-coloured', 'yellow painted', 'red colour'
# ... or straight after it, as Romance languages put it ('the sedan red, how fast ...', 'the bus yellow is moving?'),
# where a comma or a verb follows ('is the bus red?' asks a colour)
AFTER_COLOUR = {",", "is", "was", "does", "did", "has", "had", "will", "would", "moves", "moved", "moving", "goes",
                "going", "hits", "hit", "collides", "collided", "crashes", "crashed", "it", "appears", "appeared",
                "starts", "started", "begins", "began", "comes", "came", "enters", "entered", "first", "are", "were",
                "more", "less", "faster", "slower", "when", "collide", "floating", "hovering", "speeding", "accelerating",
                "flying", "standing", "travelling", "traveling", "driving", "drive", "drives", "drove", ":",
                "participates", "participated", "participate", "takes", "took", "enter", "crash", "crashes",
                # (a translation's bare verb or particle: 'If the bicycle gray let be fast ...', 'the minivan purple
                # strike', 'the airliner green ever have collide')
                "let", "be", "strike", "smash", "bang", "travel", "ever", "parked", "fly", "flies", "flew", "heading",
                "increasing", "increase", "gaining", "picking", "move", "hitting", "colliding", "crashing", "not"}
# ... or a time, where no copula before it asks the colour ('when it hits the bus purple in the moment that ...'; not
# 'is the bus red in the video?'), or the question's end after a comparison's or a collision's object ('faster than
# the car red?'; not 'is the car that gets hit by the bus red?')
AFTER_COLOUR_UNASKED = {"in", "at", "during", "initially", "afterwards", "afterward", "later", "eventually", "then"}
COPULAS_BEFORE = {"is", "was", "are", "were", "be", "been", "'s", "s"}
OBJECT_BEFORE = {"than", "with", "into", "hit", "hits", "against", "to", "of", "bump", "bumps", "bumped", "crash",
                 "strike", "strikes", "struck", "and", "or", "between", "involving",
                 # (a Romance order's verb before its subject: 'in which direction goes the cruiser cyan?')
                 "goes", "go", "moves", "move", "travels", "travel", "drives", "drive"}


def _noun_at(words: list[str], i: int) -> int:
    """How many words from i name a sub-type or category, with no colour (0 when none)."""
    k = i
    while (hit := _value_at(words, k)) and hit[0] not in COLOR_NAMES:
        k += hit[1]
    return k - i


# ... and with no article, as a translation from a language without them puts it ('When sedan brown and pickup purple
# bump each other, ...', 'Minivan yellow and sedan cyan, they hit each other?'): at the start, after a comma, 'and' or
# a preposition, before a comma, a verb or 'and' (never after a copula: 'is bus red?' asks a colour)
NO_ARTICLE_BEFORE = {",", "and", "with", "than", "into", "to", "when", "if", "suppose", "of", "for", "between", ":",
                     "hit", "hits", "crash", "bump", "case", "do", "does", "did", "will", "would", "can", "could",
                     "has", "have", "had"}
NO_ARTICLE_AFTER = {"and", "or", "one", "bump", "bumps", "bumped", "crash", "run", "runs", "go", "stay", "stays",
                    "hover", "hovers", "float", "floats", "turn", "become", "becomes", "still", "just", "they", "have",
                    "at", "in", "start", "move", "with", "only", "already", "not", "from", "accelerating", "yes",
                    "right", "stand", "speed", "collide"}


def _colour_follows(before: list[str], after: str) -> bool:
    """Whether a colour said straight after a vehicle is its own, not asked of it: `before`, the words before the
    vehicle; `after`, the word after the colour."""
    if before[-1:] in (["the"], ["a"], ["an"], ["that"], ["this"]):
        ahead = before[-2] if len(before) > 1 else ""
        return after in AFTER_COLOUR or after in AFTER_COLOUR_UNASKED and ahead not in COPULAS_BEFORE | {""} \
            or after in NO_ARTICLE_AFTER and ahead not in COPULAS_BEFORE \
            or after in ("?", ".") and ahead in OBJECT_BEFORE
    last = before[-1] if before else ""
    return (not before or last in NO_ARTICLE_BEFORE) and (
        after in AFTER_COLOUR | NO_ARTICLE_AFTER or after in ("?", ".") and last in OBJECT_BEFORE)


def _category_before_type_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the plane airliner', 'the car sedan': a category said before a sub-type of it (a translation's classifier)
    names the sub-type; 'the bus articulated', 'the bike mountain': a sub-type's word after its category (a
    Romance language's order) names it too; 'the sedan the red' (Arabic's article on the adjective) is the red
    sedan."""
    out, read, i = [], [], 0
    while i < len(words):
        # a classifier before the vehicle's name ('the vehicle bus regular gray', a Vietnamese or Thai translation's)
        if words[i] in ("vehicle", "object") and out[-1:] == ["the"] and _noun_at(words, i + 1):
            read.append((words[i], "nothing, a classifier"))
            i += 1
            continue
        cat, sub = _value_at(words, i), None
        if cat and cat[0] in CATEGORY_SUBTYPES:
            sub = _value_at(words, i + cat[1])
            turned = _value_at([*words[i + cat[1]:i + cat[1] + 1], *words[i:i + cat[1]]], 0)
            if not sub and turned and turned[0] in CATEGORY_SUBTYPES[cat[0]] and turned[1] == cat[1] + 1:
                said = [words[i + cat[1]], *words[i:i + cat[1]]]
                read.append((" ".join(words[i:i + cat[1] + 1]), " ".join(said)))
                out += said
                i += cat[1] + 1
                continue
        if sub and sub[0] in CATEGORY_SUBTYPES[cat[0]]:
            read.append((" ".join(words[i:i + cat[1] + sub[1]]), " ".join(words[i + cat[1]:i + cat[1] + sub[1]])))
            i += cat[1]
            continue
        n = _noun_at(words, i) if out[-1:] == ["the"] else 0
        if n and words[i + n:i + n + 1] == ["the"] and words[i + n + 1:i + n + 2] and \
                words[i + n + 1] in COLOR_NAMES and not _noun_at(words, i + n + 2) and \
                words[i + n + 2:i + n + 3] not in (["one"], ["thing"], ["vehicle"], ["object"]):
            read.append((" ".join(words[i:i + n + 2]), " ".join([words[i + n + 1], *words[i:i + n]])))
            out += [words[i + n + 1], *words[i:i + n]]
            i += n + 2
            continue
        out.append(words[i])
        i += 1
    return out, tuple(read)


def description_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """['the', 'bus', 'that', 'is', 'yellow'] -> (['the', 'yellow', 'bus'], (('bus that is yellow', 'yellow
    bus'),)): a colour after its vehicle, where the vehicle has no colour before it; the apposition's closing comma
    or bracket goes with it ('the scooter, the blue one, ...'). A colour joined to its vehicle by 'coloured' or
    'painted' loses the word. With the words read so, or the words as they are and ()."""
    words, named = _category_before_type_dropped(words)
    out, read, i = [], [], 0
    while i < len(words):
        n = _noun_at(words, i) if not out or out[-1] not in COLOR_NAMES else 0
        after = words[i + n + 1] if n and i + n + 1 < len(words) else ""
        if n and words[i + n:i + n + 1] and words[i + n] in COLOR_NAMES and after and _colour_follows(out, after):
            one = after == "one" and i + n + 2 < len(words) and words[i + n + 2] in (",", "?", "at", "in")
            out += [words[i + n], *words[i:i + n]]
            read.append((" ".join(words[i:i + n + 1 + one]), " ".join([words[i + n], *words[i:i + n]])))
            i += n + 1 + one
            continue
        clause = next((c for c in COLOUR_CLAUSES if n and tuple(words[i + n:i + n + len(c)]) == c), None)
        if clause:
            j = i + n + len(clause)
            if j < len(words) and words[j] in COLOR_NAMES:
                end = j + 1
                if clause[0] in (",", "("):
                    if words[end:end + 1] != ["one"]:
                        clause = None
                    else:
                        end += 1 + (words[end + 1:end + 2] in ([","], [")"]))
                elif words[end:end + 1] == ["color"]:   # 'the bus in yellow colour', 'the bus of yellow colour'
                    end += 1
                elif clause == ("of",):
                    clause = None
                if clause:
                    out += [words[j], *words[i:i + n]]
                    read.append((" ".join(words[i:end]), " ".join([words[j], *words[i:i + n]])))
                    i = end
                    continue
        if words[i] in COLOR_NAMES:
            k = i + 1 + (words[i + 1:i + 2] == ["-"])
            if words[k:k + 1] and words[k] in COLOUR_WORDS and _noun_at(words, k + 1):
                out.append(words[i])
                read.append((" ".join(words[i:k + 1]).replace(" - ", "-"), words[i]))
                i = k + 1
                continue
        out.append(words[i])
        i += 1
    return out, named + tuple(read)


# A vehicle named by its attributes in clauses, as a database is queried ('the vehicle that is a sedan and is red',
# 'the item with colour blue and type SUV', 'the object of category bus with colour brown', 'the double-decker whose
# colour is purple', 'the one that's a scooter'): the grammar's 'the red sedan'. Only a colour or a kind is taken;
# anything else ('the one that is moving') leaves the words alone.
ATTRIBUTE_HEADS = {"vehicle", "thing", "object", "one", "item", "entity", "toy"}
ATTRIBUTE_NAMES = {"color": "color", "category": "kind", "type": "kind", "kind": "kind", "class": "kind",
                   "shape": "kind", "model": "kind"}
_ATTRIBUTE_LINKS = sorted({("that", "is"), ("which", "is"), ("that", "was"), ("which", "was"), ("that", "'", "s"),
                           ("which", "'", "s"), *((w, "@", b) for w in ("whose",) for b in ("is", "was")),
                           *((w, *the, "@") for w in ("with", "having", "of", "in") for the in ((), ("the",)))},
                          key=len, reverse=True)
_AFTER_AND = (("is",), ("was",), ("@",))   # 'the vehicle that is a car and is yellow', '... and colour red'


def _attribute_clause(words: list[str], k: int) -> tuple[str, list[str], int] | None:
    """The attribute a clause from words[k] gives ('color' or 'kind'), its value and where the clause ends."""
    sep = next((n for n in ([",", "and"], [","], ["and"], []) if words[k:k + len(n)] == n), [])
    for link in [*_ATTRIBUTE_LINKS, *(_AFTER_AND if sep and sep[-1] == "and" else ())]:
        j, said = k + len(sep), None
        for w in link:
            if w == "@" and words[j:j + 1] and words[j] in ATTRIBUTE_NAMES:
                said = ATTRIBUTE_NAMES[words[j]]
            elif words[j:j + 1] != [w]:
                break
            j += 1
        else:
            j += words[j:j + 1] in (["a"], ["an"])
            n = _noun_at(words, j)
            value = ("kind", words[j:j + n]) if n else ("color", words[j:j + 1]) if words[j:j + 1] and \
                words[j] in COLOR_NAMES else None
            if value and said in (None, value[0]):
                return value[0], value[1], j + len(value[1])
    return None


def attributes_as_named(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """['the', 'item', 'with', 'color', 'blue', 'and', 'type', 'suv'] -> ['the', 'blue', 'suv']: a vehicle named by
    its colour and kind in clauses after a head word or its kind; a clause after a comma takes its closing comma.
    With the words read so, or the words as they are and ()."""
    out, read, i = [], [], 0
    while i < len(words):
        n = 1 if words[i] in ATTRIBUTE_HEADS else _noun_at(words, i)
        if not n or not out or out[-1] not in ("the", "a", "an", "that", "this", "any"):
            out.append(words[i])
            i += 1
            continue
        said, j = {}, i + n
        while (clause := _attribute_clause(words, j)) and clause[0] not in said:
            said[clause[0]] = clause[1]
            commaed = words[j] == ","
            j = clause[2] + (commaed and words[clause[2]:clause[2] + 1] == [","])
        kind = said.get("kind") if words[i] in ATTRIBUTE_HEADS else None if "kind" in said else words[i:i + n]
        if not said or kind is None and "color" not in said:
            out += words[i:i + n]
            i += n
            continue
        named = [*said.get("color", []), *(kind or words[i:i + n])]
        read.append((" ".join(words[i:j]), " ".join(named)))
        out += named
        i = j
    return (out, tuple(read)) if read else (words, ())


_CHAIN = re.compile(r"Objects((?: filter_attributes\[[a-z_]+\])+) unique")
_PLACEHOLDER = re.compile(r"<obj(\d+)>")
_VALUE = re.compile(r"\[([a-z_]+)\]")
Ref = tuple[str, ...]


_NAMES_BY_FIRST: dict[str, list[tuple[Ref, str]]] = {}
for _name, _value in _NAMES:   # the longest first, as in _NAMES
    _NAMES_BY_FIRST.setdefault(_name[0], []).append((_name, _value))


def _value_at(words: list[str], i: int) -> tuple[str, int] | None:
    for name, value in _NAMES_BY_FIRST.get(words[i], ()) if i < len(words) else ():
        if tuple(words[i:i + len(name)]) == name:
            return value, len(name)
    return None


def is_description(ref: Ref) -> bool:
    """One object's words: at most a colour, then at most a sub-type or category ('red sedan', 'bus', 'cyan')."""
    colors = [v for v in ref if v in COLOR_NAMES]
    return len(ref) <= 2 and len(colors) <= 1 and (not colors or ref[0] in COLOR_NAMES) and len(ref) - len(colors) <= 1


def mentions(words: list[str]) -> list[tuple[int, int, Ref]]:
    """Each run of attribute words as (first, past-last) word and the values it names: ['is', 'the', 'red', 'sedan',
    'fast'] -> [(2, 4, ('red', 'sedan'))]."""
    out, i = [], 0
    while i < len(words):
        start, run = i, []
        while i < len(words) and (hit := _value_at(words, i)):
            run.append(hit[0])
            i += hit[1]
        if run:
            out.append((start, i, tuple(run)))
        else:
            i += 1
    return out


def delexicalise(words: list[str]) -> tuple[list[str], list[Ref]]:
    """['is', 'the', 'red', 'sedan', 'static', '?'] -> (['is', 'the', '<obj1>', 'static', '?'], [('red', 'sedan')])."""
    out, refs, i = [], [], 0
    while i < len(words):
        run = []
        while i < len(words) and (hit := _value_at(words, i)):
            run.append(hit[0])
            i += hit[1]
        if run:
            if tuple(run) not in refs:
                refs.append(tuple(run))
            out.append(f"<obj{refs.index(tuple(run)) + 1}>")
        else:
            out.append(words[i])
            i += 1
    return out, refs


def generalises(short: Ref, full: Ref) -> bool:
    """Every word of `short` says something `full` says: one of its values, or the category of its sub-type
    ('the bus' of 'the yellow double bus', 'the dirtbike' of 'the gray dirtbike')."""
    said = set(full) | {SUBTYPES[v][0] for v in full if v in SUBTYPES}
    return set(short) <= said


_JOINING = {",", "and", "or", "nor", "the", "a", "an", "both", "either", "neither"}


def coordinated(words: list[str]) -> set[tuple[int, int]]:
    """Pairs of references (0-based) in one list joined by 'and', 'or' or 'nor' ('A , B and C')."""
    pairs, group, joined, between = set(), [], False, []
    for w in words + ["."]:
        m = _PLACEHOLDER.fullmatch(w)
        if m and (not group or all(b in _JOINING for b in between)):
            joined |= bool(group) and bool({"and", "or", "nor"} & set(between))
            group.append(int(m.group(1)) - 1)
            between = []
        elif m or w not in _JOINING:
            if joined:
                pairs |= {(a, b) for a in group for b in group if a != b}
            group, joined, between = ([int(m.group(1)) - 1], False, []) if m else ([], False, [])
        else:
            between.append(w)
    return pairs


def corefer(words: list[str], refs: list[Ref]) -> tuple[list[str], list[Ref]]:
    """A shorter mention of an object as the placeholder of its fuller one, said before or after it: 'When the cyan
    mountain bike hits the yellow double bus, is it slower than *the bus*?', 'Is *the airliner* fast when the blue
    airliner and the green scooter collide?'. A question's references each pick out one object of the scene, so a
    reference that generalises another can only be that object again (were it another, the fuller one would not be
    unique). Only where exactly one other reference fits; the placeholders are then numbered again in order of first
    mention, as training numbers them. Parsing only: the training questions' random objects need not be unique, so
    training scores them without it (`QuestionParser.corefer`). Mentions joined by 'and' or 'or' ('the bus and the
    school bus') are told apart by the question itself, so neither is read as the other."""
    apart = coordinated(words)
    fuller = {k: [j for j, r in enumerate(refs) if r != ref and generalises(ref, r) and (k, j) not in apart]
              for k, ref in enumerate(refs)}
    root = list(range(len(refs)))
    for k, js in fuller.items():
        # of several, the one whose words it says again ('When the purple car and the brown truck collide, is the
        # car faster?': a truck is a car too, but the speaker echoes 'car')
        echoed = [j for j in js if set(refs[k]) <= set(refs[j])]
        if len(js) == 1 or len(echoed) == 1:
            root[k] = js[0] if len(js) == 1 else echoed[0]
    for k in range(len(refs)):   # 'bus' -> 'double bus' -> 'yellow double bus'
        seen = {k}
        while root[root[k]] != root[k] and root[root[k]] not in seen:
            seen.add(root[k])
            root[k] = root[root[k]]
    if root == list(range(len(refs))):
        return words, refs
    said = [root[int(m.group(1)) - 1] if (m := _PLACEHOLDER.fullmatch(w)) else w for w in words]
    order = list(dict.fromkeys(w for w in said if isinstance(w, int)))
    out = [f"<obj{order.index(w) + 1}>" if isinstance(w, int) else w for w in said]
    return out, [refs[k] for k in order]


def abstract_program(tokens: list[str], refs: list[Ref]) -> list[str]:
    """A program's filter chains -> the question's placeholders; ValueError if a chain names no run of the question."""
    def sub(m: re.Match) -> str:
        values = tuple(_VALUE.findall(m.group(1)))
        return f"<obj{refs.index(values) + 1}>"

    return _CHAIN.sub(sub, " ".join(tokens)).split()


def concrete_program(tokens: list[str], refs: list[Ref]) -> list[str] | None:
    """Placeholders -> filter chains; None if a placeholder names no object of the question."""
    out = []
    for t in tokens:
        m = _PLACEHOLDER.fullmatch(t)
        if not m:
            out.append(t)
        elif 1 <= int(m.group(1)) <= len(refs):
            out += ["Objects", *[f"filter_attributes[{v}]" for v in refs[int(m.group(1)) - 1]], "unique"]
        else:
            return None
    return out


def placeholders(tokens: list[str]) -> set[int]:
    return {int(m.group(1)) for t in tokens if (m := _PLACEHOLDER.fullmatch(t))}
