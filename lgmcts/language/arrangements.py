"""Arrangements: which pattern a clause names (the sentence model with the direction words fixing a
relation), the shape goal it builds with its order and parameters, and the place setting ("set the
table") as a composite goal (:class:`_Arrangements`, mixed into :class:`.rules._Parser`).
"""

from __future__ import annotations

from dataclasses import replace
import re

from ..errors import InputError
from ..formats import RELATIONS
from .assembly import _Pending, _direction
from .clauses import _DIR_WORDS, _NOT_PATTERN, _ON_WORDS, _numbers
from .context import meal_visited
from .grounding import COLOUR_WORDS, Choice
from .matcher import FILLERS, STOPWORDS, _forms, _stem
from .passes import _GENERIC_KEY_WORDS
from .shapes import take_params
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .host import ParserHost
else:
    ParserHost = object


_EVERYTHING = frozenset({"everything", "all", "all of it", "it all", "the lot", "things", "stuff"})


#: Words after "dinner" that make it no request for a place setting ("the dinner ladies want everything tidy",
#: "a dinner party"); "dinner time!" still asks for one.
_NOT_A_SETTING = frozenset({("party",), ("parties",), ("guests",), ("ladies",), ("lady",), ("bell",),
                            ("money",), ("queue",), ("staff",), ("break",), ("hall",)})


#: Words before "dinner set" that make it the tableware ("this dinner set", "my dinner set").
_OWNING = frozenset({"this", "that", "the", "my", "our", "your", "a", "new", "whole"})
#: Verbs that ask for the table to be set when "the dinner table" is said ("set up a dinner table"); without one
#: it is only the table ("the dinner table looks very nice").
_SETTING_VERBS = frozenset({"set", "lay", "prepare", "ready", "arrange", "make", "do", "sort", "get", "fix"})


class _Arrangements(ParserHost):
    """Pattern choice, shape goals and the place setting."""

    def _word_kinds(self) -> tuple[frozenset[str], frozenset[str]]:
        """Key words found only in anchored patterns, and only in the others."""
        if not hasattr(self, "_kinds"):
            from .matcher import content_words

            rel: set[str] = set()
            free: set[str] = set()
            for info in self.infos.values():
                if info.needs_pose:
                    continue
                for k in info.keys:
                    (rel if info.anchored else free).update(content_words(k))
            skip = FILLERS | _NOT_PATTERN
            self._kinds = (frozenset(rel - free - skip), frozenset(free - rel - skip))
        return self._kinds

    def _arrangements_named(self, phrase_words) -> set[str]:
        """The arrangements that words of the clause name outright: a word found
        in the keys of exactly one arrangement (not a generic word such as
        "arrange" or "shape"), and "on top of each other" for a tower."""
        if not hasattr(self, "_own_words"):
            from .matcher import content_words

            owner: dict[str, set[str]] = {}
            for name, info in self.infos.items():
                if info.anchored or info.needs_pose:
                    continue
                for k in info.keys:
                    for w in content_words(k):
                        owner.setdefault(w, set()).add(name)
            self._own_words = {w: next(iter(ps)) for w, ps in owner.items()
                               if len(ps) == 1 and w not in _GENERIC_KEY_WORDS}
        found = set()
        for w in phrase_words:
            p = self._own_words.get(w) or self._own_words.get(_stem(w))
            if p is not None:
                found.add(p)
        if re.search(r"\b(on top of|atop) (each other|one another)\b", " ".join(phrase_words)):
            found.add("tower")
        return found

    def _match(self, phrase: str, text: str, allowed: frozenset[str]):
        dirs = {_DIR_WORDS[w] for w in re.findall(r"[a-z]+", phrase.lower()) if w in _DIR_WORDS}
        up, down = r"(?:on top of|on|onto|above|over|atop|upon)", r"(?:under|underneath|below|beneath)"
        if any((-x, -y) in dirs for x, y in dirs) or re.search(
                rf"\b(?:{up} and {down}|{down} and {up})\b", phrase.lower()):
            # "both in front of and behind the bowl", "on top of and underneath the green one"
            raise InputError(f"contradiction: '{phrase}' names opposite directions")
        m = self.matcher.match(phrase, allowed=allowed)
        if not m and m.reason != "no arrangement is named" and "'" not in m.reason:
            # Words before the first word of a pattern key are the verb and its
            # company ("balance ... on", "should end up below", "put down left
            # of"): match from that word on.
            pw = phrase.split()
            first = next((k for k, w in enumerate(pw) if (any(f in self.key_vocab and f not in FILLERS for f in _forms(w))
                                                          and w not in STOPWORDS) or w in _DIR_WORDS), None)
            if first is not None and first > 0:
                while first > 0 and pw[first - 1] in ("to", "the", "on", "in", "at", "of", "a", "an"):
                    first -= 1
                if first > 0:
                    m2 = self.matcher.match(" ".join(pw[first:]), allowed=allowed)
                    if m2:
                        m = m2
                        phrase = " ".join(pw[first:])
        if m and m.pattern in RELATIONS:
            # Directions compose: the direction words of the phrase fix the
            # relation exactly ("at the back right of" is right_behind even
            # where the sentence model puts it nearer "front right of").
            d = _direction(phrase)
            if d is not None and d != m.pattern and d in allowed:
                m = replace(m, pattern=d)
        if not m:
            known = ", ".join(sorted(self.infos))
            if m.reason == "no arrangement is named":
                raise InputError(f"'{text}' does not say how to arrange the objects (known patterns: {known})")
            hint = f"; closest is '{m.runner_up}' ({m.score:.2f})" if m.runner_up else ""
            why = f" ({m.reason})" if m.reason.startswith("'") else ""
            raise InputError(f"no pattern in the database matches '{phrase or text}'{why}{hint}; known patterns: {known}")
        return m

    def _free_word(self, w: str) -> bool:
        """Whether ``w`` names a pattern that takes no anchor (a shape), by its keys or its embedding."""
        rel, free = self._word_kinds()
        st = _stem(w)
        if st in free or (st in self.key_vocab and st not in rel and st not in FILLERS and st not in _NOT_PATTERN):
            return True
        if st in rel or st in STOPWORDS or st in FILLERS or not w.isalpha() or len(w) < 4:
            return False
        p, _, _ = self.matcher.word_pattern(w)
        return p is not None and not self.infos[p].anchored

    def _shape(self, pattern: str, sels, words, gaps, text: str, phrase_words, *, vertical: str | None = None,
               roles: dict | None = None, defer_min: bool = False) -> _Pending:
        info = self.infos[pattern]
        if info.ordered and len(sels) >= 2:
            flat = [{x for y in g for x in (y if isinstance(y, list) else [y]) if isinstance(x, int)} for g in sels]
            later = set().union(*flat[1:])
            if flat[0] and flat[0] == later and sum(len(f) for f in flat[1:]) == len(later):
                # "stack the cups, yellow on orange": the set first, then its order.
                sels, gaps = sels[1:], gaps[1:] if gaps else gaps
            elif isinstance(sels[0][0], list) and len(sels[0]) > 1:
                # The same where the list ran the set and the first of its members together.
                head = {x for x in sels[0][0] if isinstance(x, int)}
                rest = [x for g in [sels[0][1:], *sels[1:]] for y in g for x in (y if isinstance(y, list) else [y])]
                if len(head) > 1 and all(isinstance(x, int) for x in rest) and sorted(rest) == sorted(head):
                    sels = [sels[0][1:], *sels[1:]]
        order = list(range(len(sels)))
        # "A on B" said between the first two references: A above B (or below, said "under")
        paired = vertical if info.ordered and len(sels) > 1 else None
        if info.ordered and len(sels) > 1:
            if vertical == "on" or (vertical is None and any(
                    any(tuple(words[lo:hi])[-n:] in _ON_WORDS for n in (1, 2, 3)) for lo, hi in gaps[1:-1] if hi > lo)):
                order.reverse()
                if vertical is None and len(gaps) > 2 and gaps[1][1] > gaps[1][0] and any(
                        tuple(words[gaps[1][0]:gaps[1][1]])[-n:] in _ON_WORDS for n in (1, 2, 3)):
                    paired = "on"
        objs: list[int | Choice] = []
        for g in order:
            for s in sels[g]:
                for x in s if isinstance(s, list) else [s]:
                    if x not in objs:
                        objs.append(x)
                    elif info.ordered and isinstance(x, int) and not (roles and x in roles) and len(objs) > 1:
                        # "stack the red, blue and green blocks starting with green": a
                        # second mention whose part in the order is not read.
                        raise InputError(f"'{text}': object {x} is named twice and its place in the stack is "
                                         f"unclear; list the objects from the bottom up")
        downward = info.ordered and bool(re.search(r"\b(top to (the )?bottom|from the top|top down)\b", text))
        if downward:
            objs.reverse()
        if info.ordered and getattr(self, "_order_by", None) and all(isinstance(x, int) for x in objs):
            # "largest at the bottom": by volume, largest first (or smallest first).
            vol = {x[0]: x[2] for x in self.vocab.measures}
            ints = [x for x in objs if isinstance(x, int)]  # all of them (checked above)
            objs = [*sorted(ints, key=lambda x: (-vol.get(x, 0.0) if self._order_by == "desc" else vol.get(x, 0.0), x))]
            self._order_by = None
        if roles and pattern == "tower" and self._below_first:
            below = [x for x in self.state.last if x not in objs]
            objs = below + objs
            roles = {**roles, **{x: "bottom" for x in below}}
            self._below_first = False
        if roles:
            # Stack roles: bottom first, then "goes on it"/"next" in order, the
            # middle, the objects without a role, the top last.
            rank: dict[str | None, float] = {"bottom": 0, "next": 1, "middle": 2, None: 3, "top": 4}
            given = set(roles.values())
            if "middle" in given and "bottom" not in given:
                rank[None] = 1.5  # "B in the middle and C on top": the one left is at the bottom
            objs = sorted(objs, key=lambda x: rank.get(roles.get(x), 3))
            if paired is not None:
                _check_roles_keep_pairs(text, sels[:2] if paired == "under" else sels[1::-1], objs)
            if given == {"middle"}:
                # "stack the three bowls with the white one in the middle": as many below it as above it
                free = [x for x in objs if x not in roles]
                if len(free) % 2:
                    plain = " ".join(w for w in text.split() if w != "|")  # without the role marks
                    raise InputError(f"'{plain}': with {len(free)} other object{'s' if len(free) > 1 else ''} "
                                     f"there is no middle of the stack; say what goes at the bottom or the top")
                objs = free[: len(free) // 2] + [x for x in objs if x in roles] + free[len(free) // 2 :]
            said = list(roles)
            for k, x in enumerate(said):
                if roles[x] == "under_it" and k and said[k - 1] in objs and x in objs:
                    # "purple on top, orange under it": right below the object named before it.
                    objs.remove(x)
                    objs.insert(objs.index(said[k - 1]), x)
            placed = [x for x in objs if roles.get(x) in ("bottom", "next")]
            self.state.tower_prev = placed[-1] if placed and pattern == "tower" else None
        n = sum(x.k if isinstance(x, Choice) else 1 for x in objs)
        if n < info.min_objects and not (pattern == "tower" and defer_min):
            noun = "object" if n == 1 else "objects"
            raise InputError(f"'{text}': a {pattern} needs at least {info.min_objects} objects, this names {n} {noun}")
        pose = None
        if info.needs_pose:
            nums = _numbers(tuple(phrase_words))
            if len(objs) != 1 or not isinstance(objs[0], int):
                raise InputError(f"'{text}': a {pattern} goal takes exactly one definite object")
            cur = self.spec.object(objs[0]).pose
            yaw = nums[2] if len(nums) > 2 else float(cur[2] if cur else 0.0)
            pose = (nums[0], nums[1], yaw)
        self.state.last = objs
        self.state.it_pair = None
        self.state.last_tower = pattern == "tower"
        self.state.last_anchor = None
        out = _Pending(pattern, objs, None, pose, text)
        if roles and pattern == "tower":
            out.said = {x: r for x, r in roles.items() if x in objs}
        self.state.tower = out if pattern == "tower" else None
        self.state.tower_fixed = pattern == "tower" and vertical is not None  # "A on B": that order is said
        self.state.last_shape = out
        self.state.downward = pattern == "tower" and downward
        return out

    _DINNER = (("set", "the", "table"), ("set", "a", "table"), ("lay", "the", "table"), ("set", "up", "the", "table"),
               ("dinner",), ("place", "setting"), ("table", "setting"), ("set", "a", "place"), ("plate", "setting"),
               ("lay", "a", "place"), ("table", "set"), ("setting", "for", "one"), ("cover", "for", "one"),
               ("place", "is", "laid"), ("place", "laid"), ("table", "laid"), ("table", "should", "be", "set"),
               ("table", "is", "set"), ("place", "settings"))

    def _dinner_at(self, words: tuple[str, ...]) -> int | None:
        """Where a place setting is asked for ("set the table", "dinner"), if it is."""
        return next((i for i in range(len(words)) for s in self._DINNER if words[i : i + len(s)] == s
                     and not (s == ("dinner",) and i and words[i - 1] in ("before", "after", "until", "till", "since"))
                     and not (s == ("dinner",) and words[i + 1 : i + 2] in _NOT_A_SETTING)
                     and not (s == ("dinner",) and meal_visited(words, i))
                     and not (s == ("dinner",) and words[i + 1 : i + 2] == ("table",) and _SETTING_VERBS.isdisjoint(words))
                     and not (s == ("dinner",) and words[i + 1 : i + 2] == ("set",) and words[i + 2 : i + 3] != ("up",)
                              and i and words[i - 1] in _OWNING)),
                    None)

    def _setting_only(self, words: tuple[str, ...]) -> bool:
        """Whether a clause names only the setting's own objects (plate, bowls, cutlery)."""
        try:
            ms = self._find(words)
        except InputError:
            return False
        own = {"plate", "bowl", "fork", "knife", "spoon", "chopstick", "chopsticks", "cutlery", "silverware"}
        return bool(ms) and not self._unknown_nouns(words, ms) and all(
            m.names is not None and set(m.names) <= own and m.det != "pronoun" for m in ms)

    def _dinner(self, words: tuple[str, ...]) -> list[_Pending] | None:
        """"Set the table" / "a dinner in the middle": the plate with its bowls stacked on it and the cutlery
        lined up beside it (the StructFormer-style composite goal). Only when nothing else is asked.
        """
        k = self._dinner_at(words)
        if k is None:
            return None
        seq = next(s for s in self._DINNER if words[k : k + len(s)] == s)
        many = re.search(r"\bfor (two|three|four|five|six|[2-9]|\d\d+)(?: (people|persons|guests|diners|of us)|"
                         r"(?= , | \.| \?| !|$)| ,? like (?:two|three|four|five|six|\d+))\b|\b(?:two|three|four|five|six|[2-9]) "
                         r"(?:full )?place settings\b", " ".join(words))
        if many is not None:
            raise InputError(f"'{' '.join(words)}': a setting {many.group(0)} needs one plate each; "
                             f"set one place at a time")
        rest = words[:k] + words[k + len(seq):]
        # Objects named along with it must be the setting's own (plate, bowls,
        # cutlery: "set a place: bowl on the plate, silverware on the left");
        # anything else ("Set the table: put the mugs ...") is read by the
        # ordinary grammar.
        plates = {"plate"}
        cutlery = {"fork", "knife", "spoon", "chopstick", "chopsticks"}
        own = plates | {"bowl"} | cutlery
        named: dict[str, list[int]] = {"plate": [], "bowl": [], "cut": []}
        found = self._find(rest, self.key_vocab)
        if self._unknown_nouns(words, self._find(words)):
            return None  # "put the napkin left of the plate, then set the table": read (and refused) as usual
        for w, nxt in zip(words, words[1:]):
            if w in COLOUR_WORDS and w not in self.vocab.color_words and (nxt in self._cat_words
                                                                         or _stem(nxt) in self._cat_words):
                # "set the table using the black plate": the scene has no black plate.
                raise InputError(f"nothing in the scene matches 'the {w} {nxt}' (no {w} object)")
        for m in found:
            if m.names is None and m.det == "all" and m.colors is None and not m.ids and m.text in _EVERYTHING:
                continue  # "get everything ready for dinner"
            if m.names is None or not set(m.names) <= own or m.det == "pronoun":
                return None
            got = self._select(m)
            for x in got if isinstance(got, list) else []:
                nm = next(n for i, n, _ in self.vocab.objects if i == x)
                named["plate" if nm in plates else "bowl" if nm == "bowl" else "cut"].append(x)
        said = " ".join(rest)
        for k, w in enumerate(rest):
            but = rest.index("but", k) if "but" in rest[k:] else len(rest)
            if w in ("not", "never", "don't", "dont") and any(x in ("left", "right") for x in rest[k + 1 : k + 9]) \
                    and not any(x in ("left", "right") for x in rest[but:]):
                # "set a place, but don't put the cutlery on the left of the plate": the side was taken as said
                raise InputError(f"'{' '.join(x for x in rest[k:] if x.isalnum())}': a setting that something must "
                                 f"not hold is not read; say on which side the cutlery goes")
        if re.search(r"\b(?:on|to) the left\b", said) and re.search(r"\b(?:on|to) the right\b", said) and not re.search(
                r"\b(?:or|either|whichever|any|one|other)\b", said):
            raise InputError(f"contradiction: '{said}' puts the cutlery both left and right of the plate")
        side = "left"
        for w, sd in (("right", "right"), ("left", "left")):
            if w in rest:
                side = sd
                # "the plate ends up to the right of the cutlery": the cutlery on the other side.
                k_side = rest.index(w)
                before = [m for m in self._find(rest[:k_side]) if m.names is not None]
                after = [m for m in self._find(rest[k_side:]) if m.names is not None]
                if before and after and set(before[-1].names or ()) <= plates and not set(after[0].names or ()) <= plates:
                    side = "left" if sd == "right" else "right"
        params, rest2 = take_params(rest, lambda w: True) if any(
            w in rest for w in ("small", "medium", "large", "big", "facing", "top", "bottom", "middle", "center")) else ({}, rest)
        by = {n: [i for i, nn, _ in self.vocab.objects if nn == n] for n in ("plate", "bowl")}
        cut = named["cut"] or [i for i, nn, _ in self.vocab.objects if nn in cutlery]
        if named["plate"]:
            by["plate"] = sorted(set(named["plate"]))
        if named["bowl"]:
            by["bowl"] = list(dict.fromkeys(named["bowl"]))
        if len(by["plate"]) != 1:
            raise InputError(f"'{' '.join(words)}': a dinner setting needs exactly one plate, the scene has {len(by['plate'])}")
        if len(cut) < 2:
            raise InputError(f"'{' '.join(words)}': a dinner setting needs at least two pieces of cutlery")
        plate = by["plate"][0]
        meas = {x[0]: x[2] for x in self.vocab.measures}
        bowls = sorted(by["bowl"], key=lambda i: (-meas.get(i, 0.0), i))
        text = " ".join(words)
        out = []
        # Where and which way the setting goes is said of the plate, its centre.
        if bowls:
            out.append(_Pending("tower", [plate, *bowls], None, None, text, dict(params)))
        out.append(_Pending("line", list(cut), None, None, text, {} if bowls else dict(params)))
        out.append(_Pending(side, list(cut), plate, None, text))
        return out


def _check_roles_keep_pairs(text: str, pair, objs: list) -> None:
    """Refuse roles that turn round a pair said with "on" or "under" (``pair``: the references below, then
    those above): "stack the plate on the bowl with the bowl on top" asks for both orders (before, the role
    won and the plate went under the bowl)."""
    flat = [[x for s in sel for x in (s if isinstance(s, list) else [s])] for sel in pair]
    for a in flat[0]:
        for b in flat[1]:
            if a != b and a in objs and b in objs and objs.index(a) > objs.index(b):
                plain = " ".join(w for w in text.split() if w != "|")
                raise InputError(f"'{plain}': the stack's order said by the pair and by the roles disagree; "
                                 f"say which goes on top once")
