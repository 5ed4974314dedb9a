"""Word sets that more than one stage of the question parser reads (the surface readings, asides, context, times,
wordings, refusals and checks, and `QuestionParser` itself), at the bottom of their imports; with the three small
readings of them those stages share: where one of some phrases is said (`_at`), a question's head after a clause of time
said first (`_head`), and whether it speaks of a collision (`asks_impact`)."""

from __future__ import annotations

from difflib import SequenceMatcher

from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.language.references import CATEGORY_SAID, OBJECT_WORDS
from dynclevr.language.tokenize import tokenize
from dynclevr.questions.generate import templates

DURATIONS = {"duration", "durations", "lasts", "lasted", "lasting"}   # 'the duration for which it stays parked'
NUMBERS = {"two", "three", "four", "five", "2", "3", "4", "5"}
PLURALS = {"vehicles", "objects", "things", "cars", "buses", "bikes", "bicycles", "motorbikes", "planes", "aeroplanes",
           "airplanes", "collisions", "crashes", "others", "ones"}


# Words a speaker opens with that ask nothing ('So, um, does ...', 'Hmm... is it ...', 'Okay, right, what ...'). The
# decoder looks past one such unknown word, not a run of them with their commas. 'right', 'now' and 'like' only with
# a comma after them: 'Right at the start, is ...' opens with a time.
CHAT = {"ngl", "tbh", "idk", "imo", "imho", "fr", "smh", "omg", "lowkey", "srsly", "tbf"}   # a chat's asides
INTERJECTIONS = {"so", "um", "umm", "uh", "uhm", "er", "erm", "hmm", "hm", "well", "ok", "okay", "alright", "oh", "ah",
                 "hey", "anyway", "anyways", "yo", "hi", "hello", "dear", "greetings", "good", "morning", "afternoon",
                 "evening", "sure", "roger", "copy", "dude", "bro",
                 # a fan's Japanese ('yabai, was the cyan one ...', 'sugoi!')
                 "yabai", "sugoi", "nani", "kawaii", "ara", "hontou", "desu", "uwu", "owo",
                 # and Gen-Alpha's ('gyatt when the bike smashes into ...')
                 "gyatt", "bruh", "skibidi",
                 # and a showman's ('Wowee, what a smash, ...')
                 "wow", "wowee", "whoa", "gosh", "golly", "yikes", "jeez",
                 # and a weary viewer's ('Ugh, right, the brown SUV at the beginning: ...')
                 "ugh", "argh", "meh",
                 # a cab driver's horn, a New Yorker's 'nu' and 'oy'
                 "honk", "beep", "nu", "oy", "oi", "shh", "shhh", "psst"} | CHAT
COMMA_INTERJECTIONS = {"right", "now", "like"}
# a code-switcher's or a regional English's particles, said before a clause's comma as well as last ('the video stops
# halfway na, so ...', 'it hits the bus lah, or not?')
PARTICLES = {"lah", "leh", "lor", "abi", "na", "yaar", "diba", "naman", "po", "sha", "ah", "wor"}   # (Hong Kong's 'ah')
# a streamer's chat's emotes, said anywhere ('Green car meets red bus KEKW, is ...', 'paused here chat PauseChamp,')
STREAM_EMOTES = {"kekw", "monkas", "monkaw", "pog", "pogchamp", "poggers", "pogu", "lul", "lulw", "omegalul", "kappa",
                 "sadge", "pepega", "copium", "pausechamp", "modcheck", "pepehands", "pepelaugh", "peeposad",
                 "weirdchamp", "residentsleeper", "biblethump", "wutface", "notlikethis", "kreygasm", "catjam",
                 "5head", "3head", "feelsbadman", "feelsgoodman", "hypers", "jebaited", "widepeepohappy", "monkahmm"}
FILLERS = {"um", "umm", "uh", "uhh", "uhm", "er", "erm", "hmm", "already", "literally", "basically", "seriously",
           "honestly", "quite", "totally", "whatsoever", "indeed", "plumb", "pray"} | STREAM_EMOTES
# ... and the chat's words it closes with ('does the bus hit anything lol': the decoder turned on the unknown word)
CLOSING_INTERJECTIONS = {"lol", "lmao", "rofl", "haha", "hahaha", "xd", "pls", "plz", "thx", "ty", "tia", "btw",
                         "thanks", "cheers", "tho",
                         # and the particles regional Englishes close with ('they collide or not, lah?', '..., abi?')
                         "lah", "leh", "lor", "abi", "innit", "eh", "mate", "ken", "yeah", "na", "yaar", "diba",
                         "naman", "po", "sha", "ah", "wor",
                         # ... and a radio's ('..., affirmative?'; not 'over', which may end a video)
                         "affirmative", "roger", "ne", "desu", "nani",
                         # ... and a streamer's chat's emotes ('does it hit anything KEKW')
                         "gyatt", "bruh", "skibidi", "ong"} | STREAM_EMOTES | CHAT


SENTENCE_ENDS = {".", "!", "?"}
CLAUSE_MARKS = {",", ":", ";"} | SENTENCE_ENDS
# a sentence of context that imagines something otherwise, but not as a condition read here: the question is left
# whole ('if' only where a clause of it imagines: 'I can't tell if it's moving' asks whether); said alone, it makes
# the next sentence the condition ('ok weird what-if. the biplane is accelerating from the beginning instead.')
IMAGINED_SAID = {"suppose", "supposing", "imagine", "assume", "assuming", "pretend", "hypothetically",
                 "hypothetical", "instead", "otherwise", "wish", "scenario", "counterfactual", "counterfactually",
                 "intervention", "hypothesis", "alternate", "alternative", "posit", "postulate"}
# a condition given a label ('Counterfactual: the pickup moves slowly from the first frame.', 'Intervention: ...')
CONDITION_LABELS = {"counterfactual", "intervention", "hypothetical", "hypothesis", "scenario", "what-if", "if",
                    "alternative", "alternate", "change", "suppose", "assume", "imagine", "timeline", "universe",
                    "whatif", "twist", "cf", "variable", "treatment", "manipulation", "manipulate",
                    "contingency",   # mission control's ('Contingency: if the cyan aeroplane had been ...')
                    "variation", "variant", "tweak", "modification", "alteration", "perturbation",   # a physicist's
                    "ablation",   # a data scientist's
                    "conjecture", "speculation", "supposition"}   # a field log's
# ... of them, a label that makes what follows imagined ('Hypothetical: brown SUV starts slow -> collision with ...?')
IMAGINING_LABELS = {"assume", "assuming", "hypothetical", "hypothetically", "counterfactual", "cf", "what-if", "whatif",
                    "intervention", "alt"}   # a chat's 'alt timeline: red pickup starts fast -> ...
# A vehicle the context describes without naming ('Something hits the cyan jet. What colour is it?',
# 'The SUV hits a vehicle. What kind of vehicle is that?'): the question is left whole, which reads it so
UNNAMED = {"something", "someone", "somebody"}
GENERIC = {"vehicle", "vehicles", "thing", "things", "object", "objects", "toy", "toys", "one", "other"}
UNMOVED = {"budges", "budged", "budge", "moves", "moved", "move"}   # after 'never'
CATEGORY_OF = {**{v: c for v, (c, *_) in SUBTYPES.items()}, **{c: c for c, *_ in SUBTYPES.values()}}
SHAPE_ASKED = ("type", "kind", "sort", "shape", "model", "category", "class")   # the words that ask a vehicle's type


# colours no catalogue colour is (references.COLOUR_SHADES reads those that are one)
OTHER_COLOURS = {"pink", "orange", "white", "black", "silver", "navy", "teal", "tan", "khaki", "magenta", "beige",
                 "cream", "ivory", "lime", "olive", "peach", "coral", "lavender", "rose", "mauve", "copper", "amber",
                 "lilac", "fuchsia", "rainbow", "striped", "spotted"}
# vehicles no video shows ('what colour is the boat floating ...' was read as the floating vehicle's colour)
OTHER_VEHICLES = {"boat", "boats", "ship", "ships", "train", "trains", "tram", "trams", "tractor", "tractors",
                  "helicopter", "helicopters", "drone", "drones", "balloon", "balloons", "rocket", "rockets",
                  "skateboard", "skateboards", "submarine", "yacht", "canoe", "kayak", "horse", "horses", "cart",
                  "carts", "blimp", "zeppelin", "spaceship", "ufo", "taxi", "ambulance", "limo", "limousine",
                  "locomotive", "locomotives", "glider", "gliders", "hovercraft"}

NOUNS_SAID = {w for said in CATEGORY_SAID.values() for w in said if " " not in w}
NAMING = OBJECT_WORDS | NOUNS_SAID   # the words of a vehicle's name


RESTING = {"sitting", "resting", "standing", "being", "parked", "lying", "staying", "sat", "stood"}
HEADING_KEPT = {"end", "ends", "finish", "after", "before", "once", "when", "while", "later", "future", "beyond",
                "first", "last", "moment", "instant", "frame", "frames", "time", "true", "false", "yes", "no",
                "past", "predicted", "rollout", "cutoff"}


AFLOAT_SAID = {"floating", "hovering", "airborne", "flying"}
QUESTION_OPENERS = {"is", "was", "are", "were", "do", "does", "did", "will", "would", "can", "could", "has", "have",
                    "how", "what", "which", "where"}
DEFINITE = {"the", "that", "this", "a", "an"}


IMPERATIVES = (["tell", "me"], ["describe"], ["give", "me"], ["state"], ["name"])   # not "say": "say it had been ..."
# requests for a property or a vehicle, never for yes or no ('identify the colour of the plane that floats')
ASKING_FOR = (*IMPERATIVES, ["identify"], ["determine"], ["report"], ["find"], ["give"], ["list"])
AGREEING_TAGS = (["right"], ["correct"], ["true"], ["yes"], ["no"], ["or", "not"], ["or", "nah"], ["or", "nope"],
                 ["is", "that", "right"], ["is", "that", "correct"], ["am", "i", "right"], ["am", "i", "correct"],
                 ["would", "you", "say", "so"], ["right", "or", "wrong"], ["is", "that", "true"], ["is", "it", "true"],
                 ["is", "that", "the", "truth"], ["is", "that", "the", "truth", "of", "it"],
                 ["straight", "up"], ["for", "real"], ["no", "cap"], ["deadass"], ["fr"])   # and slang's
# ... of them, those that ask alone whether what was said before is right ('? Is that right?', '. True or false?')
CHECKING_TAGS = [t for t in AGREEING_TAGS if len(t) > 2] + [["true", "or", "false"]]


MOTION_NOUNS = {"speed", "velocity", "direction", "heading"}
CLASS_NOUNS = {"class", "category", "group", "bracket", "band"}   # a speed's ('which speed class is it in?')
ATTRIBUTE_NOUNS = {"color", "shape", "type", "kind", "sort"}
QUERY_NOUNS = MOTION_NOUNS | ATTRIBUTE_NOUNS


IMAGINING = {"picture", "envision", "envisage", "visualise", "visualize"}   # said first: 'imagine' (not 'the picture')
# what a question says of a world imagined before it ('In that world, does it ...?', 'in such a case')
IMAGINED_BACK = tuple((p, *d, n) for p in ("in", "within") for d in (("that",), ("this",), ("such",), ("such", "a"),
                                                                      ("the",)) for n in (
    "world", "case", "scenario", "version", "timeline", "universe", "situation", "alternate", "telling", "retelling",
    "tale", "story", "ruling", "reality", "history", "past"))


# Comparisons of speed: offered as a choice ('is X faster or slower than Y?') they ask which, which no family answers
SPEED_ORDER = {"faster": 1, "quicker": 1, "speedier": 1, "slower": -1}
COMPARISONS = set(SPEED_ORDER)


# What a question offers to choose from ('is it fast or slow?', 'is it going left or right?'), each by the words that
# say it; the grammar's list of the choices asks which one
SPEED_CHOICES = {**{(w,): "static" for w in ("static", "stationary", "still", "parked", "motionless", "stopped",
                                              "stop")},
                 **{("not", *m, *a): "static" for m in (("moving",), ("going",), ("travelling",), ("traveling",),
                                                          ("in", "motion")) for a in ((), ("at", "all"))},
                 # 'moving fast, slowly, or not at all', 'or standing still'
                 ("not", "at", "all"): "static", ("standing", "still"): "static", ("at", "rest"): "static",
                 # a learner's 'it stands, goes slow or fast?'
                 ("standing",): "static", ("stands",): "static",
                 **{(g, s): s for g in ("go", "goes") for s in ("slow", "fast")},
                 ("slow",): "slow", ("slowly",): "slow", ("fast",): "fast", ("quickly",): "fast", ("quick",): "fast",
                 ("rapidly",): "fast", ("chill",): "slow",   # a game's chat: 'afk, chill or full send?'
                 # everyday words offered ('is it sat there, pottering along, or zipping about?')
                 **{w: "static" for w in (("sat", "there"), ("sitting", "there"), ("sitting", "still"), ("idle",),
                                          ("not", "budging"), ("at", "a", "standstill"), ("idling",))},
                 **{w: "slow" for w in (("crawling",), ("dawdling",), ("creeping",), ("pottering",), ("plodding",),
                                        ("trundling",), ("moving", "slowly"), ("going", "slowly"), ("going", "slow"),
                                        ("moving", "slow"), ("sluggish",), ("leisurely",), ("creeping", "along"),
                                        ("crawling", "along"))},
                 **{w: "fast" for w in (("speeding",), ("racing",), ("hurrying",), ("zipping",), ("zooming",),
                                        ("whizzing",), ("rushing",), ("speedy",), ("swift",), ("swiftly",),
                                        ("zipping", "about"), ("zipping", "along"), ("whizzing", "along"),
                                        ("moving", "fast"), ("going", "fast"), ("moving", "quickly"),
                                        *((w, "by") for w in ("zipping", "whizzing", "zooming", "speeding", "racing",
                                                              "rushing")))}}
VIEWER = (("us",), ("me",), ("the", "camera"), ("the", "viewer"))
DIRECTION_CHOICES = {**{(w,): w for w in ("left", "right", "up", "down", "front", "back")},
                     ("upwards",): "up", ("upward",): "up", ("downwards",): "down", ("downward",): "down",
                     ("forward",): "front", ("forwards",): "front", ("backward",): "back", ("backwards",): "back",
                     ("away",): "back", **{(t, *v): "front" for t in ("towards", "toward") for v in VIEWER},
                     **{("away", "from", *v): "back" for v in VIEWER}}
# a video stopped part-way, as a predictive question says it ('given that the video is halted partway through')
STOPPED_SAID = (["stop"], ["stops"], ["stopped"], ["halted"], ["paused"], ["frozen"], ["froze"], ["freezes"],
                ["drops"], ["dropped"], ["drops", "out"], ["dropped", "out"], ["halts"],   # a feed's
                *([e, early] for e in ("ends", "ended", "finishes", "finished") for early in ("early", "abruptly")),
                ["cut", "off"], ["breaks", "off"], ["broke", "off"], ["broken", "off"],   # 'after the footage breaks off'
                ["cuts", "off"], ["cuts", "out"], ["cut", "out"], ["cuts"], ["cut"], ["terminates"], ["terminated"],
                ["cut", "short"], ["is", "cut", "short"], ["was", "cut", "short"], ["'", "s", "cut", "off"],
                ["'", "s", "cut", "short"], ["is", "truncated"], ["was", "truncated"],
                *([v, p] for v in ("is", "was", "were", "gets", "got")   # 'if the clip were paused'
                  for p in ("stopped", "halted", "paused", "frozen", "cut")),
                *([*h, p] for h in (["has", "been"], ["having", "been"], ["having"])   # 'The video having been
                  for p in ("stopped", "halted", "paused", "frozen", "cut")),             # stopped part-way, ...'
                *([*v, "cut", "off"] for v in (["is"], ["was"], ["gets"], ["got"], ["has", "been"])),
                *(["'", "s", *been, p] for p in ("stopped", "halted", "paused", "frozen") for been in ((), ("been",))),
                # learners' ('Video is stopping in the middle', 'Video is cut in between')
                ["is", "stopping"], *([*v, "cut", "in", "between"] for v in ((), ("is",), ("was",))),
                # a narrator's ('Our footage falls silent part-way through.')
                *([f, "silent"] for f in ("falls", "fell", "goes", "went", "gone")))
START_ADJECTIVES = {"initial", "starting", "start", "beginning", "first", "opening"}
REST_WORDS = {"static", "stationary", "still", "stop", "stops", "stopped", "stopping", "parked", "park", "rest",
              "motionless", "standing", "stand", "stands", "stood", "standstill", "halt", "halted", "idle", "stay",
              "stays", "stayed", "put", "kept", "frozen", "immobile", "unmoving", "resting", "without"}
MOTION_WORDS = {"moving", "move", "moves", "moved", "motion", "driving", "going", "travelling", "traveling",
                "rolling", "flying", "running", "underway"}
NEGATIONS = {"not", "never", "nothing", "neither", "nor", "non"}
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
ENGINE_WORDS = {"engine", "motor", "power", "throttle"}   # 'its engine off': not accelerating


# What a question asks is said at its head ('what is the speed of', 'how fast is', 'what colour is', 'where is it
# heading'): a word there the parser does not know is the property asked, and no other word tells the decoder what
# it is ('what is the mass of the jet' read as a collision partner's colour, 'how heavy is it' as its speed).
ASKING = {"what", "which"}
COPULAS = {"is", "was", "are", "were", "s", "'"}
AUXILIARIES = COPULAS | {"does", "did", "do"}


ROUGHLY = (["exactly"], ["precisely"], ["just"], ["about"], ["roughly"], ["around"])   # 'at about what time'
# the words that say a comparison of speed, the grammar's phrasings of FASTER and SLOWER among them
COMPARING = COMPARISONS | {"than", "more", "less", "higher", "lower", "greater", "swifter", "compared", "compare"}


# Words of a direction or a place: only the direction queries ask about them (no question asks whether a vehicle
# moves one way, or where it is); 'up' and 'down' say other things too ('speeding up', 'slowing down'), and 'right'
# a time ('right at the start')
DIRECTION_WORDS = {"left", "right", "front", "back", "forward", "forwards", "backward", "backwards", "leftward",
                   "leftwards", "rightward", "rightwards", "upward", "upwards", "downward", "downwards", "reverse",
                   "reversing", "reversed", "reverses"}
LANDING = {"land", "lands", "landed", "landing"}   # said of a plane: 'is it about to land?' (a landing)


# The motions a question asks one at a time, by the words that say them: 'is it moving fast and accelerating?' was
# read as one of them
MOTION_KINDS = {**{w: "speed" for w in ("moving", "fast", "quick", "quickly", "rapidly", "slow", "slowly", "static",
                                        "stationary", "parked", "stopped", "motionless")},
                **{w: "accelerating" for w in ("accelerating", "speeding", "gaining")},
                **{w: "floating" for w in ("floating", "hovering", "airborne", "afloat", "aloft")}}


CONDITION_OPENERS = {"if", "had", "suppose", "supposing", "imagine", "assuming"}


# A change at a time after the start ('at the end', 'halfway', 'after the collision'); 'the whole time' and 'always'
# are from the start on, as every intervention here is
LATER_TIMES = (["middle"], ["halfway"], ["half", "way"], ["midway"], ["midpoint"], ["mid", "-", "point"],
               ["later"], ["eventually"], ["afterwards"],
               ["at", "some", "point"], ["at", "one", "point"], ["now"])


# sizes and materials (CLEVR's, not DynSuperCLEVR's): before a vehicle's colour or kind they only describe it
# (`asides.owners_dropped`); asked, compared or alone ('the big one') they are refused
MATERIALS = {"shiny", "metallic", "metal", "matte", "rubber", "plastic", "wooden"}
LOOKS = {"small", "big", "large", "tiny", "huge", "little", "giant"} | MATERIALS
YES_NO_OPENERS = AUXILIARIES | {"will", "would", "can", "could", "has", "have", "had", "should", "are", "were"}
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
# the words that say a vehicle floats: the grammar's, people's ('afloat', 'off the ground', 'never touched the
# ground', 'above'), and what the lexicon reads as them
FLOATING_WORDS = {"floating", "float", "floats", "floated", "air", "airborne", "hovering", "hover", "hovers",
                  "hovered", "flying", "fly", "flies", "flew", "aloft", "afloat", "levitate", "levitating", "ground",
                  "above", "hanging", "midair", "sky", "up", "flight", "airplane"} | LANDING   # 'had it never landed'
# how a vehicle moves, said to describe one: no collision question picks its partner so ('hit a parked vehicle')
MOTION_DESCRIPTIONS = (SPEED_CLASS_WORDS - {"still"}) | {"parked", "stationary", "static", "stopped", "motionless",
                                                        "floating", "hovering", "airborne", "accelerating"}
STATIC_SAID = {"static", "stationary", "parked", "stopped", "motionless", "rest", "idle", "standing", "stand",
               "stands", "not", "never", "immobile", "unmoving"}


# the asked word and the query that answers it
ASKED_QUERIES = {**{w: "query_moving_velocity" for w in ("speed", "velocity")},
                 **{w: "query_moving_direction" for w in ("direction", "heading")},
                 **{w: "query_attributes[color]" for w in ("color", "colour")},
                 **{w: "query_attributes[shape]" for w in SHAPE_ASKED}}
PARTNER_SAID = {"that", "which", "who"}
# the grammar's words for accelerating: 'how quickly is it speeding up?' asks how much it accelerates
ACCELERATION_SAID = tuple(tokenize(phrase) for key in ("ACCELERATING", "ACCELERATE") for pool in ("seen", "heldout")
                          for phrase in templates()["lexicon"][key][pool])


END_WORDS = {"end", "ends", "ended", "ending", "endeth", "finish", "finishes", "finished", "finale", "conclusion",
             "culmination", "denouement", "termination"}


ATTRIBUTE_SAID = {w for w, query in ASKED_QUERIES.items() if query.startswith("query_attributes")} | {
    "coloured", "colored", "colours", "colors", "category", "make"}
FUTURE_CUES = {"will", "would", "going", "gonna", "later", "after", "future", "next", "predict", "predicted",
               "expect", "expected", "eventually", "soon", "continue", "continues", "continued", "kept", "keeps", "ll",
               "shall", "beyond", "afterwards", "afterward", "then", "upcoming", "remaining", "rest", "follow",
               "follows", "following", "anticipate", "ends", "end", "over", "finished", "done"}


# ... and the video stopped, said in words a predictive question may use alone ('once the clip is halted, does ...')
STOP_CUES = {w for stop in STOPPED_SAID for w in stop if w.isalpha() and w not in {"is", "was", "gets", "got", "s"}} \
    | {"hereafter", "thereafter", "past", "forecast", "forecasting", "projected", "extrapolate", "extrapolating",
       "ahead", "onward", "onwards", "resumes", "prediction", "predicting", "destined", "freeze", "paused", "cutoff",
       "truncation"}


INDEFINITES = {"anything", "something", "anyone", "someone", "anybody", "somebody"}
SPEED_NOUNS = {"speed", "velocity", "pace", "momentum"}


# Words that open a clause saying when: 'At the moment the bus hits it, is the bike parked?'.
TIME_OPENERS = {"at", "when", "during", "in", "as", "on", "upon", "while", "just", "right", "once"}
# the conjunctions that open a clause of time ('when it hits the bus , ...', 'once the bike shows up , ...')
CLAUSE_CONJUNCTIONS = {"when", "whenever", "once", "while"}
# ... unless it is a counterfactual's condition ('In case X had stopped, would it hit Y?'), whose 'it' must follow it
CONDITION_WORDS = {"had", "were", "case", "world", "if", "suppose"}


DETERMINERS = {"the", "a", "an", "that", "this"}
GENERIC_NOUNS = {"thing", "object", "vehicle", "one"}


COMES_IN_WORDS = {"appear", "appears", "enter", "enters", "shows", "show", "comes", "come", "visible", "view", "pops",
                  "pop"}
IMPACT_STEMS = ("impact", "collid", "collision", "hit", "crash", "bump", "strik", "struck", "smash", "slam", "contact",
                "touch", "bang", "knock", "ram", "accident", "meet", "fender", "wreck", "pileup", "clash", "crunch",
                "shunt", "tangl")
# ... and words that only begin like one ('a load ramping on the circuit', 'at random')
NOT_IMPACTS = ("ramp", "random", "rambl")
# 'comes into view', 'swims into focus'
SIGHT_WORDS = {"view", "sight", "frame", "picture", "scene", "shot", "camera", "focus"}

# The video's end said as a time ('at the end of the clip', 'in the last frame')
END_TIMES = [[p, *the, *very, e] for p in ("at", "by", "towards", "toward", "near") for the in ((), ("the",))
             for very in ((), ("very",)) for e in ("end", "finish", "close", "conclusion", "finale", "ending")] + \
    [["end", "of", f] for f in ("video", "clip", "footage", "film")] + \
    [[*p, *the, *very, a, *few, f] for p in (("in",), ("at",), ("during",), ()) for the in (("the",), ())
     for very in ((), ("very",)) for a in ("last", "final", "closing")
     for few in ((), ("few",), ("couple", "of")) for f in ("frame", "frames", "second", "seconds", "moment", "moments",
                                                         "timestep", "timesteps", "instant", "instants", "stage",
                                                         "stages", "part", "whistle", "shot", "shots", "scene",
                                                         "scenes", "timestamp", "image", "bit", "reel")]
START_WORDS = {"start", "starts", "started", "beginning", "begins", "begin", "began", "begun", "initially", "opening",
               "outset", "onset"}


_STARTS: dict[int, tuple[object, dict[str, list[tuple]]]] = {}


def phrase_starts(phrases) -> dict[str, list[tuple]]:
    """A module's phrases by their first word, each a tuple, in their order, made once: a scan of a question for
    any of thousands of phrases (`END_TIMES`) then tries only those that start with the word it is at (trying all
    at every word was a third of the parser's time)."""
    made = _STARTS.get(id(phrases))
    if made is None or made[0] is not phrases:
        starts: dict[str, list[tuple]] = {}
        for p in phrases:
            starts.setdefault(p[0], []).append(tuple(p))
        made = _STARTS[id(phrases)] = (phrases, starts)
    return made[1]


def _at(words: list[str], phrases) -> tuple[int, tuple] | None:
    """The first place in `words` that says one of a module's `phrases`, and the first phrase said there."""
    starts, after = phrase_starts(phrases), [*words[1:], ""]
    return next(((k, p) for k, w in enumerate(words) for p in starts.get(w, ())
                 if (len(p) == 1 or p[1] == after[k]) and tuple(words[k:k + len(p)]) == p), None)


def impact_like(word: str) -> bool:
    """Whether an unknown word may be an impact's word misspelt ('collied', 'crahsed', 'tocuh'), which the decoder
    reads a collision in from the rest of the question; 'too', 'while' are not."""
    return any(SequenceMatcher(None, word[:len(s) + 1], s).ratio() >= 0.7 for s in IMPACT_STEMS)


def asks_impact(words: list[str]) -> bool:
    """Whether the question is about collisions: an impact's word ('collides', 'struck'), 'into' not of coming
    into view ('runs into', 'bangs into'), or 'come together'."""
    return any(w.startswith(IMPACT_STEMS) and not w.startswith(NOT_IMPACTS)
               or w == "into" and not set(words[k + 1:k + 3]) & SIGHT_WORDS
               or w == "together" and words[k - 1:k] in (["come"], ["comes"], ["came"], ["coming"])   # 'come together'
               for k, w in enumerate(words))


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
# the speaker and the listener, whom no video shows ('? Hardly worth my notice, but tell me anyway.')
SPEAKER_AND_LISTENER = {"i", "me", "my", "myself", "you", "your", "yourself", "we", "us", "our"}
# no person is in the videos ('is the scooter ridden by anyone?' was read as whether it hits anything)
PEOPLE = {"anyone", "anybody", "someone", "somebody", "driver", "drivers", "rider", "riders", "pilot", "pilots",
          "person", "people", "passenger", "passengers", "pedestrian", "pedestrians", "man", "woman", "child"}
