"""The readings of a clause that build or extend a stack, registered in order by :mod:`.readings`.

A stack is often said over several clauses: "stack red, blue, green. bottom up.", "white at the
bottom, then green", "...; the red one goes in between". These handlers read such clauses against
the stack the parse state holds (``state.tower``), or turn a clause's stack roles and vertical words
("rest A on B") into a stack. Each takes the parser and the clause's :class:`.readings.Frame`, as
every reading does; where each is tried is set in :mod:`.readings`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import InputError
from .assembly import _add_params
from .clauses import _COMMAND_VERBS, _DIR_WORDS, _VERT_ON, _VERT_SKIP, _VERT_UNDER, _VERT_WORDS
from .framing import _ROLE_MARK
from .grounding import Choice
from .lexicon import says
from .matcher import _stem
from .passes import _SELECT_VERBS

if TYPE_CHECKING:
    from .assembly import _Pending
    from .readings import Frame
    from .rules import _Parser

#: A clause that only says a stack's order.
_ORDER_HEADERS = frozenset({"bottom to top", "top to bottom", "from bottom to top", "from top to bottom"})


def _read_order_of_last_stack(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"stack red, blue, green. bottom up.": the order the stack just read was listed in."""
    mentions = f.mentions
    text = f.text
    if not mentions and text in _ORDER_HEADERS \
            and self.state.tower is not None and self.state.header is None:
        # "stack red, blue, green. bottom up.": the order the stack was listed in; a list
        # after it ("pile up the cans. from top to bottom: green, blue, ...") goes downward.
        if "top to bottom" in text:
            self.state.tower.objects.reverse()
            self.state.downward = True
        return []
    return None


def _read_roles_in_last_stack(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"...; the red one goes in between": roles for objects of the stack just built."""
    roles = f.roles
    meaningful = f.meaningful
    mentions = f.mentions
    text = f.text
    params = f.params
    if (roles is not None and self.state.tower is not None and self.state.header is None
            and not any(self._free_word(w) for w in meaningful) and any(roles)):
        # "...; the red one goes in between": a role for an object of the tower just built.
        tower = self.state.tower.objects
        before = [x for x in tower if isinstance(x, int)]
        prev: int | Choice | None = None
        pairs = list(zip(mentions, roles))
        if says(text, "downward") and not self.state.downward:
            # "black bowl, then white bowl, then the blue block, from the top down, black bowl
            # highest": the list read downward first, then the roles.
            for mm, r in pairs:
                if r is None:
                    got = self._select(mm)
                    tower.extend(x for x in (got if isinstance(got, list) else [got]) if x not in tower)
            tower.reverse()
            self.state.downward = True
            pairs = [(mm, r) for mm, r in pairs if r is not None]
        for mm, role in pairs:
            got = self._select(mm)
            xs: list[int | Choice] = [*got] if isinstance(got, list) else [got]
            # "..., then green, red at the bottom": a role after a list is the last one's.
            listed = len(xs) > 1 and role in ("bottom", "top", "under_it") and any(
                w in ("and", ",") for w in mm.text.split())
            for k, x in enumerate(xs):
                r = None if listed and k < len(xs) - 1 else role
                if {r, self.state.tower.said.get(x)} == {"bottom", "top"}:
                    raise InputError(f"'{text.replace(_ROLE_MARK, '').strip()}': object {x} is given two places in "
                                     f"the stack (bottom and top)")
                if x in tower:
                    tower.remove(x)
                # "white at the bottom, then green": one without a role goes right above the one before.
                after = tower.index(prev) + 1 if prev in tower else len(tower)
                at = after if r is None else {"bottom": 0, "top": len(tower), "middle": (len(tower) + 1) // 2}.get(r, after)
                if r == "under_it":
                    # "purple on top, orange under it": right below the one before ("orange on top.
                    # green underneath it": the last one given a place, where none was given here).
                    below = prev if prev is not None else self.state.tower_prev
                    if below is None and self.state.tower.said:
                        below = list(self.state.tower.said)[-1]
                    if below in tower:
                        at = tower.index(below)
                tower.insert(at, x)
                self.state.tower.said[x] = r
                prev = x
        self.state.tower_prev = prev if roles[-1] != "top" else None
        # "red highest, then yellow, then blue": after the top, each next one goes right below.
        self.state.tower_down = prev if roles[-1] == "top" else None
        if self.state.tower_fixed and [x for x in tower if x in before] != before:
            # "stack the white bowl on the black bowl, but keep the black bowl on top"
            said = " ".join(w for w in text.split() if w != _ROLE_MARK)
            raise InputError(f"'{said}' contradicts the stacking order said before it")
        if params:
            _add_params(self.state.tower, params, text)  # "..., the red one on top, in the front right corner"
        return []
    return None


def _read_next_in_last_stack(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"white at the bottom, then green": the next one up (or, after the top, down) in the stack."""
    mentions = f.mentions
    meaningful = f.meaningful
    roles = f.roles
    params = f.params
    text = f.text
    # "white at the bottom, then green": the next one up, right above the one placed before; after the
    # top ("red highest, then yellow"), the next one down, right below it.
    objs = self.state.tower.objects if self.state.tower is not None else []
    up = self.state.tower_prev in objs
    ref = self.state.tower_prev if up else (
        self.state.tower_down if self.state.tower_prev is None and self.state.tower_down in objs else None)
    if (mentions and not meaningful and ref is not None and self.state.header is None
            and (roles is None or not any(roles))
            and all(x in objs for mm in mentions
                    for x in (lambda g: g if isinstance(g, list) else [g])(self._select(mm)))):
        assert self.state.tower is not None  # ref is one of its objects
        for mm in mentions:
            got = self._select(mm)
            for x in got if isinstance(got, list) else [got]:
                if x != ref and x in objs:
                    objs.remove(x)
                    objs.insert(objs.index(ref) + up, x)
                    self.state.tower.said[x] = "next" if up else "under_it"
                    ref = x
        if up:
            self.state.tower_prev = ref
        else:
            self.state.tower_down = ref
        if params:
            _add_params(self.state.tower, params, text)
        return []
    return None


def _read_roles_make_a_stack(self: _Parser, f: Frame) -> list[_Pending] | None:
    """Stack roles with no other arrangement word make a stack (with the stack header's parameters)."""
    roles = f.roles
    meaningful = f.meaningful
    phrase_words = f.phrase_words
    params = f.params
    if roles is not None and not any(self._free_word(w) for w in meaningful):
        phrase_words = [w for w in phrase_words if w not in _SELECT_VERBS] + ["stack"]
        meaningful = ["stack"]
        if self.state.header is not None and self.state.header[0] == "tower":
            params = {**self.state.header[1], **params}
            self.state.header = None
    f.params = params
    f.meaningful = meaningful
    f.phrase_words = phrase_words
    return None


def _read_order_makes_a_stack(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"from top to bottom the cans should go white, red, blue": a stack by its order."""
    phrase_words = f.phrase_words
    text = f.text
    mentions = f.mentions
    meaningful = f.meaningful
    if says(text, "order") and len(mentions) >= 2 and not any(
            self._free_word(w) for w in meaningful):
        # "from top to bottom the cans should go white, red, blue, green": a stack by its order.
        phrase_words, meaningful = ["stack"], ["stack"]
    f.meaningful = meaningful
    f.phrase_words = phrase_words
    return None


def _read_vertical_pair(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"rest A on B", "A should end up below B": two references with vertical words between them, a stack."""
    phrase_words = f.phrase_words
    vertical = f.vertical
    groups = f.groups
    roles = f.roles
    gaps = f.gaps
    words = f.words
    meaningful = f.meaningful
    vertical = None
    if len(groups) == 2 and roles is None:
        lo, hi = gaps[1]
        rel_words_, _ = self._word_kinds()
        # Between the two objects: the vertical words, whatever verb goes
        # with them ("rest A on B", "A should end up below B"), unless a
        # word there names a direction or an arrangement.
        between = tuple(w for w in words[lo:hi] if w in _VERT_WORDS or w in ("top", "of", "to", "neath"))
        while between and between[0] == "to" and between[:2] != ("to", "the"):
            between = between[1:]  # "to end up underneath": the "to" of the verb
        if any(_stem(w) in rel_words_ or w in _DIR_WORDS for w in words[lo:hi]):
            between = ()
        if between in _VERT_ON or between in _VERT_UNDER:
            others = [w for w in meaningful if w not in _VERT_WORDS and w not in _VERT_SKIP
                      and w not in _COMMAND_VERBS and _stem(w) not in ("stack", "tower", "pile", "top")
                      and (self._free_word(w) or _stem(w) in rel_words_ or w in _DIR_WORDS)]
            if not others:
                vertical = "on" if between in _VERT_ON else "under"
                phrase_words = ["stack"]
                meaningful = ["stack"]
    f.meaningful = meaningful
    f.phrase_words = phrase_words
    f.vertical = vertical
    return None


def _read_continue_last_stack(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"stack A as the base, then B, then C": each next clause goes on top."""
    meaningful = f.meaningful
    groups = f.groups
    params = f.params
    text = f.text
    if not meaningful and self.state.tower is not None and len(groups) == 1:
        # "stack A as the base, then B, then C": each next clause goes on top.
        tower = self.state.tower
        before = [x for x in tower.objects if isinstance(x, int)]
        named: list[int] = []
        for mm in groups[0]:
            got = self._select(mm)
            named += [x for x in (got if isinstance(got, list) else [got]) if isinstance(x, int)]
            for x in got if isinstance(got, list) else [got]:
                if x in tower.objects:
                    tower.objects.remove(x)
                # Read from the top down, each next object goes below the others.
                tower.objects.insert(0, x) if self.state.downward else tower.objects.append(x)
                # Said by name: a stack described from base to top keeps it ("red at the bottom, then
                # blue, then green, yellow on top" is four objects, blue among them).
                tower.said.setdefault(x, "under_it" if self.state.downward else "next")
        if len(named) >= 2 and len(before) > len(named) and set(named) <= set(before) and not set(tower.said) - set(named):
            # "stack the blocks, from top to bottom: red, yellow, blue, green" with six blocks: the stack is
            # the objects the order names, read as said; the others are not filled in
            tower.objects[:] = [x for x in tower.objects if not isinstance(x, int) or x in named]
        if params:
            _add_params(tower, params, text)
        return []
    return None
