"""A mention resolved on the scene: the ids its category, colours, qualifiers and exceptions allow
(:func:`candidates`), then the quantity its determiner asks for (:func:`select`: fixed ids or a
:class:`.vocabulary.Choice` made later).
"""

from __future__ import annotations

from dataclasses import replace

from ..errors import InputError
from .vocabulary import Choice, Mention, Vocabulary, colour_words


#: Relative tolerance within which two measures count as equal.
MEASURE_TOL = 0.05


def _colour_only(vocab: Vocabulary, m: Mention) -> list[int]:
    """The objects with the mention's colours, of any category."""
    try:
        return list(candidates(vocab, replace(m, names=None, head="", same_color_as=None, excluding=(), det="all")))
    except InputError:
        return []


def _any_match(vocab: Vocabulary, m: Mention) -> bool:
    """Whether some object has the mention's category and colours (exactly or in part)."""
    try:
        return bool(candidates(vocab, replace(m, same_color_as=None, excluding=(), det="all")))
    except InputError:
        return False


def describe(vocab: Vocabulary, ids: list[int] | tuple[int, ...]) -> str:
    """"5 (white bottle), 10 (blue bottle)"."""
    return ", ".join(f"{i} ({vocab.label(i)})" for i in ids)


def candidates(vocab: Vocabulary, m: Mention, *, named: frozenset[int] = frozenset(), inherit: frozenset[str] | None = None) -> list[int]:
    """Ids the mention's category, colours and qualifiers allow (before quantity)."""
    known = {i for i, _, _ in vocab.objects}
    if m.det == "ids":
        bad = [i for i in m.ids if i not in known]
        if bad:
            raise InputError(f"'{m.text}': the scene has no object with id {bad[0]}")
        return list(m.ids)
    names = m.names if m.names is not None else inherit
    out = [
        i for i, n, c in vocab.objects
        if (names is None or n in names) and (m.colors is None or c in m.colors)
    ]
    if out and m.colors is not None and m.loose and (m.plural or m.det == "all"):
        # "all the red things": everyday words take the red swirl heart too;
        # "red objects" (the peers' word) keeps exact colours.
        firsts = {colour_words(c)[0] for c in m.colors if len(colour_words(c)) == 1}
        out = sorted(set(out) | {i for i, n, c in vocab.objects if (names is None or n in names)
                                 and len(colour_words(c)) > 1 and colour_words(c)[0] in firsts})
    if not out and m.colors is not None:
        # No exact colour: the colour words given may be part of the object's
        # colour ("the swirl flower" for a red swirl flower; every word given
        # must be in it).
        wanted = [set(colour_words(c)) for c in m.colors]
        out = [
            i for i, n, c in vocab.objects
            if (names is None or n in names) and any(w <= set(colour_words(c)) for w in wanted)
        ]
    compared: set[int] = set()  # the objects whose colour the mention is compared with
    if m.same_color_as is not None:
        ref = select(vocab, m.same_color_as, named=named)
        if isinstance(ref, Choice):
            raise InputError(f"'{m.same_color_as.text}' must name a definite object to compare colours with")
        ref_colors = {c for i, _, c in vocab.objects if i in ref}
        if len(ref_colors) != 1:
            raise InputError(f"'{m.same_color_as.text}' has several colours ({', '.join(sorted(ref_colors))})")
        (rc,) = ref_colors
        # As in the peers' object selectors, the reference object itself is
        # one of "the objects whose color is the same as X".
        out = [i for i in out if any(c == rc for j, _, c in vocab.objects if j == i)]
        if m.det == "other":
            # "everything else with the bottle's colour", "the other things of its colour": "else"
            # and "other" leave the reference object out.
            out = [i for i in out if i not in ref]
        compared = set(ref)
    for f in m.filters:
        out = _apply_filter(vocab, f, out, named)
    if m.det == "the" and not m.plural and len(out) > 1:
        # "the one matching the T": one object, never the one it is compared with
        compared |= {i for a, op, r in m.filters if a == "color" and op == "eq"
                     for i in candidates(vocab, r, named=named)}
        rest = [i for i in out if i not in compared]
        if len(rest) == 1:
            out = rest
    for e in m.excluding:
        ex = candidates(vocab, e, named=named, inherit=names)
        out = [i for i in out if i not in ex]
    if m.det in ("other", "another", "fresh"):
        out = [i for i in out if i not in named]
        if m.det == "other" and names is None and m.count and named and len(out) > m.count:
            # "the red can and the white can ... the other two": of the kinds named before, where that leaves
            # exactly the number said (the blue and the green can)
            name_of = {i: n for i, n, _ in vocab.objects}
            kinds = {name_of[i] for i in named if i in name_of}
            same = [i for i in out if name_of[i] in kinds]
            if len(same) == m.count:
                out = same
    if m.color_order and len(m.color_order) > 1:
        rank = {c: k for k, c in enumerate(m.color_order)}
        color = {i: c for i, _, c in vocab.objects}
        out.sort(key=lambda i: (rank.get(color[i], 99), i))
    return out


def _apply_filter(vocab: Vocabulary, f: tuple, out: list[int], named: frozenset[int]) -> list[int]:
    attr, op, ref = f
    if attr == "value":
        vals = set(candidates(vocab, ref, named=named)) if _any_match(vocab, ref) else set()
        return [i for i in out if (i in vals) == (op == "eq")]
    if attr in ("color", "name"):
        # "the same shape as heart" with several hearts: they share the value.
        col = 2 if attr == "color" else 1
        refs = candidates(vocab, ref, named=named)
        if not refs:
            raise InputError(f"nothing in the scene matches '{ref.text}'")
        values = {o[col] for o in vocab.objects if o[0] in refs}
        if len(values) != 1 and (ref.text.split()[:1] in (["any"], ["one"], ["either"], ["some"], ["a"], ["an"])
                                 or (ref.plural and ref.det in ("the", "all"))):
            # "the blocks sharing a colour with any of the letters", "... with a bowl": any one of their values;
            # "the cans that are the same colour as the bowls": each the colour of one of them
            same = {o[0] for o in vocab.objects if o[col] in values}
            if op == "eqx":
                return [i for i in out if i in same and i not in refs]
            return [i for i in out if (i in same) == (op == "eq")]
        if len(values) != 1:
            raise InputError(f"'{ref.text}' is ambiguous: it matches objects {describe(vocab, refs)} "
                             f"of different {'colours' if attr == 'color' else 'kinds'}")
        (rv,) = values
        same = {o[0] for o in vocab.objects if o[col] == rv}
        if op == "eqx":
            return [i for i in out if i in same and i not in refs]
        return [i for i in out if (i in same) == (op == "eq")]
    sel = select(vocab, ref, named=named)
    if isinstance(sel, Choice) or len(sel) != 1:
        raise InputError(f"'{ref.text}' must name one definite object to compare with")
    (r,) = sel
    if op == "eqx":
        out = [i for i in out if i != r]
        op = "eq"
    k = {"height": 1, "volume": 2, "width": 3}[attr]
    meas = {x[0]: x[k] for x in vocab.measures}
    ref_v: float = meas.get(r, 0.0)

    def rel(v: float) -> str:
        if abs(v - ref_v) <= MEASURE_TOL * max(abs(v), abs(ref_v), 1e-9):
            return "eq"
        return "lt" if v < ref_v else "gt"

    keep = {"eq": ("eq",), "ne": ("lt", "gt"), "lt": ("lt",), "gt": ("gt",), "le": ("lt", "eq"), "ge": ("gt", "eq")}[op]
    return [i for i in out if rel(meas.get(i, 0.0)) in keep]


def select(vocab: Vocabulary, m: Mention, *, named: frozenset[int] = frozenset()) -> list[int] | Choice:
    """Resolve a mention to fixed ids, or to a :class:`Choice` for "one X"/"three X".

    Raises
    ------
    InputError
        Empty selection, ambiguity ("the bottle" with two bottles) or too few
        objects for a count.
    """
    if m.det == "pronoun":
        raise InputError(f"'{m.text}' refers to nothing before it")
    ids = candidates(vocab, m, named=named)
    if not ids:
        raise InputError(f"nothing in the scene matches '{m.text}'")
    if m.of_count is not None and len(ids) != m.of_count:
        raise InputError(f"'{m.text}' speaks of {m.of_count}, but {len(ids)} objects match: {describe(vocab, ids)}")
    if m.det in ("all", "ids"):
        return ids
    if m.det == "other":
        if m.plural or (m.count is not None and len(ids) == m.count > 1):
            return ids
        if len(ids) > 1:
            raise InputError(f"'{m.text}' is ambiguous: it matches objects {describe(vocab, ids)}")
        return ids
    if m.det in ("the", "") and m.colors is not None and len(m.colors) == len(ids) > 1 and len({
            c for i, _, c in vocab.objects if i in ids}) == len(ids):
        # "the red, blue and green block": one block of each colour named.
        return ids
    if m.det == "the":
        if len(ids) > 1:
            raise InputError(
                f"'{m.text}' is ambiguous: it matches objects {describe(vocab, ids)}; say which one (e.g. by colour or id)"
            )
        return ids
    if m.det == "both":
        if len(ids) != 2:
            raise InputError(f"'{m.text}' says both, but {len(ids)} objects match: {describe(vocab, ids)}")
        return ids
    if m.det == "half":
        if len(ids) % 2:
            raise InputError(f"'{m.text}': half of {len(ids)} objects is not a whole number")
        return Choice(tuple(ids), len(ids) // 2, m.text)
    k = 1 if m.det in ("one", "another") else int(m.count or 1)
    fresh = m.det in ("another", "fresh")
    if k < 1:
        raise InputError(f"'{m.text}' asks for no object")
    if len(ids) < k:
        raise InputError(f"'{m.text}' asks for {k} objects but only {len(ids)} match: {describe(vocab, ids)}")
    if len(ids) == k and not fresh:
        return ids
    return Choice(tuple(ids), k, m.text, fresh)
