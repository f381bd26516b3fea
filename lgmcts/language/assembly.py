"""From pending goals to goal dicts: the pending goal (:class:`_Pending`), choices resolved, towers chained,
relations merged, the checks that refuse contradictions, unused objects and words no goal took
(:class:`_Finishing`, mixed into :class:`.rules._Parser`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
import re

from . import stages
from ..errors import InputError
from ..formats import GoalSpec, RELATIONS, parse_goals
from .clauses import _DIR_WORDS
from .grounding import Choice, candidates, describe
from .lexicon import MACROS
from .shapes import merged_region
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .host import ParserHost
else:
    ParserHost = object


@dataclass
class _Pending:
    pattern: str
    objects: list[int | Choice]
    anchor: int | Choice | None
    pose: tuple[float, float, float] | None
    clause: str
    params: dict = field(default_factory=dict)
    #: A tower's objects whose place in it was said ("red at the bottom", "then blue"): their roles.
    said: dict = field(default_factory=dict)


#: Words before an object that is named without being arranged ("except the plate", "the same colour as the mug").
_NOT_USED_BEFORE = frozenset({"except", "excluding", "but", "not", "than", "as", "from", "without", "instead", "minus",
                              "besides", "leave", "touch", "move", "like", "unlike", "match", "matches", "matching",
                              "nor", "neither", "apart", "other", "besides", "alike", "to", "with", "of"})


def _with_facing(goals: list[_Pending], params: dict) -> list[_Pending]:
    """Relation goals with the facing (and any measure, refused when the goal is written) said in their clause."""
    own = {k: v for k, v in params.items() if k in ("facing", "measure")}
    for g in goals:
        g.params = {**g.params, **own}
    return goals


def _add_params(shape: _Pending, params: dict, text: str) -> None:
    """Give ``shape`` the place, size or facing said after it; a second, different one is refused."""
    for key, val in params.items():
        if shape.params.get(key, val) != val:
            if key == "region" and merged_region(shape.params[key], val) is not None:
                params = {**params, key: merged_region(shape.params[key], val)}
                continue
            where = f"'{text.strip()}': " if text.strip() else ""
            raise InputError(f"{where}two different {key}s for one arrangement")
    shape.params.update(params)


def _chain_towers(goals: list[dict]) -> list[dict]:
    """Join towers where the top of one is the bottom of another.

    "Put the red block on the blue block, then put the green block on the red
    block" gives [blue, red] and [red, green]: one tower [blue, red, green]
    (bottom first). Towers that share any other object are left as they are
    (the consistency checks refuse them).
    """
    goals = [dict(g) for g in goals]
    below: set[tuple[int, int]] = set()
    for g in goals:
        if g["pattern"] == "tower" and not g.get("unordered"):
            objs = g["objects"]
            below.update((objs[i], objs[j]) for i in range(len(objs)) for j in range(i + 1, len(objs)))
    loop = next(((a, b) for a, b in below if (b, a) in below), None)
    if loop is not None:
        raise InputError(f"contradiction: the stacking puts object {loop[0]} both below and above object {loop[1]}")
    merged = True
    while merged:
        merged = False
        towers = [k for k, g in enumerate(goals) if g["pattern"] == "tower"]
        for a in towers:
            for b in towers:
                if a == b:
                    continue
                lo, hi = goals[a]["objects"], goals[b]["objects"]
                if lo[-1] == hi[0] and set(lo) & set(hi) == {lo[-1]}:
                    goals[a] = {**goals[a], "objects": lo + hi[1:]}
                    del goals[b]
                    merged = True
                    break
            if merged:
                break
    stacks: list[list[int]] = [g["objects"] for g in goals if g["pattern"] == "tower"]

    def inside(small: list[int]) -> bool:
        n = len(small)
        return any(big is not small and len(big) > n and any(big[i : i + n] == small for i in range(len(big) - n + 1))
                   for big in stacks)

    return [g for g in goals if g["pattern"] != "tower" or not inside(g["objects"])]


_PARAM_KEYS = ("region", "size", "facing")


def _params_accepted() -> bool:
    """Whether the goal format has the optional parameters region, size and facing."""
    from ..formats import Goal

    return all(k in Goal.model_fields for k in _PARAM_KEYS)


def _same_goals_merged(goals: list[dict]) -> list[dict]:
    """One goal for each arrangement said twice ("put them in a circle, like a
    little loop"): the same pattern over the same objects (in the same order for
    a tower) and the same reference object; the place, size and facing said
    either time are the goal's (two different ones are refused)."""
    out: list[dict] = []
    for g in goals:
        same = None
        for h in out:
            if (h["pattern"] == g["pattern"] and h.get("anchor") == g.get("anchor")
                    and (h["objects"] == g["objects"] if g["pattern"] == "tower" else
                         sorted(h["objects"]) == sorted(g["objects"]))):
                same = h
                break
        if same is None:
            out.append(dict(g))
            continue
        for key in _PARAM_KEYS:
            if key in g:
                if key == "region" and key in same and merged_region(same[key], g[key]) is not None:
                    same[key] = merged_region(same[key], g[key])
                    continue
                if same.get(key, g[key]) != g[key]:
                    raise InputError(f"two different {key}s ({same[key]}, {g[key]}) for one {g['pattern']}")
                same[key] = g[key]
    return out


def _diagonals(goals: list[dict]) -> list[dict]:
    """A side and a depth said for the same objects and reference object ("E in front of R, and a bit
    to the left of it") are one diagonal relation (left and front), as "in front of R and to its left"."""
    out = [dict(g) for g in goals]
    k = 0
    while k < len(out):
        a = out[k]
        j = next((j for j in range(k + 1, len(out)) if out[j]["pattern"] in RELATIONS and a["pattern"] in RELATIONS
                  and out[j].get("anchor") == a.get("anchor") and a.get("anchor") is not None
                  and sorted(out[j]["objects"]) == sorted(a["objects"])
                  and {out[j]["pattern"], a["pattern"]} in ({"left", "front"}, {"left", "behind"},
                                                            {"right", "front"}, {"right", "behind"})), None)
        if j is None:
            k += 1
            continue
        side = a["pattern"] if a["pattern"] in ("left", "right") else out[j]["pattern"]
        depth = out[j]["pattern"] if side == a["pattern"] else a["pattern"]
        out[k] = {**a, **{x: y for x, y in out[j].items() if x not in ("pattern", "objects", "anchor")},
                  "pattern": f"{side}_{depth}"}
        del out[j]
    return out


def _merge_relations(goals: list[dict]) -> list[dict]:
    """Relation goals with one relation and one anchor whose objects together are exactly the
    objects of an arrangement of the same command become one goal: "put the spoon left of the plate;
    put the fork left of the plate; put the fork and the spoon in a line" is the line left of the
    plate (a relation holds object by object, so this changes nothing it asks). Other relation
    goals stay one per clause."""
    shapes = [set(g["objects"]) for g in goals if g["pattern"] not in RELATIONS]
    groups: dict[tuple, list[int]] = {}
    for k, g in enumerate(goals):
        if g["pattern"] in RELATIONS and "anchor" in g:
            groups.setdefault((g["pattern"], g["anchor"], tuple(sorted(set(g) - {"objects"}))), []).append(k)
    drop: set[int] = set()
    merged: dict[int, dict] = {}
    for ks in groups.values():
        if len(ks) < 2:
            continue
        union: list[int] = []
        for k in ks:
            union += [o for o in goals[k]["objects"] if o not in union]
        if set(union) in shapes:
            merged[ks[0]] = dict(goals[ks[0]], objects=union)
            drop.update(ks[1:])
    return [merged.get(k, g) for k, g in enumerate(goals) if k not in drop]


#: Words that ask for a whole group or a number of it ("all the blocks", "the six blocks").
_WHOLE_GROUP = re.compile(r"\b(?:all|every|each|both|whole|entire|everything|\d+|two|three|four|five|six|seven|eight|"
                          r"nine|ten)\b")


def _direction(phrase: str) -> str | None:
    """The relation the direction words of ``phrase`` compose to, or None."""
    words = set(re.findall(r"[a-z]+", phrase.lower()))
    hit = [_DIR_WORDS[w] for w in words if w in _DIR_WORDS]
    if not hit:
        return None
    xs, ys = {h[0] for h in hit if h[0]}, {h[1] for h in hit if h[1]}
    if len(xs) > 1 or len(ys) > 1:
        return None  # "left and right": a contradiction, left to the checks
    x, y = (xs.pop() if xs else 0), (ys.pop() if ys else 0)
    name = {(-1, 0): "left", (1, 0): "right", (0, -1): "front", (0, 1): "behind", (-1, -1): "left_front",
            (-1, 1): "left_behind", (1, -1): "right_front", (1, 1): "right_behind"}[(x, y)]
    return name if name in RELATIONS else None


#: Words that ask for a kind of goal whatever else the sentence says, with the
#: patterns of the goals that can carry them (a relation from either side:
#: "move the box so the can is in front of it" is the box behind the can).
_FRONT_BACK = ("front", "left_front", "right_front", "behind", "left_behind", "right_behind")


_LEFT_RIGHT = ("left", "left_front", "left_behind", "right", "right_front", "right_behind")


_CUES = (
    (re.compile(r"\b(in front of|ahead of|behind|in back of)\b"), _FRONT_BACK),
    (re.compile(r"\b(to the left of|to the right of|(?:left|right) of|to (?:its|their|the) (?:left|right)\b|"
                r"on the (?:left|right) of)"), _LEFT_RIGHT),
    (re.compile(r"\b(lin(?:e|es|ed|ing) (?:them |it |those |these )?up|(?:a|one|single|straight) (?:line|row)|in (?:a )?row)\b"),
     ("line",)),
    (re.compile(rf"\b({MACROS['CIRCLE']})\b"), ("circle",)),
    (re.compile(r"\b(rectangle|square|rectangular)\b"), ("rectangle",)),
    (re.compile(r"\b(stack(?:ed|ing|s)?|pil(?:e|es|ed|ing)|tower|on top of)\b"), ("tower",)),
)


#: Where a cue word describes a place on the table, not a relation between objects.
_TABLE_PLACE = re.compile(r"^\s*(?:the |this |that )?(?:table|workspace|tabletop|board|surface|counter|desk)\b")


def _unread_cue(text: str, goals: list[dict], nouns: frozenset[str] = frozenset()) -> str | None:
    """A phrase that asks for a relation, a line, a circle, a rectangle or a
    stack that no goal read from ``text`` has (the command's other words were
    read without it), or None. A goal that drops a part of the command is
    wrong; asking again is better. ``nouns``: the scene's category words
    ("ring", "square" name objects in some scenes)."""
    have = {g["pattern"] for g in goals}
    low = text.lower()
    for cue, patterns in _CUES:
        if have & set(patterns):
            continue
        for m in cue.finditer(low):
            if _TABLE_PLACE.match(low[m.end():]) or m.group(0) in nouns:
                continue  # "in front of the table": a place; "the rainbow ring": an object
            return m.group(0)
    return None


class _Finishing(ParserHost):
    """Turning the pending goals of a command into checked goals."""

    def _unused_object(self, goals: list[dict]) -> None:
        """Refuse a command that names one object by itself ("the red mug") where no goal
        read from it uses that object: a part of the command was not read."""
        used = {o for g in goals for o in g["objects"]} | {g["anchor"] for g in goals if "anchor" in g}
        used |= {o for g in goals for o in g.get("anchor_any", ())}
        stacked = any(g["pattern"] == "tower" for g in goals)
        for clause, ms in self._named_in:
            for m in ms:
                group = m.plural and m.det in ("the", "all") and m.names is not None and not m.head
                bare = m.names is None and bool(m.colors) and stacked  # "then blue" said in a stack and lost
                if not group and (m.det != "the" or m.plural or (m.names is None and not bare) or m.head):
                    continue
                before = clause[max(0, m.start - 3) : m.start]
                if any(w in _NOT_USED_BEFORE for w in before):
                    continue
                try:
                    got = candidates(self.vocab, m)
                except InputError:
                    continue
                if group and got and not set(got) & used:
                    # "letters: column; blocks: square": the letters are named, and nothing is read for them.
                    raise InputError(f"'{m.text}' are named but no goal read from the command uses them; "
                                     f"say what to do with them")
                if len(got) == 1 and got[0] not in used:
                    raise InputError(f"'{m.text}' is named but no goal read from the command uses it; "
                                     f"say what to do with it")

    def _finish(self, pending: list[_Pending]) -> GoalSpec:
        """The goals of the command from its pending goals: towers settled (:meth:`_settle_towers`), the
        "one X" targets chosen (:meth:`_picked_targets`), each goal written with its anchor and parameters
        (:meth:`_written_goals`), then towers chained, equal goals and relations merged, and the checks:
        contradictions, a measure or a named object no goal takes, a cue no goal reads; the goals are
        checked against the scene."""
        self._settle_towers(pending)
        picked = self._picked_targets(pending)
        goals = self._written_goals(pending, picked)
        unread_measure = next((m for k, m in enumerate(self._measures) if k not in self._measured), None)
        if unread_measure is not None:
            raise InputError(f"'{unread_measure.text}': a size said in numbers that no goal read from the command "
                             f"takes; say which arrangement it is for")
        goals = _chain_towers(goals)
        goals = _same_goals_merged(goals)
        goals = _diagonals(_merge_relations(goals))
        self._contradictions(goals)
        self.goal_dicts = [dict(g) for g in goals]
        self._unused_object(goals)
        unread = _unread_cue(self._said, goals, self._cat_words)
        if unread is not None:
            raise InputError(f"'{unread}' is not part of any goal read from the command; say that part again on its own")
        if not _params_accepted():
            goals = [{k: v for k, v in g.items() if k not in _PARAM_KEYS} for g in goals]
        spec = parse_goals({"goals": goals})
        try:
            spec.check_against(self.spec)
        except InputError as exc:
            raise InputError(f"contradiction: {exc}") from None
        return spec

    def _settle_towers(self, pending: list[_Pending]) -> None:
        """Refuse a tower of too few objects; keep of a tower described from its bottom to its top the
        objects said, and drop a "three blocks" choice whose blocks are then named one by one."""
        for p in pending:
            if p.pattern == "tower" and p.anchor is None:
                n = sum(x.k if isinstance(x, Choice) else 1 for x in p.objects)
                if n < self.infos["tower"].min_objects:
                    raise InputError(f"'{p.clause}': a tower needs at least {self.infos['tower'].min_objects} objects, "
                                     f"this names {n} object{'' if n == 1 else 's'}")
            said = set(p.said.values())
            if (p.pattern == "tower" and len(p.said) >= 3 and {"bottom", "top"} <= said
                    and not _WHOLE_GROUP.search(p.clause)):
                # "stack the blocks: purple on top, orange under it, yellow at the base": a stack
                # described from its bottom to its top is those objects, not the whole group.
                p.objects[:] = [x for x in p.objects if not isinstance(x, int) or x in p.said]
            # "stack three blocks: red at the bottom, then blue, then green": the
            # blocks named one by one are the three.
            if p.pattern == "tower":
                for c in [x for x in p.objects if isinstance(x, Choice)]:
                    if sum(1 for x in p.objects if isinstance(x, int) and x in c.options) >= c.k:
                        p.objects.remove(c)

    def _picked_targets(self, pending: list[_Pending]) -> dict[int, list[int]]:
        """The objects each "one X" / "three X" target takes, by the id of its :class:`.grounding.Choice`:
        objects no goal uses yet first; too few left is refused."""
        picked: dict[int, list[int]] = {}
        used: set[int] = set()
        for p in pending:
            for x in p.objects:
                if isinstance(x, int):
                    used.add(x)
        for p in pending:  # targets first: prefer objects no goal uses yet
            fixed = {x for x in p.objects if isinstance(x, int)}
            if isinstance(p.anchor, int):
                fixed.add(p.anchor)
            for x in p.objects:
                if isinstance(x, Choice) and id(x) not in picked:
                    free = [o for o in x.options if o not in used and o not in fixed]
                    rest = [] if x.fresh else [o for o in x.options if o not in free and o not in fixed]
                    got = (free + rest)[: x.k]
                    if len(got) < x.k:
                        noun = "object" if len(got) == 1 else "objects"
                        raise InputError(
                            f"'{x.text}': only {len(got)} matching {noun} left that no other goal uses, {x.k} needed"
                        )
                    picked[id(x)] = got
                    used.update(got)
                    fixed.update(got)
        return picked

    def _written_goals(self, pending: list[_Pending], picked: dict[int, list[int]]) -> list[dict]:
        """Each pending goal as a goal dict: its objects, its anchor (a "one X" anchor preferring an object of
        another goal), its pose and its parameters with any measure said; equal goals once."""
        goals: list[dict] = []
        resolved: list[tuple[_Pending, list[int]]] = []
        for p in pending:
            objs: list[int] = []
            for x in p.objects:
                for o in picked[id(x)] if isinstance(x, Choice) else [x]:
                    if o not in objs:
                        objs.append(o)
            resolved.append((p, objs))
        for k, (p, objs) in enumerate(resolved):
            anchor = p.anchor
            if isinstance(anchor, Choice):
                if id(anchor) in picked:
                    anchor = picked[id(anchor)][0]
                else:
                    others = {o for j, (_, ob) in enumerate(resolved) if j != k for o in ob}
                    opts = [o for o in anchor.options if o not in objs]
                    pref = [o for o in opts if o in others] if self.options.prefer_anchor_from_other_goal else []
                    if not opts:
                        raise InputError(f"'{anchor.text}': no object left to serve as reference")
                    choice = (pref or opts)[0]
                    picked[id(p.anchor)] = [choice]
                    anchor = choice
            if anchor is not None:
                objs = [o for o in objs if o != anchor]
                if not objs:
                    raise InputError(f"'{p.clause}': an object cannot be placed relative to itself")
            g: dict = {"pattern": p.pattern, "objects": objs}
            if anchor is not None:
                g["anchor"] = anchor
            if p.pose is not None:
                g["pose"] = list(p.pose)
            if p.params and p.pose is None:
                params = stages.measured_size(p.pattern, p.params, self._measures, len(objs), anchor is not None)
                self._measured.update([p.params["measure"]] if "measure" in p.params else [])
                g.update(params if anchor is None else {k: v for k, v in params.items() if k == "facing"})
            if g not in goals:
                goals.append(g)
        return goals

    def _contradictions(self, goals: list[dict]) -> None:
        rel = [g for g in goals if g["pattern"] in RELATIONS]
        for a_i, a in enumerate(rel):
            for b in rel[a_i + 1 :]:
                if a["anchor"] != b["anchor"]:
                    continue
                da, db = RELATIONS[a["pattern"]], RELATIONS[b["pattern"]]
                if da[0] * db[0] + da[1] * db[1] > 0:
                    continue
                common = set(a["objects"]) & set(b["objects"])
                if common:
                    o = min(common)
                    raise InputError(
                        f"contradiction: object {describe(self.vocab, [o])} cannot be both "
                        f"{a['pattern'].replace('_', ' and ')} and {b['pattern'].replace('_', ' and ')} of object "
                        f"{describe(self.vocab, [a['anchor']])}"
                    )
        above: dict[int, int] = {}
        below: dict[int, int] = {}
        for g in goals:
            if g["pattern"] != "tower":
                continue
            for lo, hi in zip(g["objects"], g["objects"][1:]):
                if above.get(lo, hi) != hi:
                    raise InputError(
                        f"contradiction: object {describe(self.vocab, [lo])} cannot carry both "
                        f"{describe(self.vocab, [above[lo]])} and {describe(self.vocab, [hi])}"
                    )
                if below.get(hi, lo) != lo:
                    raise InputError(
                        f"contradiction: object {describe(self.vocab, [hi])} cannot stand on both "
                        f"{describe(self.vocab, [below[hi]])} and {describe(self.vocab, [lo])}"
                    )
                above[lo], below[hi] = hi, lo
        pos: dict[int, tuple[float, float, float]] = {}
        for g in goals:
            if "pose" in g:
                o = g["objects"][0]
                if o in pos and tuple(pos[o]) != tuple(g["pose"]):
                    raise InputError(f"contradiction: object {o} is given two different poses")
                pos[o] = g["pose"]
