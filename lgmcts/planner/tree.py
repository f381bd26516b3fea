"""Search-tree nodes. Nodes hold an immutable :class:`SearchState`; only their
visit statistics change during the search."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..formats import Action
from .step import SearchState

__all__ = ["Node"]


@dataclass(eq=False)
class Node:
    """One search-tree node.

    ``action`` is the action that led here from ``parent`` (``None`` for the
    root and for a goal object committed where it already stood); ``attempts``
    counts expansion tries per object; ``dead`` marks a node with nothing left
    to explore below it.
    """

    state: SearchState
    parent: "Node | None" = None
    action: Action | None = None
    depth: int = 0
    n_actions: int = 0
    reward: float = 0.0
    visits: int = 0
    value: float = 0.0
    children: list["Node"] = field(default_factory=list)
    attempts: dict[int, int] = field(default_factory=dict)
    dead: bool = False

    def path(self) -> list[Action]:
        """Actions from the root to this node."""
        out, node = [], self
        while node is not None:
            if node.action is not None:
                out.append(node.action)
            node = node.parent
        return out[::-1]

    def worlds(self) -> list:
        """World states along :meth:`path`: the root's, then the one after each action."""
        out, node = [], self
        while node is not None:
            if node.action is not None or node.parent is None:
                out.append(node.state.world)
            node = node.parent
        return out[::-1]
