"""Referring expressions of the generated instructions, and their meaning.

A reference is a small tuple:

* ``("one", color, name)``: "the red swirl flower" (``color`` may be ``None``: "the flower");
* ``("all_name", name)``: "all blocks";
* ``("all_color", color)``: "all red objects";
* ``("same_color", one)``: "objects whose color is the same as the triangle"
  (the named object itself is included, as in the peers' object selectors);
* ``("list", (one, one, ...))``: "the red block, the blue heart and the granite star".

:func:`resolve` gives the set of objects a reference means. A generator keeps
a reference only when :func:`resolve` and the looser reading
:func:`resolve_loose` (colours matched by any shared word, so "red" also
touches "red swirl") agree: then no reasonable parser can read another set.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .catalog import color_words, kind

__all__ = ["phrase", "resolve", "resolve_loose", "unambiguous"]

Ref = tuple[Any, ...]


def _objs(objects: list[dict]) -> list[tuple[int, str, str]]:
    return [(int(o["id"]), str(o["name"]), str(o.get("color", ""))) for o in objects]


def resolve(ref: Ref, objects: list[dict]) -> frozenset[int]:
    """Ids that ``ref`` means in a scene of ``objects`` (exact reading)."""
    objs = _objs(objects)
    k = ref[0]
    if k == "one":
        _, color, name = ref
        return frozenset(i for i, n, c in objs if n == name and (color is None or c == color))
    if k == "all_name":
        return frozenset(i for i, n, _ in objs if n == ref[1])
    if k == "all_color":
        return frozenset(i for i, _, c in objs if c == ref[1])
    if k == "same_color":
        one = resolve(ref[1], objects)
        if len(one) != 1:
            return frozenset()
        (j,) = one
        cj = next(c for i, _, c in objs if i == j)
        return frozenset(i for i, _, c in objs if c == cj)
    if k == "list":
        out: set[int] = set()
        for r in ref[1]:
            out |= resolve(r, objects)
        return frozenset(out)
    raise ValueError(f"unknown reference kind {k}")


def resolve_loose(ref: Ref, objects: list[dict]) -> frozenset[int]:
    """Ids that a loose reading of ``ref`` could mean (colours by shared words)."""
    objs = _objs(objects)
    k = ref[0]

    def close(c1: str, c2: str) -> bool:
        return bool(color_words(c1) & color_words(c2)) or c1 == c2

    if k == "one":
        _, color, name = ref
        return frozenset(i for i, n, c in objs if n == name and (color is None or close(c, color)))
    if k == "all_name":
        return frozenset(i for i, n, _ in objs if n == ref[1])
    if k == "all_color":
        return frozenset(i for i, _, c in objs if close(c, ref[1]))
    if k == "same_color":
        one = resolve_loose(ref[1], objects)
        if len(one) != 1:
            return frozenset(i for i, _, _ in objs)
        (j,) = one
        cj = next(c for i, _, c in objs if i == j)
        return frozenset(i for i, _, c in objs if close(c, cj))
    if k == "list":
        out: set[int] = set()
        for r in ref[1]:
            out |= resolve_loose(r, objects)
        return frozenset(out)
    raise ValueError(f"unknown reference kind {k}")


def unambiguous(ref: Ref, objects: list[dict], want: frozenset[int] | set[int]) -> bool:
    """Whether ``ref`` means exactly ``want`` under both readings (and each "one" one object)."""
    want = frozenset(want)
    if ref[0] == "one" and len(want) != 1:
        return False
    if ref[0] == "list" and not all(
        unambiguous(r, objects, resolve(r, objects)) and len(resolve(r, objects)) == 1 for r in ref[1]
    ):
        return False
    if ref[0] == "same_color" and len(resolve_loose(ref[1], objects)) != 1:
        return False
    return resolve(ref, objects) == want and resolve_loose(ref, objects) == want


def _the(ref: Ref) -> str:
    _, color, name = ref
    return f"the {color} {name}" if color else f"the {name}"


def phrase(ref: Ref, rng: np.random.Generator) -> str:
    """Words for ``ref``, choosing among a few phrasings with ``rng``."""
    k = ref[0]
    if k == "one":
        return _the(ref)
    if k == "all_name":
        plural = kind(ref[1]).plural
        return str(rng.choice([f"all {plural}", f"all the {plural}", f"all {plural}"]))
    if k == "all_color":
        return str(rng.choice([f"all {ref[1]} objects", f"all the {ref[1]} objects", f"all {ref[1]} items"]))
    if k == "same_color":
        return str(
            rng.choice(
                [
                    f"objects whose color is the same as {_the(ref[1])}",
                    f"all objects with the same color as {_the(ref[1])}",
                    f"the objects of the same color as {_the(ref[1])}",
                ]
            )
        )
    if k == "list":
        words = [_the(r) for r in ref[1]]
        return ", ".join(words[:-1]) + " and " + words[-1]
    raise ValueError(f"unknown reference kind {k}")
