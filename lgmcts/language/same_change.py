"""A change said with "the same": the other side of a relation.

"Put the yellow cup on the right of the red bowl. Now do the same with the orange cup, but (put it) on the left."
is the relation before with the new objects and the side said anew (:meth:`.passes._TokenPasses._same_as_before`
calls :func:`other_side` before it reads a place, a facing or a measure said with "the same").
"""

from __future__ import annotations

__all__ = ["other_side"]


def other_side(out: list[str], more: list[str], joins: frozenset[str]) -> tuple[str, ...] | None:
    """"the same with the orange cup, but (put it) on the left" after a relation on the right: the relation's side
    said anew (left for right, front for behind and back), None where ``more`` is not one side or the clause
    before names no side of that axis once."""
    words = [w for w in more if w not in joins]
    if words[:2] in (["put", "it"], ["put", "them"], ["place", "it"], ["place", "them"], ["move", "it"]):
        words = words[2:]
    words = [w for w in words if w not in ("on", "to", "the", "its", "their", "side", "hand", "of", "it", "in")]
    side = {"left": "left", "right": "right", "front": "front", "behind": "behind", "back": "behind"}.get(
        words[0]) if len(words) == 1 else None
    if side is None:
        return None
    axis = ("left", "right") if side in ("left", "right") else ("front", "behind")
    at = [k for k, w in enumerate(out) if w in axis]
    if len(at) != 1:
        return None
    return (*out[: at[0]], side, *out[at[0] + 1 :])
