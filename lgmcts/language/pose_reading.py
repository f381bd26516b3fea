"""The reading of a pose said in numbers: one object to a pose of :mod:`.poses` (registered first among the
early readings of :mod:`.readings`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import InputError
from . import poses
from .assembly import _Pending

if TYPE_CHECKING:
    from .readings import Frame
    from .rules import _Parser

__all__ = ["read_pose"]


def read_pose(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"the mug to x = 0.10 m, y = -0.05 m, yaw 0 rad", "the cup at (10 cm, -5 cm)": one object to a pose said in
    numbers (:mod:`.poses`); a yaw not said is the object's own."""
    marks = [k for k, w in enumerate(f.words) if poses.is_mark(w)]
    if not marks:
        return None
    if len(marks) > 1:
        # "the bowl at x = 15 cm, y = -5 cm, and the plate at (-20 cm, 10 cm)": each pose with the object
        # named just before it
        if self._find(f.words[marks[-1] + 1 :]):
            raise InputError(f"'{f.text}': two poses in one clause; give each object its own")
        out: list[_Pending] = []
        lo = 0
        for k in marks:
            out += _pose_goal(self, f.words[lo:k], f.words[k], f.text)
            lo = k + 1
        return out
    return _pose_goal(self, tuple(w for w in f.words if not poses.is_mark(w)), f.words[marks[0]], f.text)


def _pose_goal(self: _Parser, words: tuple[str, ...], mark: str, text: str) -> list[_Pending]:
    """The pose goal of the one object ``words`` name, at the pose of ``mark``."""
    said = self._poses[ord(mark[-1]) - ord("a")]
    mentions = self._find(words)
    sel = self._select(mentions[0]) if len(mentions) == 1 else None
    chosen = self.state.selection
    if not mentions and chosen is not None and len(chosen) == 1 and isinstance(chosen[0], int):
        sel, self.state.selection = [chosen[0]], None  # "Box: 250 mm right of centre, 100 mm toward me."
    if not isinstance(sel, list) or len(sel) != 1:
        raise InputError(f"'{text}': a pose said in numbers is for one object; name that object")
    oid = sel[0]
    ws = self.spec.workspace
    try:
        pose = said.resolved(self.spec.object(oid).pose, ((ws.x[0] + ws.x[1]) / 2, (ws.y[0] + ws.y[1]) / 2))
    except ValueError as exc:
        raise InputError(f"'{text}': object {oid} {exc}") from None
    return [_Pending("pose", [oid], None, pose, text)]
